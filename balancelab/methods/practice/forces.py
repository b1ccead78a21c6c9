"""Forces, not energy: spring forces, generalized forces and joint loads over the range.

Two independent routes to the same statics:

* **virtual work** (:func:`generalized_force`): ``Q = dV/dq`` written out analytically,
  ``Q = sum_loads -f . dr/dq + sum_springs T/L d . (dr_b/dq - dr_a/dq)`` with the
  spring tension ``T = k (L - free_length)``, the vector ``d = r_b - r_a`` of length ``L``
  and the pose derivatives ``dr/dq`` of the kinematics (central differences of the
  poses: exact to about 1e-10 for smooth linkages). :func:`batch_generalized_force`
  evaluates it for thousands of perturbed parameter sets at once (the Monte Carlo of
  :mod:`.tolerance` uses it);
* **cutting the tree** (:func:`joint_loads`): for a design whose joints form a tree,
  cut each joint; the part beyond it is in equilibrium under its loads, the springs
  that reach it from outside, the joint's reaction force ``R`` and the holding torque
  ``t`` that the joint must supply: ``R = -sum F``, ``t = -sum (r - r_joint) x F``.
  Rotating that part about the joint by ``d phi`` does virtual work ``-t d phi``, so
  ``t = dV/dphi``: zero everywhere for a balanced design; the tests check both routes
  against each other.

:func:`compare_free_choices` ranks the members of a family of balanced designs (for
instance the free choices ``a_x`` of Singh's minimum-preload 2R) by their largest
spring force and joint load: designs with the same energy can load their parts very
differently.

A spring whose cable wraps a non-circular pulley (``spring.cable``, a
:class:`~balancelab.methods.realize.NoncircularProfile`) is included through its cable: its
tension is ``k (L - free_length)`` with ``L`` the spring's length along the cable, its
generalized force ``T dL/dq`` (central differences of the cable's length), and the cable
pulls the link with the tension along its straight part, at the tangent point (the wrapped
part and the clamp add up to that), and the ground at the eyelet and the spring's anchor.
Layer: methods (imports core, and realize for the cable's geometry).
"""
from __future__ import annotations

from typing import Callable, NamedTuple, Sequence

import numpy as np

from ...core.design import Design
from ...core.frames import turn_back
from ...core.kinematics import central_difference
from ...core.validation import finite_real, positive_int
from ..realize.profile import NoncircularProfile

__all__ = ["configurations", "pose_jacobian", "spring_forces", "generalized_force", "batch_generalized_force",
           "JointLoads", "joint_tree", "joint_loads", "compare_free_choices"]


def configurations(design: Design, q=None, n: int = 61) -> np.ndarray:
    """``q`` checked as shape ``(m, dof)``, or a grid of ``n`` points per coordinate over the range.

    A full-turn coordinate gets ``n`` points without repeating its end.

    Examples
    --------
    >>> import balancelab as bl
    >>> configurations(bl.singh.serial_2r_min_preload(), n=5).shape
    (25, 2)
    """
    if q is not None:
        return design.check_q(q).reshape(-1, design.dof)
    n = positive_int("n (configurations per coordinate)", n, 2)
    axes = []
    for lo, hi in design.q_range:
        full = hi - lo >= 2 * np.pi - 1e-12
        axes.append(np.linspace(lo, hi, n, endpoint=not full))
    grid = np.stack(np.meshgrid(*axes, indexing="ij"), -1).reshape(-1, design.dof)
    return grid[design.reachable(grid)]


def pose_jacobian(design: Design, q, h: float = 1e-6) -> tuple[np.ndarray, np.ndarray]:
    """Poses ``(m, nbodies, 3)`` and their derivatives ``(m, nbodies, 3, dof)`` by central differences.

    One-sided differences are used where a neighbour is unreachable.

    Examples
    --------
    >>> import balancelab as bl
    >>> P, J = pose_jacobian(bl.singh.serial_2r_min_preload(), [[0.0, 0.0]])
    >>> np.round(J[0, 2, :, 0], 6).tolist()   # elbow moves up when theta_1 grows
    [0.0, 1.5, 0.0]
    """
    q = design.check_q(q).reshape(-1, design.dof)
    h = finite_real("h (rad)", h, positive=True)
    B, dB = _basis_and_derivative(design, q, lambda P: np.moveaxis(P, 0, -1), h)   # samples last
    return np.moveaxis(B, -1, 0), np.moveaxis(dB, -2, 0)


