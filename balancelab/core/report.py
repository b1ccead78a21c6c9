"""The verdict of a design: its energy over many configurations, and whether it is balanced.

:func:`balance_report` is what :meth:`balancelab.Design.balance_report` computes; the
:class:`BalanceReport` it returns and the :class:`Energy` triple of
:meth:`balancelab.Design.potential_energy` live here too. Layer: core.

The verdict cannot be fooled by the three tricks that fooled it in 0.1:

* too few configurations (``n=1``, or a ``q`` that stays near one configuration) are refused
  (:data:`MIN_CONFIGURATIONS`, :data:`MIN_COVERAGE`);
* a tolerance that is not a number between 0 and 1 is refused (:func:`check_tolerance`);
* springs that cancel each other (two stiff springs whose energies sum to a constant) no longer
  make an unbalanced design look balanced: the energy is compared with the energy the *loads*
  exchange, which springs cannot change (:func:`load_scale`); loads that cancel each other
  (equal and opposite forces on a translating coupler) are summed first, so they cannot either.
"""
from __future__ import annotations

import math
import weakref
from dataclasses import dataclass
from numbers import Real
from typing import TYPE_CHECKING, Any, NamedTuple, Sequence

import numpy as np
from numpy.typing import ArrayLike

from .cancel import EXACT, null_subset
from .samples import check_spread
from .smooth import smooth_resolution, smooth_split
from .validation import positive_int

if TYPE_CHECKING:
    from .design import Design

__all__ = ["BALANCE_TOLERANCE", "MAX_ROUND_OFF_RATIO", "MIN_CONFIGURATIONS", "MIN_COVERAGE", "ROUND_OFF_ALLOWANCE", "Energy", "BalanceReport",
           "balance_report", "balanced_at", "roundoff_allowance", "check_tolerance", "reachable_extent", "load_scale", "q_units", "q_shown", "format_q",
           "q_meaning", "reference_point", "energy_change"]

#: Relative tolerance below which a design is reported balanced: the spread of its total
#: potential energy over the sampled configurations, divided by the load scale.
BALANCE_TOLERANCE: float = 1e-9

#: Fewest distinct configurations a report accepts.
MIN_CONFIGURATIONS: int = 10

#: Most configurations a report (or ``balance``) samples: ``n`` beyond it is refused, not allocated
#: until memory runs out.
MAX_CONFIGURATIONS: int = 200_000

#: Smallest part of each coordinate's reachable range the configurations must span.
MIN_COVERAGE: float = 0.25

#: Loads whose energies spread by less than this fraction of :attr:`BalanceReport.scale` are
#: round-off: the design is then treated as spring-loaded (its springs are the load).
_ROUND_OFF = 1e-12

#: Round-off allowance of the verdict (about 45 machine epsilons): the total energy cannot be
#: summed more exactly than this fraction of the energies summed, ``sum of the loads' spreads +
#: sum of the springs' largest energies`` (J), both independent of the origin.
ROUND_OFF_ALLOWANCE: float = 1e-14

#: The round-off allowance may widen the verdict to at most this many times ``tolerance * L``: past
#: that (energies some 1e14 times what the loads exchange: a far origin, an idle stiff spring, huge
#: loads that cancel) double precision cannot resolve the balance, and the report says NOT balanced
#: and why, never balanced.
MAX_ROUND_OFF_RATIO: float = 1e3

