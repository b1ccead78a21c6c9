"""Symbolic energy and balance conditions of a :class:`~balancelab.core.design.Design`.

The numeric design proves itself by sampling; this module gives the same energy as a
sympy expression in the configuration symbols and reads the balance conditions off its
trigonometric normal form. sympy is imported on first use. Layer: core.
"""
from __future__ import annotations

import numpy as np

__all__ = ["potential_energy_symbolic", "trig_coefficients", "balance_conditions",
           "conditions_residual"]


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


def potential_energy_symbolic(design, parametric: bool = True, split: bool = False):
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


def trig_coefficients(design, parametric: bool = True) -> dict:
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
    key = ("coeffs", parametric)
    if key not in design._sym_cache:
        import sympy as sp

        expr = potential_energy_symbolic(design, parametric)
        syms = design.kinematics.symbols()
        C = sp.symbols(f"C0:{len(syms)}")
        S = sp.symbols(f"S0:{len(syms)}")
        e = sp.expand(sp.expand_trig(sp.expand(expr)))
        e = e.subs({sp.cos(t): c for t, c in zip(syms, C)}).subs({sp.sin(t): s for t, s in zip(syms, S)})
        if any(e.has(t) for t in syms):
            raise ValueError(f"{design.name}: the energy is not a trigonometric polynomial in "
                             f"{syms}; no coefficient form exists")
        gens = list(S) + list(C)
        basis = [s ** 2 + c ** 2 - 1 for s, c in zip(S, C)]
        _, rem = sp.reduced(sp.expand(e), basis, *gens, order="lex")
        poly = sp.Poly(rem, *gens)
        back = {**{c: sp.cos(t) for t, c in zip(syms, C)}, **{s: sp.sin(t) for t, s in zip(syms, S)}}
        out = {}
        for monom, coeff in poly.terms():
            term = sp.Mul(*[g ** p for g, p in zip(gens, monom)]).subs(back)
            out[term] = sp.simplify(coeff) if parametric and design.symbolic is not None else coeff
        design._sym_cache[key] = out
    return dict(design._sym_cache[key])


def balance_conditions(design, parametric: bool = True) -> list:
    """The equations that make the potential energy constant.

    Every coefficient of a non-constant trigonometric term of the energy (see
    :meth:`trig_coefficients`) set to zero. For a closed loop written through its
    joints these conditions are sufficient; they are also necessary for open chains.

    Returns
    -------
    list of sympy.Eq

    Examples
    --------
    >>> import balancelab as bl
    >>> bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3).balance_conditions()
    [Eq(W*l - a_x*b_y*k, 0)]
    """
    import sympy as sp

    eqs = []
    for term, coeff in trig_coefficients(design, parametric).items():
        if term == 1:
            continue
        expr = sp.factor(coeff) if parametric and design.symbolic is not None else coeff
        if sp.sympify(expr).is_zero:
            continue
        eq = sp.Eq(expr, 0, evaluate=False)
        if eq not in eqs:
            eqs.append(eq)
    return eqs


def conditions_residual(design) -> float:
    """Largest balance-condition coefficient of this design's numbers, relative to its scale.

    Substitutes the design's values into :meth:`balance_conditions` (parametric when
    the method has symbols). Near zero (round-off) for a balanced design.

    Returns
    -------
    float
    """
    import sympy as sp

    values = design.symbolic.values if design.symbolic is not None else {}
    worst = 0.0
    for term, coeff in trig_coefficients(design, True).items():
        if term == 1:
            continue
        worst = max(worst, abs(float(sp.sympify(coeff).subs(values).evalf())))
    return worst / design.balance_report(n=200).scale
