"""Roberts-Chebyshev cognates and the balancing of all three (Deepak & Ananthasuresh 2012, Sec. 3).

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

Balancing all three (Sec. 3.2): an option of technique 2 or 3 puts ``H_i`` on a
straight line from a vertex ``W_i`` of the cognate triangle. The triangles
``H_1 H_2 H_3`` directly similar to ``W_1 W_2 W_3`` with ``H_i`` on its line solve the
*linear* homogeneous system ``c + sigma W_i = t_i d_i`` (``H_i = W_i + t_i d_i =
c + (1 + sigma) W_i``): six real equations in seven unknowns, a one-dimensional null
space. So along the family every ``t_i = |W_i H_i|`` scales by one factor, the ratio
``k_b1 : k_b2 : k_b3`` is invariant, and the fixed point ``P = -c / sigma`` of the
similarity, the *focal pivot*, stays put: case (i) parallel lines (``sigma = 0``, no
finite focal pivot, ratio of ``t`` 1:1:1), case (ii) concurrent lines (``sigma`` real,
``P`` the common point; for technique 2 it is ``K``), case (iii) otherwise (``sigma``
complex). :func:`focal_pivot_circles` is the paper's two-circle construction
(Sec. 3.1.4) and the tests check it against the null space.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ...core.design import Design
from ...core.elements import Spring
from ...core.validation import finite_real, planar_point
from ..registry import register
from ...mechanisms.base import ExplicitKinematics
from .spring_fourbar import (FourBar, _c, _numeric_only, _xy, technique2, technique3,
                             technique2_parameters, technique3_parameters)

__all__ = [
    "cognates",
    "cognate_triangle",
    "cognate_crank_angles",
    "cognate_design",
    "cognate_designs",
    "focal_pivot_circles",
    "CognateFamily",
    "cognate_family",
    "kb_ratio_from_triangle",
    "balance_cognates",
]


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
    >>> from balancelab.methods.deepak.spring_fourbar import example_fourbar
    >>> [tuple(round(v, 4) for v in p) for p in cognate_triangle(example_fourbar())]
    [(0.0, 0.0), (0.4, 0.0), (0.2286, 0.1371)]
    """
    _check(fourbar)
    A, B = _c(fourbar.A), _c(fourbar.B)
    return (fourbar.A, fourbar.B, _xy(A + fourbar.z * (B - A)))


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
    >>> from balancelab.methods.deepak.spring_fourbar import example_fourbar
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
        br = _branch_from_state(_c(p1), th, lens[0], float(a3), _c(p2))
        out.append(FourBar(p1, p2, *lens, _xy(e), br, circuit=th))
    return tuple(out)


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


def cognate_crank_angles(fourbar: FourBar, q) -> np.ndarray:
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
    >>> from balancelab.methods.deepak.spring_fourbar import example_fourbar
    >>> cognate_crank_angles(example_fourbar(), 0.3).shape
    (3,)
    """
    _check(fourbar)
    st = fourbar.state(np.asarray(q, dtype=float))
    angs = _cognate_angles(fourbar, st)
    return np.stack([np.angle(np.exp(1j * a[0])) for a in angs])


def cognate_design(fourbar: FourBar, index: int, K=None, k_l: float = 1.0) -> Design:
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
    >>> from balancelab.methods.deepak.spring_fourbar import example_fourbar
    >>> d = cognate_design(example_fourbar(), 2)
    >>> float(d.joint_error(d.sample(50)).max()) < 1e-12
    True
    """
    if isinstance(index, bool) or not isinstance(index, (int, np.integer)) or index not in (1, 2, 3):
        raise ValueError(f"index must be 1, 2 or 3, got {index!r}")
    index = int(index)
    cg = cognates(fourbar)[index - 1]
    kin = _driver(fourbar, index, cg)
    springs = []
    params = {"crank": cg.crank, "coupler": cg.coupler, "rocker": cg.rocker}
    if K is not None:
        K = planar_point("K", K)
        k_l = finite_real("k_l (N/m)", k_l, positive=True)
        springs = [Spring(k_l, 0.0, (0, K), (2, cg.coupler_point), name="k_l")]
        params["k_l"] = k_l
    lab = cg.labels()
    if K is not None:
        lab["K"] = (0, K)
    return Design(f"cognate {index} (driven by the given four-bar's crank)",
                  ("ground", "crank", "coupler", "rocker"), cg.joints(), kin, (), springs, labels=lab,
                  parameters=params, reference="Roberts-Chebyshev cognates (Deepak & Ananthasuresh 2012, "
                                               "Sec. 1.3, Fig. 3)")