def _spring_basis(P, a: int, b: int) -> np.ndarray:
    """Functions of the configuration ``(7, m)`` that, weighted per sample, give a spring's ``|d|^2``.

    ``|d|^2 = |D0 + R_b p_b - R_a p_a|^2`` with ``D0 = X_b - X_a``; see :func:`_spring_coefficients`.
    """
    Xa, Xb = P[:, a, :2], P[:, b, :2]
    D = Xb - Xa
    Da = turn_back(np.cos(P[:, a, 2]), np.sin(P[:, a, 2]), (D[:, 0], D[:, 1]))     # R_a^T D
    Db = turn_back(np.cos(P[:, b, 2]), np.sin(P[:, b, 2]), (D[:, 0], D[:, 1]))     # R_b^T D
    dl = P[:, a, 2] - P[:, b, 2]
    return np.stack([np.sum(D * D, -1), Db[0], Db[1], Da[0], Da[1], np.cos(dl), np.sin(dl)])


def _spring_coefficients(pa, pb) -> tuple[np.ndarray, np.ndarray]:
    """Per-sample weights ``(N, 7)`` of :func:`_spring_basis` and the constant ``(N,)``."""
    ax, ay, bx, by = pa[:, 0], pa[:, 1], pb[:, 0], pb[:, 1]
    w = np.stack([np.ones_like(ax), 2 * bx, 2 * by, -2 * ax, -2 * ay, -2 * (ax * bx + ay * by),
                  -2 * (by * ax - bx * ay)], -1)
    return w, ax * ax + ay * ay + bx * bx + by * by


def _load_basis(P, body: int, force) -> np.ndarray:
    """``(3, m)``: the energy ``-f . (X + R p)`` is ``[1, p_x, p_y]`` times these."""
    fx, fy = force
    local = turn_back(np.cos(P[:, body, 2]), np.sin(P[:, body, 2]), (fx, fy))      # R^T f
    return np.stack([-(fx * P[:, body, 0] + fy * P[:, body, 1]), -local[0], -local[1]])


def _basis_and_derivative(design: Design, q, basis, h: float = 1e-6):
    """``basis(P)`` at ``q`` ``(..., m)`` and its derivative ``(..., m, dof)`` by central differences.

    A one-sided difference is used where a neighbour is unreachable (none where both are).
    """
    kin = design.kinematics
    B = basis(design.poses(q))
    return B, central_difference(lambda x: basis(kin.poses(x)[0]), kin.reachable, q, h)


def _params(design: Design, values: dict, N: int) -> dict:
    """Per-sample parameters ``(N, ...)``: the design's own where not given."""
    base = {"k": np.array([s.k for s in design.springs]),
            "free_length": np.array([s.free_length for s in design.springs]),
            "a_points": np.array([s.a.point for s in design.springs]).reshape(-1, 2),
            "b_points": np.array([s.b.point for s in design.springs]).reshape(-1, 2),
            "load_points": np.array([ld.point for ld in design.loads]).reshape(-1, 2),
            "load_scale": np.ones(len(design.loads))}
    out = {}
    for key, value in base.items():
        v = values.get(key)
        out[key] = np.broadcast_to(value, (N,) + value.shape) if v is None else np.asarray(v, dtype=float)
        if out[key].shape != (N,) + value.shape:
            raise ValueError(f"{key} must have shape {(N,) + value.shape}, got {out[key].shape}")
    return out


