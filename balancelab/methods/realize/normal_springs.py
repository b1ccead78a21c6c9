"""Perfect balance with normal springs: any ZFL spring of a design swapped for an ordinary one.

Herder and co-workers showed that an inverted pendulum can be balanced *exactly* by ordinary
springs (free length ``l0 > 0``) once the spring sits in a small auxiliary linkage that makes it
see the length a ZFL spring would see (Herder 2001, *Energy-free systems*, the thesis cited by
Singh & Ananthasuresh [4] and Deepak & Ananthasuresh [6]; ASME IDETC 2004, "perfect balancing of
gravity acting on an inverted pendulum while employing normal springs between the
spring-attachment points", whose abstract states the idea and a potential-energy derivation;
the mechanisms below and their conditions are derived here, not copied).

The arrangement used here generalises :func:`~balancelab.methods.realize.sleeve.sleeve_lever`
from the lecture's link to *any* design. For a ZFL spring from ``A`` (on body ``i``) to ``C``
(on body ``j``) of rate ``k`` it adds two bodies:

* a **sleeve** pinned to body ``i`` at ``A``, whose axis always points from ``A`` to ``C``;
* a **rod** pinned to body ``j`` at ``C`` that slides in the sleeve (the prismatic pair keeps
  both on the line ``AC``) and reaches ``e`` behind ``C``.

The normal spring joins the sleeve's point ``d`` behind ``A`` to the rod's rear end. Both ends
lie on the line ``AC``, so the spring is ``|AC| - e + d`` long; with ``d = e + l0`` that is
``|AC| + l0``, and its energy ``k/2 (|AC| + l0 - l0)^2 = k/2 |AC|^2`` is the ZFL spring's at
every configuration (:func:`normal_spring_derivation` derives it with sympy from the library's
own symbolic energy). So the balance conditions of the mounted design are *the same linear
equations in the rates* as those of the ZFL design: :func:`balance_normal` runs
:func:`balancelab.balance` for ZFL candidates and mounts each spring it finds. A normal spring
mounted *directly* between ``A`` and ``C`` adds ``-k l0 |AC|``, a square root of a
trigonometric polynomial, to the energy: its conditions are not linear (not even polynomial) in
the unknowns ``bl.balance`` solves for, which is why the direct mount is not a candidate kind
of the linear solver.
"""
from __future__ import annotations

from typing import Any, Sequence


import numpy as np

from ...core.design import Design
from ...core.elements import Joint, Spring
from ...core.kinematics import Kinematics, body_to_world
from ...core.validation import finite_real
from ..registry import example

__all__ = ["mount_normal_springs", "balance_normal", "normal_spring_derivation", "lamp_arm_normal_springs"]


#: a spring whose ends come closer than this fraction of their largest distance is refused
NEAR_MEETING = 0.01


class _SleeveKinematics(Kinematics):
    """A design's kinematics plus a sleeve and a rod along the line of each mounted spring."""

    def __init__(self, base: Kinematics, lines):
        self.base, self.lines = base, tuple(lines)      # lines: ((body_i, A), (body_j, C))
        self.nbodies = base.nbodies + 2 * len(self.lines)
        self.names, self.q_range = base.names, base.q_range
        self.symbol_bodies, self.independent_symbols = base.symbol_bodies, base.independent_symbols
        self.descriptions = base.descriptions

    def poses(self, q):
        p, ok = self.base.poses(q)
        extra = []
        for (bi, a), (bj, c) in self.lines:
            ax, ay = body_to_world(p, [bi], [a])
            cx, cy = body_to_world(p, [bj], [c])
            angle = np.arctan2(cy - ay, cx - ax)[..., 0]
            extra.append(np.stack([ax[..., 0], ay[..., 0], angle], axis=-1))
            extra.append(np.stack([cx[..., 0], cy[..., 0], angle], axis=-1))
        return np.concatenate([p, np.stack(extra, axis=-2)], axis=-2), ok

    def symbolic_point(self, body, point, syms):
        if body < self.base.nbodies:
            return self.base.symbolic_point(body, point, syms)
        raise NotImplementedError("a sleeve's direction is numeric only: derive with normal_spring_derivation")


