"""Real helical extension springs: rate, index, body length, initial tension, stress, allowables.

Formulas (SI units: metres, newtons, pascals), as given in spring-design guidance,
for instance Budynas & Nisbett, *Shigley's Mechanical Engineering Design*, ch. 10
(helical springs), and the SMI *Handbook of Spring Design*:

* rate ``k = G d^4 / (8 D^3 N_a)`` (wire diameter ``d``, mean coil diameter ``D``,
  active coils ``N_a``, shear modulus ``G``); spring index ``C = D / d``;
* closed body length ``L_b = d (N_b + 1)`` with ``N_b`` body coils (here ``N_b = N_a``:
  hook ends add no active coils in this simple model);
* uncorrected shear stress ``tau = 8 F D / (pi d^3)``; with the Wahl curvature
  correction ``K_W = (4C - 1)/(4C - 4) + 0.615 / C``, the maximum stress is ``K_W tau``;
* preferred range of the uncorrected initial-tension stress as a function of ``C``
  (Shigley eq. 10-48, in its SI form):
  ``tau_i = 231 / exp(0.105 C) +- 6.9 (4 - (C - 3) / 6.5)`` MPa;
* minimum tensile strength ``S_ut = A / d^m`` (``d`` in mm, ``A`` in MPa mm^m), constants
  per material from Shigley's table 10-4;
* allowable body stress as a fraction of ``S_ut``: static 45 % (music wire) or 35 %
  (austenitic stainless) (Shigley table 10-7); in cyclic service (stress ratio 0, not
  shot-peened) 36 %, 33 % and 30 % for 1e5, 1e6 and 1e7 cycles (table 10-8),
  interpolated in ``log10(cycles)`` between those points.

The constants were taken from the textbook as the authors remember its 9th/10th
editions; they reproduce its worked example 10-7 (see ``tests/test_practice.py``), but
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
           "allowable_stress", "ExtensionSpring", "zfl_force_error"]


class Material(NamedTuple):
    """A spring wire material.

    ``shear_modulus`` (Pa); tensile strength ``S_ut = A / d^m`` with ``strength_A``
    (MPa mm^m) and ``strength_m``; ``static_fraction``: allowable body torsion stress in
    static service as a fraction of ``S_ut``; ``source``: where the numbers come from.
    """

    name: str
    shear_modulus: float
    strength_A: float
    strength_m: float
    static_fraction: float
    source: str


_SHIGLEY = "Budynas & Nisbett, Shigley's Mechanical Engineering Design, tables 10-4, 10-5, 10-7"

#: Music wire (ASTM A228), valid for wire diameters 0.10-6.5 mm.
MUSIC_WIRE = Material("music wire (ASTM A228)", 81.7e9, 2211.0, 0.145, 0.45, _SHIGLEY)
#: Stainless steel 302 (ASTM A313), valid for wire diameters 0.3-2.5 mm.
STAINLESS_302 = Material("stainless steel 302 (ASTM A313)", 69.0e9, 1867.0, 0.146, 0.35, _SHIGLEY)
#: The bundled materials by short name.
MATERIALS = {"music_wire": MUSIC_WIRE, "stainless_302": STAINLESS_302}

#: Common metric wire diameters (m) from which the parametric family is generated.
WIRE_DIAMETERS = tuple(x / 1000 for x in (0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.4, 1.6,
                                          1.8, 2.0, 2.2, 2.5, 2.8, 3.0, 3.2, 3.5, 4.0, 4.5, 5.0))

#: Fatigue allowables of the body of an extension spring (fraction of S_ut) by log10(cycles).
_FATIGUE = ((5.0, 0.36), (6.0, 0.33), (7.0, 0.30))


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

    ``tau_i = 231 / exp(0.105 C) +- 6.9 (4 - (C - 3) / 6.5)`` MPa (Shigley eq. 10-48).

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
    mid = 231.0 / np.exp(0.105 * C)
    half = 6.9 * (4.0 - (C - 3.0) / 6.5)
    return (mid - half) * 1e6, (mid + half) * 1e6


def tensile_strength(wire_diameter, material: Material = MUSIC_WIRE):
    """Minimum tensile strength ``S_ut = A / d^m`` (Pa), ``d`` in mm inside the formula.

    Examples
    --------
    >>> round(float(tensile_strength(1e-3)) / 1e6)
    2211
    """
    d_mm = _positive("wire_diameter (m)", wire_diameter) * 1000
    return material.strength_A / d_mm ** material.strength_m * 1e6


def allowable_stress(wire_diameter, material: Material = MUSIC_WIRE, cycles: float | None = None):
    """Allowable corrected body shear stress (Pa): static, or fatigue-aware for ``cycles`` load cycles.

    Static (``cycles=None``): ``material.static_fraction * S_ut``. Cyclic (stress ratio 0,
    not shot-peened): 36 / 33 / 30 % of ``S_ut`` at 1e5 / 1e6 / 1e7 cycles, linear in
    ``log10(cycles)`` between them, 36 % below 1e5 (never above the static value) and 30 %
    beyond 1e7 (the table's last entry; treat it as the endurance allowable).

    Parameters
    ----------
    wire_diameter : float or array_like
        ``d`` (m).
    material : Material
    cycles : float, optional
        Number of load cycles in service, >= 1.

    Examples
    --------
    >>> round(float(allowable_stress(1e-3)) / 1e6, 1), round(float(allowable_stress(1e-3, cycles=1e6)) / 1e6, 1)
    (995.0, 729.6)
    """
    sut = tensile_strength(wire_diameter, material)
    if cycles is None:
        return material.static_fraction * sut
    n = finite_real("cycles", cycles, positive=True)
    if n < 1:
        raise ValueError(f"cycles must be >= 1, got {n}")
    xs, ys = zip(*_FATIGUE)
    frac = float(np.interp(math.log10(n), xs, ys))
    return min(frac, material.static_fraction) * sut


@dataclass(frozen=True)
class ExtensionSpring:
    """A helical extension spring with initial tension.

    Parameters
    ----------
    wire_diameter : float
        ``d`` (m), > 0.
    coil_diameter : float
        Mean coil diameter ``D`` (m), with index ``C = D/d`` in (3, 16].
    active_coils : float
        ``N_a`` (= body coils in this model), > 0.
    initial_tension : float
        ``F_i`` (N), >= 0; see :meth:`initial_tension_range` for what can be wound.
    material : Material
    end_length : float
        Length (m), >= 0, that the hooks or end loops add between the two load points.

    Examples
    --------
    >>> s = ExtensionSpring(1e-3, 8e-3, 40, initial_tension=2.0)
    >>> round(s.k, 2), round(s.body_length, 4), round(s.equivalent_free_length, 4)
    (498.66, 0.041, 0.037)
    """

    wire_diameter: float
    coil_diameter: float
    active_coils: float
    initial_tension: float = 0.0
    material: Material = MUSIC_WIRE
    end_length: float = 0.0

    def __post_init__(self) -> None:
        d = finite_real("wire_diameter (m)", self.wire_diameter, positive=True)
        D = finite_real("coil_diameter (m)", self.coil_diameter, positive=True)
        if not 3.0 < D / d <= 16.0:
            raise ValueError(f"spring index C = coil_diameter / wire_diameter must be in (3, 16], got {D / d:.4g}")
        finite_real("active_coils", self.active_coils, positive=True)
        finite_real("initial_tension (N)", self.initial_tension, nonnegative=True)
        finite_real("end_length (m)", self.end_length, nonnegative=True)
        if not isinstance(self.material, Material):
            raise TypeError(f"material must be a Material, got {type(self.material).__name__}")

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
    def body_length(self) -> float:
        """Closed length between the load points (m): ``d (N_a + 1) + end_length``."""
        return self.wire_diameter * (self.active_coils + 1) + self.end_length

    @property
    def equivalent_free_length(self) -> float:
        """``l = L_b - F_i / k`` (m): the force is ``k (L - l)`` once stretched past ``L_b``; 0 is ZFL."""
        return self.body_length - self.initial_tension / self.k

    @property
    def is_zfl(self) -> bool:
        """True when ``F_i = k L_b`` to 1e-9 relative (the spring is exactly zero-free-length)."""
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
        """Largest corrected shear stress (Pa) at the pull ``force`` (N)."""
        return shear_stress(force, self.wire_diameter, self.coil_diameter)

    def max_force(self, cycles: float | None = None) -> float:
        """Largest pull (N) within the allowable stress (static, or for ``cycles`` cycles)."""
        tau = allowable_stress(self.wire_diameter, self.material, cycles)
        return float(tau * math.pi * self.wire_diameter ** 3 / (8 * self.coil_diameter * wahl_factor(self.index)))

    def max_deflection(self, cycles: float | None = None) -> float:
        """Largest stretch (m) past the body length within the allowable stress."""
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
