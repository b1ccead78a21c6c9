"""Roberts-Chebyshev cognates of a four-bar (Deepak & Ananthasuresh 2012, Secs 1.3 and 3).

With complex numbers for planar vectors, a four-bar ``A-D-C-B`` has the crank
``u = D - A``, coupler ``v = C - D``, rocker ``w = C - B`` and coupler point
``E = D + z v``. The third fixed pivot is ``O = A + z (B - A)``, so the *cognate
triangle* ``A B O`` is similar to the coupler triangle ``D C E``. Writing ``E`` three
ways,

* ``E = A + u + z v``               (the given four-bar, pivots ``A``, ``B``),
* ``E = B + (z - 1) v + w``         (cognate 2, pivots ``B``, ``O``: crank ``(z - 1) v``,
  coupler turning with ``w`` and carrying its rocker joint at ``(1 - z) w``, rocker
  ``(1 - z) u`` from ``O``),
* ``E = O + z w + (1 - z) u``       (cognate 3, pivots ``O``, ``A``: crank ``z w``,
  coupler turning with ``u`` and carrying its rocker joint at ``-z u``, rocker ``z v``
  from ``A``),

shows that the three four-bars trace one coupler curve. Each cognate is described
from its first pivot in the cyclic order ``A -> B -> O -> A``, so applying "base A" of
a technique to every cognate is the paper's cyclic symmetry. The coupler ratio maps
as ``z -> 1 / (1 - z) -> (z - 1) / z -> z``.

Balancing all three cognates at once is in :mod:`.cognate_balance`. Layer: methods.
"""
from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from ...core.design import Design
from ...core.elements import Spring
from ...core.validation import finite_real, planar_point, positive_int, real_array
from ...mechanisms.base import ExplicitKinematics
from ...mechanisms.fourbar import FourBar, fourbar_design
from ...mechanisms.geometry import Point, as_complex, as_point, numeric_only

__all__ = ["cognate_triangle", "cognates", "cognate_crank_angles", "cognate_design", "cognate_driver",
           "cognate_designs"]


def _check(fourbar: FourBar) -> None:
    if not isinstance(fourbar, FourBar):
        raise TypeError(f"fourbar must be a FourBar, got {type(fourbar).__name__}")
    fourbar.check_triangle()


def cognate_triangle(fourbar: FourBar) -> tuple[tuple[float, float], ...]:
    """The fixed pivots ``(A, B, O)`` of the three cognates, ``O = A + z (B - A)`` (m).

    Parameters
    ----------
    fourbar : FourBar
        The coupler point must not coincide with ``D`` or ``C``.

    Returns
    -------
    tuple of three (float, float)

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> [tuple(round(v, 4) for v in p) for p in cognate_triangle(example_fourbar())]
    [(0.0, 0.0), (0.4, 0.0), (0.2286, 0.1371)]
    """
    _check(fourbar)
    A, B = as_complex(fourbar.A), as_complex(fourbar.B)
    return (fourbar.A, fourbar.B, as_point(A + fourbar.z * (B - A)))


def _branch_from_state(A: complex, crank_angle: float, crank: float, coupler_angle: float, B: complex) -> int:
    """Assembly branch of a four-bar in a known configuration (as FourBarKinematics defines it).

    FourBarKinematics turns the direction from the crank tip to ``B`` by ``branch * gamma``
    (``0 <= gamma <= pi``) to get the coupler's direction.
    """
    J = A + crank * np.exp(1j * crank_angle)
    turn = np.angle(np.exp(1j * coupler_angle) / (B - J))
    return 1 if turn >= 0 else -1


