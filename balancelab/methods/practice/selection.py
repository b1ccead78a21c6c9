"""Choosing real springs for the ZFL springs of a balanced design.

The candidates form a parametric family generated from the formulas of
:mod:`.springs`: every common wire diameter, spring index ``C`` from 4 to 14 in steps of
0.5 and whole numbers of active coils (:func:`spring_family`). For each ZFL spring of
the design, :func:`select_spring` keeps the candidates that survive its stroke (the
range of distances between its ends over the design's range) and picks the one whose
force is closest to the ideal ``k L`` over that stroke:

* ``mode="pulley"``: the spring pulls a string over a pulley at the anchor (lecture 35;
  :class:`balancelab.Pulley`). The string is set so that the spring's force is
  ``k_real x`` with ``x`` the passed-over length, which needs the spring stretched past
  its body length: ``x >= F_i / k_real`` everywhere (the smallest initial tension of the
  preferred range is used); the force error is the rate error alone;
* ``mode="direct"``: the spring hangs between the two points. Its initial tension is
  chosen in the preferred range as close to ``k L_b`` (exact ZFL) as possible; the force
  error ``(k_real - k) L - k_real l`` includes the equivalent free length ``l``, and the
  spring must never close (``L >= L_b``).

Both modes keep the largest force within the allowable stresses of the body *and of the
hooks* (static or for a number of cycles; standard hooks by default, whose length also
counts in the direct mode's body length). :func:`select_springs` does this for every ZFL
spring, optionally moves the anchors to make the real rates balance exactly
(``retune=True``, with :func:`balancelab.methods.practice.payload.rebalance`) and returns
the residual torque curve of the built design. Over a pulley each string is routed so
that it stays on its pulley (:mod:`.routing`), and the residual includes the pulley's
radius (the exact string model of :func:`balancelab.methods.realize.pulley_energy`) and
its friction: a pulley that loses the fraction ``pulley_friction`` of the string's
tension changes each spring's generalized force by up to that fraction, in the sense
that opposes the motion. :func:`largest_pulley_radius` says which pulleys fit a budget.
Layer: methods.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..registry import register
from ...core.design import Design
from ...core.elements import Pulley, Spring
from ...core.validation import finite_real
from ..lecture.lever import single_link_spring
from ..realize import pulley_energy
from .forces import configurations, generalized_force
from .payload import rebalance
from .routing import pulley_routing
from .springs import (MUSIC_WIRE, WIRE_DIAMETERS, ExtensionSpring, Material, allowable_stress, hook_stresses,
                      initial_stress_range, wahl_factor)

__all__ = ["spring_family", "SpringChoice", "select_spring", "Selection", "spring_strokes", "select_springs",
           "largest_pulley_radius", "real_spring_lever"]


_INDICES = np.arange(4.0, 14.01, 0.5)  # spring indices D/d of the default family
_ACTIVE_COILS = np.arange(5, 401)


def spring_family(material: Material = MUSIC_WIRE, wire_diameters=WIRE_DIAMETERS,
                  indices=_INDICES, active_coils=_ACTIVE_COILS, hooks: bool = True) -> dict:
    """Every combination of wire diameter, index and active coils, with its rate and limits.

    Returns
    -------
    dict of numpy.ndarray
        ``d``, ``D`` (m), ``Na``, ``k`` (N/m), ``Fi_low``, ``Fi_high`` (N, preferred initial
        tension), ``body_length`` (m, between the load points: ``N_b = N_a - G/E`` body coils
        with hooks, and the hooks; wire diameters outside ``material.diameter_range`` are
        left out) and the
        stresses per newton of pull (Pa/N) of the ``body`` and, with ``hooks``, of the
        ``hook_torsion`` and ``hook_bending`` (``"per_newton"``); ``material``; ``hooks``.

    Examples
    --------
    >>> f = spring_family(wire_diameters=[1e-3], indices=[8.0], active_coils=[40])
    >>> round(float(f["k"][0]), 2), round(float(f["body_length"][0]), 4)
    (498.66, 0.0546)
    """
    wire = np.asarray(wire_diameters, float)
    lo_d, hi_d = material.diameter_range
    wire = wire[(wire >= lo_d * (1 - 1e-12)) & (wire <= hi_d * (1 + 1e-12))]   # only where the strength fit holds
    active = np.asarray(active_coils, float)
    if hooks:
        active = active[active > material.shear_modulus / material.youngs_modulus]
    d, C, Na = (a.ravel() for a in np.meshgrid(wire, np.asarray(indices, float),
                                                active, indexing="ij"))
    D = C * d
    hook_coils = material.shear_modulus / material.youngs_modulus if hooks else 0.0   # N_a = N_b + G/E
    lo, hi = initial_stress_range(C)
    area = np.pi * d ** 3 / (8 * D)
    per_newton = {"body": wahl_factor(C) / area}
    if hooks:
        per_newton["hook_bending"], per_newton["hook_torsion"] = hook_stresses(1.0, d, D)
    return {"d": d, "D": D, "Na": Na, "k": material.shear_modulus * d / (8 * C ** 3 * Na),
            "Fi_low": lo * area, "Fi_high": hi * area, "body_length": d * (Na - hook_coils + 1) + (2 * (D - d) if hooks else 0.0),
            "per_newton": per_newton, "material": material, "hooks": bool(hooks)}


def _allowable_force(f: dict, cycles) -> np.ndarray:
    """Largest pull (N) of every candidate within the allowables of its body and hooks."""
    return np.min([allowable_stress(f["d"], f["material"], cycles, where) / stress
                   for where, stress in f["per_newton"].items()], axis=0)


class SpringChoice(NamedTuple):
    """A chosen real spring: the spring, its relative force error over the stroke, the mode."""

    spring: ExtensionSpring
    error: float
    mode: str


def select_spring(k: float, stroke, *, mode: str = "pulley", cycles: float | None = None,
                  family: dict | None = None, max_body_length: float = np.inf,
                  rate_tolerance: float = 0.01, max_length: float = np.inf,
                  max_rate_error: float = 0.5) -> SpringChoice:
    """The real extension spring closest to a ZFL spring of rate ``k`` over a stroke.

    Parameters
    ----------
    k : float
        Rate of the ideal ZFL spring (N/m), > 0.
    stroke : (float, float)
        Shortest and longest length of the ideal spring over the range (m).
    mode : {"pulley", "direct"}
        See the module docstring.
    cycles : float, optional
        Load cycles in service (fatigue-aware allowable); static when omitted.
    family : dict, optional
        Candidates from :func:`spring_family` (music wire by default).
    max_body_length : float
        Longest acceptable closed body (m).
    max_length : float
        Longest acceptable length (m) between the load points in service (at the longest
        stroke), > 0: what the mechanism has room for.
    max_rate_error : float
        Over a pulley, the largest acceptable relative rate error ``|k_real - k| / k`` of
        the chosen spring, > 0; when even the best candidate is further off, ValueError
        instead of a spring. Hung directly the rate is traded against the free length, so
        there the refusal comes only when the force error reaches 100 % of ``k L_max``.
    rate_tolerance : float
        Among the candidates whose error is within this (or within the smallest error
        found, if larger), the one with the least wire (``d^2 D N_a``) is chosen.

    Returns
    -------
    SpringChoice
        ``error`` = largest ``|F_real - k L| / (k L_max)`` over the stroke.

    Raises
    ------
    ValueError
        When no candidate survives the stroke within the lengths, or the best error
        rate error exceeds ``max_rate_error``.

    Examples
    --------
    >>> c = select_spring(163.5, (0.1, 0.5))
    >>> c.error < 0.01, c.spring.k * 0.5 <= c.spring.max_force()
    (True, True)
    """
    k = finite_real("k (N/m)", k, positive=True)
    rate_tolerance = finite_real("rate_tolerance", rate_tolerance, nonnegative=True)
    max_rate_error = finite_real("max_rate_error", max_rate_error, positive=True)
    max_length = float(max_length)
    if not max_length > 0:
        raise ValueError(f"max_length (m) must be > 0, got {max_length!r}")
    lmin, lmax = (finite_real("stroke (m)", v, nonnegative=True) for v in stroke)
    if not lmin <= lmax or lmax == 0:
        raise ValueError(f"stroke must be (shortest, longest) with 0 <= shortest <= longest, longest > 0, got {stroke!r}")
    if mode not in ("pulley", "direct"):
        raise ValueError(f"mode must be 'pulley' or 'direct', got {mode!r}")
    f = spring_family() if family is None else family
    kc, Lb = f["k"], f["body_length"]
    F_allow = _allowable_force(f, cycles)
    if mode == "pulley":
        Fi = f["Fi_low"]
        ok = (lmin >= Fi / kc) & (kc * lmax <= F_allow)
        longest = Lb + lmax - Fi / kc                 # the spring itself, at the longest passed-over length
        err = np.abs(kc - k) / k
    else:
        Fi = np.clip(kc * Lb, f["Fi_low"], f["Fi_high"])
        ell = Lb - Fi / kc
        ok = (lmin >= Lb) & (kc * (lmax - ell) <= F_allow)
        longest = np.full_like(kc, lmax)
        err = np.maximum(np.abs((kc - k) * lmin - kc * ell), np.abs((kc - k) * lmax - kc * ell)) / (k * lmax)
    ok &= (Lb <= max_body_length) & (longest <= max_length)
    if not ok.any():
        raise ValueError(f"no {mode} spring of the family survives a stroke of {lmin:.4g}-{lmax:.4g} m at "
                         f"{k:.4g} N/m within max_body_length {max_body_length:.4g} m and max_length "
                         f"{max_length:.4g} m; try the other mode, longer allowed lengths or another material")
    err_ok = np.where(ok, err, np.inf)
    good = err_ok <= max(rate_tolerance, float(err_ok.min()))
    mass = np.where(good, f["d"] ** 2 * f["D"] * f["Na"], np.inf)  # the least wire among the good ones
    i = int(np.argmin(mass))
    if (mode == "pulley" and abs(kc[i] - k) / k > max_rate_error) or err[i] >= 1:
        raise ValueError(f"the best {mode} spring of the family has a rate {kc[i]:.4g} N/m ({100 * abs(kc[i] - k) / k:.3g}"
                         f" % off the ZFL spring's {k:.4g} N/m; max_rate_error = {100 * max_rate_error:.3g} % over a "
                         f"pulley) and a force error of {100 * err[i]:.3g} % of k L_max: no spring of the family can "
                         f"stand in for it over {lmin:.4g}-{lmax:.4g} m")
    spring = ExtensionSpring(float(f["d"][i]), float(f["D"][i]), float(f["Na"][i]), float(Fi[i]), f["material"],
                             hooks=f["hooks"])
    return SpringChoice(spring, float(err[i]), mode)


class Selection(NamedTuple):
    """Result of :func:`select_springs`: the choices, the built design and its residual torque curve.

    ``residual`` (m, dof): ``dV/dq`` of the built design (N m per rad) at ``q``, with the
    pulleys' radius; ``friction`` (m, dof): the largest extra generalized force the
    pulleys' friction can add at ``q`` (either sense); ``worst`` the largest
    ``|residual| + friction``; ``within_budget``: ``worst <= budget``.
    """

    choices: dict
    design: Design
    q: np.ndarray
    residual: np.ndarray
    worst: float
    within_budget: bool
    friction: np.ndarray | None = None


def spring_strokes(design: Design, n: int = 61) -> list[tuple[float, float]]:
    """Shortest and longest length (m) of every spring over the design's range.

    Examples
    --------
    >>> import balancelab as bl
    >>> np.round(spring_strokes(bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)), 3).tolist()
    [[0.1, 0.5]]
    """
    q = configurations(design, None, n)
    w = design.world_points(q, [at for s in design.springs for at in (s.a, s.b)])
    L = np.linalg.norm(w[:, 1::2] - w[:, 0::2], axis=-1)
    return [(float(L[:, i].min()), float(L[:, i].max())) for i in range(len(design.springs))]


def _built(s: Spring, choice: SpringChoice, routing: Pulley | None) -> Spring:
    real = choice.spring
    if choice.mode == "pulley":
        realization = routing if routing is not None else s.realization
        return Spring(real.k, 0.0, s.a, s.b, name=s.name, realization=realization)
    return Spring(real.k, real.equivalent_free_length, s.a, s.b, name=s.name, realization="coil")


def _pulley_generalized_force(design: Design, q: np.ndarray, h: float = 1e-6) -> np.ndarray:
    """``dV/dq`` (m, dof) of the exact string-over-pulley energy, by differences kept inside the range."""
    out = np.empty_like(q)
    lo, hi = design.q_range[:, 0], design.q_range[:, 1]
    for j in range(q.shape[1]):
        up, down = q.copy(), q.copy()
        up[:, j] = np.minimum(q[:, j] + h, hi[j])
        down[:, j] = np.maximum(q[:, j] - h, lo[j])
        out[:, j] = (pulley_energy(design, up) - pulley_energy(design, down)) / (up[:, j] - down[:, j])
    return out


def _pulley_friction(design: Design, q: np.ndarray, fraction: float) -> np.ndarray:
    """Largest generalized force (m, dof) that pulleys losing ``fraction`` of the tension add."""
    band = np.zeros_like(q)
    for _i, s in enumerate(design.springs):
        if s.pulley is not None and fraction > 0:
            alone = design.replace(springs=[s], loads=[])
            band += fraction * np.abs(_pulley_generalized_force(alone, q))
    return band


def select_springs(design: Design, budget: float, *, mode: str = "pulley", cycles: float | None = None,
                   retune: bool = False, family: dict | None = None, n: int = 61, pulley_radius: float = 0.0,
                   pulley_friction: float = 0.0, max_length: float = np.inf) -> Selection:
    """Real springs for every ZFL spring of ``design`` and the residual torque of the result.

    Parameters
    ----------
    design : Design
        A balanced design with ZFL springs.
    budget : float
        Largest acceptable residual generalized force (N m per rad), > 0.
    mode : {"pulley", "direct"}
    cycles : float, optional
        Load cycles in service (fatigue-aware allowable).
    retune : bool
        Move the anchors so that the real rates balance exactly (pulley mode only; the
        strokes are then checked again).
    family : dict, optional
        Candidates (:func:`spring_family`).
    n : int
        Configurations per coordinate.
    pulley_radius : float
        Radius (m), >= 0, of every pulley (pulley mode); 0 is the ideal point anchor.
    pulley_friction : float
        Fraction of the string's tension the pulley's bearing loses, in [0, 1) (pulley mode).
    max_length : float
        Longest length (m) between a spring's load points in service (room in the
        mechanism), as in :func:`select_spring`.

    Returns
    -------
    Selection
        Over a pulley, each string is routed so that it stays on its pulley
        (:func:`.routing.pulley_routing`): a spring's own routing if valid (else
        ValueError), otherwise the valid one with the least wrap.

    Examples
    --------
    >>> import balancelab as bl
    >>> sel = select_springs(bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2), budget=0.15)
    >>> sel.within_budget
    True
    """
    budget = finite_real("budget (N m)", budget, positive=True)
    radius = finite_real("pulley_radius (m)", pulley_radius, nonnegative=True)
    loss = finite_real("pulley_friction", pulley_friction, nonnegative=True)
    if loss >= 1:
        raise ValueError(f"pulley_friction must be in [0, 1), got {loss}")
    if mode != "pulley" and (radius > 0 or loss > 0):
        raise ValueError("pulley_radius and pulley_friction need mode='pulley'")
    if not any(s.is_zfl for s in design.springs):
        raise ValueError(f"{design.name} has no ZFL spring to realize")
    if retune and mode != "pulley":
        raise ValueError("retune moves anchors of ZFL springs: it needs mode='pulley'")
    strokes = spring_strokes(design, n)
    choices, built = {}, list(design.springs)
    for i, s in enumerate(design.springs):
        if s.is_zfl:
            choices[s.name or str(i)] = select_spring(s.k, strokes[i], mode=mode, cycles=cycles, family=family,
                                                       max_length=max_length)
            routing = pulley_routing(design, i, radius, n) if mode == "pulley" and s.a.body == 0 else None
            built[i] = _built(s, choices[s.name or str(i)], routing)
    real = design.replace(springs=built, name=f"{design.name}, real springs ({mode})")
    if retune:
        real = rebalance(real, "anchor", [i for i, s in enumerate(design.springs) if s.is_zfl], n=n)
        after = spring_strokes(real, n)
        for i, s in enumerate(design.springs):
            c = choices.get(s.name or str(i))
            lo, hi = after[i]
            if c is not None and (lo < c.spring.initial_tension / c.spring.k or c.spring.k * hi > c.spring.max_force(cycles)):
                raise ValueError(f"after retuning, spring {s.name or i} leaves its safe stroke ({lo:.4g}-{hi:.4g} m)")
    q, Q = generalized_force(real, None, n)
    if radius > 0:
        Q = _pulley_generalized_force(real, q)
    band = _pulley_friction(real, q, loss)
    worst = float(np.max(np.abs(Q) + band))
    return Selection(choices, real, q, Q, worst, worst <= budget, band)


def largest_pulley_radius(design: Design, budget: float, *, pulley_friction: float = 0.0,
                          cycles: float | None = None, n: int = 41, largest: float = 0.05) -> float:
    """Largest pulley radius (m) with which the selected real springs keep ``design`` within ``budget``.

    The springs are chosen as by :func:`select_springs` (pulley mode); the radius is then
    found by bisection on the exact string model, friction included (a pulley too large
    for the geometry does not fit). 0 when even ideal point pulleys do not fit.

    Parameters
    ----------
    design : Design
    budget : float
        Residual budget (N m per rad), > 0.
    pulley_friction : float
        As in :func:`select_springs`.
    cycles : float, optional
    n : int
        Configurations per coordinate.
    largest : float
        Upper end (m) of the search, > 0.

    Returns
    -------
    float

    Examples
    --------
    >>> import balancelab as bl
    >>> rho = largest_pulley_radius(bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2), 0.15)
    >>> 0 < rho < 0.05
    True
    """
    largest = finite_real("largest (m)", largest, positive=True)

    def fits(r):
        try:
            return select_springs(design, budget, cycles=cycles, n=n, pulley_radius=r,
                                  pulley_friction=pulley_friction).within_budget
        except ValueError:
            if r == 0:
                raise
            return False        # a pulley so large that a string end comes inside it

    if not fits(0.0):
        return 0.0
    lo, hi = 0.0, largest
    if fits(hi):
        return hi
    for _ in range(30):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if fits(mid) else (lo, mid)
        if hi - lo < 1e-5:
            break
    return lo


def real_spring_lever(mass: float = 2.0, length: float = 0.5, b: float = 0.3, c: float = 0.2,
                      cycles: float | None = None) -> Design:
    """The lecture's link with a real music-wire spring over a pulley, anchor moved to balance exactly.

    The spring closest to the ideal ``k = m g r / (b c)`` is chosen (:func:`select_spring`,
    pulley mode); the anchor height then becomes ``b' = m g r / (k_real c)``.

    Parameters
    ----------
    mass, length, b, c : float
        As in :func:`balancelab.lecture.single_link_spring`.
    cycles : float, optional
        Load cycles in service.

    Returns
    -------
    Design
        ``parameters`` hold the spring's ``d``, ``D``, ``Na``, ``F_i``, ``k`` and ``b``.

    Examples
    --------
    >>> d = real_spring_lever()
    >>> d.balance_report().balanced, round(d.parameters["d"] * 1000, 1)
    (True, 1.6)
    """
    ideal = single_link_spring(mass, length, b, c)
    sel = select_springs(ideal, budget=1e9, cycles=cycles, retune=True)
    sp = next(iter(sel.choices.values())).spring
    d = sel.design
    return d.replace(name="lamp link with a real spring over a pulley",
                     parameters={"d": sp.wire_diameter, "D": sp.coil_diameter, "Na": sp.active_coils,
                                 "F_i": sp.initial_tension, "k": sp.k, "b": d.springs[0].a.point[1], "c": c,
                                 "r": float(length)},
                     reference="Lecture 35 (k = m g r / (b c), string over a pulley); spring formulas: "
                               "Shigley ch. 10")


register("real_spring_lever", "Lecture's link with a real music-wire spring over a pulley, anchor "
         "moved to suit its rate (chapter 8)", real_spring_lever, chapter=8)
