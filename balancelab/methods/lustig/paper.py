"""The paper's example: a three-link chain (two moving links) and its design space.

Table 3e's four cases (:func:`lustig_table3e_case`, registered as ``lustig_case1`` to
``lustig_case4``), the angle of least gravity energy (eq. 18), ``B1`` from the linkage
alone (eq. 19), ``A1`` for a stiffness ``k1`` (eq. 20) and the invariant of spring 2
(Sec. III.B).
"""
from __future__ import annotations

import math
from typing import Mapping

import numpy as np

from ...core.design import Design
from ...core.elements import G
from ...core.validation import finite_real, positive_int
from ..registry import example
from .chain import REFERENCE, SerialChain, chain_parameter_names
from .solving import solve

__all__ = ["LUSTIG_TOPOLOGY", "LUSTIG_UNKNOWNS", "LUSTIG_L3", "lustig_values", "lustig_table3e_case",
           "lustig_case1", "lustig_case2", "lustig_case3", "lustig_case4", "lustig_alpha", "lustig_b1",
           "lustig_a1", "lustig_min_energy_pose", "spring2_invariant"]


# ----------------------------------------------------------------- the paper's example
#: Spring topology of the paper's example 2 (Fig. 2c): spring 1 from the ground to link 3
#: (body 2, bi-articular), spring 2 from link 2 to link 3 (bodies 1 and 2, mono-articular).
LUSTIG_TOPOLOGY: tuple = ((0, 2), (1, 2))

#: The parameters the paper solves for in every case of Table 3e.
LUSTIG_UNKNOWNS: tuple = ("ax1", "bx1", "by1", "bx2", "by2", "k1")

#: Length of link 3 (m). It does not enter any condition and is not printed (Fig. 3 is
#: missing from the text); 0.3 m is assumed, so that s_x3 = 0.15 m is mid-link.
LUSTIG_L3: float = 0.3

_TABLE3E_INPUTS = {
    # case: (ax2, ay2, sy2)
    1: (0.15, 0.0, 0.0),
    2: (0.18, -0.09, 0.0),
    3: (0.15, 0.0, -0.1),
    4: (0.18, -0.09, -0.1),
}


def _case(case) -> int:
    return positive_int("case", case, 1, len(_TABLE3E_INPUTS))


def lustig_values(case: int, *, solved: bool = True) -> dict:
    """Every parameter of a case of the paper's Table 3e, by name.

    Parameters
    ----------
    case : {1, 2, 3, 4}
        Column of Table 3e.
    solved : bool
        Include the six solved parameters (:data:`LUSTIG_UNKNOWNS`), computed from the
        chosen inputs with :func:`solve`; ``False`` gives only the inputs below the
        table's line (plus the assumed ``L3``).

    Returns
    -------
    dict of str to float
        Inputs: ``k2 = 600`` N/m, ``ay1 = 0.1`` m, ``ax2, ay2`` (m), ``m2 = m3 = 2`` kg,
        ``L2 = 0.3`` m, ``sx2 = 0.1``, ``sy2``, ``sx3 = 0.15``, ``sy3 = 0`` (m),
        ``L3 = 0.3`` m (assumed), ``g = 9.81``.

    Examples
    --------
    >>> round(lustig_values(4)["by2"], 4)
    -0.0739
    """
    case = _case(case)
    ax2, ay2, sy2 = _TABLE3E_INPUTS[case]
    v = dict(L2=0.3, m2=2.0, sx2=0.1, sy2=sy2, L3=LUSTIG_L3, m3=2.0, sx3=0.15, sy3=0.0,
             k2=600.0, ax2=ax2, ay2=ay2, ay1=0.1, g=G)
    if solved:
        v.update(solve(2, LUSTIG_TOPOLOGY, v, LUSTIG_UNKNOWNS))
    return v