_EXTENTS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


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
        Largest generalized force ``|dV/dq|`` (J/rad, or N for a slide) divided by ``scale``
        (1/rad or 1/m).
    scale : float
        Energy scale (J): the sum over every load and spring of the spread of its own
        energy over the configurations. It does not depend on where the origin is.
    energy : float
        Mean total potential energy (J).
    worst_q : numpy.ndarray
        Configuration with the largest residual generalized force.
    balanced : bool
        ``load_variation <= tolerance``, up to the round-off of summing the energies of very
        stiff springs (:data:`ROUND_OFF_ALLOWANCE`).
    tolerance : float
        The tolerance used (default :data:`BALANCE_TOLERANCE`).
    n : int
        Number of configurations examined.
    load_scale : float
        The energy the loads exchange (J), see :func:`load_scale`; at most ``scale``.
    load_variation : float
        ``(max V - min V) / load_scale``: the number the verdict compares with ``tolerance``.
    q_units : tuple of str
        Unit of each coordinate (``"rad"`` or ``"m"``), for printing ``worst_q``.
    cancelled : float
        Sum of the spreads (J) of the elements left out of ``load_scale`` because their energies
        sum to a constant (see :func:`load_scale`); 0 when none are.
    roundoff : float
        The round-off allowance of the verdict (J), :data:`ROUND_OFF_ALLOWANCE` times the energies
        summed. When it exceeds :data:`MAX_ROUND_OFF_RATIO` ``* tolerance * load_scale`` the
        verdict cannot be resolved and is NOT balanced (:attr:`resolvable` is False).
    smooth_variation : float
        When ``load_variation`` exceeds ``tolerance`` and only the round-off allowance covers the
        excess: the spread of the energy's smooth part (:func:`~balancelab.core.smooth.smooth_split`)
        over ``load_scale``; *balanced* then needs it within ``tolerance`` (the allowance covers noise,
        never a real variation). NaN otherwise.
    smooth_resolution : float
        When the smooth part exceeds ``tolerance`` while the rest is round-off: how large a smooth
        spread (over ``load_scale``) the noise alone can make
        (:func:`~balancelab.core.smooth.smooth_resolution`). Within it the smooth part cannot be told
        from noise: the verdict is NOT balanced and cannot be resolved. NaN otherwise.

    Examples
    --------
    >>> import balancelab as bl
    >>> r = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3).balance_report()
    >>> r.balanced, round(r.scale, 2), round(r.load_scale, 2)  # J: about W l ptp(sin) = 10 * 0.5 * 2
    (True, 20.0, 10.0)
    """

    variation: float
    residual: float
    scale: float
    energy: float
    worst_q: np.ndarray
    balanced: bool
    tolerance: float
    n: int
    load_scale: float = math.nan
    load_variation: float = math.nan
    q_units: tuple[str, ...] = ()
    cancelled: float = 0.0
    roundoff: float = 0.0
    smooth_variation: float = math.nan
    smooth_resolution: float = math.nan

    @property
    def resolvable(self) -> bool:
        """Whether double precision can resolve the verdict: the round-off allowance (J) is at most
        :data:`MAX_ROUND_OFF_RATIO` times ``tolerance * load_scale``, and the smooth part, when it was
        needed, stands out of the noise (:attr:`smooth_resolution`)."""
        drowned = self.smooth_variation - self.smooth_resolution <= self.tolerance < self.smooth_variation
        return not (self.roundoff > MAX_ROUND_OFF_RATIO * self.tolerance * self.load_scale or drowned)

    def __str__(self) -> str:
        verdict = "balanced" if self.balanced else "NOT balanced"
        units = self.q_units or ("rad",) * len(np.atleast_1d(self.worst_q))
        q = format_q(units, self.worst_q)
        per = " or ".join(sorted(set(units), reverse=True))
        left_out = (f"; elements that cancel each other, {self.cancelled:.4g} J, left out"
                    if self.cancelled > 0 else "")
        unresolved = ("" if self.resolvable else
                      f" (cannot be resolved: the round-off of energies this large, {self.roundoff:.3g} J, "
                      + (f"exceeds {MAX_ROUND_OFF_RATIO:g} x tolerance x the loads' exchange"
                         if self.roundoff > MAX_ROUND_OFF_RATIO * self.tolerance * self.load_scale else
                         f"makes a smooth part up to {self.smooth_resolution:.2e} of the loads' exchange")
                      + "; move the origin near the mechanism, or remove elements that store energy "
                      "without exchanging it)")
        smooth = ("" if math.isnan(self.smooth_variation) else
                  f", its smooth part by {self.smooth_variation:.2e} (the rest is round-off within "
                  f"{self.roundoff:.3g} J)")
        return (f"{verdict}{unresolved}: energy varies by {self.variation:.2e} of its scale "
                f"({self.scale:.4g} J) and by {self.load_variation:.2e} of the loads' "
                f"({self.load_scale:.4g} J{left_out}){smooth} over {self.n} configurations; "
                f"largest residual dV/dq = {self.residual:.2e} × scale per {per} at q = ({q}); "
                f"mean energy {self.energy:.6g} J")


def q_units(design: Design) -> tuple[str, ...]:
    """Unit of each configuration coordinate of ``design``: ``"rad"`` (an angle) or ``"m"`` (a slide).

    Examples
    --------
    >>> import balancelab as bl
    >>> q_units(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3))
    ('rad',)
    """
    units = getattr(design.kinematics, "units", None)
    return tuple(units) if units is not None else ("rad",) * design.dof


def q_meaning(design: Design) -> str:
    """What a design's ``q`` holds, for error messages: ``"angles in radians"``, ``"slides in metres"``
    or ``"angles in radians and slides in metres"``.

    Examples
    --------
    >>> import balancelab as bl
    >>> q_meaning(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3))
    'angles in radians'
    """
    units = set(q_units(design))
    parts = (["angles in radians"] if "rad" in units else []) + (["slides in metres"] if "m" in units else [])
    return " and ".join(parts) or "angles in radians"


def reference_point(design: Design) -> np.ndarray:
    """The ground point (m) about which a design's element energies are taken: the ground end of its
    first ground joint, else the first ground end of a spring or a load, else the origin.

    Energies about a point of the mechanism do not lose digits when the whole design sits far from
    the origin (a pivot 1e6 m up), so the verdict and ``dV/dq`` do not depend on where the origin is.

    Examples
    --------
    >>> import balancelab as bl
    >>> reference_point(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)).tolist()
    [0.0, 0.0]
    """
    for j in design.joints:
        if j.body_i == 0 or j.body_j == 0:
            return np.array(j.point_i if j.body_i == 0 else j.point_j, dtype=float)
    ends = [(s.b.body, s.b.point) for s in design.springs] + [(s.a.body, s.a.point) for s in design.springs]
    for body, point in ends + [(ld.body, ld.point) for ld in design.loads]:
        if body == 0:
            return np.array(point, dtype=float)
    return np.zeros(2)


def energy_change(design: Design, qp: np.ndarray, qm: np.ndarray) -> np.ndarray:
    """``V(qp) - V(qm)`` (J), each element's change taken first and then summed (energies about
    :func:`reference_point`): a large constant energy (a far origin, an idle stiff spring) costs no
    digits, as it would in the difference of two summed totals.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    >>> bool(abs(energy_change(d, np.array([[0.3]]), np.array([[0.1]]))[0]) < 1e-12)
    True
    """
    shape = qp.shape[:-1]
    vlp, vsp = design._element_energies(design._checked_poses(qp.reshape(-1, design.dof))[0])
    vlm, vsm = design._element_energies(design._checked_poses(qm.reshape(-1, design.dof))[0])
    change = np.zeros(int(np.prod(shape, dtype=int)))
    for a, b in zip(vlp + vsp, vlm + vsm):
        change = change + (a - b)
    return change.reshape(shape)


def q_shown(unit: str, value: ArrayLike) -> Any:
    """A coordinate as shown to a reader: an angle (rad) in degrees, a slide (m) as it is.

    Examples
    --------
    >>> float(q_shown("rad", np.pi)), q_shown("m", 0.4)
    (180.0, 0.4)
    """
    return np.degrees(value) if unit == "rad" else value


def format_q(units: Sequence[str], q: ArrayLike, names: Sequence[str] | None = None) -> str:
    """``"22.9°, 0.4 m"``: a configuration in its units (degrees for angles, metres for slides).

    Examples
    --------
    >>> format_q(("rad", "m"), [0.4, 0.4])
    '22.9°, 0.4 m'
    """
    out = []
    for i, (unit, v) in enumerate(zip(units, np.atleast_1d(q))):
        text = f"{np.degrees(v):.1f}°" if unit == "rad" else f"{v:.4g} m"
        out.append(f"{names[i]} = {text}" if names else text)
    return ", ".join(out)


def _q_text(unit: str, value: float, fmt: str) -> str:
    """``"12.3°"`` for an angle (rad), ``"0.25 m"`` for a slide (m)."""
    return f"{q_shown(unit, value):{fmt}}" + ("°" if unit == "rad" else " m")


def check_tolerance(tolerance: Any) -> float:
    """``tolerance`` as a float with ``0 < tolerance < 1``, or a TypeError/ValueError naming it.

    Examples
    --------
    >>> check_tolerance(1e-3)
    0.001
    >>> check_tolerance(0.0)
    Traceback (most recent call last):
    ...
    ValueError: tolerance must be a real number with 0 < tolerance < 1 (a relative energy variation), got 0.0
    """
    if isinstance(tolerance, bool) or not isinstance(tolerance, (Real, np.floating, np.integer)):
        raise TypeError("tolerance must be a real number with 0 < tolerance < 1 (a relative energy "
                        f"variation), got {type(tolerance).__name__} {tolerance!r}")
    value = float(tolerance)
    if not (math.isfinite(value) and 0.0 < value < 1.0):
        raise ValueError("tolerance must be a real number with 0 < tolerance < 1 (a relative energy "
                         f"variation), got {value}")
    return value


def reachable_extent(design: Design) -> np.ndarray:
    """Extent ``max - min`` (rad) of each coordinate over the default sample of ``design``.

    The default sample is ``design.sample(1000, seed=0)``: the configurations
    :func:`balance_report` uses when given none. Cached per design (designs are immutable).

    Examples
    --------
    >>> import balancelab as bl
    >>> reachable_extent(bl.singh.scissors_lift()).round(2).tolist()  # of [0, pi/2]
    [1.57]
    """
    extent = _EXTENTS.get(design)
    if extent is None:
        extent = np.ptp(design.sample(1000, 0), axis=0)
        _EXTENTS[design] = extent
    return extent


def _configurations(design, q, n, seed) -> np.ndarray:
    """The configurations of a report: at least MIN_CONFIGURATIONS distinct ones spanning
    at least MIN_COVERAGE of each coordinate's reachable range."""
    if q is None:
        what = "n"
        n = positive_int("n (number of configurations)", n, minimum=MIN_CONFIGURATIONS, maximum=MAX_CONFIGURATIONS)
        q = design.sample(n, seed)
    else:
        what = "q"
        q = design.check_q(q).reshape(-1, design.dof)
        units = q_units(design)
        wrapped = np.where(np.array(units) == "rad", np.angle(np.exp(1j * q)), q)  # q and q + 2 pi alike
        distinct = len(np.unique(np.round(wrapped, 12), axis=0))
        if distinct < MIN_CONFIGURATIONS:
            raise ValueError(f"q must hold at least {MIN_CONFIGURATIONS} distinct configurations to show "
                             f"that the energy is constant, got {distinct}")
    extent = np.ptp(q, axis=0)
    reach = extent if (what == "n" and n == 1000 and seed == 0) else reachable_extent(design)
    for name, unit, span, full in zip(design.q_names, q_units(design), extent, reach):
        if span < MIN_COVERAGE * full:
            raise ValueError(
                f"{what} must give configurations spanning at least {MIN_COVERAGE:g} of each "
                f"coordinate's reachable range: {name} spans {_q_text(unit, span, '.3g')} of "
                f"{_q_text(unit, full, '.4g')}" + (" (sample more configurations)" if what == "n" else ""))
    if what == "q":
        check_spread(q, q_units(design), design.q_names)
    return q


