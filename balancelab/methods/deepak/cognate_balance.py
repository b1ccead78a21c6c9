"""Balancing the three Roberts-Chebyshev cognates at once (Deepak & Ananthasuresh 2012, Sec. 3).

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

The cognates themselves are in :mod:`.roberts`. Layer: methods.
"""
from __future__ import annotations

import math
from typing import NamedTuple, Sequence

import numpy as np

from ...core.design import Design
from ...core.validation import MAX_MAGNITUDE, finite_real, instance_of, planar_point, planar_points
from ...mechanisms.fourbar import FourBar, pivot_name
from ...mechanisms.geometry import Point, as_complex, as_point
from .roberts import cognate_driver, cognates
from .techniques import technique2, technique2_parameters, technique3, technique3_parameters

__all__ = ["focal_pivot_circles", "CognateFamily", "similar_triangle_family", "cognate_family",
           "kb_ratio_from_triangle", "balance_cognates"]


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


def _tangent_circle(P: complex, Q: complex, dP: complex) -> complex:
    """Centre of the circle through ``P`` and ``Q`` tangent at ``P`` to the direction ``dP``."""
    n = 1j * dP / abs(dP)
    s = abs(Q - P) ** 2 / (2 * ((Q - P) * n.conjugate()).real)
    return P + s * n


def _two_circles(V: list, D: list, scale: float) -> complex:
    """Case iii of :func:`focal_pivot_circles`: the second intersection of the two circles."""
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
        if O1 is None:
            O1 = _tangent_circle(A, B, D[a]) if abs(Iab - A) <= 1e-12 * scale else _tangent_circle(B, A, D[b])
        if O2 is None:
            O2 = _tangent_circle(A, C, D[a]) if abs(Ica - A) <= 1e-12 * scale else _tangent_circle(C, A, D[c])
    # second intersection: reflection of A across the line of centres
    d = O2 - O1
    if abs(d) < 1e-14 * scale:
        raise ValueError("the two circles coincide: the lines are concurrent (case ii)")
    e = d / abs(d)
    r = A - O1
    M = O1 + e * (r * e.conjugate()).conjugate()
    return M


def focal_pivot_circles(vertices: Sequence[Point], directions: Sequence[Point]) -> tuple[str, Point | None]:
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
    vertices = planar_points("vertices (m)", vertices, 3)
    directions = planar_points("directions", directions, 3)
    V = [as_complex(planar_point(f"vertex {i}", v)) for i, v in enumerate(vertices)]
    D = [as_complex(planar_point(f"direction {i}", d)) for i, d in enumerate(directions)]
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
        return "ii", as_point(X)
    return "iii", as_point(_two_circles(V, D, scale))


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

    Examples
    --------
    >>> from balancelab.methods.deepak import example_fourbar
    >>> fam = cognate_family(example_fourbar(), (0.1, -0.2), 100.0, 2)
    >>> [round(m["h"], 6) for m in fam.member(0.1)] == [round(0.1 * t, 6) for t in fam.tau]
    True
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
            W, L = as_complex(self.W[i]), as_complex(self.L[i])
            k_b = self.k_e[i] * abs(W - L) / h
            out.append({"h": h, "H": as_point(W + h * as_complex(self.direction[i])), "k_b": k_b,
                        "k_t": k_b + self.k_e[i]})
        return out


def _three_complex(name: str, value) -> tuple:
    """Three complex numbers (points or directions as ``x + i y``), checked."""
    if isinstance(value, (str, bytes)) or value is None:
        raise TypeError(f"{name} must be three complex numbers, got {value!r}")
    try:
        items = [complex(v) if not isinstance(v, (str, bytes, bool)) else None for v in value]
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be three complex numbers, got {value!r}") from None
    numbers = [v for v in items if v is not None]
    if len(items) != 3 or len(numbers) != 3:
        raise ValueError(f"{name} must be three complex numbers, got {value!r}")
    if not all(math.isfinite(v.real) and math.isfinite(v.imag) and abs(v) <= MAX_MAGNITUDE for v in numbers):
        raise ValueError(f"{name} must be finite, of magnitude <= {MAX_MAGNITUDE:g}, got {value!r}")
    return tuple(numbers)


def similar_triangle_family(W: Sequence[complex], d: Sequence[complex]
                            ) -> tuple[complex, complex, np.ndarray]:
    """The triangles ``H_1 H_2 H_3`` directly similar to ``W_1 W_2 W_3``, ``H_i`` on the line ``W_i + t d_i``.

    They solve the linear homogeneous system ``c + sigma W_i = t_i d_i`` (``H_i = W_i +
    t_i d_i = c + (1 + sigma) W_i``): six real equations in seven unknowns ``c``,
    ``sigma`` (complex) and ``t_1, t_2, t_3`` (real). The null space is one-dimensional
    and is returned scaled so that ``max |t_i| = 1`` and ``sum t_i >= 0``; the focal pivot
    is ``-c / sigma`` (none when ``sigma = 0``).

    Parameters
    ----------
    W : sequence of three complex
        The vertices (m, as ``x + i y``).
    d : sequence of three complex
        Directions of the lines (non-zero).

    Returns
    -------
    (complex, complex, numpy.ndarray)
        ``c``, ``sigma`` and ``t`` (shape (3,)).

    Raises
    ------
    ValueError
        If the null space is not one-dimensional (a degenerate triangle or coincident
        lines).

    Examples
    --------
    Lines from the vertices away from ``K`` (technique 2) meet at ``K``, the focal pivot:

    >>> K, W = 0.1 - 0.2j, [0j, 0.4 + 0j, 0.2 + 0.3j]
    >>> c, sigma, t = similar_triangle_family(W, [w - K for w in W])
    >>> P = -c / sigma
    >>> round(P.real, 12), round(P.imag, 12), [round(float(v), 12) for v in t]
    (0.1, -0.2, [1.0, 1.0, 1.0])
    """
    W, d = _three_complex("W", W), _three_complex("d", d)
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
        return "ii", as_point(P)
    return "iii", as_point(P)


