"""`Design`: the one type every balancing method returns and every tool takes.

A design is a planar linkage of rigid bodies (body 0 the ground) joined by revolute
joints, loaded by constant forces (weights, counterweights, external loads) and by
linear springs. It knows its configuration space through a
:class:`~balancelab.core.Kinematics` object and can prove itself balanced: its
potential energy is evaluated over many configurations (:meth:`Design.balance_report`)
and derived symbolically (:meth:`Design.potential_energy_symbolic`,
:meth:`Design.balance_conditions`). A design is a value: its fields are read-only, and
:meth:`Design.replace` returns a changed copy, checked again from scratch.
"""
from __future__ import annotations

import dataclasses
from dataclasses import KW_ONLY, FrozenInstanceError, dataclass, field
from functools import cached_property
from types import MappingProxyType
from typing import Any, ClassVar, Hashable, Mapping, Sequence, TypeVar

import numpy as np
from numpy.typing import ArrayLike

from . import report as _report
from .elements import Joint, Load, Spring, SymbolicParts
from .errors import UnreachableConfiguration
from .frames import place
from .kinematics import Kinematics, body_to_world, central_difference, joint_gaps, spread
from .packed import PackedElements, packed_field as _packed, pack_elements
from .report import BALANCE_TOLERANCE, BalanceReport, Energy
from .symbolic import SymbolicMethods
from .validation import positive_int, real_array, sequence_of, step_size

__all__ = ["Design", "Energy", "BalanceReport", "UnreachableConfiguration", "BALANCE_TOLERANCE"]

_CHUNK = 16384  # configurations evaluated at once by potential_energy


#: a named point of a figure: ``(body, local point (m))``
Label = tuple[int, tuple[float, float]]

_D = TypeVar("_D")


def _check_items(loads, springs, joints, nb: int) -> None:
    """Every load is a Load, every spring a Spring, and all name existing bodies."""
    for ld in loads:
        if not isinstance(ld, Load):
            raise TypeError(f"loads: every load must be a Load, got {type(ld).__name__}")
        if not 0 <= ld.body < nb:
            raise ValueError(f"load {ld.name or ld} acts on body {ld.body}; bodies are 0..{nb - 1}")
    for sp in springs:
        if not isinstance(sp, Spring):
            raise TypeError(f"springs: every spring must be a Spring, got {type(sp).__name__}")
        for at in (sp.a, sp.b):
            if not 0 <= at.body < nb:
                raise ValueError(f"spring {sp.name or sp} is attached to body {at.body}; "
                                 f"bodies are 0..{nb - 1}")
    for j in joints:
        for b in (j.body_i, j.body_j):
            if not 0 <= b < nb:
                raise ValueError(f"joint {j} names body {b}; bodies are 0..{nb - 1}")


def _immutable_message(cls: type[_D]) -> type[_D]:
    """Make a frozen dataclass's refusal to change a field say how to get a changed copy.

    ``dataclass(frozen=True)`` forbids defining ``__setattr__`` in the class body; its generated
    ``__init__`` sets the fields with ``object.__setattr__``, so replacing the two methods after
    the decorator only changes the error message (still a ``FrozenInstanceError``, an
    ``AttributeError``).
    """
    def __setattr__(self: object, key: str, value: object) -> None:
        raise FrozenInstanceError(f"a Design is immutable: use design.replace({key}=...) to get a "
                                  "changed copy")

    def __delattr__(self: object, key: str) -> None:
        raise FrozenInstanceError("a Design is immutable: use design.replace(...) to get a changed copy")

    setattr(cls, "__setattr__", __setattr__)  # noqa: B010 (mypy refuses assigning to a method)
    setattr(cls, "__delattr__", __delattr__)  # noqa: B010
    return cls


