"""Symbolic energy and balance conditions of a :class:`~balancelab.core.design.Design`.

The numeric design proves itself by sampling; this module gives the same energy as a
sympy expression in the configuration symbols and reads the balance conditions off its
trigonometric normal form. sympy is imported on first use. Layer: core.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, cast

import numpy as np

if TYPE_CHECKING:
    from .design import Design
    from .kinematics import Kinematics

__all__ = ["potential_energy_symbolic", "trig_coefficients", "symbols_are_independent",
           "constrained_coefficients", "balance_conditions", "conditions_residual", "SymbolicMethods"]


def _symbolic_parts(design, parametric: bool):
    import sympy as sp

    if parametric and design.symbolic is not None:
        return design.symbolic.loads, design.symbolic.springs
    f = sp.Float
    loads = [(ld.body, tuple(f(v) for v in ld.point), tuple(f(v) for v in ld.force))
             for ld in design.loads]
    springs = [(f(s.k), f(s.free_length), (s.a.body, tuple(f(v) for v in s.a.point)),
                (s.b.body, tuple(f(v) for v in s.b.point))) for s in design.springs]
    return loads, springs


def potential_energy_symbolic(design: Design, parametric: bool = True, split: bool = False) -> Any:
    """The potential energy as a sympy expression in the configuration angles.

    Parameters
    ----------
    parametric : bool
        Use the method's symbolic design parameters (when it has them, see
        ``design.symbolic.values``); otherwise the numbers of this design.
    split : bool
        Return ``(load part, spring part)`` instead of their sum.

    Returns
    -------
    sympy.Expr or tuple of sympy.Expr

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
    >>> d.potential_energy_symbolic()
    W*l*sin(theta) + k*(a_x**2*cos(theta)**2 + (a_x*sin(theta) - b_y)**2)/2
    """
    key = ("pe", parametric)
    if key not in design._sym_cache:
        import sympy as sp

        kin = design.kinematics
        if parametric and design.symbolic is not None and design.symbolic.kinematics is not None:
            kin = design.symbolic.kinematics
        if any(s.cable is not None for s in design.springs):
            raise NotImplementedError(f"{design.name}: a spring's length runs along a cable over a profile "
                                      "(a CablePath), which has no symbolic form; check the design "
                                      "numerically with balance_report()")
        syms = kin.symbols()
        loads, springs = _symbolic_parts(design, parametric)
        point = kin.symbolic_point
        vl = sp.S.Zero
        for body, p, force in loads:
            x, y = point(body, p, syms)
            vl += -(force[0] * x + force[1] * y)
        vs = sp.S.Zero
        for k, l0, (ba, pa), (bb, pb) in springs:
            ax, ay = point(ba, pa, syms)
            bx, by = point(bb, pb, syms)
            d2 = (bx - ax) ** 2 + (by - ay) ** 2
            if sp.sympify(l0).is_zero:
                vs += k / 2 * d2
            else:
                length = sp.powdenest(sp.sqrt(sp.factor(sp.trigsimp(sp.expand(d2)))), force=True)
                length = length.replace(sp.Abs, lambda x: x)
                _check_symbolic_length(design, syms, length, ((ba, pa), (bb, pb)), parametric)
                vs += k / 2 * (length - l0) ** 2
        design._sym_cache[key] = (vl, vs)
    vl, vs = design._sym_cache[key]
    return (vl, vs) if split else vl + vs


def _check_symbolic_length(design, syms, length, ends, parametric) -> None:
    """A finite-free-length spring's symbolic length must match the numeric one."""
    import sympy as sp

    q = design.sample(3, seed=1)
    values = dict(design.symbolic.values) if (parametric and design.symbolic is not None) else {}
    for qi in q:
        sub = dict(values)
        sub.update(dict(zip(syms, design.kinematics.symbol_values(qi))))
        num = float(sp.sympify(length).subs(sub).evalf())
        pts = []
        for body, p in ends:
            pp = tuple(float(sp.sympify(v).subs(values)) for v in p)
            pts.append(design.world_points(qi, [(body, pp)])[0])
        ref = float(np.hypot(*(pts[1] - pts[0])))
        if not np.isclose(num, ref, rtol=1e-9, atol=1e-12):
            raise NotImplementedError(
                f"{design.name}: a finite-free-length spring's length is not a polynomial in the "
                "sines and cosines of the coordinates; no symbolic energy is available")