def cognates(fourbar: FourBar) -> tuple[FourBar, FourBar, FourBar]:
    """The given four-bar and its two Roberts-Chebyshev cognates, in cyclic order.

    Cognate 1 is ``fourbar`` (pivots ``A``, ``B``); cognate 2 has pivots ``B``, ``O``
    and cognate 3 pivots ``O``, ``A`` (each listed from its crank's pivot). The branch
    of each cognate is the one that puts its coupler point on ``E`` in the middle of
    the given four-bar's crank range.

    Parameters
    ----------
    fourbar : FourBar
        The coupler point must not coincide with ``D`` or ``C`` (a cognate would have a
        link of zero length).

    Returns
    -------
    tuple of three FourBar

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> c1, c2, c3 = cognates(example_fourbar())
    >>> round(c2.crank, 4), round(c3.crank, 4)
    (0.1921, 0.1999)
    """
    _check(fourbar)
    z = fourbar.z
    r2, r3, r4 = fourbar.crank, fourbar.coupler, fourbar.rocker
    A, B, O = cognate_triangle(fourbar)
    c2_len = (abs(z - 1) * r3, abs(1 - z) * r4, abs(1 - z) * r2)
    c3_len = (abs(z) * r4, abs(z) * r2, abs(z) * r3)
    e2 = c2_len[1] / (1 - z)
    e3 = c3_len[1] * (z - 1) / z
    lo, hi = fourbar.kinematics.q_range[0]
    qm = 0.5 * (lo + hi)
    angs = _cognate_angles(fourbar, fourbar.state(np.array(qm)))
    out = [fourbar]
    for (p1, p2), lens, e, (a2, a3, _) in (((B, O), c2_len, e2, angs[1]), ((O, A), c3_len, e3, angs[2])):
        th = float(np.angle(np.exp(1j * a2)))
        br = _branch_from_state(as_complex(p1), th, lens[0], float(a3), as_complex(p2))
        out.append(FourBar(p1, p2, *lens, as_point(e), br, circuit=th))
    return out[0], out[1], out[2]


def _cognate_angles(fourbar: FourBar, st: dict):
    """(crank, coupler, rocker) angles of the three cognates from the given state."""
    z = fourbar.z
    th2, th3, th4 = st["th2"], st["th3"], st["th4"]
    # cognate 2: crank (z - 1) v, coupler along (1 - z) w, rocker (1 - z) u
    # cognate 3: crank z w, coupler along -z u, rocker z v
    a_1mz, a_mz, a_z, a_zm1 = np.angle(1 - z), np.angle(-z), np.angle(z), np.angle(z - 1)
    return ((th2, th3, th4),
            (th3 + a_zm1, th4 + a_1mz, th2 + a_1mz),
            (th4 + a_z, th2 + a_mz, th3 + a_z))


def cognate_crank_angles(fourbar: FourBar, q: ArrayLike) -> np.ndarray:
    """Crank angles of the three cognates when the given four-bar's crank is at ``q`` (rad).

    Parameters
    ----------
    fourbar : FourBar
    q : array_like
        Crank angles of the given four-bar (rad).

    Returns
    -------
    numpy.ndarray, shape (3, ...)

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> cognate_crank_angles(example_fourbar(), 0.3).shape
    (3,)
    """
    q = real_array("q (crank angles, rad)", q)
    _check(fourbar)
    st = fourbar.state(np.asarray(q, dtype=float))
    angs = _cognate_angles(fourbar, st)
    return np.stack([np.angle(np.exp(1j * a[0])) for a in angs])


def _index(index) -> int:
    return positive_int("index", index, 1, 3)


