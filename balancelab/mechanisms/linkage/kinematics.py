"""`LinkageKinematics`: numeric kinematics of any planar linkage of revolute joints.

The coordinates are the absolute angles of the *driving* bodies (``theta_<body index>``,
from the global x-axis, as ``theta_1``, ``theta_2`` of the course); the other bodies'
angles are solved from the loop-closure equations (:mod:`.topology`). The linkage is
first *assembled* (damped Newton from a guess, then from fixed pseudo-random starts),
which picks its circuit; the degrees of freedom are the number of body angles minus the
numeric rank of the closure Jacobian there (compared with Grübler's count). A drawing at a
singular pose (a change point: a parallelogram or an s + l = p + q four-bar drawn flat, where the
rank drops and two branches cross) is first moved about 0.02 rad off it, onto the branch on which
the most pairs of bodies keep their drawn relative angle (a parallelogram stays a parallelogram);
pass ``guess=`` to pick another branch. Then:

* a tree (no loop): every body angle is a coordinate, each turns fully;
* one degree of freedom: the circuit is followed by continuation from the assembled
  configuration in both directions (steps of 2 degrees, halved down to 1e-9 rad at a
  limit), which gives the range of the driving angle and a table of solutions;
* more degrees of freedom: a grid over one turn of each coordinate is flood-filled from
  the assembled configuration, each node solved from a solved neighbour.

``poses(q)`` starts Newton from the table (a cubic Hermite interpolation with the circuit's
tangents at the nodes, good to about 1e-8 rad, so that one Newton step reaches round-off) or from
the nearest solved grid node (three continuation sub-steps, each predicted along the tangent),
for all configurations at once. A
configuration is reported reachable only when it lies in the range, Newton closes every
loop to ``1e-10`` of the linkage's size, and the solution stayed on the circuit (moved
less than 0.3 rad from its start). Layer: mechanisms.
"""
from __future__ import annotations

from typing import Mapping, Sequence

import numpy as np

from ...core.elements import Joint
from ...core.kinematics import Kinematics
from ..geometry import rotate
from .topology import Slider, Topology, newton

__all__ = ["LinkageKinematics", "STEP"]

#: continuation step along a single driving angle (rad)
STEP = np.radians(2.0)
_JUMP = 0.3  # largest change (rad) of a dependent angle from its start that still counts as the same circuit
_STARTS = 96  # pseudo-random starting configurations tried when assembling