def load_scale(design: Design, q: np.ndarray, load_energies: np.ndarray, scale: float, roundoff: float = 0.0,
               spring_energies: np.ndarray | None = None, tolerance: float = BALANCE_TOLERANCE) -> float:
    """The energy (J) the loads exchange over the configurations ``q``: the verdict's yardstick.

    Loads acting at the same point (the same world position in every configuration,
    e.g. a force and its opposite) are added up first, then groups whose energies cancel
    (equal and opposite forces at two points of a translating body, say); ``L`` is the
    sum of the spreads ``max - min`` of these groups' energies. Springs do not enter it, so springs that
    cancel each other cannot inflate it.

    Loads that form a *set* of zero resultant force and zero moment on one body (three forces, say)
    do no work in any motion: they are left out first (:func:`_null_sets`). Then, with the springs'
    energies given, the largest part of the design whose elements' energies sum to a constant
    (:func:`balancelab.core.cancel.null_subset`, to ``min(tolerance, 1e-9)``; loads ``F, F, -F`` on
    three bodies of a parallelogram, or stiff springs pulling against each other) is left out too,
    whatever bodies it acts on: it exchanges no energy with the rest, so it cannot make the rest look
    balanced. When what is left sums to a constant as well (the design is made of balanced parts) the
    yardstick is the loads' sum above. A design whose loads exchange no energy (a spring-loaded
    mechanism, or loads that only stand still; ``L`` below ``roundoff`` and below ``1e-12`` of the
    loads' largest energy) has its springs as the load: the spreads of the springs left over, or
    ``scale``, the sum of the spreads of every element's own energy, when they all cancel.

    Parameters
    ----------
    design : Design
    q : numpy.ndarray, shape (m, dof)
        Configurations (rad).
    load_energies : numpy.ndarray, shape (m, n_loads)
        Energy of each load (J), as from ``design.element_energies(q)[0]``.
    scale : float
        Sum of the spreads of every load's and spring's energy (J).
    roundoff : float
        The round-off of the summed energy (J), see :data:`ROUND_OFF_ALLOWANCE`.
    spring_energies : numpy.ndarray, shape (m, n_springs), optional
        Energy of each spring (J); without it no set cancelling across bodies is left out.
    tolerance : float
        The verdict's tolerance; sets cancelling to ``min(tolerance, 1e-9)`` are left out.

    Returns
    -------
    float

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.catalog()["single_link_counterweight"]()
    >>> q = d.sample(100)
    >>> vl, vs = d.element_energies(q)
    >>> s = float(np.ptp(vl, axis=0).sum())
    >>> bool(abs(load_scale(d, q, vl, s) - s) < 1e-9 * s)  # counterweights: every load counts
    True
    """
    return _yardstick(design, q, load_energies, scale, roundoff, spring_energies, tolerance)[0]