def _trig_polynomial(design, expr, syms):
    """``expr`` as a polynomial in ``S_i = sin(q_i)``, ``C_i = cos(q_i)``: ``(poly expr, S, C)``."""
    import sympy as sp

    C = sp.symbols(f"C0:{len(syms)}")
    S = sp.symbols(f"S0:{len(syms)}")
    e = sp.expand(sp.expand_trig(sp.expand(expr)))
    e = e.subs({sp.cos(t): c for t, c in zip(syms, C)}).subs({sp.sin(t): s for t, s in zip(syms, S)})
    if any(e.has(t) for t in syms) or not e.is_polynomial(*S, *C):
        raise NotImplementedError(
            f"{design.name}: the energy is not a polynomial in the sines and cosines of {syms} (a "
            "finite-free-length spring's length is a square root), so no balance conditions can be "
            "read off its coefficients; check the design numerically with balance_report()")
    return sp.expand(e), S, C


def _coefficient_dict(poly, gens, syms, S, C, simplify: bool) -> dict:
    import sympy as sp

    back = {**{c: sp.cos(t) for t, c in zip(syms, C)}, **{s: sp.sin(t) for t, s in zip(syms, S)}}
    out = {}
    for monom, coeff in poly.terms():
        term = sp.Mul(*[g ** p for g, p in zip(gens, monom)]).subs(back)
        out[term] = sp.simplify(coeff) if simplify else coeff
    return out


def trig_coefficients(design: Design, parametric: bool = True) -> dict:
    """Coefficients of the potential energy in a unique trigonometric form.

    The energy is expanded into a polynomial in ``cos(q_i)`` and ``sin(q_i)`` and
    reduced with ``sin^2 = 1 - cos^2``; in that normal form it is constant exactly when
    every coefficient other than the constant term vanishes.

    Returns
    -------
    dict
        Maps each trigonometric monomial (a sympy expression, ``1`` for the constant)
        to its coefficient.

    Raises
    ------
    NotImplementedError
        If the energy is not a polynomial in the sines and cosines (a finite-free-length
        spring whose length is a square root).

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
    >>> sorted(map(str, trig_coefficients(d)))
    ['1', 'sin(theta)']
    """
    key = ("coeffs", parametric)
    if key not in design._sym_cache:
        import sympy as sp

        syms = design.kinematics.symbols()
        e, S, C = _trig_polynomial(design, potential_energy_symbolic(design, parametric), syms)
        gens = list(S) + list(C)
        basis = [s ** 2 + c ** 2 - 1 for s, c in zip(S, C)]
        _, rem = sp.reduced(e, basis, *gens, order="lex")
        poly = sp.Poly(rem, *gens)
        design._sym_cache[key] = _coefficient_dict(poly, gens, syms, S, C,
                                                   parametric and design.symbolic is not None)
    return dict(design._sym_cache[key])


def symbols_are_independent(kinematics: Kinematics) -> bool:
    """Whether the sympy symbols of ``kinematics`` are independent coordinates.

    True when the kinematics says so (its ``independent_symbols``: the relaxed
    Peaucellier model, a relaxed four-bar), and otherwise when there are as many symbols
    as degrees of freedom. A closed loop written in more symbols than it has degrees of
    freedom (the ``"loop"`` four-bar: crank and rocker angles) is not: its symbols are
    tied by the loop-closure equation.

    Examples
    --------
    >>> import balancelab as bl
    >>> symbols_are_independent(bl.FourBarKinematics((0, 0), (0.4, 0), 0.1, 0.35, 0.3))
    False
    >>> symbols_are_independent(bl.FourBarKinematics((0, 0), (0.4, 0), 0.1, 0.35, 0.3, symbolic="relaxed"))
    True
    """
    flag = getattr(kinematics, "independent_symbols", None)
    if flag is not None:
        return bool(flag)
    return len(kinematics.symbols()) == kinematics.dof


def _constraints(design, syms, S, C) -> list:
    """Polynomials in ``S, C`` that vanish in every pose: rigidity of each body between its
    joint points and the closure of each joint, as written by the symbolic kinematics."""
    import itertools

    import sympy as sp

    kin = design.kinematics
    out = []
    for j in design.joints:
        p, q = kin.symbolic_point(j[0], j[1], syms), kin.symbolic_point(j[2], j[3], syms)
        out += [p[0] - q[0], p[1] - q[1]]
    for body in range(1, kin.nbodies):
        pts = {tuple(j[1]) for j in design.joints if j[0] == body} | {tuple(j[3]) for j in design.joints
                                                                      if j[2] == body}
        for u, v in itertools.combinations(sorted(pts), 2):
            pu, pv = kin.symbolic_point(body, u, syms), kin.symbolic_point(body, v, syms)
            r2 = (u[0] - v[0]) ** 2 + (u[1] - v[1]) ** 2
            out.append((pu[0] - pv[0]) ** 2 + (pu[1] - pv[1]) ** 2 - r2)
    circles = [s ** 2 + c ** 2 - 1 for s, c in zip(S, C)]
    gens = list(S) + list(C)
    polys = []
    for c in out:
        e, _, _ = _trig_polynomial(design, sp.sympify(c), syms)
        e = sp.nsimplify(e, rational=True)
        if sp.reduced(e, circles, *gens, order="grevlex")[1] != 0:
            polys.append(e)
    return circles + polys