def _spans(design: Design, spring: Spring, n: int) -> tuple[float, float]:
    """Least and largest distance (m) between the spring's ends over ``n`` sampled configurations."""
    q = design.sample(n)
    ends = design.world_points(q, [spring.a, spring.b])
    dist = np.hypot(*(ends[:, 1] - ends[:, 0]).T)
    return float(dist.min()), float(dist.max())


def _which(design: Design, springs) -> list[int]:
    zfl = [i for i, s in enumerate(design.springs) if s.free_length == 0]
    if isinstance(springs, str) and springs == "all":
        if not zfl:
            raise ValueError(f"design {design.name!r} has no ZFL spring to mount (springs with free_length == 0)")
        return zfl
    if springs is None or isinstance(springs, str) or not (hasattr(springs, "__iter__")
                                                           or isinstance(springs, (int, np.integer))):
        raise TypeError(f"springs must be 'all', a spring index or a sequence of indices, got {springs!r}")
    chosen = [springs] if isinstance(springs, (int, np.integer)) else list(springs)
    for i in chosen:
        if isinstance(i, bool) or not isinstance(i, (int, np.integer)):
            raise TypeError(f"springs must hold spring indices (int), got {i!r}")
        if i not in zfl:
            raise ValueError(f"springs: index {i} is not a ZFL spring of the design; valid: {zfl}")
    return sorted(set(int(i) for i in chosen))


def mount_normal_springs(design: Design, free_length: float, springs: str | Sequence[int] = "all", *, margin: float = 0.1,
                         n: int = 2000) -> Design:
    """Replace ZFL springs by ordinary springs of ``free_length`` mounted in pivoted sleeves.

    Each chosen spring (rate ``k`` from ``A`` to ``C``) becomes a spring of the same rate and
    free length ``free_length`` between a sleeve pinned at ``A`` and a rod pinned at ``C`` that
    slides in it; the design's energy is computed from the new spring's end points and equals the
    ZFL design's at every configuration.

    Parameters
    ----------
    design : Design
        Any design with ZFL springs (``free_length == 0``).
    free_length : float
        Free length of the ordinary springs (m), > 0.
    springs : "all", int or sequence of int
        Indices of the ZFL springs to mount; ``"all"`` (default): every ZFL spring.
    margin : float
        Extra rod length behind the sleeve's pivot at the longest stretch (m), >= 0.
    n : int
        Number of sampled configurations used to size the rods, >= 10.

    Returns
    -------
    Design
        Two more bodies per mounted spring (``sleeve<i>``, ``rod<i>``); the spring keeps its index.
        ``parameters`` gain ``l0_<i>`` (the free length), ``e<i>`` (rod behind ``C``) and
        ``d<i>`` (sleeve point behind ``A``), in m.

    Raises
    ------
    ValueError
        When a spring's ends meet somewhere in the sampled range, or come closer than
        :data:`NEAR_MEETING` (1 %) of their largest distance (the sleeve would have no direction, or
        turn abruptly).

    Examples
    --------
    >>> import balancelab as bl
    >>> zfl = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> real = mount_normal_springs(zfl, free_length=0.08)
    >>> real.springs[0].free_length, real.balance_report().balanced
    (0.08, True)
    """
    if not isinstance(design, Design):
        raise TypeError(f"design must be a balancelab Design, got {type(design).__name__}")
    l0 = finite_real("free_length (m)", free_length, positive=True)
    margin = finite_real("margin (m)", margin, nonnegative=True)
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 10:
        raise ValueError(f"n must be an integer >= 10, got {n!r}")
    which = _which(design, springs)
    nb = len(design.bodies)
    bodies, joints, new_springs = list(design.bodies), list(design.joints), list(design.springs)
    lines, params = [], dict(design.parameters)
    for m, i in enumerate(which):
        s = design.springs[i]
        lo, hi = _spans(design, s, n)
        if lo <= NEAR_MEETING * hi:
            raise ValueError(f"springs: spring {i}'s ends meet, or come within {lo:.3g} m of each other "
                             f"(under {NEAR_MEETING:.0%} of their largest distance, {hi:.3g} m): a sleeve there "
                             "has no direction or turns abruptly")
        e = hi + margin
        d = e + l0
        sleeve, rod = nb + 2 * m, nb + 2 * m + 1
        bodies += [f"sleeve{i}", f"rod{i}"]
        joints += [Joint(s.a.body, s.a.point, sleeve, (0.0, 0.0)), Joint(s.b.body, s.b.point, rod, (0.0, 0.0))]
        new_springs[i] = Spring(s.k, l0, (sleeve, (-d, 0.0)), (rod, (-e, 0.0)), name=s.name)
        lines.append(((s.a.body, s.a.point), (s.b.body, s.b.point)))
        params.update({f"l0_{i}": l0, f"e{i}": e, f"d{i}": d})
    return Design(design.name + " with normal springs in sleeves", bodies, joints,
                  _SleeveKinematics(design.kinematics, lines), design.loads, new_springs,
                  labels=design.labels, parameters=params,
                  reference=(design.reference + "; " if design.reference else "")
                  + "normal springs in pivoted sleeves (balancelab.realize.mount_normal_springs)")


