"""Sec. 4 of Deepak & Ananthasuresh (2012): gravity as the limit of a spring load, 2R arms, slider-cranks.

A weight on the coupler point is the limit of a ZFL load spring anchored far below
(:func:`gravity_technique2`, :func:`gravity_as_spring_limit`); technique 2 based at the
crank's pivot balances a 2R arm (the four-bar without its rocker,
:func:`serial_2r_technique2`) and a slider-crank (:func:`slider_crank_technique2`),
since the rocker or the slider takes no part in the balance. Layer: methods.
"""
from __future__ import annotations

import math

import numpy as np

from ...core.design import Design
from ...core.elements import G, Joint, Load, Spring
from ...core.validation import finite_real, instance_of, planar_point
from ...mechanisms.base import ExplicitKinematics, TreeKinematics
from ...mechanisms.fourbar import FourBar, fourbar_design, pivot_name
from ...mechanisms.geometry import Point, as_complex, as_point, numeric_only
from .blocks import balancing_springs
from .techniques import technique2

__all__ = ["gravity_technique2", "gravity_as_spring_limit", "serial_2r_technique2", "slider_crank_technique2"]


def gravity_technique2(fourbar: FourBar, mass: float, k_b: float, base: str = "A") -> Design:
    """A weight at the coupler point balanced by technique 2: the limit of a far spring (Sec. 4).

    A load spring ``k_l = m g / R`` anchored a distance ``R`` below ``W`` pulls on ``E``
    with ``k_l (K - E) -> (0, -m g)`` as ``R -> oo``: gravity is the limit of a ZFL spring
    load. Eqs 2-4 then give ``k_b (H - W) = (0, m g)``, i.e. ``H`` straight above ``W``
    at the height ``m g / k_b``, and ``k_t = k_b``.

    Parameters
    ----------
    fourbar : FourBar
    mass : float
        Mass at the coupler point (kg), > 0.
    k_b : float
        Chosen stiffness of balancing spring 1 (N/m), > 0 (the free parameter).
    base : {"A", "B"}
        Base of the balanced parallelogram.

    Returns
    -------
    Design

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> gravity_technique2(example_fourbar(), 2.0, 400.0).balance_report().balanced
    True
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    pivot_name("base", base)
    mass = finite_real("mass (kg)", mass, positive=True)
    k_b = finite_real("k_b (N/m)", k_b, positive=True)
    base = pivot_name("base", base)
    W = fourbar.pivot(base)
    H = W + 1j * mass * G / k_b
    ex, ey = fourbar.coupler_point
    T = (-ex, -ey) if base == "A" else (2 * fourbar.coupler - ex, -ey)
    springs = [Spring(k_b, 0.0, (0, as_point(H)), (2, fourbar.coupler_point), name="k_b"),
               Spring(k_b, 0.0, (0, as_point(W)), (2, T), name="k_t")]
    loads = [Load(2, fourbar.coupler_point, (0.0, -mass * G), "m", kind="weight")]
    return fourbar_design(f"four-bar with a weight, technique 2 (parallelogram at {base})", fourbar, loads,
                          springs, labels={"H": (0, as_point(H)), "W": (0, as_point(W)), "T": (2, T)},
                          parameters={"mass": mass, "k_b": k_b, "k_t": k_b, "H_x": H.real, "H_y": H.imag},
                          reference="Deepak & Ananthasuresh 2012, Sec. 4 (gravity as a limiting spring load)")


def gravity_as_spring_limit(fourbar: FourBar, mass: float, k_b: float, R: float, base: str = "A") -> Design:
    """Technique 2 for a load spring ``m g / R`` anchored ``R`` below ``W``.

    As ``R`` grows the springs and anchors tend to those of :func:`gravity_technique2`:
    ``H`` is the same, ``k_t = k_b + m g / R -> k_b``, and the load spring's energy differs
    from the weight's by a constant plus ``m g |E - W|^2 / (2 R)``.

    Parameters
    ----------
    fourbar : FourBar
    mass : float
        Mass whose weight the spring stands for (kg), > 0.
    k_b : float
        Balancing spring 1 stiffness (N/m), > 0.
    R : float
        Distance of the anchor below ``W`` (m), > 0.
    base : {"A", "B"}

    Returns
    -------
    Design

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> d = gravity_as_spring_limit(example_fourbar(), 2.0, 400.0, 100.0)
    >>> round(d.parameters["k_t"] - 400.0, 4)
    0.1962
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    pivot_name("base", base)
    mass = finite_real("mass (kg)", mass, positive=True)
    k_b = finite_real("k_b (N/m)", k_b, positive=True)
    R = finite_real("R (m)", R, positive=True)
    W = fourbar.pivot(pivot_name("base", base))
    K = W - 1j * R
    k_l = mass * G / R
    return technique2(fourbar, as_point(K), k_l, base, mass * G / k_b).replace(
        name=f"four-bar, load spring {R:g} m below {base} (gravity limit)")