def _standard_monomials(G, gens, degree: int) -> list:
    """Monomials of total degree <= ``degree`` not divisible by a leading monomial of ``G``."""
    import itertools

    import sympy as sp

    leads = [sp.Poly(g, *gens).monoms(order="grevlex")[0] for g in G.exprs]
    out = []
    for monom in itertools.product(range(degree + 1), repeat=len(gens)):
        if sum(monom) <= degree and not any(all(m >= l for m, l in zip(monom, lead)) for lead in leads):
            out.append(monom)
    return out


def _check_necessary(design, G, gens, degree: int) -> None:
    """Refuse unless no nonzero normal form of degree <= ``degree`` vanishes on the design's
    reachable configurations (then a constant energy forces every condition)."""
    kin = design.kinematics
    monoms = _standard_monomials(G, gens, degree)
    q = design.sample(max(400, 4 * len(monoms)), seed=1)
    ang = np.asarray(kin.symbol_values(q), dtype=float).reshape(len(q), -1)
    vals = np.concatenate([np.sin(ang), np.cos(ang)], axis=1)
    M = np.stack([np.prod(vals ** np.array(m), axis=1) for m in monoms], axis=1)
    sv = np.linalg.svd(M, compute_uv=False)
    if sv[-1] < 1e-9 * sv[0]:
        raise NotImplementedError(
            f"{design.name}: the symbols {kin.symbols()} are not independent coordinates and their "
            "loop-closure equations do not describe this linkage's motion alone (a reducible or "
            "degenerate loop); exact balance conditions cannot be derived in these symbols. Check "
            "the design numerically with balance_report()")


def constrained_coefficients(design: Design, parametric: bool = True) -> dict:
    """Coefficients of the energy reduced modulo the linkage's own closure equations.

    For kinematics whose symbols are tied (a ``"loop"`` four-bar: crank and rocker
    angles), the energy is reduced to its normal form modulo a Groebner basis of the
    circle identities and the closure polynomials (each body rigid between its joint
    points, each joint closed). The energy is constant on the motion exactly when every
    non-constant coefficient of that normal form vanishes; this is checked to be a
    necessary condition on the design's reachable configurations.

    Raises
    ------
    NotImplementedError
        If the conditions would not be necessary (degenerate loop), the symbolic
        kinematics has symbolic link lengths, or the energy is not a trigonometric
        polynomial.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lecture.fourbar_counterweights()
    >>> max(abs(float(c)) for t, c in constrained_coefficients(d, False).items() if t != 1) < 1e-9
    True
    """
    key = ("ccoeffs", parametric)
    if key not in design._sym_cache:
        import sympy as sp

        if parametric and design.symbolic is not None and design.symbolic.kinematics is not None:
            raise NotImplementedError(
                f"{design.name}: closure equations with symbolic link lengths are not supported; use "
                "balance_conditions(parametric=False) or balance_report()")
        syms = design.kinematics.symbols()
        e, S, C = _trig_polynomial(design, potential_energy_symbolic(design, parametric), syms)
        gens = list(S) + list(C)
        G = sp.groebner(_constraints(design, syms, S, C), *gens, order="grevlex")
        _check_necessary(design, G, gens, max(sp.Poly(e, *gens).total_degree(), 1))
        _, rem = sp.reduced(e, list(G.exprs), *gens, order="grevlex")
        design._sym_cache[key] = _coefficient_dict(sp.Poly(rem, *gens), gens, syms, S, C,
                                                   parametric and design.symbolic is not None)
    return dict(design._sym_cache[key])


def _condition_coefficients(design, parametric: bool) -> dict:
    if symbols_are_independent(design.kinematics):
        return trig_coefficients(design, parametric)
    return constrained_coefficients(design, parametric)