def _driver(fourbar: FourBar, index: int, cg: FourBar) -> ExplicitKinematics:
    """Kinematics of cognate ``index``'s bodies 0-3 as functions of the given crank angle."""
    kin0 = fourbar.kinematics

    def pose_fn(q, lib):
        _numeric_only(lib)
        st = fourbar.state(q[0])
        a2, a3, a4 = _cognate_angles(fourbar, st)[index - 1]
        Ac, Bc = _c(cg.A), _c(cg.B)
        D = Ac + cg.crank * np.exp(1j * a2)
        one = np.ones_like(q[0])
        return [(0 * one, 0 * one, 0 * one), (Ac.real * one, Ac.imag * one, a2), (D.real, D.imag, a3),
                (Bc.real * one, Bc.imag * one, a4)]

    return ExplicitKinematics(4, ("theta",), kin0.q_range, pose_fn, lambda q: kin0.poses(q)[1])


def cognate_designs(fourbar: FourBar, K, k_l: float) -> tuple[Design, Design, Design]:
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
    >>> from balancelab.methods.deepak.spring_fourbar import example_fourbar
    >>> [d.balance_report().balanced for d in cognate_designs(example_fourbar(), (0.1, -0.2), 100.0)]
    [False, False, False]
    """
    return tuple(cognate_design(fourbar, i, K, k_l) for i in (1, 2, 3))


# ------------------------------------------------------------------- focal pivot
def _line_intersection(p1: complex, d1: complex, p2: complex, d2: complex):
    den = (d1.conjugate() * d2).imag
    if abs(den) < 1e-12 * abs(d1) * abs(d2):
        return None
    t = ((p2 - p1).conjugate() * d2).imag / den
    return p1 + t * d1


def _circumcentre(a: complex, b: complex, c: complex) -> complex:
    den = a.conjugate() * (b - c) + b.conjugate() * (c - a) + c.conjugate() * (a - b)
    if abs(den) < 1e-14 * max(abs(a - b), abs(b - c), abs(c - a)) ** 2:
        raise ValueError("the three points of a circle are collinear")
    return (abs(a) ** 2 * (b - c) + abs(b) ** 2 * (c - a) + abs(c) ** 2 * (a - b)) / den


def focal_pivot_circles(vertices, directions):
    """The focal pivot by the paper's two-circle construction (Deepak Sec. 3.1.4).

    Lines ``a, b, c`` start at the vertices ``A, B, C`` along ``directions``. If they
    are all parallel there is no finite focal pivot (case i, returns ``None``); if they
    meet in one point that point is returned (case ii). Otherwise (case iii) the
    circle through ``A``, ``B`` and ``I_ab`` and the circle through ``C``, ``A`` and
    ``I_ca`` (``I`` the intersections of the lines, relabelled so both exist) meet at
    ``A`` and at the focal pivot ``M``; when they touch at ``A``, ``A`` is the focal pivot.

    Parameters
    ----------
    vertices : sequence of three (float, float)
        ``A, B, C`` (m).
    directions : sequence of three (float, float)
        Directions of ``a, b, c`` (any length, non-zero).

    Returns
    -------
    (str, (float, float) or None)
        The case (``"i"``, ``"ii"`` or ``"iii"``) and the focal pivot.

    Examples
    --------
    >>> focal_pivot_circles([(0, 0), (1, 0), (0, 1)], [(1, 1), (0, 1), (1, 0)])
    ('ii', (1.0, 1.0))
    """
    V = [_c(planar_point(f"vertex {i}", v)) for i, v in enumerate(vertices)]
    D = [_c(planar_point(f"direction {i}", d)) for i, d in enumerate(directions)]
    if len(V) != 3 or len(D) != 3:
        raise ValueError("need three vertices and three directions")
    if any(abs(d) == 0 for d in D):
        raise ValueError("a direction is zero")
    scale = max(abs(V[0] - V[1]), abs(V[1] - V[2]), abs(V[2] - V[0]))
    pairs = [(i, j) for i in range(3) for j in range(i + 1, 3)
             if _line_intersection(V[i], D[i], V[j], D[j]) is not None]
    if not pairs:
        return "i", None
    # concurrency
    i, j = pairs[0]
    X = _line_intersection(V[i], D[i], V[j], D[j])
    k = 3 - i - j
    off = abs(((X - V[k]) * D[k].conjugate()).imag) / abs(D[k])
    if off <= 1e-10 * scale:
        return "ii", _xy(X)
    # pick a vertex "a" whose line meets both others
    for a in range(3):
        b, c = (a + 1) % 3, (a + 2) % 3
        Iab = _line_intersection(V[a], D[a], V[b], D[b])
        Ica = _line_intersection(V[c], D[c], V[a], D[a])
        if Iab is not None and Ica is not None:
            break
    else:  # pragma: no cover - two non-parallel pairs always share a line
        raise ValueError("no two pairs of non-parallel lines")
    A, B, C = V[a], V[b], V[c]
    O1 = _circumcentre(A, B, Iab) if abs(Iab - A) > 1e-12 * scale and abs(Iab - B) > 1e-12 * scale else None
    O2 = _circumcentre(C, A, Ica) if abs(Ica - A) > 1e-12 * scale and abs(Ica - C) > 1e-12 * scale else None
    if O1 is None or O2 is None:
        # I_ab at A (or B): line a is tangent to the circle there; build it from the tangent
        def tangent_circle(P, Q, dP):
            # circle through P and Q, tangent at P to the direction dP
            n = 1j * dP / abs(dP)
            s = abs(Q - P) ** 2 / (2 * ((Q - P) * n.conjugate()).real)
            return P + s * n
        if O1 is None:
            O1 = tangent_circle(A, B, D[a]) if abs(Iab - A) <= 1e-12 * scale else tangent_circle(B, A, D[b])
        if O2 is None:
            O2 = tangent_circle(A, C, D[a]) if abs(Ica - A) <= 1e-12 * scale else tangent_circle(C, A, D[c])
    # second intersection: reflection of A across the line of centres
    d = O2 - O1
    if abs(d) < 1e-14 * scale:
        raise ValueError("the two circles coincide: the lines are concurrent (case ii)")
    e = d / abs(d)
    r = A - O1
    M = O1 + e * (r * e.conjugate()).conjugate()
    return "iii", _xy(M)


class CognateFamily(NamedTuple):
    """Balancing of all three cognates with one option, as one family (Deepak Sec. 3.2).

    Attributes
    ----------
    cognates : tuple of FourBar
    technique : int
        2 or 3.
    W, L, direction : tuple of three (float, float)
        Base pivots (the cognate triangle's vertices), anchors of the equivalent load
        springs, unit directions of the loci of ``H_i``.
    m : tuple of three float
        Plagiograph scales (1 for technique 2).
    tau : tuple of three float
        ``|W_i H_i|`` of the member with ``lambda = 1``; every member is ``lambda tau``.
    case : str
        ``"i"``, ``"ii"`` or ``"iii"`` (Sec. 3.1).
    focal_pivot : (float, float) or None
        ``None`` in case (i).
    kb_ratio : tuple of three float
        ``k_b1 : k_b2 : k_b3`` normalized to sum 1 (NaN if no member is feasible).
    feasible : bool
        True if positive ``lambda`` gives positive ``k_b`` on all three cognates.
    """

    cognates: tuple
    technique: int
    W: tuple
    L: tuple
    direction: tuple
    m: tuple
    k_e: tuple
    tau: tuple
    case: str
    focal_pivot: tuple | None
    kb_ratio: tuple
    feasible: bool

    def member(self, lam: float) -> list[dict]:
        """The balancing parameters ``H, h, k_b, k_t`` of the three cognates at ``lambda``.

        Raises ValueError when ``lambda`` gives a zero or negative ``h`` on any cognate.
        """
        lam = finite_real("lambda", lam)
        out = []
        for i in range(3):
            h = lam * self.tau[i]
            if h <= 0:
                raise ValueError(f"lambda = {lam} gives |W{i + 1}H{i + 1}| = {h} <= 0: infinite or negative "
                                 f"k_b on cognate {i + 1}")
            W, L = _c(self.W[i]), _c(self.L[i])
            k_b = self.k_e[i] * abs(W - L) / h
            out.append({"h": h, "H": _xy(W + h * _c(self.direction[i])), "k_b": k_b, "k_t": k_b + self.k_e[i]})
        return out


def _family_solve(W, d):
    """Null space of c + sigma W_i - t_i d_i = 0 -> (c, sigma, t)."""
    M = np.zeros((6, 7))
    for i in range(3):
        # real part: c_x + s_r Wx - s_i Wy - t_i dx ; imag: c_y + s_r Wy + s_i Wx - t_i dy
        M[2 * i] = [1, 0, W[i].real, -W[i].imag, 0, 0, 0]
        M[2 * i + 1] = [0, 1, W[i].imag, W[i].real, 0, 0, 0]
        M[2 * i, 4 + i] = -d[i].real
        M[2 * i + 1, 4 + i] = -d[i].imag
    _, sv, Vt = np.linalg.svd(M)  # sv has 6 values, Vt is 7 x 7: its last row spans the null space
    if sv[-1] < 1e-10 * sv[0]:
        raise ValueError("the family of similar triangles is not one-parameter here (degenerate cognate "
                         "triangle or coincident loci)")
    x = Vt[-1]
    t = x[4:]
    if np.sum(t) < 0 or (np.sum(t) == 0 and t[np.argmax(np.abs(t))] < 0):
        x = -x
    x = x / np.max(np.abs(x[4:]))
    return complex(x[0], x[1]), complex(x[2], x[3]), x[4:]


def _classify(sigma: complex, c: complex, t, scale: float):
    if abs(sigma) < 1e-10:
        return "i", None
    P = -c / sigma
    if abs(sigma.imag) <= 1e-10 * abs(sigma):
        return "ii", _xy(P)
    return "iii", _xy(P)


def cognate_family(fourbar: FourBar, K, k_l: float, technique: int = 2, plagiograph_base: str = "A",
                   parallelogram_base: str = "A") -> CognateFamily:
    """Apply one option of technique 2 or 3 to all three cognates with cyclic symmetry.

    Every cognate uses the same option relative to its own pivots (``"A"``: its first
    pivot in the order ``A -> B -> O -> A``). Returns the one-parameter family in the
    paper's parametrization: ``H_1 H_2 H_3`` similar to the cognate triangle, the focal
    pivot and the invariant ratio ``k_b1 : k_b2 : k_b3`` (Table 3).

    Parameters
    ----------
    fourbar : FourBar
    K : (float, float)
        Load spring anchor (m), shared by the three cognates.
    k_l : float
        Load spring stiffness (N/m), > 0.
    technique : {2, 3}
    plagiograph_base : {"A", "B"}
        Technique 3 only.
    parallelogram_base : {"A", "B"}

    Returns
    -------
    CognateFamily

    Examples
    --------
    >>> from balancelab.methods.deepak.spring_fourbar import example_fourbar
    >>> f = cognate_family(example_fourbar(), (0.1, -0.2), 100.0, 2)
    >>> f.case, [round(v, 12) for v in f.focal_pivot], [round(r, 12) for r in f.kb_ratio]
    ('ii', [0.1, -0.2], [0.333333333333, 0.333333333333, 0.333333333333])
    """
    if technique not in (2, 3):
        raise ValueError(f"technique must be 2 or 3, got {technique!r}")
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    cgs = cognates(fourbar)
    W, L, dirs, ms, kes = [], [], [], [], []
    for cg in cgs:
        if technique == 2:
            p = technique2_parameters(cg, K, k_l, parallelogram_base, 1.0)
            W.append(_c(p.W)), L.append(_c(K)), ms.append(1.0)
        else:
            p = technique3_parameters(cg, K, k_l, plagiograph_base, parallelogram_base, 1.0)
            W.append(_c(p.W)), L.append(_c(p.L)), ms.append(p.m)
        dirs.append(_c(p.direction))
        kes.append(k_l / ms[-1] ** 2)
    c, sigma, t = _family_solve(W, dirs)
    scale = max(abs(W[0] - W[1]), abs(W[1] - W[2]), abs(W[2] - W[0]))
    case, P = _classify(sigma, c, t, scale)
    feasible = bool(np.all(t > 1e-12))
    if feasible:
        kb = np.array([kes[i] * abs(W[i] - L[i]) / t[i] for i in range(3)])
        ratio = tuple(float(v) for v in kb / kb.sum())
    else:
        ratio = (math.nan,) * 3
    return CognateFamily(cgs, technique, tuple(_xy(w) for w in W), tuple(_xy(x) for x in L),
                         tuple(_xy(x) for x in dirs), tuple(ms), tuple(kes), tuple(float(v) for v in t),
                         case, P, ratio, feasible)


def kb_ratio_from_triangle(triangle, K, technique: int = 2, plagiograph_base: str = "A",
                           parallelogram_base: str = "A") -> tuple[tuple, str, tuple | None]:
    """``k_b1 : k_b2 : k_b3`` from the cognate triangle and ``K`` alone (Deepak Table 2, 3).

    ``W_i`` is the vertex ``i`` (or ``i + 1``) of the triangle; the plagiograph factor of
    cognate ``i`` based at its first pivot is ``(W_{i+1} - W_i) / (W_{i-1} - W_i)`` and at
    its second pivot ``(W_i - W_{i+1}) / (W_{i-1} - W_{i+1})`` (scale ``m_i`` its modulus,
    rotation its argument); ``L_i = U_i + rho_i (K - U_i)``. The ratio is
    ``|L_i W_i| / (m_i^2 |W_i P|)`` (``P`` the focal pivot; ``|L_i W_i| / m_i^2`` in
    case i); for technique 2 the lines meet at ``K`` and the ratio is 1:1:1.

    Parameters
    ----------
    triangle : sequence of three (float, float)
        The cognate triangle ``W_1 W_2 W_3`` (m), in the cyclic order of :func:`cognates`.
    K : (float, float)
        Load spring anchor (m).
    technique, plagiograph_base, parallelogram_base
        As in :func:`cognate_family`.

    Returns
    -------
    (tuple of three float, str, (float, float) or None)
        The ratio normalized to sum 1, the case and the focal pivot.

    Examples
    --------
    >>> r, case, P = kb_ratio_from_triangle([(0, 0), (0.4, 0), (0.2, 0.3)], (0.1, -0.2))
    >>> case, [round(v, 6) for v in r]
    ('ii', [0.333333, 0.333333, 0.333333])
    """
    Wv = [_c(planar_point(f"triangle vertex {i + 1}", p)) for i, p in enumerate(triangle)]
    Kc = _c(planar_point("K", K))
    if technique not in (2, 3):
        raise ValueError(f"technique must be 2 or 3, got {technique!r}")
    W, L, dirs, ms = [], [], [], []
    for i in range(3):
        first, second, prev = Wv[i], Wv[(i + 1) % 3], Wv[(i - 1) % 3]
        Wi = first if parallelogram_base == "A" else second
        if technique == 2:
            Li, m = Kc, 1.0
        else:
            if plagiograph_base == "A":
                U, rho = first, (second - first) / (prev - first)
            else:
                U, rho = second, (first - second) / (prev - second)
            Li, m = U + rho * (Kc - U), abs(rho)
        if abs(Wi - Li) == 0:
            raise ValueError(f"the equivalent load anchor of cognate {i + 1} is on its base pivot")
        W.append(Wi), L.append(Li), ms.append(m), dirs.append((Wi - Li) / abs(Wi - Li))
    c, sigma, t = _family_solve(W, dirs)
    scale = max(abs(W[0] - W[1]), abs(W[1] - W[2]), abs(W[2] - W[0]))
    case, P = _classify(sigma, c, t, scale)
    if case == "i":
        kb = np.array([abs(W[i] - L[i]) / ms[i] ** 2 for i in range(3)])
    else:
        Pc = _c(P)
        kb = np.array([abs(W[i] - L[i]) / (ms[i] ** 2 * abs(W[i] - Pc)) for i in range(3)])
    return tuple(float(v) for v in kb / kb.sum()), case, P


def balance_cognates(fourbar: FourBar, K, k_l: float, technique: int = 2, plagiograph_base: str = "A",
                     parallelogram_base: str = "A", lam: float = 0.1, *, driven: bool = True
                     ) -> tuple[Design, Design, Design]:
    """The three cognates each balanced by the same option, at the family member ``lambda``.

    With ``driven=True`` every cognate is placed from the *given* four-bar's crank angle
    (so the three designs share one coordinate and run along the whole common coupler
    curve, switching assembly branch where they must); with ``driven=False`` each is a
    four-bar of its own on one branch of its own crank range.

    Parameters
    ----------
    fourbar, K, k_l, technique, plagiograph_base, parallelogram_base
        As in :func:`cognate_family`.
    lam : float
        Family parameter: ``|W_i H_i| = lambda tau_i`` (m), > 0.
    driven : bool
        See above.

    Returns
    -------
    tuple of three Design
        Balanced.

    Examples
    --------
    >>> from balancelab.methods.deepak.spring_fourbar import example_fourbar
    >>> ds = balance_cognates(example_fourbar(), (0.1, -0.2), 100.0, 2, lam=0.1)
    >>> [d.balance_report().balanced for d in ds]
    [True, True, True]
    """
    fam = cognate_family(fourbar, K, k_l, technique, plagiograph_base, parallelogram_base)
    if not fam.feasible:
        raise ValueError("this option cannot give positive k_b on all three cognates at once "
                         f"(signed |W_i H_i| of the family: {fam.tau})")
    mem = fam.member(lam)
    out = []
    for i, cg in enumerate(fam.cognates):
        drv = _driver(fourbar, i + 1, cg) if driven else None
        if technique == 2:
            d = technique2(cg, K, k_l, parallelogram_base, mem[i]["h"], driver=drv)
        else:
            d = technique3(cg, K, k_l, plagiograph_base, parallelogram_base, mem[i]["h"], driver=drv)
        out.append(d.replace(name=f"cognate {i + 1}: " + d.name))
    return tuple(out)


def _cognate_example(i: int) -> Design:
    """Cognate ``i`` of the example four-bar with the load spring ``k_l = 100 N/m`` from
    ``K = (0.1, -0.2)``, balanced by technique 2 based at its first pivot (``lambda = 0.1``)."""
    from .spring_fourbar import example_fourbar

    return balance_cognates(example_fourbar(), (0.1, -0.2), 100.0, 2, "A", "A", 0.1)[i]


for _i in range(3):
    register(f"deepak_cognate_{_i + 1}", f"Cognate {_i + 1} of the example four-bar, balanced by technique 2 "
             "(Deepak Sec. 3)", _cognate_example, chapter=5, args=(_i,))