def cognate_design(fourbar: FourBar, index: int, K: Point | None = None, k_l: float = 1.0) -> Design:
    """Cognate ``index`` (1, 2 or 3) driven by the *given* four-bar's crank angle.

    The bodies of the cognate are placed from the given four-bar's closed-form
    solution, so ``design.joint_error(q)`` checks that the cognate closes and its
    coupler point is compared with the given one's at the same ``q``.

    Parameters
    ----------
    fourbar : FourBar
    index : {1, 2, 3}
    K : (float, float), optional
        Anchor of a ZFL load spring on the coupler point (m); none when omitted.
    k_l : float
        Its stiffness (N/m), > 0.

    Returns
    -------
    Design
        Bodies: ground, crank, coupler, rocker of the cognate; ``labels["E"]`` is its
        coupler point.

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> d = cognate_design(example_fourbar(), 2)
    >>> float(d.joint_error(d.sample(50)).max()) < 1e-12
    True
    """
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    index = _index(index)
    cg = cognates(fourbar)[index - 1]
    springs, labels = [], {}
    params = {"crank": cg.crank, "coupler": cg.coupler, "rocker": cg.rocker}
    if K is not None:
        K = planar_point("K", K)
        k_l = finite_real("k_l (N/m)", k_l, positive=True)
        springs = [Spring(k_l, 0.0, (0, K), (2, cg.coupler_point), name="k_l")]
        params["k_l"] = k_l
        labels["K"] = (0, K)
    return fourbar_design(f"cognate {index} (driven by the given four-bar's crank)", cg, (), springs,
                          kinematics=cognate_driver(fourbar, index, cg), labels=labels, parameters=params,
                          reference="Roberts-Chebyshev cognates (Deepak & Ananthasuresh 2012, "
                                    "Sec. 1.3, Fig. 3)")


def cognate_driver(fourbar: FourBar, index: int, cognate: FourBar | None = None) -> ExplicitKinematics:
    """Kinematics of cognate ``index``'s bodies 0-3 as functions of the *given* four-bar's crank angle.

    The cognate's crank, coupler and rocker angles follow from the given four-bar's by
    fixed offsets (the similar triangles of the module docstring), so the driven cognate
    runs along the whole common coupler curve, switching assembly branch where it must.

    Parameters
    ----------
    fourbar : FourBar
        The given four-bar (cognate 1).
    index : {1, 2, 3}
    cognate : FourBar, optional
        ``cognates(fourbar)[index - 1]``, when already computed.

    Returns
    -------
    ExplicitKinematics
        Numeric only; coordinate ``theta``, the given four-bar's crank angle (rad).

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> kin = cognate_driver(example_fourbar(), 3)
    >>> kin.nbodies, kin.names
    (4, ('theta',))
    """
    index = _index(index)
    cg = cognates(fourbar)[index - 1] if cognate is None else cognate
    kin0 = fourbar.kinematics

    def pose_fn(q, lib):
        numeric_only(lib)
        st = fourbar.state(q[0])
        a2, a3, a4 = _cognate_angles(fourbar, st)[index - 1]
        Ac, Bc = as_complex(cg.A), as_complex(cg.B)
        D = Ac + cg.crank * np.exp(1j * a2)
        one = np.ones_like(q[0])
        return [(0 * one, 0 * one, 0 * one), (Ac.real * one, Ac.imag * one, a2), (D.real, D.imag, a3),
                (Bc.real * one, Bc.imag * one, a4)]

    return ExplicitKinematics(4, ("theta",), kin0.q_range, pose_fn, lambda q: kin0.poses(q)[1],
                              descriptions=("crank angle of the given four-bar from the x-axis",))


def cognate_designs(fourbar: FourBar, K: Point, k_l: float) -> tuple[Design, Design, Design]:
    """The three cognates, each loaded by the same ZFL spring ``k_l`` from ``K`` (Fig. 3).

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Load spring anchor (m).
    k_l : float
        Load spring stiffness (N/m), > 0.

    Returns
    -------
    tuple of three Design
        As :func:`cognate_design`; none of them is balanced.

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> [d.balance_report().balanced for d in cognate_designs(example_fourbar(), (0.1, -0.2), 100.0)]
    [False, False, False]
    """
    K = planar_point("K (m)", K)
    return cognate_design(fourbar, 1, K, k_l), cognate_design(fourbar, 2, K, k_l), cognate_design(fourbar, 3, K, k_l)


