"""Free choices of Singh's chain with minimum preload, counted from the rank of its conditions.

The chain: ``N`` bodies in series, body 1 pivoted on the ground at the origin, body
``i + 1`` pivoted at ``(l_i, 0)`` on body ``i``; absolute angles ``theta_i``. Each body
``i`` carries a weight ``W_i`` at ``(p_xi, p_yi)``. One ZFL spring runs from the ground to
body 1 and two from the ground to every other body: ``2N - 1`` springs, numbered as in
the paper (spring 1 on body 1, springs 2 and 3 on body 2, 4 and 5 on body 3, ...), each
with the five unknowns ``k_s, a_xs, a_ys`` (the point on the body) and ``b_xs, b_ys``
(the ground anchor).

The conditions, all polynomial in the unknowns:

* balance: every non-constant coefficient of the energy's trigonometric normal form in
  ``cos theta_i, sin theta_i, cos(theta_i -+ theta_j), sin(theta_i -+ theta_j)``;
* minimum preload: every spring has zero length in the configuration of maximum work of
  the loads, ``theta_i* = atan2(C_i, D_i)`` with ``C_i, D_i`` the coefficients of
  ``sin theta_i`` and ``cos theta_i`` in the loads' energy: two scalar equations a spring.

The number of free choices is the dimension of the solution set: unknowns minus the
rank of the Jacobian of all conditions at a generic solution point, built exactly in
rational numbers by :func:`chain_solution_point`. Layer: methods.
"""
from __future__ import annotations

import functools
import random
from dataclasses import dataclass
from fractions import Fraction

from ...core.design import Design
from ...core.validation import instance_of, positive_int

__all__ = ["ChainConditions", "chain_conditions", "chain_solution_point", "design_point",
           "conditions_rank"]


@dataclass(frozen=True)
class ChainConditions:
    """The unknowns and conditions of Singh's chain of ``N`` bodies (sympy objects).

    Attributes
    ----------
    N : int
        Number of moving bodies.
    unknowns : tuple of sympy.Symbol
        ``k_s, a_xs, a_ys, b_xs, b_ys`` for ``s = 1 .. 2N - 1``, spring after spring.
    loads : tuple of sympy.Symbol
        ``W_i, p_xi, p_yi`` for every body, then the lengths ``l_1 .. l_{N-1}`` (N, m).
    balance : dict
        Trigonometric term -> its coefficient in the energy (the constant left out, and
        the coefficients that vanish identically left out).
    zero_length : tuple of sympy.Expr
        ``x`` and ``y`` of (point on the body - ground anchor) at the maximum-work
        configuration, for every spring.
    max_work : tuple of (sympy.Expr, sympy.Expr)
        ``(cos theta_i*, sin theta_i*)`` as functions of the loads.

    Examples
    --------
    >>> import sympy as sp
    >>> c = chain_conditions(2)
    >>> t1, t2 = sp.symbols("theta_1:3", real=True)
    >>> sp.factor(c.balance[sp.sin(t1 - t2)])
    l_1*(a_y2*k_2 + a_y3*k_3)
    """

    N: int
    unknowns: tuple
    loads: tuple
    balance: dict
    zero_length: tuple
    max_work: tuple

    def equations(self) -> list:
        """Every condition, balance first: a list of sympy expressions (each ``= 0``).

        Examples
        --------
        >>> len(chain_conditions(3).equations())   # 12 coefficients + 2 x 5 springs
        22
        """
        return list(self.balance.values()) + list(self.zero_length)

    def jacobian(self, values: dict, which: str = "all"):
        """Jacobian of the conditions w.r.t. the unknowns at ``values`` (a sympy Matrix).

        ``which`` is ``"all"``, ``"balance"`` or ``"zero_length"``.

        Examples
        --------
        >>> c = chain_conditions(1)
        >>> c.jacobian(chain_solution_point(1)).shape       # 2 balance + 2 zero length, 5 unknowns
        (4, 5)
        """
        import sympy as sp

        eqs = {"all": self.equations(), "balance": list(self.balance.values()),
               "zero_length": list(self.zero_length)}[which]
        loads = {s: v for s, v in values.items() if s in self.loads}
        J = sp.Matrix([sp.sympify(e).xreplace(loads) for e in eqs]).jacobian(self.unknowns)
        return J.xreplace(values)

    def residuals(self, values: dict) -> list:
        """The conditions evaluated at ``values`` (all zero at a solution).

        Examples
        --------
        >>> set(chain_conditions(1).residuals(chain_solution_point(1)))
        {0}
        """
        import sympy as sp

        return [sp.sympify(e).xreplace(values) for e in self.equations()]