def serial_2r_technique2(A: Point, length_1: float, length_2: float, coupler_point: Point, K: Point,
                         k_l: float, h: float) -> Design:
    """A spring-loaded 2R arm balanced by technique 2 based at its pivot (Deepak Sec. 4).

    Removing the rocker from a four-bar balanced by technique 2 based at ``A`` leaves a
    2R arm ``A-D-E`` that stays balanced for both of its angles: the rocker took no part
    in the balance.

    Parameters
    ----------
    A : (float, float)
        Ground pivot (m).
    length_1 : float
        Length ``|AD|`` of link 1 (m), > 0.
    length_2 : float
        Length of link 2 (along its x-axis, m), > 0.
    coupler_point : (float, float)
        ``E`` in link 2's frame (origin ``D``, m).
    K : (float, float)
        Load spring anchor (m), not ``A``.
    k_l : float
        Load spring stiffness (N/m), > 0.
    h : float
        ``|AH|`` (m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> serial_2r_technique2((0, 0), 0.2, 0.3, (0.2, 0.1), (0.1, -0.2), 100.0, 0.1).balance_report().balanced
    True
    """
    A = planar_point("A", A)
    l1 = finite_real("length_1 (of link 1, m)", length_1, positive=True)
    finite_real("length_2 (of link 2, m)", length_2, positive=True)
    E = planar_point("coupler_point", coupler_point)
    K = planar_point("K", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    H, k_b, k_t = balancing_springs(as_complex(A), as_complex(K), k_l, h)
    joints = [Joint(0, A, 1, (0.0, 0.0)), Joint(1, (l1, 0.0), 2, (0.0, 0.0))]
    kin = TreeKinematics(3, joints, [[0, 0], [1, 0], [0, 1]], ("theta_1", "theta_2"),
                         ((-math.pi, math.pi), (-math.pi, math.pi)))
    T = (-E[0], -E[1])
    springs = [Spring(k_l, 0.0, (0, K), (2, E), name="k_l"),
               Spring(k_b, 0.0, (0, as_point(H)), (2, E), name="k_b"),
               Spring(k_t, 0.0, (0, A), (2, T), name="k_t")]
    return Design("spring-loaded 2R arm, technique 2", ("ground", "link 1", "link 2"), joints, kin, (),
                  springs,
                  labels={"A": (0, A), "K": (0, K), "H": (0, as_point(H)), "D": (1, (l1, 0.0)), "E": (2, E),
                          "T": (2, T)},
                  parameters={"k_l": k_l, "k_b": k_b, "k_t": k_t, "h": float(h)},
                  reference="Deepak & Ananthasuresh 2012, Sec. 4 (2R linkages)")


def slider_crank_technique2(crank: float, coupler: float, offset: float, coupler_point: Point, K: Point,
                            k_l: float, h: float) -> Design:
    """A spring-loaded slider-crank balanced by technique 2 based at the crank pivot (Sec. 4).

    The crank ``AD`` turns about the origin; the coupler ``DC`` ends at ``C`` on a slider
    moving along the line ``y = offset``. The slider is an extra constraint on a
    balanced 2R arm, so the balance survives. The crank must turn fully
    (``coupler >= crank + |offset|``).

    Parameters
    ----------
    crank, coupler : float
        ``|AD|``, ``|DC|`` (m), > 0.
    offset : float
        Height of the slider's line (m).
    coupler_point : (float, float)
        ``E`` in the coupler frame (origin ``D``, x-axis to ``C``, m).
    K : (float, float)
        Load spring anchor (m), not the origin.
    k_l : float
        Load spring stiffness (N/m), > 0.
    h : float
        ``|AH|`` (m), > 0.

    Returns
    -------
    Design
        Bodies: ground, crank, coupler, slider (its frame at ``C``, angle 0).

    Examples
    --------
    >>> d = slider_crank_technique2(0.1, 0.3, 0.05, (0.1, 0.05), (0.2, -0.2), 100.0, 0.1)
    >>> d.balance_report().balanced
    True
    """
    r2 = finite_real("crank (m)", crank, positive=True)
    r3 = finite_real("coupler (m)", coupler, positive=True)
    e = finite_real("offset (m)", offset)
    E = planar_point("coupler_point", coupler_point)
    K = planar_point("K", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    if r3 < r2 + abs(e):
        raise ValueError(f"the crank cannot turn fully: need coupler >= crank + |offset| "
                         f"({r3} < {r2 + abs(e)})")
    H, k_b, k_t = balancing_springs(0j, as_complex(K), k_l, h)

    def pose_fn(q, lib):
        numeric_only(lib)
        th = q[0]
        Dx, Dy = r2 * np.cos(th), r2 * np.sin(th)
        Cx = Dx + np.sqrt(np.clip(r3 * r3 - (e - Dy) ** 2, 0.0, None))
        phi = np.arctan2(e - Dy, Cx - Dx)
        z = np.zeros_like(th)
        return [(z, z, z), (z, z, th), (Dx, Dy, phi), (Cx, z + e, z)]

    kin = ExplicitKinematics(4, ("theta",), ((-math.pi, math.pi),), pose_fn,
                              descriptions=("crank angle from the x-axis",))
    joints = [Joint(0, (0.0, 0.0), 1, (0.0, 0.0)), Joint(1, (r2, 0.0), 2, (0.0, 0.0)),
              Joint(2, (r3, 0.0), 3, (0.0, 0.0))]
    T = (-E[0], -E[1])
    springs = [Spring(k_l, 0.0, (0, K), (2, E), name="k_l"),
               Spring(k_b, 0.0, (0, as_point(H)), (2, E), name="k_b"),
               Spring(k_t, 0.0, (0, (0.0, 0.0)), (2, T), name="k_t")]
    return Design("spring-loaded slider-crank, technique 2", ("ground", "crank", "coupler", "slider"), joints,
                  kin, (), springs,
                  labels={"A": (0, (0.0, 0.0)), "K": (0, K), "H": (0, as_point(H)), "E": (2, E), "T": (2, T),
                          "C": (3, (0.0, 0.0))},
                  parameters={"k_l": k_l, "k_b": k_b, "k_t": k_t, "h": float(h), "offset": e},
                  reference="Deepak & Ananthasuresh 2012, Sec. 4 (slider-crank linkages)")