def balance_normal(design: Design, springs: Sequence[Any] = (), counterweights: Sequence[Any] = (),
                   free_length: float = 0.05, **options: Any) -> Design:
    """Balance ``design`` exactly with *ordinary* springs of ``free_length`` mounted in sleeves.

    The mounted springs' energy equals the ZFL springs' (module docstring), so the balance
    conditions are those :func:`balancelab.balance` solves, linear in the rates: this runs it on
    the ZFL candidates and mounts every spring it adds.

    Parameters
    ----------
    design : Design
        Any design, as for :func:`balancelab.balance`.
    springs, counterweights
        Candidates, as for :func:`balancelab.balance`.
    free_length : float
        Free length of the ordinary springs (m), > 0.
    **options
        Passed to :func:`balancelab.balance` (``objective``, ``box``, ``n``).

    Returns
    -------
    Design
        The balanced design with its new springs mounted (:func:`mount_normal_springs`).

    Raises
    ------
    ValueError
        When a spring's ends meet in the range. A free end placed for the least preload
        (Singh's minimum) makes the spring's ends meet, since its ZFL length then reaches 0:
        fix both ends, or pick ``objective="min_stiffness"``.

    Examples
    --------
    >>> import balancelab as bl
    >>> arm = bl.Linkage("arm")
    >>> arm.revolute("ground", (0.0, 0.0), "link", (0.0, 0.0))
    >>> arm.mass("link", 1.5, com=(0.4, 0.0))
    >>> d = balance_normal(arm.build(), springs=[(("ground", (0.0, 0.25)), ("link", (0.15, 0.0)))],
    ...                    free_length=0.06)
    >>> d.springs[0].free_length, d.balance_report().balanced
    (0.06, True)
    """
    from ..general import balance     # methods.general sits beside realize; imported when used

    l0 = finite_real("free_length (m)", free_length, positive=True)
    for name, value in (("springs", springs), ("counterweights", counterweights)):
        if value is None or isinstance(value, (str, bytes)) or not hasattr(value, "__iter__"):
            raise TypeError(f"{name} must be a sequence of candidates, as for balancelab.balance, got {value!r}")
    before = len(design.springs) if isinstance(design, Design) else 0
    balanced = balance(design, springs, counterweights, **options)
    added = list(range(before, len(balanced.springs)))
    return mount_normal_springs(balanced, l0, added) if added else balanced