def _yardstick(design, q, load_energies, scale, roundoff=0.0, spring_energies=None, tolerance=BALANCE_TOLERANCE):
    """``(load_scale, weight)`` (J): the yardstick, and the sum of the spreads of the null set left out."""
    null = _null_sets(design.loads)
    loads = [ld for i, ld in enumerate(design.loads) if i not in null]
    load_energies = load_energies[:, [i for i in range(len(design.loads)) if i not in null]]
    total = 0.0
    if loads:
        pts = design.world_points(q, [(ld.body, ld.point) for ld in loads])  # (m, nL, 2)
        size = max(float(np.max(np.ptp(pts, axis=0))), 1e-300)
        group = list(range(len(loads)))
        for i in range(len(loads)):
            for j in range(i):
                if group[j] == j and np.max(np.abs(pts[:, i] - pts[:, j])) <= 1e-9 * size:
                    group[i] = j
                    break
        sums = _cancel([load_energies[:, [i for i, gi in enumerate(group) if gi == g]].sum(-1)
                        for g in sorted(set(group))])
        total = sum(float(np.ptp(e)) for e in sums)
    else:
        sums = []
    # the loads stand still when what they exchange is below their own round-off AND below the sum's
    # (a real exchange drowned in the round-off of huge elements is not "still": the verdict is then
    # unresolvable, see MAX_ROUND_OFF_RATIO, never judged against the springs instead)
    still = min(_ROUND_OFF * (float(np.max(np.abs(load_energies))) if load_energies.size else 0.0), roundoff)
    if spring_energies is not None:
        left = _left_over(sums, np.asarray(spring_energies, dtype=float), min(tolerance, EXACT))
        if left is not None:
            loads_left, springs_left, weight = left
            return (loads_left if loads_left > still else springs_left if springs_left > roundoff else scale), weight
    return (total if total > still else scale), 0.0


