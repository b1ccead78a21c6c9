"""The prototype of Deepak & Ananthasuresh (2012, Sec. 2.3): Watt's linkage balanced in the ratio 1:1:2.

Watt's straight-line four-bar (:func:`watt_fourbar`) loaded by a ZFL spring and
balanced by technique 2 with three springs of stiffness ratio ``k_l : k_b : k_t = 1 : 1
: 2``, every one a string over a pulley (:func:`watt_prototype`). Layer: methods.
"""
from __future__ import annotations

import math

from ...core.design import Design
from ...core.elements import Spring
from ...core.validation import finite_real, planar_point
from ...mechanisms.fourbar import FourBar
from ...mechanisms.geometry import Point
from .techniques import technique2

__all__ = ["watt_fourbar", "watt_prototype"]


def watt_fourbar(rocker: float = 0.1, coupler: float = 0.05) -> FourBar:
    """Watt's straight-line four-bar: two equal rockers, the coupler point at mid-coupler.

    In the middle position both rockers are horizontal and point at each other's
    side, the coupler is vertical and its midpoint moves on a nearly straight vertical
    line. Pivots ``A = (0, 0)`` and ``B = (2 rocker, coupler)``.

    Parameters
    ----------
    rocker : float
        Length of each rocker (m), > 0.
    coupler : float
        Length of the coupler (m), > 0.

    Returns
    -------
    FourBar

    Examples
    --------
    >>> watt_fourbar().B
    (0.2, 0.05)
    """
    rocker = finite_real("rocker (m)", rocker, positive=True)
    coupler = finite_real("coupler (m)", coupler, positive=True)
    return FourBar((0.0, 0.0), (2 * rocker, coupler), rocker, coupler, rocker, (coupler / 2, 0.0), branch=1)


def watt_prototype(k: float = 200.0, rocker: float = 0.1, coupler: float = 0.05, K: Point = (0.1, -0.15)
                   ) -> Design:
    """The prototype of Deepak Sec. 2.3: Watt's linkage balanced by technique 2 in the ratio 1:1:2.

    Technique 2 based at ``A`` with ``|AH| = |KA|``, i.e. ``H`` the reflection of ``K``
    through ``A``: eq. 3 gives ``k_b = k_l`` and eq. 4 (corrected) ``k_t = 2 k_l``, so three
    identical springs do, one of them used at half its length (twice the stiffness).
    Spring 1 shares the coupler point ``E`` with the load spring and spring 2's
    attachment ``T`` is the mirror of ``E`` about the joint ``D``, as in the prototype,
    and every spring is drawn as a string over a pulley (Fig. 20). The dimensions are
    assumed (the paper gives none).

    Parameters
    ----------
    k : float
        Stiffness of the load spring (N/m), > 0.
    rocker, coupler : float
        Link lengths (m) of :func:`watt_fourbar`.
    K : (float, float)
        Load spring anchor (m).

    Returns
    -------
    Design

    Examples
    --------
    >>> d = watt_prototype()
    >>> [round(d.parameters[n] / d.parameters["k_l"], 12) for n in ("k_l", "k_b", "k_t")]
    [1.0, 1.0, 2.0]
    """
    fb = watt_fourbar(rocker, coupler)
    K = planar_point("K", K)
    d = technique2(fb, K, k, "A", math.hypot(*K))
    # the prototype realized all three ZFL springs with strings over pulleys (Fig. 20)
    springs = [Spring(s.k, 0.0, s.a, s.b, name=s.name, realization="pulley") for s in d.springs]
    return d.replace(name="Watt straight-line four-bar, technique 2 (1:1:2 prototype)", springs=springs,
                     reference="Deepak & Ananthasuresh 2012, Sec. 2.3, Figs 19-20")


