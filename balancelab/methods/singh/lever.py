"""Singh & Ananthasuresh: LaCoste's lever, the generalized lever and the lever with minimum preload (eqs 1-20)."""
from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike



from ..registry import example
from ...core.design import Design
from ...core.elements import Load, Spring, SymbolicParts
from ...core.validation import MIN_POSITIVE, finite_real, real_array
from ...mechanisms.lever import lever_design

__all__ = ["lacoste_lever", "lacoste_energies", "generalized_lever", "min_preload_lever"]


@example("lacoste_lever", "LaCoste's lever (Singh eqs 1-3)", chapter=2,
         weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
def lacoste_lever(weight: float, length: float, a_x: float, b_y: float) -> Design:
    """LaCoste's lever: a load ``W`` at ``(l, 0)`` balanced by one ZFL spring (Singh eqs 1-3).

    The spring runs from the fixed anchor ``b = (0, b_y)`` to ``a = (a_x, 0)`` on the
    lever. The energy ``k/2 (a_x^2 + b_y^2) + (W l - k a_x b_y) sin(theta)`` is constant
    when ``k = W l / (a_x b_y)`` (eq. 2); its constant value is
    ``W l / 2 (a_x / b_y + b_y / a_x)`` (eq. 3), smallest (``W l``) when ``a_x = b_y``.

    Parameters
    ----------
    weight : float
        The load W (N), > 0, acting downwards.
    length : float
        Length of the lever: the distance ``l`` of the load from the pivot (m), > 0.
    a_x : float
        Attachment on the lever (m), > 0.
    b_y : float
        Height of the fixed anchor above the pivot (m), > 0.

    Returns
    -------
    Design

    Examples
    --------
    >>> d = lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
    >>> round(d.parameters["k"], 4), round(d.parameters["PE"], 4)
    (83.3333, 5.4167)
    """
    W = finite_real("weight W (N)", weight, positive=True)
    l = finite_real("length (m)", length, positive=True)
    a_x = finite_real("a_x (m)", a_x, positive=True)
    b_y = finite_real("b_y (m)", b_y, positive=True)
    k = W * l / (a_x * b_y)
    import sympy as sp

    Ws, ls, axs, bys, ks = sp.symbols("W l a_x b_y k", positive=True)
    sym = SymbolicParts(((1, (ls, 0), (0, -Ws)),), ((ks, 0, (0, (0, bys)), (1, (axs, 0))),),
                        {Ws: W, ls: l, axs: a_x, bys: b_y, ks: k})
    return lever_design(
        "LaCoste lever", [Load(1, (l, 0.0), (0.0, -W), "W", kind="weight")],
        [Spring(k, 0.0, (0, (0.0, b_y)), (1, (a_x, 0.0)), name="k")], symbolic=sym,
        labels={"O": (0, (0.0, 0.0)), "a": (1, (a_x, 0.0)), "b": (0, (0.0, b_y)), "p": (1, (l, 0.0))},
        parameters={"k": k, "a_x": a_x, "b_y": b_y, "PE": W * l / 2 * (a_x / b_y + b_y / a_x)},
        reference="Singh & Ananthasuresh, eqs 1-3 (LaCoste 1934)", link="lever")


def lacoste_energies(weight: float, length: float, a_x: ArrayLike, b_y: ArrayLike) -> np.ndarray:
    """Energy (J) of the LaCoste lever built at every ``(a_x, b_y)``: its design space as numbers.

    Each lever is :func:`lacoste_lever` with those attachments; it is balanced, so its
    energy is the same at every configuration, and the mean over four configurations
    spread over a turn is that constant.

    Parameters
    ----------
    weight : float
        Weight at the tip (N), > 0.
    length : float
        Length of the lever (m), > 0.
    a_x, b_y : array_like
        Attachment on the link and anchor height (m), each > 0; broadcast together.

    Returns
    -------
    numpy.ndarray
        The energies (J), of the broadcast shape of ``a_x`` and ``b_y``.

    Examples
    --------
    >>> lacoste_energies(10.0, 0.5, [0.2, 0.4], 0.4).round(3).tolist()
    [6.25, 5.0]
    """
    a_x, b_y = np.broadcast_arrays(real_array("a_x (m)", a_x), real_array("b_y (m)", b_y))
    if a_x.size == 0:
        raise ValueError(f"a_x and b_y (m) must hold at least one point each, got shapes "
                         f"{np.shape(a_x)} and {np.shape(b_y)}")
    out = np.empty(a_x.shape)
    q = np.linspace(-np.pi, np.pi, 4, endpoint=False)[:, None]
    for idx in np.ndindex(a_x.shape):
        design = lacoste_lever(weight, length, float(a_x[idx]), float(b_y[idx]))
        out[idx] = float(np.mean(design.potential_energy(q).total))
    return out


@example("generalized_lever", "Generalized lever (Singh eqs 12-17)", chapter=2,
         weight=10.0, length=0.5, a_x=0.2, b_x=0.1, b_y=0.3)
def generalized_lever(weight: float, length: float, a_x: float, b_x: float, b_y: float) -> Design:
    """The generalized lever of Singh & Ananthasuresh (eqs 12-17).

    A load ``W`` at ``p = (l, 0)`` and one ZFL spring from ``b = (b_x, b_y)`` (ground) to
    ``a = (a_x, a_y)`` (lever). Balance needs ``a_x b_x + a_y b_y = 0`` (eq. 13) and
    ``W l + k(-a_x b_y + a_y b_x) = 0`` (eq. 14), hence ``a_y = -a_x b_x / b_y`` (eq. 15) and
    ``k = W l b_y / (a_x (b_x^2 + b_y^2))`` (eq. 16). The balanced energy
    ``W l / (2 a_x b_y) (a_x^2 + b_y^2)`` (eq. 17) does not depend on ``b_x``.

    Parameters
    ----------
    weight : float
        W (N), > 0.
    length : float
        Length of the lever: the distance ``l`` of the load from the pivot (m), > 0.
    a_x, b_x, b_y : float
        Free choices (m). ``a_x`` and ``b_y`` must be non-zero and of the same sign
        (otherwise ``k`` would be negative).

    Returns
    -------
    Design

    Examples
    --------
    >>> d = generalized_lever(10.0, 0.5, 0.2, 0.1, 0.3)
    >>> round(d.parameters["a_y"], 4), round(d.parameters["k"], 3)
    (-0.0667, 75.0)
    """
    W = finite_real("weight W (N)", weight, positive=True)
    l = finite_real("length (m)", length, positive=True)
    a_x = finite_real("a_x (m)", a_x)
    b_x = finite_real("b_x (m)", b_x)
    b_y = finite_real("b_y (m)", b_y)
    if abs(a_x) < MIN_POSITIVE:
        raise ValueError("a_x must be non-zero: a spring attached on the line through the pivot "
                         "perpendicular to the lever cannot balance it (eq. 16 divides by a_x; |a_x| >= 1e-12 m)")
    if abs(b_y) < MIN_POSITIVE:
        raise ValueError("b_y must be non-zero (|b_y| >= 1e-12 m): eq. 15 divides by b_y")
    if a_x * b_y < 0:
        raise ValueError(f"a_x and b_y must have the same sign (k = W l b_y / (a_x (b_x^2 + b_y^2)) "
                         f"would be negative); got a_x = {a_x}, b_y = {b_y}")
    a_y = -a_x * b_x / b_y
    k = W * l * b_y / (a_x * (b_x ** 2 + b_y ** 2))
    return _general_lever_design("generalized lever", W, l, (a_x, a_y), (b_x, b_y), k,
                                 "Singh & Ananthasuresh, eqs 12-17")


def _general_lever_design(name, W, l, a, b, k, reference) -> Design:
    import sympy as sp

    Ws, ls, ks = sp.symbols("W l k", positive=True)
    axs, ays, bxs, bys = sp.symbols("a_x a_y b_x b_y", real=True)
    sym = SymbolicParts(((1, (ls, 0), (0, -Ws)),), ((ks, 0, (0, (bxs, bys)), (1, (axs, ays))),),
                        {Ws: W, ls: l, ks: k, axs: a[0], ays: a[1], bxs: b[0], bys: b[1]})
    pe = W * l / (2 * a[0] * b[1]) * (a[0] ** 2 + b[1] ** 2)
    return lever_design(
        name, [Load(1, (l, 0.0), (0.0, -W), "W", kind="weight")],
        [Spring(k, 0.0, (0, b), (1, a), name="k")], symbolic=sym,
        labels={"O": (0, (0.0, 0.0)), "a": (1, a), "b": (0, b), "p": (1, (l, 0.0))},
        parameters={"k": k, "a_x": a[0], "a_y": a[1], "b_x": b[0], "b_y": b[1], "PE": pe},
        reference=reference, link="lever")


@example("min_preload_lever", "Lever with minimum preload, Singh's rocker: k4 = 20 N/m (eqs 18-20)",
         chapter=2, weight=10.0, length=0.5, a_x=0.5, a_y=0.0)
def min_preload_lever(weight: float, length: float, a_x: float, a_y: float = 0.0) -> Design:
    """The lever balanced with the least spring preload (Singh eqs 18-20, ``PE_min = W l``).

    The spring's two ends coincide in the configuration of maximum external work
    (``theta = 90 deg``): ``b = (-a_y, a_x)``, i.e. ``a_x = b_y`` (eq. 18) and
    ``a_y = -b_x`` (eq. 19), and ``k = W l / (b_x^2 + b_y^2)`` (eq. 20). The constant
    energy is then ``W l``, the maximum of the load's energy: the lower bound for any
    balanced design (the spring energy cannot be negative).

    Parameters
    ----------
    weight : float
        W (N), > 0.
    length : float
        Length of the lever: the distance ``l`` of the load from the pivot (m), > 0.
    a_x : float
        Attachment on the lever along it (m), > 0.
    a_y : float
        Attachment across the lever (m).

    Returns
    -------
    Design

    Examples
    --------
    >>> d = min_preload_lever(10.0, 0.5, 0.5)
    >>> d.parameters["b_x"], d.parameters["b_y"], d.parameters["k"], d.parameters["PE"]
    (0.0, 0.5, 20.0, 5.0)
    """
    W = finite_real("weight W (N)", weight, positive=True)
    l = finite_real("length (m)", length, positive=True)
    a_x = finite_real("a_x (m)", a_x, positive=True)
    a_y = finite_real("a_y (m)", a_y)
    b = (0.0 - a_y, a_x)
    k = W * l / (b[0] ** 2 + b[1] ** 2)
    return _general_lever_design("lever with minimum preload", W, l, (a_x, a_y), b, k,
                                 "Singh & Ananthasuresh, eqs 18-20")