def normal_spring_derivation() -> dict:
    """The sleeve-mounted normal spring's balance conditions, derived with sympy.

    Starts from the library's symbolic energy of the lecture's ZFL link
    (:meth:`Design.potential_energy_symbolic`, ``V = m g r sin(theta) + k/2 s^2`` with
    ``s = |BC|``), replaces the ZFL spring by an ordinary spring of free length ``l0`` whose ends
    sit ``d`` behind ``B`` and ``e`` behind ``C`` on the line ``BC`` (length ``s - e + d``), and
    writes the conditions: the coefficient of ``s`` (not a trigonometric polynomial, so it must
    vanish on its own) and the coefficients of ``cos(theta)`` and ``sin(theta)``.

    Returns
    -------
    dict
        ``zfl``: the library's energy of the ZFL link (J); ``mounted``: the energy with the
        mount (J), a polynomial in ``s`` and ``theta``; ``conditions``: the three coefficients;
        ``rank``: the rank of their Jacobian in the unknowns ``(k, d)``; ``solution``: ``k``
        and ``d``; ``residual``: the mounted energy minus its value at ``theta = 0`` once
        solved (0); ``direct``: the energy of the spring mounted directly between ``B`` and
        ``C``, whose ``s`` term ``-k l0 s`` no choice of ``k`` removes.

    Examples
    --------
    >>> out = normal_spring_derivation()
    >>> out["rank"], out["residual"]
    (2, 0)
    """
    import sympy as sp     # imported here: importing balancelab stays light
    from ..lecture import single_link_spring

    m, g, r, b, c, k, l0, d, e, s = sp.symbols("m g r b c k l0 d e s", positive=True)
    zfl = single_link_spring(2.0, 0.5, 0.3, 0.2).potential_energy_symbolic(parametric=True)
    named = {str(x): x for x in zfl.free_symbols}
    theta = named["theta"] if "theta" in named else next(x for x in zfl.free_symbols if str(x).startswith("theta"))
    zfl = zfl.subs({named[n]: v for n, v in (("m", m), ("g", g), ("r", r), ("b", b), ("c", c), ("k", k))
                    if n in named})
    s2 = sp.expand(b ** 2 + c ** 2 - 2 * b * c * sp.sin(theta))      # |BC|^2, B = (0, b), C = c (cos, sin)
    gravity = sp.simplify(zfl - k / 2 * s2)                          # what is left of the library's energy
    c2, c1, c0 = sp.Poly(k / 2 * (s - e + d - l0) ** 2, s).all_coeffs()   # the mounted normal spring
    trig = sp.expand(gravity + c2 * s2 + c0)                         # the part that is a trig polynomial
    mounted = trig + c1 * s
    conditions = [sp.factor(c1), trig.coeff(sp.cos(theta)), trig.coeff(sp.sin(theta))]
    conditions = [x for x in conditions if x != 0]
    unknowns = [k, d]
    solution = sp.solve(conditions, unknowns, dict=True)[0]
    solved = mounted.subs(solution).subs(s, sp.sqrt(s2))
    return {"zfl": zfl, "gravity": gravity, "mounted": mounted, "conditions": conditions,
            "rank": sp.Matrix(conditions).jacobian(unknowns).subs(solution).rank(), "solution": solution,
            "residual": sp.simplify(solved - solved.subs(theta, 0)),
            "direct": sp.expand(gravity + k / 2 * (s2 + l0 ** 2)) - k * l0 * s}


@example("lamp_arm_normal_springs", "The desk-lamp arm balanced exactly by two normal springs in sleeves",
         chapter=9, free_length=0.05)
def lamp_arm_normal_springs(free_length: float = 0.05) -> Design:
    """Lecture 35's desk-lamp arm (both springs at the base) with ordinary springs in sleeves.

    Parameters
    ----------
    free_length : float
        Free length of both springs (m), > 0.

    Returns
    -------
    Design
        :func:`balancelab.lecture.serial_2r_base_springs` with unit masses at the middle of two
        0.5 m links, anchors 0.3 m and 0.25 m above the base, its two ZFL springs mounted by
        :func:`mount_normal_springs`.

    Examples
    --------
    >>> arm = lamp_arm_normal_springs(0.05)
    >>> [s.free_length for s in arm.springs], arm.balance_report().balanced
    ([0.05, 0.05], True)
    """
    from ..lecture import serial_2r_base_springs

    zfl = serial_2r_base_springs(masses=(1.0, 1.0), length=0.5, coms=((0.25, 0.0), (0.25, 0.0)),
                                 b=(0.3, 0.25), c=(0.15, 0.1))
    return mount_normal_springs(zfl, free_length)