def _left_over(load_sums: list, spring_energies: np.ndarray, eta: float):
    """``(loads' spread, springs' spread, null set's spread)`` (J) of what is left of the design once its largest null set
    is taken out, or None when nothing is taken out or what is left is null too (the design is then
    made of balanced parts, and the loads' sum is the yardstick)."""
    m = len(spring_energies)
    E = np.column_stack(list(load_sums) + [spring_energies]) if load_sums else spring_energies
    E = E.reshape(m, -1)
    null = null_subset(E, eta)
    if not null.any() or null.sum() == int((np.ptp(E, axis=0) > 0).sum()):
        return None  # nothing cancels, or the whole design does
    rest = E[:, ~null]
    spread = np.ptp(rest, axis=0)
    if np.ptp(rest.sum(-1)) <= eta * spread.sum() + 1e-14 * float(np.abs(rest).max(initial=0.0)):
        return None
    is_load = (np.arange(E.shape[1]) < len(load_sums))[~null]
    return float(spread[is_load].sum()), float(spread[~is_load].sum()), float(np.ptp(E[:, null], axis=0).sum())


def _null_sets(loads) -> set:
    """Indices of loads that form, on one body, a set of zero resultant force and zero moment (and
    zero ``sum p . F``): such a set does no work in any motion of the body, it is no load at all.
    On each body (up to 12 loads) the largest such subset is taken."""
    from itertools import combinations

    out: set = set()
    bodies = sorted({ld.body for ld in loads})
    for body in bodies:
        idx = [i for i, ld in enumerate(loads) if ld.body == body]
        if len(idx) < 2 or len(idx) > 12:
            continue
        F = np.array([loads[i].force for i in idx], dtype=float)
        P = np.array([loads[i].point for i in idx], dtype=float)
        for size in range(len(idx), 1, -1):
            found = None
            for sub in combinations(range(len(idx)), size):
                f, p = F[list(sub)], P[list(sub)]
                mag = float(np.abs(f).sum())
                arm = mag * (float(np.abs(p).max()) + 1e-300)
                net = np.abs(f.sum(0)).max()
                moment = abs(float(np.sum(p[:, 0] * f[:, 1] - p[:, 1] * f[:, 0])))
                dot = abs(float(np.sum(p * f)))
                if mag > 0 and net <= 1e-12 * mag and moment <= 1e-12 * arm and dot <= 1e-12 * arm:
                    found = sub
                    break
            if found is not None:
                out.update(idx[k] for k in found)
                break
    return out


