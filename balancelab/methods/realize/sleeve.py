"""A normal spring that balances exactly: mounted in a sleeve that turns about the anchor.

The lecture's link (pivot ``O``, mass ``m`` at distance ``r``, anchor ``B`` at height ``b``
above ``O``, attachment ``C`` at distance ``c`` along the link) is balanced by a ZFL spring of
rate ``k = m g r / (b c)`` from ``B`` to ``C``. With a *normal* spring (free length ``l0 > 0``)
between those two points it is not. Two links more make it exact:

* a **sleeve** pinned to the ground at ``B``, free to turn;
* a **rod** pinned to the link at ``C`` that slides in the sleeve (a prismatic joint), so the
  sleeve always points along ``BC``; the rod reaches ``e`` back from ``C`` along the line.

The normal spring joins the sleeve's rear point ``B''``, ``d`` behind ``B`` on the line, to
the rod's rear end ``R``. Both ends lie on the line ``BC``, so the spring's length is
``|BC| - e + d``; with ``d - e = l0`` it is ``|BC| + l0`` and the spring's energy is
``k/2 |BC|^2``, the ZFL spring's, whatever the angle: the balance condition stays
``k b c = m g r``. The spring is an ordinary spring mounted directly between points of two
links; the design's energy is computed from those points (no ideal formula), and
:func:`sleeve_derivation` derives the condition with sympy. The rod is ``e = b + c`` long
behind ``C`` (its rear end reaches ``B`` when the link points straight down) and
``d = e + l0``.
"""
from __future__ import annotations

import math

from ...core.design import Design
from ...core.elements import G
from ...core.validation import finite_real
from ...mechanisms.linkage import Linkage

__all__ = ["sleeve_lever", "sleeve_derivation"]


def sleeve_derivation() -> dict:
    """The sleeve arrangement's balance condition, derived with sympy.

    Returns
    -------
    dict
        ``length``: the spring's length (m) in terms of ``theta`` (rad, the link's angle from
        the horizontal), ``b``, ``c`` and ``l0``; ``energy``: the total potential energy (J);
        ``k``: the rate that makes ``dV/dtheta`` vanish for every angle; ``residual``:
        ``dV/dtheta`` with that rate (0).

    Examples
    --------
    >>> out = sleeve_derivation()
    >>> out["k"], out["residual"]
    (g*m*r/(b*c), 0)
    """
    import sympy as sp     # imported here: importing balancelab stays light

    theta, b, c, l0, k, m, g, r = sp.symbols("theta b c l0 k m g r", positive=True)
    bc = sp.sqrt(b ** 2 + c ** 2 - 2 * b * c * sp.sin(theta))   # |BC|: B = (0, b), C = c (cos, sin)
    e = b + c
    d = e + l0
    length = bc - e + d                                           # from B'' (d behind B) to R (e behind C)
    energy = m * g * r * sp.sin(theta) + k / 2 * (length - l0) ** 2
    slope = sp.expand(sp.diff(energy, theta))
    rate = sp.solve(sp.Eq(slope.coeff(sp.cos(theta)), 0), k)[0]
    return {"length": sp.simplify(length), "energy": energy, "k": rate,
            "residual": sp.simplify(slope.subs(k, rate))}


def sleeve_lever(mass: float = 2.0, length: float = 0.5, b: float = 0.3, c: float = 0.2,
                 free_length: float = 0.05) -> Design:
    """The lecture's link balanced exactly by a normal spring in a sleeve pivoted at the anchor.

    Parameters
    ----------
    mass : float
        Mass at the tip of the link (kg), > 0.
    length : float
        The link's length ``r`` (m), > 0.
    b : float
        Height of the anchor ``B`` (the sleeve's pivot) above the link's pivot (m), > 0.
    c : float
        Distance of the rod's pin ``C`` along the link (m), > 0, with ``c != b`` (the link's pin
        and the sleeve's pivot would meet).
    free_length : float
        The spring's free length (m), > 0: an ordinary spring.

    Returns
    -------
    Design
        Bodies ``ground``, ``link``, ``sleeve``, ``rod``; one coordinate, the link's angle
        ``theta_1`` (rad, from the horizontal) over a whole turn; one spring of rate
        ``k = m g r / (b c)`` and free length ``free_length`` from the sleeve's point ``d``
        behind ``B`` to the rod's point ``e`` behind ``C``. ``parameters`` hold ``k``,
        ``free_length``, ``e`` and ``d`` (m).

    Examples
    --------
    >>> d = sleeve_lever(free_length=0.05)
    >>> d.balance_report().balanced, d.springs[0].free_length
    (True, 0.05)
    """
    mass = finite_real("mass (kg)", mass, positive=True)
    r = finite_real("length (m)", length, positive=True)
    b = finite_real("b (m)", b, positive=True)
    c = finite_real("c (m)", c, positive=True)
    l0 = finite_real("free_length (m)", free_length, positive=True)
    if abs(b - c) <= 1e-9 * max(b, c):
        raise ValueError(f"c must differ from b (the rod's pin would reach the sleeve's pivot at 90°), got b = c = {b}")
    k = mass * G * r / (b * c)
    e = b + c
    d = e + l0
    lk = Linkage("single link: a normal spring in a sleeve pivoted at the anchor")
    lk.revolute("ground", (0.0, 0.0), "link", (0.0, 0.0))
    lk.revolute("ground", (0.0, b), "sleeve", (0.0, 0.0))
    lk.revolute("link", (c, 0.0), "rod", (0.0, 0.0))
    # the rod's pin C slides on the sleeve's axis; the rod keeps the sleeve's direction
    lk.prismatic("sleeve", (0.0, 0.0), "rod", (0.0, 0.0), axis=(1.0, 0.0), stroke=(abs(b - c), b + c))
    lk.mass("link", mass, com=(r, 0.0))
    lk.spring("sleeve", (-d, 0.0), "rod", (-e, 0.0), k=k, free_length=l0)
    lk.label("B", "ground", (0.0, b))
    lk.label("C", "link", (c, 0.0))
    # drawn at theta = 0: the sleeve points from B to C, down and to the right
    design = lk.build(driving=["link"], guess={"link": 0.0, "sleeve": math.atan2(-b, c), "rod": math.atan2(-b, c)})
    return design.replace(parameters={"k": k, "free_length": l0, "e": e, "d": d, "b": b, "c": c},
                          reference="balancelab: a normal spring in a pivoted sleeve behaves as a ZFL spring "
                                    "(derived in balancelab.realize.sleeve_derivation); Lecture 35, k = m g r / (b c)")