def lustig_table3e_case(case: int) -> Design:
    """The balanced three-link chain (two moving links) of a case of Table 3e.

    Two ZFL springs: spring 1 from the ground point ``A1 = (ax1, ay1)`` to ``B1`` on link
    3, spring 2 from ``A2`` on link 2 to ``B2`` on link 3 (Fig. 2c). The six parameters
    ``ax1, bx1, by1, bx2, by2, k1`` are solved from eq. 17; the rest are the table's
    inputs. ``L3`` (not printed) is taken as 0.3 m; it does not affect the balance.

    Parameters
    ----------
    case : {1, 2, 3, 4}
        1: springs along the links; 2: ``A2`` turned about ``J2``; 3: centre of mass of
        link 2 moved off its axis (``sy2 = -0.1`` m); 4: both.

    Returns
    -------
    Design
        ``q`` = absolute angles (rad) of links 2 and 3 (bodies 1 and 2).

    Examples
    --------
    >>> d = lustig_table3e_case(2)
    >>> round(d.parameters["bx2"], 4), d.balance_report().balanced
    (-0.0785, True)
    """
    case = _case(case)
    v = lustig_values(case)
    chain = SerialChain.from_values(2, LUSTIG_TOPOLOGY, v)
    return chain.design(f"Lustig et al. Table 3e, case {case}", symbolic=True,
                        reference=REFERENCE + f" (case {case})")


@example("lustig_case1", "Stiffness-matrix 2R, Table 3e case 1: springs along the links (Lustig et al.)", chapter=4)
def lustig_case1() -> Design:
    """Table 3e case 1: both springs along the links. See :func:`lustig_table3e_case`.

    Examples
    --------
    >>> lustig_case1().balance_report().balanced
    True
    """
    return lustig_table3e_case(1)


@example("lustig_case2", "Stiffness-matrix 2R, Table 3e case 2: A2 turned about J2 (Lustig et al.)", chapter=4)
def lustig_case2() -> Design:
    """Table 3e case 2: ``A2`` turned about ``J2``. See :func:`lustig_table3e_case`.

    Examples
    --------
    >>> round(lustig_case2().parameters["by2"], 4)
    -0.0589
    """
    return lustig_table3e_case(2)


@example("lustig_case3", "Stiffness-matrix 2R, Table 3e case 3: centre of mass of link 2 off its axis (Lustig et al.)", chapter=4)
def lustig_case3() -> Design:
    """Table 3e case 3: centre of mass of link 2 off its axis. See :func:`lustig_table3e_case`.

    Examples
    --------
    >>> round(lustig_case3().parameters["ax1"], 3)
    -0.025
    """
    return lustig_table3e_case(3)


@example("lustig_case4", "Stiffness-matrix 2R, Table 3e case 4: cases 2 and 3 combined (Lustig et al.)", chapter=4)
def lustig_case4() -> Design:
    """Table 3e case 4: cases 2 and 3 combined. See :func:`lustig_table3e_case`.

    Examples
    --------
    >>> round(lustig_case4().parameters["bx2"], 2)
    -0.06
    """
    return lustig_table3e_case(4)


_POSITIVE_NAMES = ("m2", "m3", "L2", "k1", "k2", "g")


def _vals(values, needs: tuple = ()) -> dict:
    """The parameters as a dict; each name in ``needs`` must be there and finite
    (masses, ``L2``, spring rates and ``g`` > 0)."""
    if isinstance(values, Design):
        v = dict(values.parameters)
    elif isinstance(values, Mapping):
        v = dict(values)
    else:
        raise TypeError(f"values must be a mapping of parameter names or a Design, got {type(values).__name__}")
    known = chain_parameter_names(2, LUSTIG_TOPOLOGY)
    extra = [name for name in v if name not in known]
    if extra and not isinstance(values, Design):
        raise ValueError(f"values has entries {extra} that are not parameters of Lustig's chain; "
                         f"valid names: {known}")
    missing = [name for name in needs if name not in v]
    if missing:
        raise ValueError(f"values lacks {', '.join(missing)} (needed: {', '.join(needs)})")
    for name in needs:
        unit = {"m": "kg", "k": "N/m", "g": "m/s^2"}.get(name[0], "m")
        v[name] = finite_real(f"values[{name!r}] ({unit})", v[name], positive=name in _POSITIVE_NAMES)
    return v


def lustig_alpha(values) -> float:
    """Angle ``alpha`` (rad) of link 2 from the downward vertical at minimum gravity energy (eq. 18d).

    ``alpha = atan(m2 sy2 / (m2 sx2 + m3 L2))``: in the pose of least gravity energy of
    the unbalanced chain, link 2's x-axis points at ``-pi/2 - alpha`` from the global
    x-axis (so that its first moment ``(m2 sx2 + m3 L2, m2 sy2)`` hangs straight down).

    Parameters
    ----------
    values : mapping or Design
        Needs ``m2, m3, L2, sx2, sy2``.

    Returns
    -------
    float

    Examples
    --------
    >>> round(lustig_alpha(lustig_values(3, solved=False)), 6)
    -0.244979
    """
    v = _vals(values, ("m2", "m3", "L2", "sx2", "sy2"))
    return math.atan2(v["m2"] * v["sy2"], v["m2"] * v["sx2"] + v["m3"] * v["L2"])