def _cancel(energies: list) -> list:
    """Merge groups of loads whose energies cancel (the sum of two varies by at most ``1e-9`` of their
    own spreads: equal and opposite forces on a translating body, or on two bodies that turn alike),
    so that loads that cancel each other cannot inflate the yardstick (what is left of a cancelling pair
    is round-off and counts zero); repeated until none merge."""
    groups = [np.asarray(e, dtype=float) for e in energies]
    merged = True
    while merged and len(groups) > 1:
        merged = False
        for i in range(len(groups)):
            for j in range(i):
                both = groups[i] + groups[j]
                if np.ptp(both) <= 1e-9 * (np.ptp(groups[i]) + np.ptp(groups[j])) and np.ptp(groups[i]) > 0:
                    groups[j] = np.zeros_like(both)  # what is left of them is round-off
                    del groups[i]
                    merged = True
                    break
            if merged:
                break
    return groups


#: A closed loop is solved to a joint gap of about 1e-13 m; a point's position is then uncertain by
#: up to this many times the largest gap, and so is each element's energy by force times that.
CLOSURE_FACTOR: float = 10.0


def _closure_allowance(design, poses, spring_energies) -> float:
    """What a closed loop's solving error can add to the summed energy (J): ``CLOSURE_FACTOR`` times
    the largest joint gap over ``q`` times the sum of the loads' and the springs' largest forces
    (huge loads cancelling across a loop's bodies amplify it; an open chain has no gap)."""
    if not design.joints:
        return 0.0
    from .kinematics import joint_gaps

    gap = float(np.max(joint_gaps(poses, design.joints), initial=0.0))
    forces = sum(math.hypot(*ld.force) for ld in design.loads)
    forces += sum(math.sqrt(2.0 * s.k * float(np.max(spring_energies[:, i], initial=0.0)))
                  for i, s in enumerate(design.springs))
    return CLOSURE_FACTOR * gap * forces


