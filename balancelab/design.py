"""`Design`: the one type every balancing method returns and every tool takes.

A design is a planar linkage of rigid bodies (body 0 the ground) joined by revolute
joints, loaded by constant forces (weights, counterweights, external loads) and by
linear springs. It knows its configuration space through a
:class:`~balancelab.kinematics.Kinematics` object and can prove itself balanced: its
potential energy is evaluated over many configurations (:meth:`Design.balance_report`)
and derived symbolically (:meth:`Design.potential_energy_symbolic`,
:meth:`Design.balance_conditions`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, NamedTuple, Sequence

import numpy as np

from .elements import Joint, Load, Spring, SymbolicParts
from .kinematics import Kinematics

__all__ = ["Design", "Energy", "BalanceReport", "UnreachableConfiguration", "BALANCE_TOLERANCE"]

#: Relative tolerance below which a design is reported balanced: the spread of its total
#: potential energy over the sampled configurations, divided by the energy scale.
BALANCE_TOLERANCE: float = 1e-9

_CHUNK = 16384  # configurations evaluated at once by potential_energy


class UnreachableConfiguration(ValueError):
    """Raised when a configuration is outside what the linkage can reach."""


class Energy(NamedTuple):
    """Potential energy (J): ``total = load + spring``, each of the shape of the configurations."""

    total: np.ndarray
    load: np.ndarray
    spring: np.ndarray


@dataclass(frozen=True)
class BalanceReport:
    """How well a design is balanced over a set of configurations.

    Attributes
    ----------
    variation : float
        ``(max V - min V) / scale`` over the configurations: 0 for a perfect balance.
    residual : float
        Largest generalized force ``|dV/dq|`` (J/rad) divided by ``scale`` (1/rad).
    scale : float
        Energy scale (J): the sum over every load and spring of the spread of its own
        energy over the configurations. It does not depend on where the origin is.
    energy : float
        Mean total potential energy (J).
    worst_q : numpy.ndarray
        Configuration with the largest residual generalized force.
    balanced : bool
        ``variation <= tolerance``.
    tolerance : float
        The tolerance used (default :data:`BALANCE_TOLERANCE`).
    n : int
        Number of configurations examined.
    """

    variation: float
    residual: float
    scale: float
    energy: float
    worst_q: np.ndarray
    balanced: bool
    tolerance: float
    n: int

    def __str__(self) -> str:
        verdict = "balanced" if self.balanced else "NOT balanced"
        q = ", ".join(f"{np.degrees(v):.1f}°" for v in np.atleast_1d(self.worst_q))
        return (f"{verdict}: energy varies by {self.variation:.2e} of its scale "
                f"({self.scale:.4g} J) over {self.n} configurations; "
                f"largest residual dV/dq = {self.residual:.2e} × scale per rad at q = ({q}); "
                f"mean energy {self.energy:.6g} J")


class Design:
    """A planar linkage with its loads and springs, balanced or not.

    Parameters
    ----------
    name : str
        Short title shown in figures and reports.
    bodies : sequence of str
        Names of the bodies; index 0 is the ground.
    joints : sequence of Joint
        Revolute joints ``(body_i, point_i, body_j, point_j)``: local points that coincide
        in every configuration.
    kinematics : Kinematics
        Maps configuration coordinates ``q`` (rad) to the pose of every body.
    loads : sequence of Load, optional
        Constant forces (weights, counterweights, external loads).
    springs : sequence of Spring, optional
        Linear springs (``free_length == 0`` for ZFL springs).
    symbolic : SymbolicParts, optional
        The same loads and springs with sympy expressions in design parameters, for
        :meth:`potential_energy_symbolic`.
    labels : mapping of str to (int, (float, float)), optional
        Named points (the papers' A, B, E, K, a1, b1 ...) for figures.
    parameters : mapping of str to float, optional
        Named numbers of the design (spring constants, anchor coordinates ...).
    reference : str, optional
        Where the method comes from (paper and equations).

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3)
    >>> d.balance_report().balanced
    True
    >>> round(d.parameters["k"], 4)
    83.3333
    """

    def __init__(self, name: str, bodies: Sequence[str], joints: Sequence[Joint],
                 kinematics: Kinematics, loads: Sequence[Load] = (), springs: Sequence[Spring] = (),
                 *, symbolic: SymbolicParts | None = None, labels: Mapping | None = None,
                 parameters: Mapping[str, float] | None = None, reference: str = "",
                 prismatic: Sequence = ()):
        self.name = str(name)
        self.bodies = tuple(str(b) for b in bodies)
        nb = len(self.bodies)
        if nb < 2:
            raise ValueError("a design needs the ground and at least one moving body")
        if kinematics.nbodies != nb:
            raise ValueError(f"kinematics describes {kinematics.nbodies} bodies but {nb} are named")
        self.joints = tuple(Joint(*j) for j in joints)
        self.kinematics = kinematics
        self.loads = tuple(loads)
        self.springs = tuple(springs)
        for what, items in (("load", self.loads), ("spring", self.springs)):
            for it in items:
                if not isinstance(it, Load if what == "load" else Spring):
                    raise TypeError(f"every {what} must be a {('Load' if what == 'load' else 'Spring')}, "
                                    f"got {type(it).__name__}")
        for j in self.joints:
            for b in (j.body_i, j.body_j):
                if not 0 <= b < nb:
                    raise ValueError(f"joint {j} names body {b}; bodies are 0..{nb - 1}")
        for ld in self.loads:
            if not 0 <= ld.body < nb:
                raise ValueError(f"load {ld.name or ld} acts on body {ld.body}; bodies are 0..{nb - 1}")
        for s in self.springs:
            for at in (s.a, s.b):
                if not 0 <= at.body < nb:
                    raise ValueError(f"spring {s.name or s} is attached to body {at.body}; "
                                     f"bodies are 0..{nb - 1}")
        self.symbolic = symbolic
        self.labels = dict(labels or {})
        self.parameters = dict(parameters or {})
        self.reference = reference
        self.prismatic = tuple(prismatic)
        self._pack()
        self._sym_cache: dict = {}

    # ------------------------------------------------------------------ basics
    def __repr__(self) -> str:
        return (f"<Design {self.name!r}: {len(self.bodies) - 1} moving bodies, dof {self.dof}, "
                f"{len(self.loads)} loads, {len(self.springs)} springs>")

    @property
    def dof(self) -> int:
        """Number of configuration coordinates."""
        return self.kinematics.dof

    @property
    def q_names(self) -> tuple[str, ...]:
        """Names of the configuration coordinates."""
        return self.kinematics.names

    @property
    def q_range(self) -> np.ndarray:
        """Bounds of the configuration coordinates, shape ``(dof, 2)`` (rad)."""
        return self.kinematics.q_range

    def replace(self, **changes) -> "Design":
        """Return a copy with some constructor arguments changed (e.g. ``springs=...``).

        Parameters
        ----------
        **changes
            Any of the constructor's arguments.

        Returns
        -------
        Design

        Examples
        --------
        >>> import balancelab as bl
        >>> d = bl.lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3)
        >>> heavier = d.replace(loads=[bl.Load(1, (0.5, 0.0), (0.0, -11.0))])
        >>> heavier.balance_report().balanced
        False
        """
        args = dict(name=self.name, bodies=self.bodies, joints=self.joints,
                    kinematics=self.kinematics, loads=self.loads, springs=self.springs,
                    symbolic=self.symbolic, labels=self.labels, parameters=self.parameters,
                    reference=self.reference, prismatic=self.prismatic)
        if "loads" in changes or "springs" in changes:
            args["symbolic"] = None
        args.update(changes)
        return Design(**args)

    def _pack(self) -> None:
        L = self.loads
        self._lb = np.array([ld.body for ld in L], dtype=int)
        self._lp = np.array([ld.point for ld in L], dtype=float).reshape(-1, 2)
        self._lf = np.array([ld.force for ld in L], dtype=float).reshape(-1, 2)
        S = self.springs
        self._sab = np.array([s.a.body for s in S], dtype=int)
        self._sap = np.array([s.a.point for s in S], dtype=float).reshape(-1, 2)
        self._sbb = np.array([s.b.body for s in S], dtype=int)
        self._sbp = np.array([s.b.point for s in S], dtype=float).reshape(-1, 2)
        self._sk = np.array([s.k for s in S], dtype=float)
        self._sl0 = np.array([s.free_length for s in S], dtype=float)

    # ------------------------------------------------------------- kinematics
    def _as_q(self, q) -> np.ndarray:
        if isinstance(q, (str, bytes)):
            raise TypeError("q must be numbers (radians), got a string")
        try:
            q = np.asarray(q, dtype=float)
        except (TypeError, ValueError):
            raise TypeError(f"q must be an array of angles in radians, got {q!r}") from None
        if self.dof == 1 and (q.ndim == 0 or q.shape[-1] != 1):
            q = q[..., None]
        if q.ndim == 0 or q.shape[-1] != self.dof:
            raise ValueError(f"q must have shape (..., {self.dof}) for the coordinates {self.q_names}, "
                             f"got shape {q.shape}")
        if not np.all(np.isfinite(q)):
            raise ValueError("q must be finite")
        return q

    def reachable(self, q) -> np.ndarray:
        """Boolean mask of the configurations the linkage can reach.

        Parameters
        ----------
        q : array_like, shape (..., dof)
            Configuration coordinates (rad). For one degree of freedom a plain array of
            angles is accepted too.

        Returns
        -------
        numpy.ndarray of bool, shape (...)

        Examples
        --------
        >>> import balancelab as bl
        >>> bl.scissors_lift().reachable([0.5, 2.0]).tolist()
        [True, False]
        """
        return self.kinematics.poses(self._as_q(q))[1]

    def poses(self, q) -> np.ndarray:
        """Pose ``(x, y, angle)`` of every body, shape ``(..., len(bodies), 3)``.

        Parameters
        ----------
        q : array_like, shape (..., dof)
            Configuration coordinates (rad); any leading shape.

        Returns
        -------
        numpy.ndarray
            Positions (m) of each body's frame origin and its angle (rad).

        Raises
        ------
        UnreachableConfiguration
            If any configuration is outside what the linkage can reach (on its declared
            assembly branch); the message gives the first such ``q`` and the valid range.

        Examples
        --------
        >>> import balancelab as bl
        >>> d = bl.lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3)
        >>> d.poses(0.0)[1].tolist()
        [0.0, 0.0, 0.0]
        """
        return self._checked_poses(q)[0]

    def _checked_poses(self, q, trig: bool = False):
        """Poses (and the kinematics' cached cos/sin when ``trig``), or a clear error."""
        qa = self._as_q(q)
        if trig:
            poses, ok, cache = self.kinematics.poses_with_trig(qa)
        else:
            (poses, ok), cache = self.kinematics.poses(qa), {}
        if not np.all(ok):
            bad = qa[~ok][0] if qa.ndim > 1 else qa
            rng = ", ".join(f"{n} in [{np.degrees(lo):.2f}°, {np.degrees(hi):.2f}°]"
                            for n, (lo, hi) in zip(self.q_names, self.q_range))
            raise UnreachableConfiguration(
                f"{self.name}: configuration q = {np.round(np.atleast_1d(bad), 6).tolist()} rad "
                f"({np.round(np.degrees(np.atleast_1d(bad)), 3).tolist()}°) cannot be reached; "
                f"valid range: {rng}")
        return poses, cache

    @staticmethod
    def _world(poses: np.ndarray, bodies: np.ndarray, points: np.ndarray):
        P = poses[..., bodies, :]
        c, s = np.cos(P[..., 2]), np.sin(P[..., 2])
        x = P[..., 0] + c * points[:, 0] - s * points[:, 1]
        y = P[..., 1] + s * points[:, 0] + c * points[:, 1]
        return x, y

    def world_points(self, q, attachments) -> np.ndarray:
        """Global coordinates (m) of body points, shape ``(..., len(attachments), 2)``.

        Parameters
        ----------
        q : array_like, shape (..., dof)
            Configuration (rad).
        attachments : sequence of (int, (float, float))
            ``(body, local point)`` pairs.

        Returns
        -------
        numpy.ndarray

        Examples
        --------
        >>> import balancelab as bl
        >>> d = bl.lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3)
        >>> d.world_points(0.0, [(1, (0.5, 0.0))]).round(3).tolist()
        [[0.5, 0.0]]
        """
        poses = self.poses(q)
        b = np.array([a[0] for a in attachments], dtype=int)
        p = np.array([a[1] for a in attachments], dtype=float).reshape(-1, 2)
        x, y = self._world(poses, b, p)
        return np.stack([x, y], axis=-1)

    def joint_error(self, q) -> np.ndarray:
        """Largest gap (m) between the two sides of any joint, per configuration.

        Zero (to rounding) for a correct kinematic model; the tests use it to check the
        closed-form loop solutions.

        Parameters
        ----------
        q : array_like, shape (..., dof)

        Returns
        -------
        numpy.ndarray, shape (...)
        """
        poses = self.poses(q)
        if not self.joints:
            return np.zeros(poses.shape[:-2])
        bi = np.array([j.body_i for j in self.joints])
        pi = np.array([j.point_i for j in self.joints], dtype=float)
        bj = np.array([j.body_j for j in self.joints])
        pj = np.array([j.point_j for j in self.joints], dtype=float)
        xi, yi = self._world(poses, bi, pi)
        xj, yj = self._world(poses, bj, pj)
        return np.max(np.hypot(xi - xj, yi - yj), axis=-1)

    def sample(self, n: int = 1000, seed: int | None = 0) -> np.ndarray:
        """``n`` reachable configurations spread uniformly over the configuration range.

        Parameters
        ----------
        n : int
            Number of configurations, >= 1.
        seed : int or None
            Seed of the random generator (``None`` for fresh randomness).

        Returns
        -------
        numpy.ndarray, shape (n, dof)

        Examples
        --------
        >>> import balancelab as bl
        >>> bl.scissors_lift().sample(5).shape
        (5, 1)
        """
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
            raise ValueError(f"n must be a positive integer, got {n!r}")
        rng = np.random.default_rng(seed)
        lo, hi = self.q_range[:, 0], self.q_range[:, 1]
        out = []
        count = 0
        for _ in range(200):
            q = lo + (hi - lo) * rng.random((max(2 * n, 64), self.dof))
            ok = self.kinematics.poses(q)[1]
            out.append(q[ok])
            count += int(ok.sum())
            if count >= n:
                break
        q = np.concatenate(out)[:n]
        if len(q) < n:
            raise RuntimeError(f"{self.name}: could only find {len(q)} reachable configurations")
        return q

    # ----------------------------------------------------------------- energy
    def _element_energies(self, poses: np.ndarray, trig: dict | None = None):
        """Energy of each load and each spring: two lists of arrays of shape (...).

        ``trig`` may hold ``{body: (cos, sin)}`` of body angles already computed.
        """
        lead = poses.shape[:-2]
        trig = dict(trig or {})

        def world(body, p):
            if body == 0:  # the ground sits at the origin and never turns
                return p[0], p[1]
            x, y = poses[..., body, 0], poses[..., body, 1]
            if p[0] == 0 and p[1] == 0:
                return x, y
            if body not in trig:
                angle = poses[..., body, 2]
                trig[body] = (np.cos(angle), np.sin(angle))
            c, s = trig[body]
            if p[1] == 0:
                return x + c * p[0], y + s * p[0]
            return x + c * p[0] - s * p[1], y + s * p[0] + c * p[1]

        vl = []
        for b, p, f in zip(self._lb, self._lp, self._lf):
            x, y = world(b, p)
            vl.append(np.broadcast_to(-(f[0] * x + f[1] * y), lead))
        vs = []
        for i in range(len(self.springs)):
            ax, ay = world(self._sab[i], self._sap[i])
            bx, by = world(self._sbb[i], self._sbp[i])
            dx, dy = bx - ax, by - ay
            d2 = dx * dx + dy * dy
            if self._sl0[i] == 0.0:
                vs.append(0.5 * self._sk[i] * d2)
            else:
                ext = np.sqrt(d2) - self._sl0[i]
                vs.append(0.5 * self._sk[i] * ext * ext)
        return vl, vs

    def potential_energy(self, q) -> Energy:
        """Potential energy (J) of the loads, of the springs and in total.

        Parameters
        ----------
        q : array_like, shape (..., dof)
            Configurations (rad), any leading shape.

        Returns
        -------
        Energy
            Named tuple ``(total, load, spring)`` of arrays of shape ``(...)``.

        Examples
        --------
        >>> import balancelab as bl, numpy as np
        >>> d = bl.lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3)
        >>> e = d.potential_energy(np.linspace(0, 3, 4))
        >>> bool(np.ptp(e.total) < 1e-12)
        True
        """
        q = self._as_q(q)
        lead = q.shape[:-1]
        flat = q.reshape(-1, self.dof)
        out = np.empty((3, len(flat)))
        for start in range(0, len(flat), _CHUNK):  # chunks that stay in the CPU cache
            part = flat[start:start + _CHUNK]
            poses, trig = self._checked_poses(part, trig=True)
            vl, vs = self._element_energies(poses, trig)
            load = sum(vl[1:], vl[0]) if vl else 0.0
            spring = sum(vs[1:], vs[0]) if vs else 0.0
            out[1, start:start + len(part)] = load
            out[2, start:start + len(part)] = spring
        out[0] = out[1] + out[2]
        return Energy(*(row.reshape(lead) for row in out))

    def generalized_force(self, q, h: float = 1e-6) -> np.ndarray:
        """``dV/dq`` (J/rad) by central differences, shape ``(..., dof)``.

        Near a limit of the range a one-sided difference is used.

        Parameters
        ----------
        q : array_like, shape (..., dof)
        h : float
            Step (rad).

        Returns
        -------
        numpy.ndarray
        """
        q = self._as_q(q)
        out = np.empty(q.shape)
        for i in range(self.dof):
            e = np.zeros(self.dof)
            e[i] = h
            okp = self.reachable(q + e)
            okm = self.reachable(q - e)
            qp = np.where(okp[..., None], q + e, q)
            qm = np.where(okm[..., None], q - e, q)
            vp = self.potential_energy(qp).total
            vm = self.potential_energy(qm).total
            den = np.where(okp, h, 0.0) + np.where(okm, h, 0.0)
            out[..., i] = (vp - vm) / np.where(den > 0, den, 1.0)
        return out

    def balance_report(self, q=None, *, n: int = 1000, seed: int | None = 0,
                       tolerance: float = BALANCE_TOLERANCE) -> BalanceReport:
        """Check that the potential energy is constant over many configurations.

        The total energy is evaluated over ``n`` sampled configurations (or the given
        ``q``). Its spread ``max - min`` is divided by an energy scale, the sum over every
        load and spring of the spread of its *own* energy over the same configurations
        (so the verdict does not depend on where the origin is, and a counterweight
        design, whose gravity energy is constant in total, still has a scale). The
        design is reported balanced when this ratio is at most ``tolerance``
        (:data:`BALANCE_TOLERANCE` = 1e-9 by default). The largest generalized force
        ``|dV/dq|``, divided by the same scale, is reported too.

        Parameters
        ----------
        q : array_like, shape (m, dof), optional
            Configurations to use instead of sampling.
        n : int
            Number of sampled configurations when ``q`` is not given.
        seed : int or None
            Seed for the sampling.
        tolerance : float
            Relative tolerance for the ``balanced`` verdict.

        Returns
        -------
        BalanceReport

        Examples
        --------
        >>> import balancelab as bl
        >>> print(bl.lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3).balance_report().balanced)
        True
        """
        q = self.sample(n, seed) if q is None else self._as_q(q).reshape(-1, self.dof)
        poses = self.poses(q)
        vl, vs = self._element_energies(poses)
        vl = np.stack(vl, -1) if vl else np.zeros((len(q), 0))
        vs = np.stack(vs, -1) if vs else np.zeros((len(q), 0))
        total = vl.sum(-1) + vs.sum(-1)
        scale = float(np.sum(np.ptp(vl, axis=0)) + np.sum(np.ptp(vs, axis=0))) if len(q) else 0.0
        if scale == 0.0:
            scale = float(np.max(np.abs(total))) if total.size else 0.0
        if scale == 0.0:
            raise ValueError(f"{self.name}: nothing in this design stores energy as it moves, "
                             "so there is nothing to balance")
        variation = float(np.ptp(total)) / scale
        gf = self.generalized_force(q)
        mag = np.max(np.abs(gf), axis=-1)
        worst = int(np.argmax(mag))
        return BalanceReport(variation=variation, residual=float(mag[worst]) / scale, scale=scale,
                             energy=float(np.mean(total)), worst_q=q[worst].copy(),
                             balanced=bool(variation <= tolerance), tolerance=tolerance, n=len(q))

    # --------------------------------------------------------------- symbolic
    def _symbolic_parts(self, parametric: bool):
        import sympy as sp

        if parametric and self.symbolic is not None:
            return self.symbolic.loads, self.symbolic.springs
        f = sp.Float
        loads = [(ld.body, tuple(f(v) for v in ld.point), tuple(f(v) for v in ld.force))
                 for ld in self.loads]
        springs = [(f(s.k), f(s.free_length), (s.a.body, tuple(f(v) for v in s.a.point)),
                    (s.b.body, tuple(f(v) for v in s.b.point))) for s in self.springs]
        return loads, springs

    def potential_energy_symbolic(self, parametric: bool = True, split: bool = False):
        """The potential energy as a sympy expression in the configuration angles.

        Parameters
        ----------
        parametric : bool
            Use the method's symbolic design parameters (when it has them, see
            ``design.symbolic.values``); otherwise the numbers of this design.
        split : bool
            Return ``(load part, spring part)`` instead of their sum.

        Returns
        -------
        sympy.Expr or tuple of sympy.Expr

        Examples
        --------
        >>> import balancelab as bl
        >>> d = bl.lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3)
        >>> d.potential_energy_symbolic()
        W*l*sin(theta) + k*(a_x**2*cos(theta)**2 + (a_x*sin(theta) - b_y)**2)/2
        """
        key = ("pe", parametric)
        if key not in self._sym_cache:
            import sympy as sp

            kin = self.kinematics
            if parametric and self.symbolic is not None and self.symbolic.kinematics is not None:
                kin = self.symbolic.kinematics
            syms = kin.symbols()
            loads, springs = self._symbolic_parts(parametric)
            point = kin.symbolic_point
            vl = sp.S.Zero
            for body, p, force in loads:
                x, y = point(body, p, syms)
                vl += -(force[0] * x + force[1] * y)
            vs = sp.S.Zero
            for k, l0, (ba, pa), (bb, pb) in springs:
                ax, ay = point(ba, pa, syms)
                bx, by = point(bb, pb, syms)
                d2 = (bx - ax) ** 2 + (by - ay) ** 2
                if sp.sympify(l0).is_zero:
                    vs += k / 2 * d2
                else:
                    length = sp.powdenest(sp.sqrt(sp.factor(sp.trigsimp(sp.expand(d2)))), force=True)
                    length = length.replace(sp.Abs, lambda x: x)
                    self._check_symbolic_length(syms, length, ((ba, pa), (bb, pb)), parametric)
                    vs += k / 2 * (length - l0) ** 2
            self._sym_cache[key] = (vl, vs)
        vl, vs = self._sym_cache[key]
        return (vl, vs) if split else vl + vs

    def _check_symbolic_length(self, syms, length, ends, parametric) -> None:
        """A finite-free-length spring's symbolic length must match the numeric one."""
        import sympy as sp

        q = self.sample(3, seed=1)
        values = dict(self.symbolic.values) if (parametric and self.symbolic is not None) else {}
        for qi in q:
            sub = dict(values)
            sub.update(dict(zip(syms, self.kinematics.symbol_values(qi))))
            num = float(sp.sympify(length).subs(sub).evalf())
            pts = []
            for body, p in ends:
                pp = tuple(float(sp.sympify(v).subs(values)) for v in p)
                pts.append(self.world_points(qi, [(body, pp)])[0])
            ref = float(np.hypot(*(pts[1] - pts[0])))
            if not np.isclose(num, ref, rtol=1e-9, atol=1e-12):
                raise NotImplementedError(
                    f"{self.name}: a finite-free-length spring's length is not a polynomial in the "
                    "sines and cosines of the coordinates; no symbolic energy is available")

    def trig_coefficients(self, parametric: bool = True) -> dict:
        """Coefficients of the potential energy in a unique trigonometric form.

        The energy is expanded into a polynomial in ``cos(q_i)`` and ``sin(q_i)`` and
        reduced with ``sin^2 = 1 - cos^2``; in that normal form it is constant exactly when
        every coefficient other than the constant term vanishes.

        Returns
        -------
        dict
            Maps each trigonometric monomial (a sympy expression, ``1`` for the constant)
            to its coefficient.
        """
        key = ("coeffs", parametric)
        if key not in self._sym_cache:
            import sympy as sp

            expr = self.potential_energy_symbolic(parametric)
            syms = self.kinematics.symbols()
            C = sp.symbols(f"C0:{len(syms)}")
            S = sp.symbols(f"S0:{len(syms)}")
            e = sp.expand(sp.expand_trig(sp.expand(expr)))
            e = e.subs({sp.cos(t): c for t, c in zip(syms, C)}).subs({sp.sin(t): s for t, s in zip(syms, S)})
            if any(e.has(t) for t in syms):
                raise ValueError(f"{self.name}: the energy is not a trigonometric polynomial in "
                                 f"{syms}; no coefficient form exists")
            gens = list(S) + list(C)
            basis = [s ** 2 + c ** 2 - 1 for s, c in zip(S, C)]
            _, rem = sp.reduced(sp.expand(e), basis, *gens, order="lex")
            poly = sp.Poly(rem, *gens)
            back = {**{c: sp.cos(t) for t, c in zip(syms, C)}, **{s: sp.sin(t) for t, s in zip(syms, S)}}
            out = {}
            for monom, coeff in poly.terms():
                term = sp.Mul(*[g ** p for g, p in zip(gens, monom)]).subs(back)
                out[term] = sp.simplify(coeff) if parametric and self.symbolic is not None else coeff
            self._sym_cache[key] = out
        return dict(self._sym_cache[key])

    def balance_conditions(self, parametric: bool = True) -> list:
        """The equations that make the potential energy constant.

        Every coefficient of a non-constant trigonometric term of the energy (see
        :meth:`trig_coefficients`) set to zero. For a closed loop written through its
        joints these conditions are sufficient; they are also necessary for open chains.

        Returns
        -------
        list of sympy.Eq

        Examples
        --------
        >>> import balancelab as bl
        >>> bl.lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3).balance_conditions()
        [Eq(W*l - a_x*b_y*k, 0)]
        """
        import sympy as sp

        eqs = []
        for term, coeff in self.trig_coefficients(parametric).items():
            if term == 1:
                continue
            expr = sp.factor(coeff) if parametric and self.symbolic is not None else coeff
            if sp.sympify(expr).is_zero:
                continue
            eq = sp.Eq(expr, 0, evaluate=False)
            if eq not in eqs:
                eqs.append(eq)
        return eqs

    def conditions_residual(self) -> float:
        """Largest balance-condition coefficient of this design's numbers, relative to its scale.

        Substitutes the design's values into :meth:`balance_conditions` (parametric when
        the method has symbols). Near zero (round-off) for a balanced design.

        Returns
        -------
        float
        """
        import sympy as sp

        values = self.symbolic.values if self.symbolic is not None else {}
        worst = 0.0
        for term, coeff in self.trig_coefficients(True).items():
            if term == 1:
                continue
            worst = max(worst, abs(float(sp.sympify(coeff).subs(values).evalf())))
        return worst / self.balance_report(n=200).scale