def batch_generalized_force(design: Design, q, **values) -> np.ndarray:
    """``dV/dq`` (N m per rad) for many parameter sets at once, shape ``(N, m, dof)``.

    Parameters
    ----------
    design : Design
    q : array_like, shape (m, dof)
        Configurations (rad).
    **values
        Optional arrays with a leading sample axis ``N``: ``k (N, n_springs)``,
        ``free_length (N, n_springs)``, ``a_points``/``b_points (N, n_springs, 2)`` (local),
        ``load_points (N, n_loads, 2)`` and ``load_scale (N, n_loads)`` (a factor on each
        load's force: a mass error). Missing ones are the design's own. For a spring on a
        non-circular pulley ``a_points`` moves its eyelet (the tangent point follows) and
        ``b_points`` its clamp, which lengthens the cable by the move along the profile.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> Q = batch_generalized_force(d, [[0.0]], k=[[d.springs[0].k * 1.1]])
    >>> round(float(Q[0, 0, 0]), 4)   # 10 % too stiff: -0.1 m g r at theta = 0
    -0.981
    """
    unknown = set(values) - {"k", "free_length", "a_points", "b_points", "load_points", "load_scale"}
    if unknown:
        raise TypeError(f"unknown parameter arrays {sorted(unknown)}")
    N = max([len(np.asarray(v)) for v in values.values()] + [1])
    p = _params(design, values, N)
    q = design.check_q(q).reshape(-1, design.dof)
    m, dof = len(q), design.dof
    Q = np.zeros((N, m * dof))
    for i, ld in enumerate(design.loads):
        _, dB = _basis_and_derivative(design, q, lambda P, ld=ld: _load_basis(P, ld.body, ld.force))
        w = np.concatenate([np.ones((N, 1)), p["load_points"][:, i]], -1) * p["load_scale"][:, i, None]
        Q += w @ dB.reshape(3, m * dof)
    for i, s in enumerate(design.springs):
        if s.cable is not None:
            Q += _cable_generalized_force(design, q, i, p).reshape(N, m * dof)
            continue
        B, dB = _basis_and_derivative(design, q, lambda P, s=s: _spring_basis(P, s.a.body, s.b.body))
        w, const = _spring_coefficients(p["a_points"][:, i], p["b_points"][:, i])
        k, l0 = p["k"][:, i, None], p["free_length"][:, i, None]
        dS = w @ dB.reshape(7, m * dof)
        if np.any(l0 != 0):
            L = w @ B
            L += const[:, None]
            np.sqrt(np.maximum(L, 1e-300, out=L), out=L)
            np.divide(l0, L, out=L)
            np.subtract(1.0, L, out=L)
            L *= 0.5 * k
            dS.reshape(N, m, dof)[...] *= L[..., None]
        else:
            dS *= 0.5 * k
        Q += dS
    return Q.reshape(N, m, dof)


def _cable_of(design: Design, i: int) -> NoncircularProfile:
    cab = design.springs[i].cable
    if not isinstance(cab, NoncircularProfile):
        raise NotImplementedError(f"{design.name}: spring {i} runs along a cable path of type {type(cab).__name__}; "
                                  "forces know the cable of a non-circular pulley (NoncircularProfile) only")
    return cab


def _clamp_direction(cab: NoncircularProfile) -> np.ndarray:
    """Unit tangent (link frame) at the cable's clamp, pointing on past the wrapped arc."""
    end = cab.end_parameter
    t = cab.local_points(end) - cab.local_points(end - 1e-6 * end)
    return t / float(np.hypot(*t))


def _cable_generalized_force(design: Design, q, i: int, p: dict) -> np.ndarray:
    """``T dL/dq`` ``(N, m, dof)`` of cable spring ``i`` for the per-sample parameters ``p``.

    ``L`` is the spring's length along the cable from the (possibly misplaced) eyelet;
    a misplaced clamp shortens the spring by the move along the profile beyond its end.
    """
    s, cab = design.springs[i], _cable_of(design, i)
    anchor = np.asarray(cab.anchor) + (p["a_points"][:, i] - np.asarray(s.a.point))      # (N, 2)
    extra = (p["b_points"][:, i] - np.asarray(s.b.point)) @ _clamp_direction(cab)      # (N,)
    nominal = not (np.any(anchor != np.asarray(cab.anchor)) or np.any(extra != 0))

    def length(P):
        theta = P[:, s.b.body, 2]
        if nominal:
            return np.broadcast_to(cab.cable(theta).path - cab.cable_length, (len(anchor), len(theta)))
        return cab.path_from(theta[None, :], anchor[:, None, :]) - cab.cable_length + extra[:, None]

    L, dL = _basis_and_derivative(design, q, length)
    tension = p["k"][:, i, None] * (L - p["free_length"][:, i, None])
    return tension[..., None] * dL