def _trig_normal_form(energy, C, S) -> dict:
    """Coefficients of a polynomial in ``C_i = cos theta_i``, ``S_i = sin theta_i`` (degree <= 1 in each
    angle after ``S_i^2 = 1 - C_i^2``) in the basis ``1, cos, sin, cos(ti -+ tj), sin(ti -+ tj)``."""
    import sympy as sp

    th = sp.symbols(f"theta_1:{len(C) + 1}", real=True)
    poly = sp.Poly(sp.expand(energy), *C, *S)
    mono: dict = {}
    for powers, coeff in poly.terms():
        pc, ps = list(powers[:len(C)]), list(powers[len(C):])
        terms = [(coeff, pc, ps)]
        for i in range(len(C)):           # S_i^2 -> 1 - C_i^2, then C_i^2 + S_i^2 pairs are gone
            new = []
            for c, a, b in terms:
                if b[i] == 2:
                    b2 = b.copy()
                    b2[i] = 0
                    a2 = a.copy()
                    a2[i] += 2
                    new += [(c, a, b2), (-c, a2, b2)]
                else:
                    new.append((c, a, b))
            terms = new
        for c, a, b in terms:
            key = (tuple(a), tuple(b))
            mono[key] = mono.get(key, 0) + c
    out: dict = {}
    n = len(C)
    for (a, b), c in mono.items():
        c = sp.expand(c)
        if c == 0:
            continue
        used = [i for i in range(n) if a[i] or b[i]]
        if any(a[i] + b[i] > 1 for i in range(n)) or len(used) > 2:
            raise ValueError("the energy is not of degree one in each angle; not a ZFL chain")
        if not used:
            out[sp.S.One] = out.get(sp.S.One, 0) + c
        elif len(used) == 1:
            i = used[0]
            term = sp.cos(th[i]) if a[i] else sp.sin(th[i])
            out[term] = out.get(term, 0) + c
        else:
            i, j = used
            parts = {(1, 1, 0, 0): [(sp.cos(th[i] - th[j]), 1), (sp.cos(th[i] + th[j]), 1)],
                     (0, 0, 1, 1): [(sp.cos(th[i] - th[j]), 1), (sp.cos(th[i] + th[j]), -1)],
                     (0, 1, 1, 0): [(sp.sin(th[i] - th[j]), 1), (sp.sin(th[i] + th[j]), 1)],
                     (1, 0, 0, 1): [(sp.sin(th[i] - th[j]), -1), (sp.sin(th[i] + th[j]), 1)]}
            for term, sign in parts[(a[i], a[j], b[i], b[j])]:
                out[term] = out.get(term, 0) + sign * c / 2
    return {t: sp.expand(c) for t, c in out.items() if sp.expand(c) != 0}


def _spring_bodies(N: int) -> list:
    """Body of every spring: 1, 2, 2, 3, 3, ..."""
    return [1] + [i for i in range(2, N + 1) for _ in range(2)]


@functools.lru_cache(maxsize=8)
def _build(N: int) -> ChainConditions:
    import sympy as sp

    C = sp.symbols(f"C_1:{N + 1}", real=True)
    S = sp.symbols(f"S_1:{N + 1}", real=True)
    W = sp.symbols(f"W_1:{N + 1}", positive=True)
    px = sp.symbols(f"p_x1:{N + 1}", real=True)
    py = sp.symbols(f"p_y1:{N + 1}", real=True)
    ls = sp.symbols(f"l_1:{N}", positive=True)
    bodies = _spring_bodies(N)
    springs = [sp.symbols(f"k_{s} a_x{s} a_y{s} b_x{s} b_y{s}", real=True) for s in range(1, len(bodies) + 1)]

    def point(body, x, y, c, s):
        """World point of local (x, y) on ``body`` with unit vectors (c[i], s[i])."""
        X = sum(ls[j] * c[j] for j in range(body - 1)) + x * c[body - 1] - y * s[body - 1]
        Y = sum(ls[j] * s[j] for j in range(body - 1)) + x * s[body - 1] + y * c[body - 1]
        return X, Y

    v_load = sum(W[i] * point(i + 1, px[i], py[i], C, S)[1] for i in range(N))
    v_spring = 0
    for body, (k, ax, ay, bx, by) in zip(bodies, springs):
        X, Y = point(body, ax, ay, C, S)
        v_spring += k / 2 * ((X - bx) ** 2 + (Y - by) ** 2)
    load_form = _trig_normal_form(v_load, C, S)
    th = sp.symbols(f"theta_1:{N + 1}", real=True)
    if any(t != 1 and t.args[0] not in th for t in load_form):
        raise AssertionError("the loads' energy couples two angles")  # never for a chain under weights
    star = []
    for i in range(N):
        Ci, Di = load_form.get(sp.sin(th[i]), 0), load_form.get(sp.cos(th[i]), 0)
        G = sp.sqrt(Ci ** 2 + Di ** 2)
        star.append((Di / G, Ci / G))
    cs, ss = [c for c, _ in star], [s for _, s in star]
    zero = []
    for body, (_k, ax, ay, bx, by) in zip(bodies, springs):
        X, Y = point(body, ax, ay, cs, ss)
        zero += [X - bx, Y - by]
    balance = {t: c for t, c in _trig_normal_form(v_load + v_spring, C, S).items() if t != 1}
    loads = tuple(v for i in range(N) for v in (W[i], px[i], py[i])) + tuple(ls)
    return ChainConditions(N, tuple(v for sp_ in springs for v in sp_), loads, balance, tuple(zero),
                           tuple(star))


