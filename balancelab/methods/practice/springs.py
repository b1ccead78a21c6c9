"""Real helical extension springs: rate, index, body length, initial tension, stress, allowables.

Formulas (SI units: metres, newtons, pascals), as given in spring-design guidance,
for instance Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, ch. 10
(helical springs), and the SMI *Handbook of Spring Design*:

* rate ``k = G d^4 / (8 D^3 N_a)`` (wire diameter ``d``, mean coil diameter ``D``,
  active coils ``N_a``, shear modulus ``G``); spring index ``C = D / d``;
* closed body length ``L_b = d (N_b + 1)`` with ``N_b`` body coils. The coil count the API
  takes (``active_coils``) is ``N_a``, the one in the rate. For an extension spring with
  hooks the hooks' deflection counts as extra active turns: ``N_a = N_b + G / E``
  (Shigley eq. 10-39; ``G/E`` ≈ 0.42 coil for music wire), so its body holds
  ``N_b = N_a - G / E`` coils; without hooks (a bare body) ``N_b = N_a``;
* uncorrected shear stress ``tau = 8 F D / (pi d^3)``; with the Wahl curvature
  correction ``K_W = (4C - 1)/(4C - 4) + 0.615 / C``, the maximum stress is ``K_W tau``;
* preferred range of the uncorrected initial-tension stress as a function of ``C``
  (Shigley eq. 10-48, in its SI form):
  ``tau_i = 231 / exp(0.105 C) +- 6.9 (4 - (C - 3) / 6.5)`` MPa;
* minimum tensile strength ``S_ut = A / d^m`` (``d`` in mm, ``A`` in MPa mm^m), constants
  per material from Shigley's table 10-4;
* allowable stresses as fractions of ``S_ut`` (Shigley table 10-7, static): body torsion
  45 % (music wire) or 35 % (austenitic stainless), hook torsion 40 % or 30 %, hook bending
  75 % or 55 %; in cyclic service (table 10-8: stress ratio 0, not shot-peened) body
  36 / 33 / 30 %, hook torsion 34 / 30 / 28 % and hook bending 51 / 47 / 45 % for 1e5, 1e6
  and 1e7 cycles, interpolated in ``log10(cycles)`` between those points;
* the hooks (Shigley eqs. 10-34 to 10-36): at the hook's bend (point A, mean bend radius
  ``r1``, ``C1 = 2 r1 / d``) the wire is bent and pulled,
  ``sigma_A = F (K_A 16 D / (pi d^3) + 4 / (pi d^2))`` with
  ``K_A = (4 C1^2 - C1 - 1) / (4 C1 (C1 - 1))``; where the hook turns up from the body
  (point B, bend radius ``r2``, ``C2 = 2 r2 / d``) it is twisted,
  ``tau_B = K_B 8 F D / (pi d^3)`` with ``K_B = (4 C2 - 1) / (4 C2 - 4)``. A standard
  full-loop machine hook has ``r1 = D / 2`` (``C1 = C``) and here ``r2 = 2 d`` (``C2 = 4``,
  the smallest the guidance recommends); each hook adds its inside diameter ``D - d`` to
  the length between the load points (free length ``L_0 = (N_b + 1) d + 2 (D - d)``).

The constants were taken from the textbook as the authors remember its 9th/10th
editions; they reproduce its worked example 10-7 (see ``tests/test_practice.py``), and
the static fractions and the cyclic hook-bending fractions agree with a secondary source
quoting tables 10-7 and 10-8 (the cyclic hook-torsion fractions were not rechecked), but
check them against the edition you use before ordering springs.

**When is an extension spring a ZFL spring?** Wound with initial tension ``F_i``, the
spring stays closed at ``L_b`` until the pull exceeds ``F_i``; beyond, it pulls with
``F = F_i + k (L - L_b) = k (L - l)`` with the *equivalent free length*
``l = L_b - F_i / k``. It acts as a ZFL spring only over the part of its stroke where it
is stretched past ``L_b``, and it is exactly ZFL when ``F_i = k L_b`` (``l = 0``).
Elsewhere the force differs from the ZFL force ``k L`` by ``-k l``
(:func:`zfl_force_error`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from ...core.validation import finite_real

__all__ = ["Material", "MUSIC_WIRE", "STAINLESS_302", "MATERIALS", "WIRE_DIAMETERS", "spring_rate",
           "spring_index", "wahl_factor", "shear_stress", "initial_stress_range", "tensile_strength",
           "allowable_stress", "hook_bending_factor", "hook_torsion_factor", "hook_stresses", "ExtensionSpring",
           "zfl_force_error"]


class Material(NamedTuple):
    """A spring wire material.

    ``shear_modulus`` (Pa); tensile strength ``S_ut = A / d^m`` with ``strength_A``
    (MPa mm^m) and ``strength_m``; ``static_fraction``: allowable body torsion stress in
    static service as a fraction of ``S_ut``; ``source``: where the numbers come from;
    ``hook_torsion_fraction`` and ``hook_bending_fraction``: the static allowables of the
    hooks (torsion at the hook's root, bending at its bend) as fractions of ``S_ut``;
    ``youngs_modulus`` (Pa); ``diameter_range`` (m): the wire diameters the strength fit
    covers.
    """

    name: str
    shear_modulus: float
    strength_A: float
    strength_m: float
    static_fraction: float
    source: str
    hook_torsion_fraction: float = 0.40
    hook_bending_fraction: float = 0.75
    youngs_modulus: float = 196.5e9
    diameter_range: tuple = (0.10e-3, 6.5e-3)


_SHIGLEY = "Budynas & Nisbett, Shigley's Mechanical Engineering Design, tables 10-4, 10-5, 10-7"

#: Music wire (ASTM A228), valid for wire diameters 0.10-6.5 mm.
MUSIC_WIRE = Material("music wire (ASTM A228)", 81.7e9, 2211.0, 0.145, 0.45, _SHIGLEY, 0.40, 0.75, 196.5e9,
                      (0.10e-3, 6.5e-3))
#: Stainless steel 302 (ASTM A313), valid for wire diameters 0.3-2.5 mm.
STAINLESS_302 = Material("stainless steel 302 (ASTM A313)", 69.0e9, 1867.0, 0.146, 0.35, _SHIGLEY, 0.30, 0.55,
                         193.0e9, (0.3e-3, 2.5e-3))
#: The bundled materials by short name.
MATERIALS = {"music_wire": MUSIC_WIRE, "stainless_302": STAINLESS_302}

#: Common metric wire diameters (m) from which the parametric family is generated.
WIRE_DIAMETERS = tuple(x / 1000 for x in (0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.4, 1.6,
                                          1.8, 2.0, 2.2, 2.5, 2.8, 3.0, 3.2, 3.5, 4.0, 4.5, 5.0))

#: Fatigue allowables of an extension spring (fraction of S_ut, stress ratio 0) by log10(cycles),
#: for its body (torsion), its hooks' roots (torsion) and its hooks' bends (bending); table 10-8.
_FATIGUE = {"body": ((5.0, 0.36), (6.0, 0.33), (7.0, 0.30)),
            "hook_torsion": ((5.0, 0.34), (6.0, 0.30), (7.0, 0.28)),
            "hook_bending": ((5.0, 0.51), (6.0, 0.47), (7.0, 0.45))}
_STATIC = {"body": "static_fraction", "hook_torsion": "hook_torsion_fraction",
           "hook_bending": "hook_bending_fraction"}


def _positive(name, value):
    arr = np.asarray(value, dtype=float)
    if arr.size == 0 or not np.all(np.isfinite(arr)) or np.any(arr <= 0):
        raise ValueError(f"{name} must be finite and > 0, got {value!r}")
    return arr


def spring_rate(wire_diameter, coil_diameter, active_coils, shear_modulus: float = MUSIC_WIRE.shear_modulus):
    """Rate ``k = G d^4 / (8 D^3 N_a)`` (N/m) of a helical spring.

    Parameters
    ----------
    wire_diameter, coil_diameter : float or array_like
        ``d`` and the mean coil diameter ``D`` (m), > 0.
    active_coils : float or array_like
        ``N_a``, > 0.
    shear_modulus : float
        ``G`` (Pa), > 0.

    Returns
    -------
    float or numpy.ndarray

    Examples
    --------
    >>> round(float(spring_rate(1e-3, 10e-3, 20)), 3)
    510.625
    """
    d = _positive("wire_diameter (m)", wire_diameter)
    D = _positive("coil_diameter (m)", coil_diameter)
    n = _positive("active_coils", active_coils)
    G = finite_real("shear_modulus (Pa)", shear_modulus, positive=True)
    return G * d ** 4 / (8 * D ** 3 * n)


def spring_index(wire_diameter, coil_diameter):
    """Spring index ``C = D / d`` (dimensionless).

    Examples
    --------
    >>> float(spring_index(1e-3, 8e-3))
    8.0
    """
    return _positive("coil_diameter (m)", coil_diameter) / _positive("wire_diameter (m)", wire_diameter)


def wahl_factor(index):
    """Wahl curvature factor ``K_W = (4C - 1)/(4C - 4) + 0.615 / C`` for spring index ``C > 1``.

    Examples
    --------
    >>> round(float(wahl_factor(6.0)), 4)
    1.2525
    """
    C = _positive("index C", index)
    if np.any(C <= 1):
        raise ValueError(f"index C must be > 1, got {index!r}")
    return (4 * C - 1) / (4 * C - 4) + 0.615 / C


def shear_stress(force, wire_diameter, coil_diameter, corrected: bool = True):
    """Largest shear stress (Pa) in the wire: ``K_W 8 F D / (pi d^3)`` (without ``K_W`` if not ``corrected``).

    Parameters
    ----------
    force : float or array_like
        Axial force (N).
    wire_diameter, coil_diameter : float or array_like
        ``d`` and ``D`` (m).
    corrected : bool
        Apply the Wahl factor.

    Examples
    --------
    >>> round(float(shear_stress(10.0, 1e-3, 8e-3, corrected=False)) / 1e6, 2)
    203.72
    """
    d = _positive("wire_diameter (m)", wire_diameter)
    D = _positive("coil_diameter (m)", coil_diameter)
    tau = 8 * np.asarray(force, dtype=float) * D / (math.pi * d ** 3)
    return tau * wahl_factor(D / d) if corrected else tau


def initial_stress_range(index):
    """Preferred range (Pa) of the uncorrected initial-tension stress for spring index ``C``.

    ``tau_i = 231 / exp(0.105 C) +- 6.9 (4 - (C - 3) / 6.5)`` MPa (Shigley eq. 10-48), a
    fit to the preferred band over indices ``C`` in [3, 16]; outside it raises ValueError.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        Lower and upper bound (Pa).

    Examples
    --------
    >>> lo, hi = initial_stress_range(6.0)
    >>> round(float(lo) / 1e6, 1), round(float(hi) / 1e6, 1)
    (98.6, 147.4)
    """
    C = _positive("index C", index)
    if np.any((C < 3.0) | (C > 16.0)):
        raise ValueError(f"index C must be in [3, 16] (the range of the preferred initial-stress fit), got {index!r}")
    mid = 231.0 / np.exp(0.105 * C)
    half = 6.9 * (4.0 - (C - 3.0) / 6.5)
    return (mid - half) * 1e6, (mid + half) * 1e6


def tensile_strength(wire_diameter, material: Material = MUSIC_WIRE):
    """Minimum tensile strength ``S_ut = A / d^m`` (Pa), ``d`` in mm inside the formula.

    The fit holds only over ``material.diameter_range`` (music wire 0.10-6.5 mm); a wire
    outside it raises ValueError.

    Examples
    --------
    >>> round(float(tensile_strength(1e-3)) / 1e6)
    2211
    """
    d = _positive("wire_diameter (m)", wire_diameter)
    lo, hi = material.diameter_range
    if np.any((d < lo * (1 - 1e-12)) | (d > hi * (1 + 1e-12))):
        raise ValueError(f"wire_diameter must be in [{lo:.4g}, {hi:.4g}] m for {material.name} "
                         f"(the range of its strength fit), got {wire_diameter!r}")
    d_mm = d * 1000
    return material.strength_A / d_mm ** material.strength_m * 1e6


def allowable_stress(wire_diameter, material: Material = MUSIC_WIRE, cycles: float | None = None,
                     where: str = "body"):
    """Allowable stress (Pa) of the body or a hook: static, or fatigue-aware for ``cycles`` load cycles.

    Static (``cycles=None``): the material's fraction of ``S_ut`` for ``where``. Cyclic
    (stress ratio 0, not shot-peened): Shigley's table 10-8 at 1e5 / 1e6 / 1e7 cycles,
    linear in ``log10(cycles)`` between them, its 1e5 value below (never above the static
    value) and its 1e7 value beyond (treat it as the endurance allowable).

    Parameters
    ----------
    wire_diameter : float or array_like
        ``d`` (m).
    material : Material
    cycles : float, optional
        Number of load cycles in service, >= 1.
    where : {"body", "hook_torsion", "hook_bending"}
        The body's torsion (Wahl-corrected), the torsion at a hook's root or the bending
        at a hook's bend.

    Examples
    --------
    >>> round(float(allowable_stress(1e-3)) / 1e6, 1), round(float(allowable_stress(1e-3, cycles=1e6)) / 1e6, 1)
    (995.0, 729.6)
    >>> round(float(allowable_stress(1e-3, where="hook_bending")) / 1e6, 1)
    1658.2
    """
    if where not in _FATIGUE:
        raise ValueError(f"where must be one of {sorted(_FATIGUE)}, got {where!r}")
    sut = tensile_strength(wire_diameter, material)
    static = getattr(material, _STATIC[where])
    if cycles is None:
        return static * sut
    n = finite_real("cycles", cycles, positive=True)
    if n < 1:
        raise ValueError(f"cycles must be >= 1, got {n}")
    xs, ys = zip(*_FATIGUE[where])
    frac = float(np.interp(math.log10(n), xs, ys))
    return min(frac, static) * sut


def hook_bending_factor(index):
    """Stress factor ``K_A = (4 C1^2 - C1 - 1) / (4 C1 (C1 - 1))`` at a hook's bend of index ``C1 = 2 r1 / d > 1``.

    Examples
    --------
    >>> round(float(hook_bending_factor(10.0)), 4)
    1.0806
    """
    C = _positive("hook index C1", index)
    if np.any(C <= 1):
        raise ValueError(f"hook index C1 must be > 1, got {index!r}")
    return (4 * C ** 2 - C - 1) / (4 * C * (C - 1))


def hook_torsion_factor(index):
    """Stress factor ``K_B = (4 C2 - 1) / (4 C2 - 4)`` at a hook's root of index ``C2 = 2 r2 / d > 1``.

    Examples
    --------
    >>> float(hook_torsion_factor(4.0))
    1.25
    """
    C = _positive("hook index C2", index)
    if np.any(C <= 1):
        raise ValueError(f"hook index C2 must be > 1, got {index!r}")
    return (4 * C - 1) / (4 * C - 4)


def hook_stresses(force, wire_diameter, coil_diameter, bend_radius=None, root_radius=None):
    """Bending stress at a hook's bend and torsion at its root (Pa) at the pull ``force`` (N).

    ``sigma_A = F (K_A 16 D / (pi d^3) + 4 / (pi d^2))`` and ``tau_B = K_B 8 F D / (pi d^3)``
    (Shigley eqs. 10-34 to 10-36).

    Parameters
    ----------
    force : float or array_like
        Pull (N).
    wire_diameter, coil_diameter : float
        ``d`` and ``D`` (m).
    bend_radius : float, optional
        Mean radius ``r1`` (m) of the hook's bend; ``D / 2`` (a standard full loop) by default.
    root_radius : float, optional
        Mean radius ``r2`` (m) of the bend where the hook leaves the body; ``2 d`` by default.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        ``sigma_A`` and ``tau_B``.

    Examples
    --------
    >>> sA, tB = hook_stresses(10.0, 1e-3, 10e-3)
    >>> round(float(sA) / 1e6, 1), round(float(tB) / 1e6, 1)
    (563.1, 318.3)
    """
    d = _positive("wire_diameter (m)", wire_diameter)
    D = _positive("coil_diameter (m)", coil_diameter)
    r1 = D / 2 if bend_radius is None else _positive("bend_radius (m)", bend_radius)
    r2 = 2 * d if root_radius is None else _positive("root_radius (m)", root_radius)
    F = np.asarray(force, dtype=float)
    sigma = F * (hook_bending_factor(2 * r1 / d) * 16 * D / (math.pi * d ** 3) + 4 / (math.pi * d ** 2))
    tau = hook_torsion_factor(2 * r2 / d) * 8 * F * D / (math.pi * d ** 3)
    return sigma, tau


@dataclass(frozen=True)
class ExtensionSpring:
    """A helical extension spring with initial tension, by default with a standard hook at each end.

    Parameters
    ----------
    wire_diameter : float
        ``d`` (m), > 0.
    coil_diameter : float
        Mean coil diameter ``D`` (m), with index ``C = D/d`` in (3, 16].
    active_coils : float
        ``N_a``, the coil count in the rate (with hooks ``> G/E``: the body then holds
        ``N_b = N_a - G/E`` coils, Shigley eq. 10-39; see :attr:`body_coils`).
    initial_tension : float
        ``F_i`` (N), from 0 up to the static :meth:`max_force` (a larger one breaks the
        spring before it is stretched); :attr:`windable` says whether it lies within the
        preferred range that can be wound (:meth:`initial_tension_range`).
    material : Material
    end_length : float
        Further length (m), >= 0, between the load points (beyond the hooks).
    hooks : bool
        Standard full-loop machine hooks at both ends (``r1 = D/2``, ``r2 = 2 d``): they add
        ``2 (D - d)`` to the length between the load points and their stresses limit the
        pull (:meth:`max_force`). ``False``: the coil body alone (a bare model).

    Examples
    --------
    >>> s = ExtensionSpring(1e-3, 8e-3, 40, initial_tension=2.0)
    >>> round(s.k, 2), round(s.body_coils, 2), round(s.body_length, 4), round(s.equivalent_free_length, 4)
    (498.66, 39.58, 0.0546, 0.0506)
    >>> s.windable
    True
    >>> s.governing()
    'hook_torsion'
    """

    wire_diameter: float
    coil_diameter: float
    active_coils: float
    initial_tension: float = 0.0
    material: Material = MUSIC_WIRE
    end_length: float = 0.0
    hooks: bool = True

    def __post_init__(self) -> None:
        d = finite_real("wire_diameter (m)", self.wire_diameter, positive=True)
        D = finite_real("coil_diameter (m)", self.coil_diameter, positive=True)
        if not 3.0 < D / d <= 16.0:
            raise ValueError(f"spring index C = coil_diameter / wire_diameter must be in (3, 16], got {D / d:.4g}")
        finite_real("active_coils", self.active_coils, positive=True)
        if not isinstance(self.material, Material):
            raise TypeError(f"material must be a Material, got {type(self.material).__name__}")
        if not isinstance(self.hooks, (bool, np.bool_)):
            raise TypeError(f"hooks must be True or False, got {self.hooks!r}")
        finite_real("end_length (m)", self.end_length, nonnegative=True)
        if self.hooks and self.active_coils <= self._hook_coils:
            raise ValueError(f"active_coils must be > G/E = {self._hook_coils:.3f} for a spring with hooks, "
                             f"got {self.active_coils}")
        Fi = finite_real("initial_tension (N)", self.initial_tension, nonnegative=True)
        top = self.max_force()
        if Fi > top:
            raise ValueError(f"initial_tension (the initial tension, N) must be in [0, {top:.4g}] (the static "
                             f"max_force of this spring; windable: {self.initial_tension_range()[1]:.4g} N at most), "
                             f"got {Fi}")

    @property
    def index(self) -> float:
        """Spring index ``C = D/d``."""
        return self.coil_diameter / self.wire_diameter

    @property
    def k(self) -> float:
        """Rate (N/m)."""
        return float(spring_rate(self.wire_diameter, self.coil_diameter, self.active_coils,
                                 self.material.shear_modulus))

    @property
    def _hook_coils(self) -> float:
        return self.material.shear_modulus / self.material.youngs_modulus if self.hooks else 0.0

    @property
    def body_coils(self) -> float:
        """Coils in the body ``N_b``: ``N_a - G/E`` with hooks (Shigley eq. 10-39), ``N_a`` without."""
        return self.active_coils - self._hook_coils

    @property
    def coil_length(self) -> float:
        """Closed length of the coils (m): ``d (N_b + 1)``."""
        return self.wire_diameter * (self.body_coils + 1)

    @property
    def hook_length(self) -> float:
        """Length (m) the two hooks add between the load points: ``2 (D - d)``, or 0 without hooks."""
        return 2 * (self.coil_diameter - self.wire_diameter) if self.hooks else 0.0

    @property
    def body_length(self) -> float:
        """Closed length between the load points (m): ``d (N_a + 1) + hook_length + end_length``."""
        return self.coil_length + self.hook_length + self.end_length

    @property
    def equivalent_free_length(self) -> float:
        """``l = L_b - F_i / k`` (m): the force is ``k (L - l)`` once stretched past ``L_b``; 0 is ZFL."""
        return self.body_length - self.initial_tension / self.k

    @property
    def windable(self) -> bool:
        """True when ``F_i`` is at most the top of the preferred range (:meth:`initial_tension_range`)."""
        return self.initial_tension <= self.initial_tension_range()[1] * (1 + 1e-12)

    @property
    def is_zfl(self) -> bool:
        """True when ``F_i = k L_b`` to 1e-9 relative: the force law is zero-free-length.

        Says nothing about whether it can be made: check :attr:`windable` too (an exactly
        ZFL extension spring is never windable within the preferred range, chapter 8).
        """
        return abs(self.equivalent_free_length) <= 1e-9 * self.body_length

    def initial_tension_range(self) -> tuple[float, float]:
        """Preferred range of ``F_i`` (N) for this index: ``pi d^3 tau_i / (8 D)``."""
        lo, hi = initial_stress_range(self.index)
        f = math.pi * self.wire_diameter ** 3 / (8 * self.coil_diameter)
        return float(lo * f), float(hi * f)

    def force(self, length):
        """Pull (N) at the distance ``length`` (m) between the load points; ``nan`` below ``L_b``."""
        L = np.asarray(length, dtype=float)
        return np.where(L >= self.body_length, self.k * (L - self.equivalent_free_length), np.nan)

    def stress(self, force):
        """Largest corrected shear stress (Pa) in the body at the pull ``force`` (N, >= 0)."""
        F = np.asarray(force, dtype=float)
        if not np.all(np.isfinite(F)) or np.any(F < 0):
            raise ValueError(f"force must be finite and >= 0 N (an extension spring only pulls), got {force!r}")
        return shear_stress(F, self.wire_diameter, self.coil_diameter)

    def stresses(self, force) -> dict:
        """Stresses (Pa) at the pull ``force`` (N): ``body`` and, with hooks, ``hook_torsion`` and ``hook_bending``."""
        out = {"body": self.stress(force)}     # checks force >= 0
        if self.hooks:
            out["hook_bending"], out["hook_torsion"] = hook_stresses(force, self.wire_diameter, self.coil_diameter)
        return out

    def max_forces(self, cycles: float | None = None) -> dict:
        """Largest pull (N) each place can carry within its allowable stress (static or for ``cycles``)."""
        return {where: float(allowable_stress(self.wire_diameter, self.material, cycles, where) / stress)
                for where, stress in self.stresses(1.0).items()}

    def governing(self, cycles: float | None = None) -> str:
        """Where the spring fails first: ``"body"``, ``"hook_torsion"`` or ``"hook_bending"``."""
        limits = self.max_forces(cycles)
        return min(limits, key=lambda where: limits[where])

    def max_force(self, cycles: float | None = None) -> float:
        """Largest pull (N) within every allowable stress (body and hooks; static, or for ``cycles``)."""
        return min(self.max_forces(cycles).values())

    def max_deflection(self, cycles: float | None = None) -> float:
        """Largest stretch (m) past the body length within the allowable stresses."""
        return max(0.0, (self.max_force(cycles) - self.initial_tension) / self.k)


def zfl_force_error(spring: ExtensionSpring, length):
    """Force error (N) of a real spring used as a ZFL spring: ``F - k L`` at ``length`` (m).

    Equal to ``-k l`` (``l`` the equivalent free length) once stretched past the body
    length; below it the spring is closed and cannot reach that length (``nan``).

    Examples
    --------
    >>> s = ExtensionSpring(1e-3, 8e-3, 40, initial_tension=2.0)
    >>> float(np.round(zfl_force_error(s, 0.1), 4)) == round(-s.k * s.equivalent_free_length, 4)
    True
    """
    return spring.force(length) - spring.k * np.asarray(length, dtype=float)