def generalized_force(design: Design, q=None, n: int = 61) -> tuple[np.ndarray, np.ndarray]:
    """Configurations ``(m, dof)`` and the generalized force ``dV/dq`` there ``(m, dof)`` (N m per rad).

    The residual torque curve of a design: zero for a balanced one.

    Examples
    --------
    >>> import balancelab as bl
    >>> q, Q = generalized_force(bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2), n=11)
    >>> bool(np.abs(Q).max() < 1e-8)
    True
    """
    q = configurations(design, q, n)
    return q, batch_generalized_force(design, q)[0]


def spring_forces(design: Design, q) -> np.ndarray:
    """Tension ``T = k (L - free_length)`` (N) of every spring, shape ``(..., n_springs)``.

    A spring on a non-circular pulley: ``L`` is its length along the cable.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> round(float(spring_forces(d, np.pi / 2)[0]), 2)   # k (b - c) with the link up
    16.35
    """
    if not design.springs:
        return np.zeros(np.shape(design.check_q(q))[:-1] + (0,))
    ends = [at for s in design.springs for at in (s.a, s.b)]
    w = design.world_points(q, ends)
    d = w[..., 1::2, :] - w[..., 0::2, :]
    L = np.sqrt(np.sum(d * d, -1))
    for i, s in enumerate(design.springs):
        if s.cable is not None:        # the length along the cable (the design's own model)
            P = design.poses(q)
            L[..., i] = _cable_of(design, i).length(P[..., s.a.body, :], P[..., s.b.body, :])
    return np.array([s.k for s in design.springs]) * (L - np.array([s.free_length for s in design.springs]))


class JointLoads(NamedTuple):
    """Statics of a tree design: per configuration and joint (in ``design.joints`` order).

    ``force (m, n_joints, 2)``: reaction (N) the parent body exerts on the child part;
    ``torque (m, n_joints)``: holding torque (N m) the joint must supply (0 when balanced);
    ``children``: for each joint, the bodies of the part beyond it.
    """

    force: np.ndarray
    torque: np.ndarray
    children: tuple


def joint_tree(design: Design) -> tuple:
    """For each joint, the set of bodies beyond it (away from the ground); the joints must form a tree.

    Examples
    --------
    >>> import balancelab as bl
    >>> joint_tree(bl.singh.serial_2r_min_preload())
    (frozenset({1, 2}), frozenset({2}))
    """
    nb, joints = len(design.bodies), design.joints
    if len(joints) != nb - 1:
        raise ValueError(f"{design.name}: joint loads (and the friction built on them: stays_put, holding "
                         f"torques) are computed for open chains only today, whose joints form a tree "
                         f"({nb - 1} joints for {nb} bodies); this design has {len(joints)} joints, a closed loop. "
                         "A loop of revolute joints is statically determinate, but not supported here yet")
    parent: dict[int, int | None] = {0: None}
    child_of = {}
    frontier = [0]
    while frontier:
        b = frontier.pop()
        for j, jt in enumerate(joints):
            other = jt.body_j if jt.body_i == b else jt.body_i if jt.body_j == b else None
            if other is not None and other not in parent:
                parent[other], child_of[j] = b, other
                frontier.append(other)
    if len(parent) != nb:
        raise ValueError(f"{design.name}: not every body is joined to the ground")

    def beyond(b):
        return {b}.union(*[beyond(c) for c, p in parent.items() if p == b])

    return tuple(frozenset(beyond(child_of[j])) for j in range(len(joints)))


def _cable_forces(design: Design, q, i: int, tension) -> list:
    """``(body, point, force)`` of cable spring ``i``: on the link at the tangent point, on the ground.

    The cable leaves the profile at the tangent point along its straight part, so the link
    feels the tension along that line there; on the ground the spring's anchor is pulled
    towards the eyelet and the eyelet by both strands (their sum is the opposite force).
    """
    s, cab = design.springs[i], _cable_of(design, i)
    P = design.poses(q)
    geo = cab.cable(P[:, s.b.body, 2])
    pull = geo.anchor - geo.tangent
    pull = pull / np.linalg.norm(pull, axis=-1, keepdims=True)
    out = [(s.b.body, geo.tangent, tension[:, None] * pull)]
    if cab.spring_anchor is None:       # the spring's far end unknown: the whole pull on the eyelet
        return out + [(s.a.body, geo.anchor, -tension[:, None] * pull)]
    away = np.broadcast_to(cab.direction, pull.shape)
    return out + [(s.a.body, geo.anchor, tension[:, None] * (away - pull)),
                  (s.a.body, np.broadcast_to(cab.spring_anchor, pull.shape), -tension[:, None] * away)]