def cognate_family(fourbar: FourBar, K: Point, k_l: float, technique: int = 2, plagiograph_base: str = "A",
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
    >>> from balancelab.methods.deepak import example_fourbar
    >>> f = cognate_family(example_fourbar(), (0.1, -0.2), 100.0, 2)
    >>> f.case, [round(v, 12) for v in f.focal_pivot], [round(r, 12) for r in f.kb_ratio]
    ('ii', [0.1, -0.2], [0.333333333333, 0.333333333333, 0.333333333333])
    """
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    pivot_name("plagiograph_base", plagiograph_base)
    pivot_name("parallelogram_base", parallelogram_base)
    if technique not in (2, 3):
        raise ValueError(f"technique must be 2 or 3, got {technique!r}")
    K = planar_point("K (load spring anchor, m)", K)
    k_l = finite_real("k_l (N/m)", k_l, positive=True)
    cgs = cognates(fourbar)
    W, L, dirs, ms, kes = [], [], [], [], []
    for cg in cgs:
        if technique == 2:
            p2 = technique2_parameters(cg, K, k_l, parallelogram_base, 1.0)
            W.append(as_complex(p2.W))
            L.append(as_complex(K))
            ms.append(1.0)
            dirs.append(as_complex(p2.direction))
        else:
            p3 = technique3_parameters(cg, K, k_l, plagiograph_base, parallelogram_base, 1.0)
            W.append(as_complex(p3.W))
            L.append(as_complex(p3.L))
            ms.append(p3.m)
            dirs.append(as_complex(p3.direction))
        kes.append(k_l / ms[-1] ** 2)
    c, sigma, t = similar_triangle_family(W, dirs)
    scale = max(abs(W[0] - W[1]), abs(W[1] - W[2]), abs(W[2] - W[0]))
    case, P = _classify(sigma, c, t, scale)
    feasible = bool(np.all(t > 1e-12))
    if feasible:
        kb = np.array([kes[i] * abs(W[i] - L[i]) / t[i] for i in range(3)])
        ratio = tuple(float(v) for v in kb / kb.sum())
    else:
        ratio = (math.nan,) * 3
    return CognateFamily(cgs, technique, tuple(as_point(w) for w in W), tuple(as_point(x) for x in L),
                         tuple(as_point(x) for x in dirs), tuple(ms), tuple(kes), tuple(float(v) for v in t),
                         case, P, ratio, feasible)


def kb_ratio_from_triangle(triangle: Sequence[Point], K: Point, technique: int = 2,
                           plagiograph_base: str = "A", parallelogram_base: str = "A"
                           ) -> tuple[tuple, str, Point | None]:
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
    triangle = planar_points("triangle (m)", triangle, 3)
    pivot_name("plagiograph_base", plagiograph_base)
    pivot_name("parallelogram_base", parallelogram_base)
    Wv = [as_complex(planar_point(f"triangle vertex {i + 1}", p)) for i, p in enumerate(triangle)]
    Kc = as_complex(planar_point("K", K))
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
        W.append(Wi)
        L.append(Li)
        ms.append(m)
        dirs.append((Wi - Li) / abs(Wi - Li))
    c, sigma, t = similar_triangle_family(W, dirs)
    scale = max(abs(W[0] - W[1]), abs(W[1] - W[2]), abs(W[2] - W[0]))
    case, P = _classify(sigma, c, t, scale)
    if case == "i":
        kb = np.array([abs(W[i] - L[i]) / ms[i] ** 2 for i in range(3)])
    else:
        Pc = as_complex(P)
        den = [ms[i] ** 2 * abs(W[i] - Pc) for i in range(3)]
        if min(den) == 0:  # the focal pivot on a base pivot: no finite k_b (as cognate_family says)
            return (math.nan,) * 3, case, P
        kb = np.array([abs(W[i] - L[i]) / den[i] for i in range(3)])
    return tuple(float(v) for v in kb / kb.sum()), case, P


def balance_cognates(fourbar: FourBar, K: Point, k_l: float, technique: int = 2, plagiograph_base: str = "A",
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
    >>> from balancelab.methods.deepak import example_fourbar
    >>> ds = balance_cognates(example_fourbar(), (0.1, -0.2), 100.0, 2, lam=0.1)
    >>> [d.balance_report().balanced for d in ds]
    [True, True, True]
    """
    lam = finite_real("lam (m)", lam, positive=True)
    instance_of("fourbar", fourbar, FourBar, "a FourBar (balancelab.mechanisms.FourBar)")
    pivot_name("plagiograph_base", plagiograph_base)
    pivot_name("parallelogram_base", parallelogram_base)
    fam = cognate_family(fourbar, K, k_l, technique, plagiograph_base, parallelogram_base)
    if not fam.feasible:
        raise ValueError("this option cannot give positive k_b on all three cognates at once "
                         f"(signed |W_i H_i| of the family: {fam.tau})")
    mem = fam.member(lam)
    out = []
    for i, cg in enumerate(fam.cognates):
        drv = cognate_driver(fourbar, i + 1, cg) if driven else None
        if technique == 2:
            d = technique2(cg, K, k_l, parallelogram_base, mem[i]["h"], driver=drv)
        else:
            d = technique3(cg, K, k_l, plagiograph_base, parallelogram_base, mem[i]["h"], driver=drv)
        out.append(d.replace(name=f"cognate {i + 1}: " + d.name))
    return out[0], out[1], out[2]