def _verdict(design: Design, q: np.ndarray, tolerance: float):
    """``(total energy, scale, roundoff, yardstick, null set's weight, balanced, smooth part, its
    noise)`` at the configurations ``q``. When the variation passes only thanks to the round-off allowance, the verdict
    is that of its smooth part (:func:`~balancelab.core.smooth.smooth_split`: the allowance covers noise,
    never a real variation); the smooth part's spread (J) is NaN when it was not needed, and so is the
    spread the noise alone can give it (:func:`~balancelab.core.smooth.smooth_resolution`, J) unless
    the smooth part failed."""
    poses = design.poses(q)  # once: the energies and the closure allowance both need them
    vl, vs = (np.stack(e, -1) if e else np.zeros((len(q), 0)) for e in design._element_energies(poses))
    total = vl.sum(-1) + vs.sum(-1)
    scale = float(np.sum(np.ptp(vl, axis=0)) + np.sum(np.ptp(vs, axis=0)))
    if scale == 0.0:
        raise ValueError(f"{design.name}: nothing in this design stores energy as it moves, "
                         "so there is nothing to balance")
    summed = np.sum(np.ptp(vl, axis=0)) + np.sum(np.max(vs, axis=0) if len(design.springs) else 0.0)
    roundoff = ROUND_OFF_ALLOWANCE * float(summed) + _closure_allowance(design, poses, vs)
    yardstick, null_weight = _yardstick(design, q, vl, scale, roundoff, vs, tolerance)
    bound = tolerance * yardstick
    spread = float(np.ptp(total))
    balanced = bool(spread <= bound + roundoff and not roundoff > MAX_ROUND_OFF_RATIO * bound)
    smooth = noise = math.nan
    if balanced and spread > bound:  # only the allowance passes it: its smooth part must pass alone
        smooth, rest = smooth_split(poses, q, q_units(design), total)
        balanced = smooth <= bound and rest <= bound + roundoff
        if not balanced and rest <= bound + roundoff:  # could the noise alone make that smooth part?
            noise = smooth_resolution(poses, q, q_units(design), total)
    return total, scale, roundoff, yardstick, null_weight, balanced, smooth, noise


def roundoff_allowance(design: Design, q: ArrayLike) -> float:
    """The round-off allowance (J) of the verdict of ``design`` at the configurations ``q``
    (:attr:`BalanceReport.roundoff`: the summing round-off and a closed loop's solving error).

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    >>> roundoff_allowance(d, d.sample(50)) < 1e-12
    True
    """
    return _verdict(design, design.check_q(q).reshape(-1, design.dof), BALANCE_TOLERANCE)[2]


def balanced_at(design: Design, q: ArrayLike, tolerance: float = BALANCE_TOLERANCE) -> bool:
    """The verdict of :func:`balance_report` at the configurations ``q`` (rad or m), without its
    ``dV/dq`` readout: the one yardstick the balancer uses too (a design balanced already needs nothing).

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    >>> balanced_at(d, d.sample(50))
    True
    """
    return _verdict(design, design.check_q(q).reshape(-1, design.dof), check_tolerance(tolerance))[5]


def balance_report(design: Design, q: ArrayLike | None = None, *, n: int = 1000, seed: int | None = 0,
                   tolerance: float = BALANCE_TOLERANCE) -> BalanceReport:
    """The :class:`BalanceReport` of ``design`` (see :meth:`balancelab.Design.balance_report`).

    Examples
    --------
    >>> import balancelab as bl
    >>> balance_report(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)).balanced
    True
    """
    tolerance = check_tolerance(tolerance)
    q = _configurations(design, q, n, seed)
    total, scale, roundoff, yardstick, null_weight, balanced, smooth, noise = _verdict(design, q, tolerance)
    spread = float(np.ptp(total))
    gf = design.generalized_force(q)
    mag = np.max(np.abs(gf), axis=-1)
    worst = int(np.argmax(mag))
    return BalanceReport(variation=spread / scale, residual=float(mag[worst]) / scale, scale=scale,
                         energy=float(np.mean(total)) - float(np.sum(design._lf @ design._ref)),  # about the origin
                         worst_q=q[worst].copy(),
                         balanced=balanced,
                         tolerance=tolerance, n=len(q), load_scale=yardstick, load_variation=spread / yardstick,
                         q_units=q_units(design), cancelled=null_weight, roundoff=roundoff,
                         smooth_variation=smooth / yardstick, smooth_resolution=noise / yardstick)