@_immutable_message
@dataclass(frozen=True, eq=False, repr=False)
class Design(SymbolicMethods):
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
    >>> d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
    >>> d.balance_report().balanced
    True
    >>> round(d.parameters["k"], 4)
    83.3333
    """

    name: str
    bodies: Sequence[str]
    joints: Sequence[Joint]
    kinematics: Kinematics
    loads: Sequence[Load] = ()
    springs: Sequence[Spring] = ()
    _: KW_ONLY
    symbolic: SymbolicParts | None = None
    labels: Mapping[str, Label] = field(default_factory=dict)
    parameters: Mapping[str, float] = field(default_factory=dict)
    reference: str = ""
    _sym_cache: dict[Hashable, Any] = field(init=False, repr=False, default_factory=dict)

    #: largest joint gap (m) accepted between the kinematics and the declared joints
    JOINT_TOLERANCE: ClassVar[float] = 1e-9

    def __post_init__(self) -> None:
        """Check the fields and store them as tuples and read-only mappings."""
        bodies = tuple(str(b) for b in self.bodies)
        nb = len(bodies)
        if nb < 2:
            raise ValueError("bodies must name the ground and at least one moving body")
        kinematics = self.kinematics
        if not isinstance(kinematics, Kinematics):
            raise TypeError("kinematics must be a balancelab Kinematics (see balancelab.mechanisms), "
                            f"got {type(kinematics).__name__}")
        if kinematics.nbodies != nb:
            raise ValueError(f"kinematics describes {kinematics.nbodies} bodies but {nb} are named")
        joints = tuple(Joint(*j) for j in self.joints)
        loads = sequence_of("loads", self.loads, Load)
        springs = sequence_of("springs", self.springs, Spring)
        _check_items(loads, springs, joints, nb)
        init = object.__setattr__  # the dataclass idiom for normalizing a frozen field
        init(self, "name", str(self.name))
        init(self, "bodies", bodies)
        init(self, "joints", joints)
        init(self, "loads", loads)
        init(self, "springs", springs)
        init(self, "labels", MappingProxyType(dict(self.labels or {})))
        init(self, "parameters", MappingProxyType(dict(self.parameters or {})))
        init(self, "reference", str(self.reference))
        self._check_joints()

    def _check_joints(self) -> None:
        """The kinematics must close every declared joint (gap <= JOINT_TOLERANCE)."""
        if not self.joints:
            return
        poses, ok = self.kinematics.poses(spread(self.q_range, 24))
        poses = poses[ok] if ok.any() else self.kinematics.poses(self.sample(24))[0]
        gaps = joint_gaps(poses, self.joints)
        worst = gaps.max(axis=0)
        j = int(np.argmax(worst))
        if worst[j] > self.JOINT_TOLERANCE:
            raise ValueError(f"{self.name}: joint {j} {self.joints[j]} opens by {worst[j]:.3g} m in the "
                             "kinematics' poses; the joints and the kinematics describe different "
                             "linkages")

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

    def replace(self, **changes: Any) -> Design:
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
        >>> d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
        >>> heavier = d.replace(loads=[bl.Load(1, (0.5, 0.0), (0.0, -11.0))])
        >>> heavier.balance_report().balanced
        False
        """
        names = tuple(f.name for f in dataclasses.fields(self) if f.init)
        unknown = set(changes) - set(names)
        if unknown:
            raise TypeError(f"replace() got unknown fields {sorted(unknown)}; a Design has {names}")
        if ("loads" in changes or "springs" in changes) and "symbolic" not in changes:
            changes["symbolic"] = None  # the symbolic parts describe the old loads and springs
        return dataclasses.replace(self, **changes)

    @cached_property
    def _arrays(self) -> PackedElements:
        """The loads and springs as arrays for the vectorized energy (once: a Design is immutable)."""
        return pack_elements(self.loads, self.springs)

    _lb, _lp, _lf = _packed("lb"), _packed("lp"), _packed("lf")
    _sab, _sap, _sbb, _sbp = _packed("sab"), _packed("sap"), _packed("sbb"), _packed("sbp")
    _sk, _sl0, _scable = _packed("sk"), _packed("sl0"), _packed("scable")

    @cached_property
    def _ref(self) -> np.ndarray:
        """The ground point (m) about which element energies are taken (see ``report.reference_point``)."""
        return _report.reference_point(self)

    # ------------------------------------------------------------- kinematics
    def check_q(self, q: ArrayLike) -> np.ndarray:
        """``q`` as a float array of shape ``(..., dof)``, or a clear error (plain angles for one dof)."""
        q = real_array(f"q ({_report.q_meaning(self)})", q)
        if self.dof == 1 and (q.ndim == 0 or q.shape[-1] != 1):
            q = q[..., None]
        if q.ndim == 0 or q.shape[-1] != self.dof:
            raise ValueError(f"q must have shape (..., {self.dof}) for the coordinates {self.q_names}, "
                             f"got shape {q.shape}")
        return q

    def reachable(self, q: ArrayLike) -> np.ndarray:
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
        >>> bl.singh.scissors_lift().reachable([0.5, 2.0]).tolist()
        [True, False]
        """
        return self.kinematics.poses(self.check_q(q))[1]

    def poses(self, q: ArrayLike) -> np.ndarray:
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
        >>> d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
        >>> d.poses(0.0)[1].tolist()
        [0.0, 0.0, 0.0]
        """
        return self._checked_poses(q)[0]

    def _checked_poses(self, q, trig: bool = False):
        """Poses (and the kinematics' cached cos/sin when ``trig``), or a clear error."""
        qa = self.check_q(q)
        if trig:
            poses, ok, cache = self.kinematics.poses_with_trig(qa)
        else:
            (poses, ok), cache = self.kinematics.poses(qa), {}
        if not np.all(ok):
            bad = qa[~ok][0] if qa.ndim > 1 else qa
            units = _report.q_units(self)  # degrees for angles, metres for slides
            rng = ", ".join(f"{n} in [{_report.format_q((u, u), r)}]" for n, u, r in zip(self.q_names, units, self.q_range))
            raise UnreachableConfiguration(
                f"{self.name}: configuration q = {np.round(np.atleast_1d(bad), 6).tolist()} "
                f"({' and '.join(sorted(set(units)))}: "
                f"{_report.format_q(units, np.atleast_1d(bad))}) cannot be reached; "
                f"valid range: {rng}")
        return poses, cache

    def world_points(self, q: ArrayLike, attachments: Sequence[tuple[int, Sequence[float]]]) -> np.ndarray:
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
        >>> d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
        >>> d.world_points(0.0, [(1, (0.5, 0.0))]).round(3).tolist()
        [[0.5, 0.0]]
        """
        poses = self.poses(q)
        b = np.array([a[0] for a in attachments], dtype=int)
        p = np.array([a[1] for a in attachments], dtype=float).reshape(-1, 2)
        x, y = body_to_world(poses, b, p)
        return np.stack([x, y], axis=-1)

    def joint_error(self, q: ArrayLike) -> np.ndarray:
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
        gaps = joint_gaps(poses, self.joints)
        return gaps.max(axis=-1) if self.joints else np.zeros(poses.shape[:-2])

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
        >>> bl.singh.scissors_lift().sample(5).shape
        (5, 1)
        """
        n = positive_int("n (number of configurations)", n)
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
        rx, ry = self._ref

        def world(body, p):  # about the reference point: far origins lose no digits
            if body == 0:  # the ground sits at the origin and never turns
                return p[0] - rx, p[1] - ry
            x, y = poses[..., body, 0] - rx, poses[..., body, 1] - ry
            if p[0] == 0 and p[1] == 0:
                return x, y
            if body not in trig:
                angle = poses[..., body, 2]
                trig[body] = (np.cos(angle), np.sin(angle))
            c, s = trig[body]
            return place(x, y, c, s, p)

        vl = []
        for b, p, f in zip(self._lb, self._lp, self._lf):
            x, y = world(b, p)
            vl.append(np.broadcast_to(-(f[0] * x + f[1] * y), lead))
        vs = []
        for i in range(len(self.springs)):
            if self._scable[i] is not None:  # the length runs along a cable over a profile
                ext = self._scable[i].length(poses[..., self._sab[i], :], poses[..., self._sbb[i], :]) - self._sl0[i]
                vs.append(0.5 * self._sk[i] * ext * ext)
                continue
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

    def element_energies(self, q: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
        """Energy (J) of each load and of each spring: arrays of shape ``(m, n_loads)``, ``(m, n_springs)``.

        ``q`` is flattened to ``m`` configurations of shape ``(m, dof)``. A load's energy is taken
        about a ground point of the design (the ground end of its first ground joint), not about the
        origin: it differs from :meth:`potential_energy`'s by a constant, and does not lose digits
        when the design sits far from the origin.
        """
        q = self.check_q(q).reshape(-1, self.dof)
        vl, vs = self._element_energies(self.poses(q))
        return (np.stack(vl, -1) if vl else np.zeros((len(q), 0)),
                np.stack(vs, -1) if vs else np.zeros((len(q), 0)))

    def potential_energy(self, q: ArrayLike) -> Energy:
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
        >>> d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
        >>> e = d.potential_energy(np.linspace(0, 3, 4))
        >>> bool(np.ptp(e.total) < 1e-12)
        True
        """
        q = self.check_q(q)
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
        out[1] -= float(np.sum(self._lf @ self._ref)) if len(self.loads) else 0.0  # about the origin again
        out[0] = out[1] + out[2]
        return Energy(*(row.reshape(lead) for row in out))

    def generalized_force(self, q: ArrayLike, h: float | None = None) -> np.ndarray:
        """``dV/dq`` (J/rad for an angle, N for a slide) by central differences, shape ``(..., dof)``.

        Near a limit of the range a one-sided difference is used.

        Parameters
        ----------
        q : array_like, shape (..., dof)
        h : float, optional
            Step (rad for angles, m for slides) for every coordinate, in ``(0, 0.1]``. By default
            angles step by ``1e-6`` rad and a slide by ``1e-6`` of its range (:meth:`difference_steps`),
            so a micrometre stroke is differenced as finely as a metre one.

        Returns
        -------
        numpy.ndarray

        Examples
        --------
        >>> import balancelab as bl
        >>> lk = bl.Linkage("block")
        >>> _ = lk.prismatic("ground", (0, 0), "block", (0, 0), axis=(1, 0), stroke=(-1e-6, 1e-6))
        >>> _ = lk.load("block", (3.0, 0.0))
        >>> bool(abs(lk.build().generalized_force([0.0])[0] + 3.0) < 1e-6)   # dV/ds = -F_x (N)
        True
        """
        q = self.check_q(q)
        if h is None:
            steps = self.difference_steps()
        else:
            steps = np.full(self.dof, step_size(f"h (step, {'rad or m' if 'm' in _report.q_units(self) else 'rad'})", h, 0.1))
        flat = q.reshape(-1, self.dof)

        def energies(x: np.ndarray) -> np.ndarray:
            # each element's energy about the design's reference point, differenced before summing:
            # a far origin or an idle stiff spring costs no digits (see report.energy_change)
            vl, vs = self._element_energies(self._checked_poses(x)[0])
            return np.array(list(vl) + list(vs), dtype=float).reshape(-1, len(x))

        return central_difference(energies, self.reachable, flat, steps).sum(0).reshape(q.shape)

    def difference_steps(self, relative: float = 1e-6) -> np.ndarray:
        """Default finite-difference step of each coordinate, shape ``(dof,)``.

        ``relative`` rad for an angle; ``relative`` times the slide's range (m) for a slide, so
        the step scales with the design (a 1 um stroke gets a 1e-12 m step).

        Parameters
        ----------
        relative : float
            Step of an angle (rad) and fraction of a slide's range, in ``(0, 0.1]``.

        Returns
        -------
        numpy.ndarray

        Examples
        --------
        >>> import balancelab as bl
        >>> bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3).difference_steps().tolist()
        [1e-06]
        """
        relative = step_size("relative (step)", relative, 0.1)
        span = np.diff(np.asarray(self.q_range, dtype=float), axis=1)[:, 0]
        slide = np.array([u == "m" for u in _report.q_units(self)]) & np.isfinite(span) & (span > 0)
        return np.where(slide, relative * np.where(slide, span, 1.0), relative)

    def balance_report(self, q: ArrayLike | None = None, *, n: int = 1000, seed: int | None = 0,
                       tolerance: float = BALANCE_TOLERANCE) -> BalanceReport:
        """Check that the potential energy ``V`` is constant over many configurations.

        *Balanced* means: over the configurations, ``max V - min V <= tolerance * L``, where
        ``L`` (``load_scale``) is the energy the loads exchange: the sum of the spreads
        ``max - min`` of the loads' energies (loads acting at the same point added up first).
        Springs never enter ``L``, and loads and springs whose energies sum to a constant (on any
        bodies: ``F, F, -F`` on a parallelogram) are left out first, so they cannot make an unbalanced
        design look balanced. When the loads exchange no energy the springs are the load (see
        :func:`~balancelab.core.report.load_scale`, :class:`BalanceReport`). At least 10 distinct
        configurations, spanning a quarter of each coordinate's reachable range, are needed.

        Parameters
        ----------
        q : array_like, shape (m, dof), optional
            Configurations (rad) to use instead of sampling.
        n : int
            Number of sampled configurations when ``q`` is not given, >= 10.
        seed : int or None
            Seed for the sampling.
        tolerance : float
            Relative tolerance, ``0 < tolerance < 1`` (:data:`BALANCE_TOLERANCE` = 1e-9).

        Returns
        -------
        BalanceReport

        Examples
        --------
        >>> import balancelab as bl
        >>> print(bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3).balance_report().balanced)
        True
        """
        return _report.balance_report(self, q, n=n, seed=seed, tolerance=tolerance)