class LinkageKinematics(Kinematics):
    """Kinematics of a planar linkage of revolute joints, solved numerically.

    Parameters
    ----------
    nbodies : int
        Number of bodies, the ground (body 0) included.
    joints : sequence of Joint
        The revolute joints.
    driving : sequence of int, optional
        Bodies whose absolute angles are the coordinates (as many as the degrees of
        freedom); chosen automatically (earliest bodies first) by default.
    guess : mapping of int to float, optional
        Body angles (rad) to start the assembly from: this picks the circuit (branch).
    names : sequence of str, optional
        Body names, for error messages.

    Raises
    ------
    ValueError
        If the linkage does not assemble, is over-constrained (no mobility), or the
        driving bodies do not determine the other angles.

    Examples
    --------
    A four-bar (ground pivots 1 m apart, crank 0.4 m, coupler 1 m, rocker 0.8 m):

    >>> J = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (0.4, 0.0), 2, (0.0, 0.0)),
    ...      Joint(2, (1.0, 0.0), 3, (0.8, 0.0)), Joint(3, (0.0, 0.0), 0, (1.0, 0.0))]
    >>> kin = LinkageKinematics(4, J, guess={1: 1.0, 2: 0.0, 3: 1.5})
    >>> kin.names, kin.dof, kin.full_turn
    (('theta_1',), 1, True)
    >>> float(kin.joint_error([[0.3], [2.0]], J).max()) < 1e-12
    True
    """

    def __init__(self, nbodies: int, joints: Sequence[Joint], driving: Sequence[int] | None = None,
                 guess: Mapping[int, float] | None = None, names: Sequence[str] | None = None,
                 sliders: Sequence[Slider] = (), strokes: Sequence | None = None) -> None:
        self.nbodies = int(nbodies)
        self.joints = tuple(Joint(*j) for j in joints)
        self.sliders = tuple(p if isinstance(p, Slider) else Slider(*p) for p in sliders)
        self.body_names = tuple(names) if names is not None else tuple(f"body {i}" for i in range(nbodies))
        ends = [(j.body_i, j.point_i) for j in self.joints] + [(j.body_j, j.point_j) for j in self.joints]
        ends += [(sl.body_a, sl.point_a) for sl in self.sliders] + [(sl.body_b, sl.point_b) for sl in self.sliders]
        ground = [np.asarray(p, dtype=float) for b, p in ends if b == 0]
        ref = ground[0] if ground else np.zeros(2)  # ground points count from one of them: the linkage's
        pts = [abs(v) for b, p in ends for v in (np.asarray(p, dtype=float) - ref if b == 0 else p)]  # size,
        self.size = max(max(pts, default=0.0), 1e-9)  # not its distance from the origin
        self.topology = Topology(self.nbodies, self.joints, self.sliders, self.size)
        self.nvar = self.topology.nvar
        self.strokes = np.array([(-2 * self.size, 2 * self.size) if st is None else st
                                 for st in (strokes or [None] * len(self.sliders))], dtype=float).reshape(-1, 2)
        self.scale = np.where(np.arange(self.nvar) >= self.nbodies, self.size, 1.0)  # rad, or m for a slide
        # closure to 1e-13 of the size, and to 1e-10 m where round-off allows (a linkage 1e5 m across
        # still closes its joints to the 1e-9 m a Design checks)
        self.tol = max(min(1e-13 * self.size, 1e-10), 1e-15 * self.size)
        self.accept = 1e-10 * self.size
        self.solved = self.topology.nequations > 0  # else every body angle is a coordinate
        self.assembled = self._assemble(guess)
        self.grubler = 3 * (self.nbodies - 1) - 2 * (len(self.joints) + len(self.sliders))
        self._mobility()
        self.driving = self._driving(driving)
        self.dependent = [b for b in range(1, self.nvar) if b not in self.driving]
        self.names = tuple(self.variable_name(b) for b in self.driving)
        self.descriptions = tuple(self._describe(b) for b in self.driving)
        self.independent_symbols = True if not self.solved else None
        self.full_turn = False
        self._table: tuple[np.ndarray, np.ndarray] | None = None  # (driving angles, Hermite coefficients)
        self._grid: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None  # (lowest q, steps, solutions)
        if not self.topology.loops:
            self.full_turn = not any(b >= self.nbodies for b in self.driving)
            self.q_range = np.array([self._span(b) for b in self.driving]).reshape(-1, 2)
        elif self.dof == 1:
            self._follow_circuit()
        else:
            self._fill_grid()

    # ------------------------------------------------------------------ variables
    def variable_name(self, v: int) -> str:
        """``theta_<body>`` for a body angle, ``s_<k>`` (k from 1) for the slide of the k-th prismatic joint."""
        return f"theta_{v}" if v < self.nbodies else f"s_{v - self.nbodies + 1}"

    @property
    def units(self) -> tuple[str, ...]:
        """Unit of each coordinate: ``"rad"`` for a body angle, ``"m"`` for a slide."""
        return tuple("rad" if v < self.nbodies else "m" for v in self.driving)

    def _describe(self, v: int) -> str:
        if v < self.nbodies:
            return f"angle of {self.body_names[v]} from the x-axis"
        sl = self.sliders[v - self.nbodies]
        return f"slide of {self.body_names[sl.body_b]} along {self.body_names[sl.body_a]} (m)"

    def _span(self, v: int) -> tuple[float, float]:
        """Range of a free variable of a tree: a turn (rad), or the slide's stroke (m)."""
        return (-np.pi, np.pi) if v < self.nbodies else tuple(self.strokes[v - self.nbodies])

    # ------------------------------------------------------------------ set-up
    def _assemble(self, guess) -> np.ndarray:
        """Angles of an assembled configuration at which the linkage has its generic mobility.

        The starts are tried in order: ``guess``, the drawing (every body angle zero: the local
        frames as the joint points were written), the drawing with each slide in the middle of its
        stroke and a quarter of the stroke above it, then fixed pseudo-random starts; the first that
        closes every loop with every slide within its stroke (the first that closes them, if none
        does) and on which, once moved off a change point, every slide can move is taken (not a
        degenerate component such as a scissors drawn folded, whose arms lie on each other and turn
        together while its slide stays at 0). If the constraint Jacobian loses rank there (a change point,
        such as a parallelogram drawn flat), the configuration is moved off it (:meth:`_regular`)."""
        n = self.nvar
        starts = np.random.default_rng(0).uniform(-np.pi, np.pi, (_STARTS, n)) * self.scale
        starts[0] = 0.0
        if guess:
            first = np.zeros(n)
            for b, a in dict(guess).items():
                first[int(b)] = float(a)
            starts = np.vstack([first, starts])
        if len(self.sliders):  # the drawing again, each slide in the middle of its stroke, then a quarter up
            mid = np.zeros((2, n))
            mid[:, self.nbodies:] = self.strokes.mean(axis=1)
            mid[1, self.nbodies:] += (self.strokes[:, 1] - self.strokes[:, 0]) / 4
            at = 1 if guess else 0
            starts = np.vstack([starts[:at + 1], mid, starts[at + 1:]])
        starts[:, 0] = 0.0
        if not self.solved:
            return starts[0]
        th, err = newton(self.topology, starts, range(1, n), self.tol, iterations=80, damping=1e-9)
        good = np.flatnonzero(err <= self.accept)
        inside = [g for g in good if self._in_strokes(th[g])]
        good = np.array(inside if inside else good, dtype=int)  # a slide outside its stroke is no configuration
        if not len(good):
            raise ValueError(
                f"the linkage does not assemble: from {len(starts)} starting configurations the loop-closure "
                f"gap stays >= {err.min():.3g} m (check the joint points: a loop must be able to close)")
        for g in good:  # the first start (moved off a change point) on which every slide can move: not a
            moved = self._regular(th[g])  # degenerate component (a scissors drawn folded: its arms on top of
            if self._slides_move(moved):  # each other turn together, its slide stuck at 0)
                return moved
        return self._regular(th[good[0]])

    def _slides_move(self, x: np.ndarray) -> bool:
        """Whether every slide has a motion of the closure's null space at ``x`` that moves it."""
        if not len(self.sliders) or not self.solved:
            return True
        jac = (self.topology.residual_and_jacobian(x)[1] * self.scale)[:, 1:]
        _, s, vt = np.linalg.svd(jac)
        r = int((s > 1e-9 * max(s.max(initial=0.0), 1e-300)).sum())
        null = vt[r:]
        return bool(len(null)) and bool(np.all(np.abs(null[:, self.nbodies - 1:]).max(axis=0) > 1e-6))

    def _in_strokes(self, x: np.ndarray) -> bool:
        """Whether every slide of the configuration ``x`` is within its stroke (to 1e-9 of the size)."""
        slides = x[self.nbodies:]
        tol = 1e-9 * self.size
        return bool(np.all((slides >= self.strokes[:, 0] - tol) & (slides <= self.strokes[:, 1] + tol)))

    def _regular(self, at: np.ndarray) -> np.ndarray:
        """``at`` if the closure Jacobian has its local generic rank there; otherwise a nearby
        assembled configuration (about 0.02 rad away) where the rank is higher. At a change point this
        picks the branch on which the most pairs of bodies keep their relative angle (a parallelogram
        drawn flat stays a parallelogram: crank and rocker stay parallel, and so do coupler and ground);
        among equals, the most mobile branch, then the one whose joints' relative angles change least
        for the size of the move."""
        moving = range(1, self.nvar)
        rank0 = self._rank(at, moving)
        kick = np.random.default_rng(1).normal(0.0, 0.02, (24, self.nvar)) * self.scale
        kick[:, 0] = 0.0
        near, err = newton(self.topology, at + kick, moving, self.tol, iterations=80, damping=1e-9)
        delta = (near - at) / self.scale
        size = np.abs(delta).max(axis=-1)
        ok = (err <= self.accept) & (size < 0.2) & (size > 1e-6)
        ranks = np.array([self._rank(y, moving) if o else -1 for y, o in zip(near, ok)])
        if not ok.any() or ranks.max() <= rank0:
            return at
        pick = ok & (ranks > rank0)
        pairs = np.abs(delta[:, :, None] - delta[:, None, :]) <= 1e-6 * np.maximum(size, 1e-300)[:, None, None]
        kept = pairs.sum((1, 2))
        rel = np.stack([delta[:, j.body_i] - delta[:, j.body_j] for j in self.joints], -1)
        change = (rel ** 2).sum(-1) / np.maximum(size, 1e-300) ** 2
        # off the singular point first, then most pairs kept, then the most mobile branch, then least change
        order = np.lexsort((change, ranks, -kept, ~pick))
        return near[int(order[0])]

    def _rank(self, angles: np.ndarray, columns) -> int:
        if not self.solved:
            return 0
        jac = (self.topology.residual_and_jacobian(angles)[1] * self.scale)[:, list(columns)]
        s = np.linalg.svd(jac, compute_uv=False)
        return int((s > 1e-9 * max(s.max(), 1e-300)).sum()) if s.size else 0

    def _mobility(self) -> None:
        moving = range(1, self.nvar)
        rank = self._rank(self.assembled, moving)
        self.rank = rank
        mobility = self.nvar - 1 - rank
        if mobility <= 0:
            raise ValueError(
                f"the linkage is over-constrained: it cannot move (Grübler's count 3(n - 1) - 2j = "
                f"{self.grubler} with n = {self.nbodies} bodies and j = {len(self.joints) + len(self.sliders)} "
                f"joints; the constraint Jacobian has rank {rank} for {self.nvar - 1} body angles and slides)")
        self.redundant = mobility - self.grubler  # constraints that do not count (e.g. a parallelogram's)

    def _driving(self, driving) -> tuple[int, ...]:
        dof = self.nvar - 1 - self.rank
        moving = list(range(1, self.nvar))
        if driving is None:
            chosen: list[int] = []
            for b in moving:
                if len(chosen) == dof:
                    break
                rest = [c for c in moving if c not in chosen and c != b]
                if self._rank(self.assembled, rest) == self.rank:
                    chosen.append(b)
            return tuple(chosen)
        chosen = [int(b) for b in driving]
        if len(chosen) != dof or len(set(chosen)) != dof or not all(1 <= b < self.nvar for b in chosen):
            raise ValueError(f"driving must name {dof} distinct moving bodies or slides (the linkage has {dof} "
                             f"degrees of freedom), got {[self._label(b) for b in chosen]}")
        rest = [c for c in moving if c not in chosen]
        if self._rank(self.assembled, rest) != self.rank:
            raise ValueError(f"the driving coordinates {[self._label(b) for b in chosen]} do not "
                             "determine the other bodies in the assembled configuration; choose other driving bodies")
        return tuple(chosen)

    def _label(self, v: int):
        return self.body_names[v] if 0 <= v < self.nbodies else self.variable_name(v) if v < self.nvar else v

    def _predict(self, start: np.ndarray, q: np.ndarray) -> np.ndarray:
        """First-order predictor: move the dependent angles of ``start`` along the circuit's tangent
        ``dz/dq = -J_z^+ J_q`` to the driving angles ``q`` (each move clipped to 0.5 rad). Following the
        tangent keeps the continuation on its branch where two branches cross (a parallelogram's
        change point)."""
        jac = self.topology.residual_and_jacobian(start)[1]
        unit = self.scale[self.dependent]  # columns alike, so that the damping cannot swamp a tiny linkage's angles
        Jz, Jq = jac[..., self.dependent] * unit, jac[..., list(self.driving)]
        Jzt = np.swapaxes(Jz, -1, -2)
        A = Jzt @ Jz
        A = A + (1e-12 * np.trace(A, axis1=-2, axis2=-1)[..., None, None] + 1e-300) * np.eye(len(self.dependent))
        dq = q - start[..., list(self.driving)]
        with np.errstate(all="ignore"):
            dz = -np.linalg.solve(A, (Jzt @ (Jq @ dq[..., None])))[..., 0] * unit
        out = np.array(start, dtype=float, copy=True)
        lim = 0.5 * self.scale[self.dependent]
        out[..., self.dependent] += np.clip(np.where(np.isfinite(dz), dz, 0.0), -lim, lim)
        return out

    def _solve(self, start: np.ndarray, q: np.ndarray, iterations: int = 12, predict: bool = False):
        """Set the driving angles of ``start`` to ``q`` and solve; returns (angles, ok)."""
        th = self._predict(start, q) if predict else np.array(start, dtype=float, copy=True)
        th[..., list(self.driving)] = q
        sol, err = newton(self.topology, th, self.dependent, self.tol, iterations)
        jump = np.abs((sol - th)[..., self.dependent] / self.scale[self.dependent]).max(axis=-1)
        return sol, (err <= self.accept) & (jump < _JUMP)

    def _march(self, direction: int) -> list[np.ndarray]:
        """Solutions along the driving coordinate from the assembled configuration (one direction): a
        turn for an angle, up to the stroke's end for a slide (steps of :data:`STEP` times the size)."""
        d = self.driving[0]
        unit = self.scale[d]
        if d < self.nbodies:
            length = 2 * np.pi
        else:
            lo, hi = self.strokes[d - self.nbodies]
            length = max((hi if direction > 0 else -lo) + (-1 if direction > 0 else 1) * self.assembled[d], 0.0)
        top = STEP * unit
        nodes, prev, h, total = [self.assembled], self.assembled, top, 0.0
        slope = np.zeros(self.nvar)
        while total < length - 1e-12 * unit and h > 1e-9 * unit:
            step = min(h, length - total)
            q = prev[self.driving[0]] + direction * step
            # the first step follows the tangent (the start may sit next to a change point)
            sol, ok = self._solve(prev + slope * step, np.array([q]), predict=len(nodes) == 1)
            if ok:
                slope = (sol - prev) / step
                nodes.append(sol)
                prev, total, h = sol, total + step, min(2 * h, top)
            else:
                h /= 2
        return nodes

    def _follow_circuit(self) -> None:
        d = self.driving[0]
        up = self._march(+1)
        q0 = self.assembled[d]
        closed = (d < self.nbodies and abs(up[-1][d] - q0 - 2 * np.pi) < 1e-9 and
                  np.allclose(np.angle(np.exp(1j * (up[-1] - self.assembled))), 0.0, atol=1e-6))
        if closed:
            self.full_turn = True
            nodes = up
            self.q_range = np.array([[q0 - np.pi, q0 + np.pi]])
        else:
            down = self._march(-1)
            nodes = down[::-1] + up[1:]
            self.q_range = np.array([[nodes[0][d], nodes[-1][d]]])
        table = np.array(nodes)
        if len(table) < 2:  # never an IndexError from the look-up: say what is wrong
            raise ValueError(f"the linkage cannot move from its assembled configuration along "
                             f"{self.variable_name(d)}: its stroke or range leaves no room "
                             "(pass strokes that contain the assembled configuration, or a guess=)")
        self._table = (table[:, d], self._hermite(table))

    def _hermite(self, table: np.ndarray) -> np.ndarray:
        """Cubic Hermite coefficients ``(intervals, 4, dependent)`` of the dependent angles between
        the table's nodes, from the tangents ``dz/dq`` there; linear where a tangent is too steep."""
        d = self.driving[0]
        dq = 1e-3 * self.scale[d]
        slope = (self._predict(table, table[:, [d]] + dq) - table)[:, self.dependent] / dq
        smooth = np.all(np.abs(slope) * dq < 0.49 * self.scale[self.dependent], axis=-1)  # the tangent was not clipped
        z = table[:, self.dependent]
        h = np.diff(table[:, d])[:, None]
        delta, s0, s1 = np.diff(z, axis=0), h * slope[:-1], h * slope[1:]
        cubic = np.stack([z[:-1], s0, 3 * delta - 2 * s0 - s1, s0 + s1 - 2 * delta], axis=1)
        line = np.stack([z[:-1], delta, 0 * delta, 0 * delta], axis=1)
        return np.where((smooth[:-1] & smooth[1:])[:, None, None], cubic, line)

    def _fill_grid(self) -> None:
        """Flood-fill a grid over one turn of each driving angle (the stroke of a driving slide) from the
        assembled configuration."""
        dof = self.dof
        m = max(9, int(round(4000 ** (1 / dof))) | 1)
        q0 = self.assembled[list(self.driving)]
        axes = [q0[i] + np.linspace(-np.pi, np.pi, m) if d < self.nbodies else
                np.linspace(self.strokes[d - self.nbodies][0], self.strokes[d - self.nbodies][1], m) for i, d in enumerate(self.driving)]
        shape = (m,) * dof
        sol = np.full(shape + (self.nvar,), np.nan)
        seen = np.zeros(shape, dtype=bool)
        centre = tuple(m // 2 if d < self.nbodies else int(np.argmin(np.abs(axes[i] - q0[i])))
                       for i, d in enumerate(self.driving))
        # the assembled configuration, moved onto the grid node nearest to it along each slide
        got, ok = self._solve(self.assembled[None], np.array([[axes[i][c] for i, c in enumerate(centre)]]),
                              predict=True)
        if not ok[0]:
            raise ValueError("the linkage does not assemble at the grid node next to its assembled configuration; "
                             "pass strokes that contain it or a guess=")
        self.assembled = got[0]
        sol[centre], seen[centre] = self.assembled, True
        frontier = [centre]
        while frontier:
            parents: dict[tuple[int, ...], tuple[int, ...]] = {}
            children: list[tuple[int, ...]] = []
            for node in frontier:
                for i in range(dof):
                    for s in (-1, 1):
                        moved = list(node)
                        moved[i] += s
                        child = tuple(moved)
                        if 0 <= child[i] < m and not seen[child]:
                            seen[child] = True
                            parents[child] = node
                            children.append(child)
            if not children:
                break
            start = np.array([sol[parents[c]] for c in children])
            q = np.array([[axes[i][c[i]] for i in range(dof)] for c in children])
            got, ok = self._solve(start, q, predict=True)
            frontier = [c for c, g, o in zip(children, got, ok) if o]
            for c, g in zip(frontier, got[ok]):
                sol[c] = g
        solved = ~np.isnan(sol[..., 0])
        if solved.all() and all(d < self.nbodies for d in self.driving):  # a full turn when opposite faces agree
            faces = [np.take(sol, [0, m - 1], axis=i) for i in range(dof)]
            self.full_turn = all(np.allclose(np.angle(np.exp(1j * (f.take(0, axis=i) - f.take(1, axis=i)))), 0.0,
                                             atol=1e-6) for i, f in enumerate(faces))
        idx = np.argwhere(solved)
        steps = np.array([a[1] - a[0] for a in axes])
        self.q_range = np.array([[max(axes[i][idx[:, i].min()] - steps[i] / 2, axes[i][0]),
                                  min(axes[i][idx[:, i].max()] + steps[i] / 2, axes[i][-1])] for i in range(dof)])
        self._grid = (np.array([a[0] for a in axes]), steps, sol)

    # ------------------------------------------------------------------ poses
    def _start(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Starting angles for ``q`` from the table or the grid, and the mask of usable starts."""
        if self._table is not None:
            tq, coef = self._table
            x = tq[0] + np.mod(q[..., 0] - tq[0], 2 * np.pi) if self.full_turn else q[..., 0]
            j = np.clip(np.searchsorted(tq, x) - 1, 0, len(tq) - 2)
            w = ((x - tq[j]) / (tq[j + 1] - tq[j]))[..., None]
            c = coef[j]
            th = np.zeros(q.shape[:-1] + (self.nvar,))
            th[..., self.dependent] = ((c[..., 3, :] * w + c[..., 2, :]) * w + c[..., 1, :]) * w + c[..., 0, :]
            th[..., self.driving[0]] = q[..., 0]
            return th, np.ones(q.shape[:-1], dtype=bool)
        assert self._grid is not None  # set by _fill_grid when there is no table
        lo, h, sol = self._grid
        m = sol.shape[0]
        turns = np.floor((q - lo) / (2 * np.pi)) * 2 * np.pi if self.full_turn else 0.0
        q = q - turns  # inside the grid's turn; the whole turns are added back to the driving angles
        idx = np.clip(np.rint((q - lo) / h).astype(int), 0, m - 1)
        start = sol[tuple(idx[..., i] for i in range(self.dof))]
        good = ~np.isnan(start[..., 0])
        start = np.where(good[..., None], start, self.assembled)
        node_q = lo + idx * h
        for t in (1 / 3, 2 / 3, 1.0):  # continuation sub-steps from the grid node
            start, done = self._solve(start, node_q + t * (q - node_q), predict=True)
            good &= done
        start[..., list(self.driving)] += turns
        return start, good

    def angles(self, q) -> tuple[np.ndarray, np.ndarray]:
        """All variables ``(..., nvar)`` (body angles in rad, then slides in m) at configurations ``q``
        and the reachable mask."""
        q = np.asarray(q, dtype=float)
        lo, hi = self.q_range[:, 0], self.q_range[:, 1]
        if self.full_turn:  # every angle is reachable (the table is looked up modulo a turn)
            inside = np.ones(q.shape[:-1], dtype=bool)
        else:
            inside = np.all((q >= lo - 1e-12) & (q <= hi + 1e-12), axis=-1)
        if not self.topology.loops:
            th = np.zeros(q.shape[:-1] + (self.nvar,))
            th[..., list(self.driving)] = q
            if not self.solved:
                return th, inside
            th, ok = self._solve(th, q, iterations=3)  # a tree with sliders: the relative angles, linear
            return th, inside & ok
        start, good = self._start(q)
        if self._grid is not None:  # the last sub-step solved at q already
            return start, inside & good
        th, ok = self._solve(start, q)
        return th, inside & good & ok

    def poses(self, q):
        th, ok = self.angles(q)
        return self.topology.poses(th), ok

    # --------------------------------------------------------------- symbolic
    def symbols(self):
        import sympy as sp

        return tuple(sp.Symbol(n, real=True) for n in self.names)

    def symbolic_point(self, body, point, syms):
        """Global position of a body point as sympy expressions (trees of revolute joints only: every
        angle a symbol)."""
        if self.solved:
            raise NotImplementedError("a linkage with loops or sliders has numeric kinematics only; its energy "
                                      "is checked numerically by balance_report()")
        import sympy as sp

        angle = dict(zip(self.driving, syms))
        coef, _ = self.topology.point(body, point)
        x, y = sp.Float(coef[0, 0]) if coef[0, 0] else 0, sp.Float(coef[0, 1]) if coef[0, 1] else 0
        for b in range(1, self.nbodies):
            if coef[b].any():
                px, py = rotate(sp, angle[b], tuple(sp.Float(v) if v else 0 for v in coef[b]))
                x, y = x + px, y + py
        return (x, y)