def lustig_b1(values) -> tuple[float, float]:
    """Attachment ``B1 = (bx1, by1)`` on link 3 from the linkage alone (eq. 19), in m.

    Parameters
    ----------
    values : mapping or Design
        Needs ``L2, m2, m3, sx2, sy2, sx3, sy3``.

    Returns
    -------
    (float, float)

    Examples
    --------
    >>> [round(x, 4) for x in lustig_b1(lustig_values(3, solved=False))]
    [0.1059, 0.0265]
    """
    v = _vals(values, ("L2", "m2", "m3", "sx2", "sy2", "sx3", "sy3"))
    L, m2, m3 = v["L2"], v["m2"], v["m3"]
    den = (L * m3 + m2 * v["sx2"]) ** 2 + m2 ** 2 * v["sy2"] ** 2
    bx = (L ** 2 * m3 ** 2 * v["sx3"] + L * m2 * m3 * (v["sx2"] * v["sx3"] + v["sy2"] * v["sy3"])) / den
    by = (L ** 2 * m3 ** 2 * v["sy3"] + L * m2 * m3 * (v["sx2"] * v["sy3"] - v["sx3"] * v["sy2"])) / den
    return bx, by


def lustig_a1(values) -> tuple[float, float]:
    """Ground attachment ``A1 = (ax1, ay1)`` for a stiffness ``k1`` (eqs 20a, 20b), in m.

    ``|A1|`` is inversely proportional to ``k1`` and ``ax1 / ay1 = tan(alpha)`` (eq. 20c).

    Parameters
    ----------
    values : mapping or Design
        Needs ``k1, L2, m2, m3, sx2, sy2`` (and ``g``, default 9.81).

    Returns
    -------
    (float, float)

    Examples
    --------
    >>> [round(x, 4) for x in lustig_a1(dict(lustig_values(3, solved=False), k1=250.0))]
    [-0.0262, 0.1046]
    """
    v = _vals(dict({"g": G}, **_vals(values)), ("k1", "L2", "m2", "m3", "sx2", "sy2", "g"))
    g, k1 = v["g"], v["k1"]
    return (v["m2"] * g * v["sy2"] / (v["L2"] * k1),
            (v["m2"] * g * v["sx2"] + v["m3"] * g * v["L2"]) / (v["L2"] * k1))


def lustig_min_energy_pose(values) -> np.ndarray:
    """Absolute link angles (rad) of the unbalanced chain's least gravity energy (Fig. 4a).

    Link 2 at ``-pi/2 - alpha`` (eq. 18) and link 3 with its centre of mass straight
    below ``J2``. In this pose ``A1, J1, J2, B1`` lie on one line, and so do
    ``A2, J2, B2`` (Fig. 4c).

    Parameters
    ----------
    values : mapping or Design

    Returns
    -------
    numpy.ndarray, shape (2,)

    Examples
    --------
    >>> lustig_min_energy_pose(lustig_values(1, solved=False)).round(4).tolist()
    [-1.5708, -1.5708]
    """
    v = _vals(values, ("m2", "m3", "L2", "sx2", "sy2", "sx3", "sy3"))
    return np.array([-math.pi / 2 - lustig_alpha(v), -math.pi / 2 - math.atan2(v["sy3"], v["sx3"])])


def spring2_invariant(values) -> float:
    """``k2 |A2 - J2| |B2 - J2|`` (N m) of the paper's example: constant over the family.

    With spring 1 fixed, spring 2 may be moved and re-sized freely as long as this
    product stays the same (Sec. III.B); it equals ``k1 L2 |B1|``.

    Parameters
    ----------
    values : mapping or Design
        Needs ``k2, L2, ax2, ay2, bx2, by2``.

    Returns
    -------
    float

    Examples
    --------
    >>> round(spring2_invariant(lustig_values(1)), 3)
    8.829
    """
    v = _vals(values, ("k2", "L2", "ax2", "ay2", "bx2", "by2"))
    return v["k2"] * math.hypot(v["ax2"] - v["L2"], v["ay2"]) * math.hypot(v["bx2"], v["by2"])