def balance_conditions(design: Design, parametric: bool = True) -> list:
    """The equations that make the potential energy constant.

    Every coefficient of a non-constant trigonometric term of the energy set to zero:
    of :func:`trig_coefficients` when the symbols are independent coordinates (open
    chains; relaxed models, whose conditions are those of the relaxed linkage and so
    sufficient for the real one), of :func:`constrained_coefficients` (the energy
    reduced modulo the loop-closure equations) otherwise. Either way a balanced design
    satisfies them.

    Returns
    -------
    list of sympy.Eq

    Raises
    ------
    NotImplementedError
        When no exact conditions can be derived (see :func:`constrained_coefficients`,
        :func:`trig_coefficients`); ``balance_report()`` still checks the design.

    Examples
    --------
    >>> import balancelab as bl
    >>> bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3).balance_conditions()
    [Eq(W*l - a_x*b_y*k, 0)]
    """
    import sympy as sp

    eqs = []
    for term, coeff in _condition_coefficients(design, parametric).items():
        if term == 1:
            continue
        expr = sp.factor(coeff) if parametric and design.symbolic is not None else coeff
        if sp.sympify(expr).is_zero:
            continue
        eq = sp.Eq(expr, 0, evaluate=False)
        if eq not in eqs:
            eqs.append(eq)
    return eqs


def conditions_residual(design: Design) -> float:
    """Largest balance-condition coefficient of this design's numbers, relative to its scale.

    Substitutes the design's values into :func:`balance_conditions` (parametric when
    the method has symbols). Near zero (round-off) for a balanced design.

    Returns
    -------
    float

    Raises
    ------
    NotImplementedError
        As :func:`balance_conditions`.

    Examples
    --------
    >>> import balancelab as bl
    >>> conditions_residual(bl.catalog()["deepak_watt_prototype"]()) < 1e-9
    True
    """
    import sympy as sp

    values = design.symbolic.values if design.symbolic is not None else {}
    worst = 0.0
    for term, coeff in _condition_coefficients(design, True).items():
        if term == 1:
            continue
        worst = max(worst, abs(float(sp.sympify(coeff).subs(values).evalf())))
    return worst / design.balance_report(n=200).scale


class SymbolicMethods:
    """The symbolic side of :class:`~balancelab.Design`: its energy as a sympy expression and its
    balance conditions (a base class of ``Design``; every method reads only the design's fields)."""

    def potential_energy_symbolic(self, parametric: bool = True, split: bool = False) -> Any:
        """The potential energy as a sympy expression in the configuration angles.

        Parameters
        ----------
        parametric : bool
            Use the method's symbolic design parameters (when it has them, see
            ``design.symbolic.values``); otherwise the numbers of this design.
        split : bool
            Return ``(load part, spring part)`` instead of their sum.

        Returns
        -------
        sympy.Expr or tuple of sympy.Expr

        Examples
        --------
        >>> import balancelab as bl
        >>> d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
        >>> d.potential_energy_symbolic()
        W*l*sin(theta) + k*(a_x**2*cos(theta)**2 + (a_x*sin(theta) - b_y)**2)/2
        """
        return potential_energy_symbolic(cast("Design", self), parametric, split)

    def trig_coefficients(self, parametric: bool = True) -> dict:
        """Coefficients of the potential energy in a unique trigonometric form.

        The energy is expanded into a polynomial in ``cos(q_i)`` and ``sin(q_i)`` and
        reduced with ``sin^2 = 1 - cos^2``; in that normal form it is constant exactly when
        every coefficient other than the constant term vanishes.

        Returns
        -------
        dict
            Maps each trigonometric monomial (a sympy expression, ``1`` for the constant)
            to its coefficient.
        """
        return trig_coefficients(cast("Design", self), parametric)

    def balance_conditions(self, parametric: bool = True) -> list:
        """The equations that make the potential energy constant.

        Every coefficient of a non-constant trigonometric term of the energy (see
        :meth:`trig_coefficients`) set to zero: exact for independent coordinates; for a
        loop whose symbols are tied, the energy is first reduced by the closure equations.
        Raises ``NotImplementedError`` where no exact conditions exist (use
        :meth:`balance_report`).

        Returns
        -------
        list of sympy.Eq

        Examples
        --------
        >>> import balancelab as bl
        >>> bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3).balance_conditions()
        [Eq(W*l - a_x*b_y*k, 0)]
        """
        return balance_conditions(cast("Design", self), parametric)

    def conditions_residual(self) -> float:
        """Largest balance-condition coefficient of this design's numbers, relative to its scale.

        Substitutes the design's values into :meth:`balance_conditions` (parametric when
        the method has symbols). Near zero (round-off) for a balanced design.

        Returns
        -------
        float
        """
        return conditions_residual(cast("Design", self))