def chain_conditions(N: int) -> ChainConditions:
    """Unknowns and conditions of Singh's chain of ``N`` bodies with minimum preload.

    Parameters
    ----------
    N : int
        Number of moving bodies, >= 1.

    Returns
    -------
    ChainConditions

    Examples
    --------
    >>> c = chain_conditions(2)
    >>> len(c.unknowns), len(c.balance), len(c.zero_length)
    (15, 6, 6)
    """
    return _build(positive_int("N (number of bodies)", N))


def _rational(rng: random.Random, lo: float, hi: float) -> Fraction:
    return Fraction(rng.randint(int(lo * 8), int(hi * 8)), 8)


def chain_solution_point(N: int, seed: int = 0) -> dict:
    """A random exact (rational) solution of every condition of :func:`chain_conditions`.

    Every max-work direction is a rational point of the unit circle; the springs are
    chosen body by body from the tip: on body ``m >= 2`` the first spring and the
    second's stiffness set the other unknowns through ``sum k a = (-l_m T_m, 0)`` and
    ``sum k |a|^2 = G_m - l_m^2 T_m`` (``T_m`` the stiffness beyond body ``m``, ``G_m`` the
    amplitude of body ``m``'s load energy), on body 1 ``k_1 |a_1|^2 = G_1 - l_1^2 T_1``;
    every anchor is its point at the max-work configuration. All stiffnesses are positive.

    Parameters
    ----------
    N : int
        Number of bodies, >= 1.
    seed : int
        Seed of the random choices.

    Returns
    -------
    dict
        sympy symbol -> sympy Rational, loads and unknowns.

    Examples
    --------
    >>> import sympy as sp
    >>> c, p = chain_conditions(2), chain_solution_point(2)
    >>> {sp.simplify(e.xreplace(p)) for e in c.equations()}
    {0}
    """
    import sympy as sp

    cond = chain_conditions(N)
    rng = random.Random(positive_int("seed", seed, minimum=0))
    W = [_rational(rng, 1, 10) for _ in range(N)]
    ls = [_rational(rng, 0.5, 2) for _ in range(N - 1)]
    dirs = []
    for _ in range(N):
        u = Fraction(rng.randint(1, 7), 8)                       # rational point of the circle
        dirs.append(((1 - u * u) / (1 + u * u), 2 * u / (1 + u * u)))
    bodies = _spring_bodies(N)
    k = [Fraction(0)] * len(bodies)
    a = [(Fraction(0), Fraction(0))] * len(bodies)
    px, py = [Fraction(0)] * N, [Fraction(0)] * N
    T = Fraction(0)                                               # stiffness on the bodies beyond
    for m in range(N, 0, -1):
        l_m = ls[m - 1] if m < N else Fraction(0)
        G = l_m ** 2 * T + _rational(rng, 5, 40)                  # amplitude > l_m^2 T: k > 0
        c, s = dirs[m - 1]
        outer = l_m * sum(W[m:], Fraction(0))
        px[m - 1] = (G * s - outer) / W[m - 1]
        py[m - 1] = G * c / W[m - 1]
        R = G - l_m ** 2 * T
        idx = [i for i, b in enumerate(bodies) if b == m]
        aa = (_rational(rng, -2, 2) or Fraction(1), _rational(rng, -2, 2))
        norm = aa[0] ** 2 + aa[1] ** 2
        if len(idx) == 1:
            k[idx[0]], a[idx[0]] = R / norm, aa
        else:
            ka = R / norm * Fraction(rng.randint(2, 6), 8)
            t = (-l_m * T - ka * aa[0], -ka * aa[1])
            kb = (t[0] ** 2 + t[1] ** 2) / (R - ka * norm)
            k[idx[0]], a[idx[0]] = ka, aa
            k[idx[1]], a[idx[1]] = kb, (t[0] / kb, t[1] / kb)
        T += sum(k[i] for i in idx)
    Q = sp.Rational
    values = {}
    for i in range(N):
        values.update(dict(zip(cond.loads[3 * i:3 * i + 3], (Q(W[i]), Q(px[i]), Q(py[i])))))
    values.update(dict(zip(cond.loads[3 * N:], (Q(v) for v in ls))))
    for j_s, body in enumerate(bodies):
        cos_, si = [Q(d[0]) for d in dirs], [Q(d[1]) for d in dirs]
        x, y = Q(a[j_s][0]), Q(a[j_s][1])
        X = sum(Q(ls[j]) * cos_[j] for j in range(body - 1)) + x * cos_[body - 1] - y * si[body - 1]
        Y = sum(Q(ls[j]) * si[j] for j in range(body - 1)) + x * si[body - 1] + y * cos_[body - 1]
        values.update(dict(zip(cond.unknowns[5 * j_s:5 * j_s + 5], (Q(k[j_s]), x, y, X, Y))))
    return values