def _external_forces(design: Design, q):
    """List of ``(body, world point (m, 2), force (m, 2))`` of every load and spring end."""
    out = []
    if design.loads:
        P = design.world_points(q, [(ld.body, ld.point) for ld in design.loads])
        for i, ld in enumerate(design.loads):
            out.append((ld.body, P[:, i], np.broadcast_to(np.asarray(ld.force), P[:, i].shape)))
    if design.springs:
        T = spring_forces(design, q)
        w = design.world_points(q, [at for s in design.springs for at in (s.a, s.b)])
        for i, s in enumerate(design.springs):
            if s.cable is not None:
                out.extend(_cable_forces(design, q, i, T[:, i]))
                continue
            ra, rb = w[:, 2 * i], w[:, 2 * i + 1]
            d = rb - ra
            u = d / np.linalg.norm(d, axis=-1, keepdims=True)
            out.append((s.a.body, ra, T[:, i, None] * u))
            out.append((s.b.body, rb, -T[:, i, None] * u))
    return out


def joint_loads(design: Design, q=None, n: int = 61) -> JointLoads:
    """Reaction force and holding torque of every joint of a tree design, over configurations.

    Parameters
    ----------
    design : Design
        Its joints must form a tree (levers, serial arms).
    q : array_like, shape (m, dof), optional
        Configurations (rad); by default a grid of ``n`` per coordinate over the range.
    n : int

    Returns
    -------
    JointLoads

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> jl = joint_loads(d, [[np.pi / 2]])   # link up: weight 19.62 N down, spring k (b - c) = 16.35 N up
    >>> np.round(jl.force[0, 0], 3).tolist(), abs(round(float(jl.torque[0, 0]), 9))
    ([0.0, 3.27], 0.0)
    """
    q = configurations(design, q, n)
    parts = joint_tree(design)
    ext = _external_forces(design, q)
    force = np.zeros((len(q), len(parts), 2))
    torque = np.zeros((len(q), len(parts)))
    for j, part in enumerate(parts):
        jt = design.joints[j]
        anchor = (jt.body_j, jt.point_j) if jt.body_j in part else (jt.body_i, jt.point_i)
        rj = design.world_points(q, [anchor])[:, 0]
        for body, r, f in ext:
            if body in part:
                force[:, j] -= f
                arm = r - rj
                torque[:, j] -= arm[:, 0] * f[:, 1] - arm[:, 1] * f[:, 0]
    return JointLoads(force, torque, parts)


def compare_free_choices(build: Callable[..., Design], choices: Sequence, n: int = 61) -> dict:
    """Largest spring force and joint load of each member of a family of designs.

    Parameters
    ----------
    build : callable
        ``build(choice) -> Design`` (tree designs, to have joint loads).
    choices : sequence
        The free choices to compare.
    n : int
        Configurations per coordinate.

    Returns
    -------
    dict
        ``choice`` (list), ``max_spring_force`` (N), ``max_joint_load`` (N),
        ``max_holding_torque`` (N m; round-off for balanced designs) and ``energy`` (J, the
        constant potential energy), arrays over the choices.

    Examples
    --------
    >>> import balancelab as bl
    >>> c = compare_free_choices(lambda a: bl.singh.min_preload_lever(10.0, 0.5, a), [0.25, 0.5], n=20)
    >>> np.round(c["max_spring_force"], 3).tolist(), np.round(c["energy"], 6).tolist()
    ([40.0, 20.0], [5.0, 5.0])
    """
    rows = []
    for choice in choices:
        d = build(choice)
        q = configurations(d, None, n)
        jl = joint_loads(d, q)
        rows.append((float(np.max(np.abs(spring_forces(d, q)))), float(np.max(np.linalg.norm(jl.force, axis=-1))),
                     float(np.max(np.abs(jl.torque))), float(np.mean(d.potential_energy(q).total))))
    cols = np.array(rows).reshape(-1, 4).T
    return {"choice": list(choices), "max_spring_force": cols[0], "max_joint_load": cols[1],
            "max_holding_torque": cols[2], "energy": cols[3]}