def design_point(design, exact: bool = False) -> dict:
    """The values of :func:`chain_conditions` ``(2)`` read off a Singh 2R design with three springs.

    Parameters
    ----------
    design : Design
        A 2R of :mod:`balancelab.methods.singh.serial` with the springs ``k1, k2, k3``
        (ground anchor first, point on body 1 or 2 second).
    exact : bool
        Turn every number into the nearest fraction with a denominator up to ``10**6``
        (exact when the design's numbers are such fractions); otherwise sympy Floats.

    Returns
    -------
    dict
        sympy symbol -> value.

    Examples
    --------
    >>> import balancelab as bl
    >>> p = design_point(bl.singh.serial_2r_min_preload(coms=((1.0, 3.0), (2.0, 0.0))), exact=True)
    >>> [str(p[s]) for s in chain_conditions(2).unknowns[:5]]
    ['55/2', '1', '0', '3/5', '4/5']
    """
    instance_of("design", design, Design, "a balancelab Design (a Singh 2R)")
    import sympy as sp

    def num(v):
        return sp.Rational(Fraction(float(v)).limit_denominator(10 ** 6)) if exact else sp.Float(v)

    cond = chain_conditions(2)
    springs = {s.name: s for s in design.springs}
    if sorted(springs) != ["k1", "k2", "k3"] or len(design.loads) != 2:
        raise ValueError(f"design must be a Singh 2R with springs k1, k2, k3 and two loads, got "
                         f"springs {sorted(springs)} and {len(design.loads)} loads")
    values = {}
    for i, load in enumerate(design.loads):
        values.update(dict(zip(cond.loads[3 * i:3 * i + 3], (num(-load.force[1]), *map(num, load.point)))))
    values[cond.loads[6]] = num(design.labels["J"][1][0])
    for s in range(3):
        spring = springs[f"k{s + 1}"]
        if spring.a.body != 0 or spring.b.body != _spring_bodies(2)[s]:
            raise ValueError(f"spring k{s + 1} must run from the ground to body {_spring_bodies(2)[s]}")
        vals = (spring.k, *spring.b.point, *spring.a.point)
        values.update(dict(zip(cond.unknowns[5 * s:5 * s + 5], map(num, vals))))
    return values


def conditions_rank(N: int, values: dict | None = None, seed: int = 0) -> dict:
    """Ranks of the conditions of Singh's chain at an exact solution point.

    Parameters
    ----------
    N : int
        Number of bodies, >= 1.
    values : dict, optional
        An exact (rational) solution, e.g. from :func:`design_point` with ``exact=True``;
        by default :func:`chain_solution_point` ``(N, seed)``.
    seed : int
        Seed of the default solution point.

    Returns
    -------
    dict
        ``unknowns``, ``balance_rank``, ``zero_length_rank``, ``rank`` (of all conditions)
        and ``free = unknowns - rank``.

    Raises
    ------
    ValueError
        If ``values`` does not satisfy every condition exactly.

    Examples
    --------
    >>> conditions_rank(2)
    {'unknowns': 15, 'balance_rank': 6, 'zero_length_rank': 6, 'rank': 10, 'free': 5}
    """
    positive_int("seed", seed, minimum=0)
    cond = chain_conditions(N)
    values = chain_solution_point(N, seed) if values is None else values
    bad = [r for r in cond.residuals(values) if r != 0]
    if bad:
        raise ValueError(f"values must solve every condition exactly; {len(bad)} residuals are not 0, "
                         f"e.g. {bad[0]}")
    ranks = {which: cond.jacobian(values, which).rank() for which in ("balance", "zero_length", "all")}
    n = len(cond.unknowns)
    return {"unknowns": n, "balance_rank": ranks["balance"], "zero_length_rank": ranks["zero_length"],
            "rank": ranks["all"], "free": n - ranks["all"]}
