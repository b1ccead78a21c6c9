"""Solving the balance conditions for a chosen set of unknown parameters.

The conditions (:func:`constraint_equations`) are solved once per ``(n, topology,
unknowns)`` with sympy, symbolically in every other parameter, block by block, and the
solution is kept as a small program of lambdified assignments (cached); :func:`solve`
then only evaluates it with the numbers, checks the residuals and keeps the physically
admissible branch. :func:`synthesize` returns the balanced :class:`balancelab.Design`.
"""
from __future__ import annotations

import functools
import math
from typing import Mapping, Sequence

from ...core.design import Design
from ...core.elements import G
from ...core.errors import InfeasibleDesign, SingularChoice
from ...core.validation import finite_real
from .chain import SerialChain, chain_parameter_names, check_topology
from .conditions import condition_system

__all__ = ["InfeasibleDesign", "SingularChoice", "SolutionFamily", "solve", "solve_family", "solve_symbolic",
           "synthesize"]


class SolutionFamily:
    """A family of solutions of the balance conditions: some unknowns stay free.

    Attributes
    ----------
    unknowns : tuple of str
        The unknowns solved for.
    free : tuple of str
        The unknowns the conditions leave free (the family's parameters).
    expressions : dict of str to sympy expression
        Every unknown in the free ones (a free unknown maps to its own symbol), with the
        known values substituted (exact rationals of the given floats).

    Examples
    --------
    >>> from balancelab.methods.lustig import LUSTIG_TOPOLOGY, lustig_values
    >>> unknowns = ("k1", "ax1", "ay1", "bx1", "by1", "k2")
    >>> v = {k: x for k, x in lustig_values(1).items() if k not in unknowns}
    >>> family = solve_family(2, LUSTIG_TOPOLOGY, v, unknowns)[0]
    >>> family.free
    ('k1',)
    >>> round(family(k1=300.0)["ay1"], 6), round(family(k1=300.0)["bx1"], 4)
    (0.0872, 0.1125)
    """

    def __init__(self, unknowns: tuple, free: tuple, expressions: dict) -> None:
        self.unknowns = tuple(unknowns)
        self.free = tuple(free)
        self.expressions = dict(expressions)

    def symbols(self) -> tuple:
        """The free unknowns as the sympy symbols of :attr:`expressions`, in :attr:`free` order."""
        return tuple(self.expressions[f] for f in self.free)

    def __call__(self, **free_values: float) -> dict:
        """The member of the family with the given values of the free unknowns (floats).

        Not checked for admissibility: a member may need a negative stiffness.
        """
        import sympy as sp

        missing = [f for f in self.free if f not in free_values]
        extra = [k for k in free_values if k not in self.free]
        if missing or extra:
            raise ValueError(f"give exactly the free unknowns {list(self.free)}; missing {missing}, "
                             f"not free {extra}")
        subs = {sym: finite_real(name, free_values[name]) for sym, name in zip(self.symbols(), self.free)}
        out = {}
        for name in self.unknowns:
            value = complex(sp.sympify(sp.sympify(self.expressions[name]).xreplace(subs)).evalf(17))
            if abs(value.imag) > 1e-9 * max(1.0, abs(value.real)):
                raise ValueError(f"{name} is complex for these values of {list(self.free)}")
            out[name] = value.real
        return out

    def __repr__(self) -> str:
        return f"SolutionFamily(free={self.free}, expressions={self.expressions})"


_POSITIVE_PREFIX = ("k", "m", "L")


def _is_positive_name(name: str) -> bool:
    return name[0] in _POSITIVE_PREFIX and name[1:].isdigit()


class _Program:
    """One solution branch as a sequence of small assignments, evaluated in order.

    ``steps`` is a tuple of ``(targets, exprs, args, fn)``: the unknown names a block
    solves for, their sympy expressions in the known parameters *and the unknowns
    solved by earlier steps* (no substitution, so nothing swells), the names ``fn``
    takes and ``fn`` itself (lambdified with ``math``). ``free`` lists the unknowns no
    step determines.
    """

    def __init__(self, steps, free):
        self.steps = tuple(steps)
        self.free = tuple(free)

    def __call__(self, known: dict) -> dict:
        env = dict(known)
        pending = list(range(len(self.steps)))
        while pending:
            ready = [i for i in pending if all(a in env for a in self.steps[i][2])]
            if not ready:
                raise ValueError("singular choice of unknowns: the solution steps depend on each "
                                 "other in a cycle (some unknowns are not determined)")
            for i in ready:
                targets, _, args, fn = self.steps[i]
                env.update(zip(targets, fn(*[env[a] for a in args])))
            pending = [i for i in pending if i not in ready]
        return env

    def expressions(self) -> dict:
        """Closed-form expression of every solved unknown in the known parameters."""
        import sympy as sp

        sub: dict = {}
        for targets, exprs, _, _ in self.steps:
            for t, e in zip(targets, exprs):
                sub[sp.Symbol(t, real=True)] = e
        for _ in range(len(self.steps) + 1):
            new = {k: v.xreplace(sub) for k, v in sub.items()}
            if new == sub:
                break
            sub = new
        return {str(k): v for k, v in sub.items()}


# ------------------------------------------------------------------ symbolic solution
@functools.lru_cache(maxsize=128)
def _symbolic_solution(n: int, topology: tuple, unknowns: tuple) -> tuple:
    """Generic symbolic solution branches of the constraints for ``unknowns`` (cached)."""
    syms, eqs = condition_system(n, topology)
    exprs = [e.lhs for e in eqs.values()]
    unk = [syms[u] for u in unknowns]
    return tuple(_block_solve(exprs, unk))


def _next_block(has: list, whole: bool) -> list:
    """Indices of the equations to solve next: one with a single unknown, else a pair of
    equations (a rotation-scale block) in the same two unknowns, else all of them."""
    if whole:
        return list(range(len(has)))
    for i, h in enumerate(has):
        if len(h) == 1:
            return [i]
    for h in has:
        if len(h) == 2:
            js = [j for j, h2 in enumerate(has) if h2 <= h]
            if len(js) >= 2:
                return js
    return list(range(len(has)))


def _block_solve(exprs, unk, steps=(), whole: bool = False) -> list:
    """Solve polynomial equations for ``unk`` block by block with sympy, every branch.

    The balance conditions are nearly triangular: an equation often contains a single
    unknown, or two equations (one rotation-scale block) share the same two. Solving
    such small blocks first, then treating their unknowns as known, is far faster than
    one ``sympy.solve`` on the whole system; whatever is left over is handed to
    ``sympy.solve`` in one piece. Equations the remaining unknowns do not enter only
    restrict the known values; the caller checks them with the numbers.

    Returns
    -------
    list of _Program
    """
    import sympy as sp

    unkset = set(unk)
    live = [e for e in exprs if e.free_symbols & unkset]
    if not unk or not live:
        return [_Program(steps, [str(u) for u in unk])]
    has = [e.free_symbols & unkset for e in live]
    block = _next_block(has, whole)
    bunk = sorted(set().union(*(has[i] for i in block)), key=str)
    sols = sp.solve([live[i] for i in block], bunk, dict=True, simplify=False, rational=False)
    rest = [live[i] for i in range(len(live)) if i not in block]
    out = []
    for sol in sols:
        solved = [u for u in bunk if u in sol and not (sol[u].free_symbols & set(bunk))]
        if not solved:
            if len(block) < len(live):  # a degenerate small block: solve everything at once
                return _block_solve(live, unk, steps, whole=True)
            # the conditions leave some unknowns free: infinitely many solutions
            out.append(_Program(steps, [str(u) for u in bunk if u not in sol] or
                                [str(u) for u in bunk]))
            continue
        targets = tuple(str(u) for u in solved)
        texprs = tuple(sol[u] for u in solved)
        args = tuple(sorted({str(a) for e in texprs for a in e.free_symbols}))
        fn = sp.lambdify([sp.Symbol(a, real=True) for a in args], list(texprs), modules="math")
        remaining = [u for u in unk if u not in solved]
        # the block's own equations may still tie unsolved block unknowns together
        again = [live[i] for i in block] if len(solved) < len(bunk) else []
        out += _block_solve(rest + again, remaining, steps + ((targets, texprs, args, fn),))
    return out


def _exact_solutions(n, topology, known_values: dict, unknowns: tuple) -> list:
    """Every solution branch with the known numbers substituted as exact rationals.

    ``sympy.solve`` on rationals (floats make it slow and miss degenerate branches);
    a branch that leaves unknowns free is a family. Returns ``(free, {name: expr})`` pairs.
    """
    import sympy as sp

    syms, eqs = condition_system(n, topology)
    subs = {syms[k]: sp.Rational(repr(float(v))) for k, v in known_values.items()}
    exprs = [e for e in (sp.expand(e.lhs.xreplace(subs)) for e in eqs.values()) if e != 0]
    unk = [syms[u] for u in unknowns]
    if not exprs:
        return [(tuple(unknowns), {u: syms[u] for u in unknowns})]
    out = []
    for sol in sp.solve(exprs, unk, dict=True):
        free = tuple(u for u in unknowns if syms[u] not in sol)
        out.append((free, {u: sol.get(syms[u], syms[u]) for u in unknowns}))
    return out


def solve_symbolic(n: int, topology, unknowns: Sequence[str], *, simplify: bool = True) -> list:
    """Closed-form solutions of the balance conditions for ``unknowns`` (sympy).

    The same generic solution that :func:`solve` evaluates (cached), written out in
    the remaining parameters. Equations the unknowns do not enter are not included;
    they are conditions on the other parameters.

    Parameters
    ----------
    n : int
        Number of moving links.
    topology : sequence of (int, int)
        ``(proximal body, distal body)`` of each spring.
    unknowns : sequence of str
        Parameters to solve for.
    simplify : bool
        Bring every expression to a factored rational form (``sympy.factor`` of
        ``sympy.cancel``); can be slow for long chains.

    Returns
    -------
    list of dict
        One dict per solution branch, ``{name: sympy expression}``.

    Examples
    --------
    >>> sol = solve_symbolic(2, ((0, 2), (1, 2)), ("ax1", "ay1"))[0]
    >>> sol["ax1"]
    g*m2*sy2/(L2*k1)
    """
    if unknowns is None or isinstance(unknowns, (str, bytes, dict)) or not hasattr(unknowns, "__iter__"):
        raise TypeError(f"unknowns must be a sequence of parameter names, got {unknowns!r}")
    n, topology = check_topology(n, topology)
    names = chain_parameter_names(n, topology)
    unknowns = tuple(unknowns)
    bad = [u for u in unknowns if u not in names]
    if bad:
        raise ValueError(f"unknowns {bad} are not parameters of this chain; valid names: {names}")
    out = [p.expressions() for p in _symbolic_solution(n, topology, unknowns)]
    if simplify:
        import sympy as sp

        out = [{k: sp.factor(sp.cancel(v)) for k, v in sol.items()} for sol in out]
    return out


# ------------------------------------------------------------------- numeric solution
def _checked_unknowns(names: tuple, unknowns) -> tuple:
    if isinstance(unknowns, str):
        unknowns = (unknowns,)
    if unknowns is None or isinstance(unknowns, (bytes, dict)) or not hasattr(unknowns, "__iter__"):
        raise TypeError(f"unknowns must be a sequence of parameter names, got {unknowns!r}")
    unknowns = tuple(unknowns)
    if not unknowns:
        raise ValueError("unknowns is empty: name the parameters to solve for")
    bad = [u for u in unknowns if u not in names]
    if bad:
        raise ValueError(f"unknowns {bad} are not parameters of this chain; valid names: {names}")
    if len(set(unknowns)) != len(unknowns):
        raise ValueError(f"unknowns has repeated names: {unknowns}")
    return unknowns


def _known_values(names: tuple, values: Mapping[str, float], unknowns: tuple) -> dict:
    """Every parameter that is not an unknown, checked (``g`` defaults to 9.81 m/s^2)."""
    if not isinstance(values, Mapping):
        raise TypeError(f"values must be a mapping of parameter names to numbers, got {values!r}"[:300])
    extra = [k for k in values if k not in names]
    if extra:
        raise ValueError(f"values has entries {extra} that are not parameters of this chain; "
                         f"valid names: {names}")
    known = {}
    for k in names:
        if k in unknowns:
            continue
        if k == "g" and k not in values:
            known[k] = G
            continue
        if k not in values:
            missing = [m for m in names if m not in unknowns and m not in values and m != "g"]
            raise ValueError(f"values is missing {missing} (every parameter that is not an unknown "
                             "needs a number)")
        known[k] = finite_real(f"values[{k!r}]", values[k], positive=_is_positive_name(k) or k == "g")
    return known


def _check_determinable(n: int, topology: tuple, unknowns: tuple) -> None:
    """Every unknown enters a condition, and there are no more unknowns than conditions."""
    syms, eqs = condition_system(n, topology)
    used = set().union(*(e.lhs.free_symbols for e in eqs.values()))
    absent = [u for u in unknowns if syms[u] not in used]
    if absent:
        raise ValueError(f"unknowns {absent} do not enter any balance condition of this chain, so "
                         "the conditions cannot determine them")
    if len(unknowns) > len(eqs):
        raise ValueError(f"{len(unknowns)} unknowns but only {len(eqs)} balance conditions: the "
                         "choice is singular (underdetermined); fix some of them")


def _evaluate(programs, known: dict, unknowns: tuple) -> tuple[list, bool, tuple | None]:
    """Evaluate every solution branch with the numbers.

    Returns the candidate solutions (complex), whether a branch failed numerically (a
    vanishing denominator of the generic solution) and the unknowns a branch left free.
    """
    candidates, failed, singular = [], False, None
    for prog in programs:
        if prog.free:
            singular = prog.free
            continue
        try:
            env = prog(known)
        except (ZeroDivisionError, OverflowError, TypeError):
            failed = True  # the generic solution divides by zero for these numbers
            continue
        except ValueError as err:
            if "singular" in str(err):
                singular = unknowns
                continue
            failed = True
            continue
        candidates.append({u: complex(env[u]) for u in unknowns})
    return candidates, failed, singular


def _candidate_solutions(n: int, topology: tuple, known: dict, unknowns: tuple) -> list:
    """The generic solution evaluated with the numbers; where it fails, or leaves unknowns
    free, the system solved again exactly with the numbers substituted."""
    candidates, failed, singular = _evaluate(_symbolic_solution(n, topology, unknowns), known,
                                             unknowns)
    families = []
    if not candidates:   # generic solution fails, is empty or leaves unknowns free for these numbers
        for free, sol in _exact_solutions(n, topology, known, unknowns):
            if free:
                families.append(SolutionFamily(unknowns, free, sol))
            else:
                candidates.append({u: complex(sol[u].evalf(17)) for u in unknowns})
    if not candidates and (families or singular):
        free = sorted({f for fam in families for f in fam.free}) or list(singular or ())
        raise SingularChoice(f"singular choice of unknowns: the balance conditions leave {free} free "
                             f"(a {len(free)}-parameter family of solutions, in the error's "
                             "`families` and from solve_family); choose fewer or other unknowns",
                             families)
    if not candidates:
        raise ValueError(f"the balance conditions have no solution for the unknowns {list(unknowns)} "
                         "with these values (the system is overdetermined or inconsistent)")
    return candidates


def _real_solutions(candidates: list, unknowns: tuple) -> list:
    real = []
    for c in candidates:
        scale = max(1.0, *(abs(v) for v in c.values()))
        if all(abs(v.imag) <= 1e-9 * scale for v in c.values()):
            real.append({k: v.real for k, v in c.items()})
    if not real:
        raise ValueError(f"the balance conditions have only complex solutions for {list(unknowns)}")
    return real


@functools.lru_cache(maxsize=64)
def _constraint_function(n: int, topology: tuple):
    """Lambdified constraint entries: f(*values in chain_parameter_names order) -> list."""
    import sympy as sp

    syms, eqs = condition_system(n, topology)
    names = chain_parameter_names(n, topology)
    return sp.lambdify([syms[k] for k in names], [e.lhs for e in eqs.values()], modules="math")


def _numeric_residual(n: int, topology: tuple, allv: dict, names: tuple) -> float:
    """Largest constraint entry divided by a gravity moment scale (dimensionless)."""
    vals = _constraint_function(n, topology)(*[allv[k] for k in names])
    g = allv["g"]
    scale = g * sum(allv[f"m{u}"] * (math.hypot(allv[f"sx{u}"], allv[f"sy{u}"]) + allv[f"L{u}"])
                    for u in range(2, n + 2))
    return max(abs(v) for v in vals) / scale


def _admissible_solution(checked: list, unknowns: tuple) -> dict:
    """The one solution with positive stiffnesses, masses and lengths."""
    feasible = [r for r in checked if all(r[k] > 0 for k in r if _is_positive_name(k))]
    if not feasible:
        bad = {k: v for k, v in checked[0].items() if _is_positive_name(k) and v <= 0}
        raise InfeasibleDesign(f"the only solutions need non-positive {bad}: a negative stiffness, "
                               "mass or length cannot be built")
    unique: list[dict] = []
    for r in feasible:
        if not any(all(math.isclose(r[k], u[k], rel_tol=1e-9, abs_tol=1e-12) for k in r) for u in unique):
            unique.append(r)
    if len(unique) > 1:
        raise ValueError(f"the balance conditions have {len(unique)} admissible solutions for "
                         f"{list(unknowns)}: {unique}; fix more parameters to pick one")
    return unique[0]


def solve(n: int, topology, values: Mapping[str, float], unknowns: Sequence[str], *,
          tol: float = 1e-9) -> dict:
    """Solve the balance conditions of a chain for a chosen set of unknown parameters.

    The ``N (N - 1)`` constraint equations (:func:`constraint_equations`) are solved
    with ``sympy.solve`` for ``unknowns``, symbolically in all the other parameters
    (cached per ``(n, topology, unknowns)``, so later calls only evaluate the cached
    solution), then the known ``values`` are substituted. When the generic solution
    does not apply to the given numbers (a vanishing denominator) the system is solved
    again with the numbers substituted.

    Parameters
    ----------
    n : int
        Number of moving links.
    topology : sequence of (int, int)
        ``(proximal body, distal body)`` of each spring (0 is the ground).
    values : mapping of str to float
        Numbers of every other parameter, by the names of
        :func:`chain_parameter_names` (m, kg, N/m); ``g`` defaults to 9.81 m/s^2.
        Entries for the unknowns themselves are ignored.
    unknowns : sequence of str
        Parameters to solve for.
    tol : float
        Relative tolerance on the constraint residuals of the solution.

    Returns
    -------
    dict of str to float
        The value of every unknown.

    Raises
    ------
    ValueError
        Unknown names, missing values, an unknown that does not enter any condition,
        more unknowns than conditions, or no solution / several admissible solutions.
    SingularChoice
        A ``ValueError``: the conditions leave some unknowns free; its ``families``
        (and :func:`solve_family`) give the free unknowns and the parametrized solution.
    InfeasibleDesign
        If every real solution needs a negative stiffness (or a non-positive mass or
        length).

    Examples
    --------
    >>> from balancelab.methods.lustig import LUSTIG_TOPOLOGY, LUSTIG_UNKNOWNS, lustig_values
    >>> v = {k: x for k, x in lustig_values(1).items() if k not in LUSTIG_UNKNOWNS}
    >>> sol = solve(2, LUSTIG_TOPOLOGY, v, LUSTIG_UNKNOWNS)
    >>> round(sol["bx1"], 4), round(sol["bx2"], 4)
    (0.1125, -0.0981)
    """
    n, topology = check_topology(n, topology)
    tol = finite_real("tol", tol, positive=True)
    if tol >= 1:
        raise ValueError(f"tol must be a relative tolerance in (0, 1), got {tol}")
    names = chain_parameter_names(n, topology)
    unknowns = _checked_unknowns(names, unknowns)
    known = _known_values(names, values, unknowns)
    _check_determinable(n, topology, unknowns)
    real = _real_solutions(_candidate_solutions(n, topology, known, unknowns), unknowns)
    # check residuals with the numbers (guards against spurious generic solutions)
    checked = [r for r in real if _numeric_residual(n, topology, dict(known, **r), names) <= tol]
    if not checked:
        raise ValueError(f"the balance conditions have no solution for the unknowns {list(unknowns)} "
                         "with these values: the conditions the unknowns do not enter are violated "
                         "(overdetermined or inconsistent choice)")
    return _admissible_solution(checked, unknowns)


def solve_family(n: int, topology, values: Mapping[str, float], unknowns: Sequence[str]) -> list:
    """Every solution of the balance conditions for ``unknowns``, free unknowns included.

    Where :func:`solve` needs a unique solution (and raises :class:`SingularChoice` when
    the conditions leave unknowns free), this returns each solution branch as a
    :class:`SolutionFamily`: its ``free`` unknowns (none for an isolated solution) and
    every unknown as an expression in them. The known numbers are substituted as exact
    rationals, so a choice that is singular only for these numbers (Lustig's case 1 with
    ``k1, a1, b1, k2`` unknown: one condition vanishes identically) is found.

    Parameters
    ----------
    n, topology, values, unknowns
        As in :func:`solve`.

    Returns
    -------
    list of SolutionFamily
        One per branch; empty if the conditions have no solution.

    Examples
    --------
    >>> from balancelab.methods.lustig import LUSTIG_TOPOLOGY, lustig_values
    >>> v = {k: x for k, x in lustig_values(1).items() if k not in ("k1", "ay1", "bx1", "k2")}
    >>> [f.free for f in solve_family(2, LUSTIG_TOPOLOGY, v, ("k1", "ay1", "bx1", "k2"))]
    [('k2',)]
    """
    n, topology = check_topology(n, topology)
    names = chain_parameter_names(n, topology)
    unknowns = _checked_unknowns(names, unknowns)
    known = _known_values(names, values, unknowns)
    _check_determinable(n, topology, unknowns)
    return [SolutionFamily(unknowns, free, sol) for free, sol in _exact_solutions(n, topology, known, unknowns)]


def synthesize(n: int, topology, values: Mapping[str, float], unknowns: Sequence[str], *,
               name: str = "serial chain balanced by the stiffness-matrix method",
               symbolic: bool = True) -> Design:
    """Solve the balance conditions (:func:`solve`) and return the balanced design.

    Parameters
    ----------
    n, topology, values, unknowns
        As in :func:`solve`.
    name : str
        Title of the design.
    symbolic : bool
        Attach the symbolic parts in the paper's symbols.

    Returns
    -------
    Design
        Configuration ``q`` = absolute link angles (rad); ``parameters`` holds every
        parameter by its paper name.

    Examples
    --------
    >>> from balancelab.methods.lustig import LUSTIG_TOPOLOGY, LUSTIG_UNKNOWNS, lustig_values
    >>> v = {k: x for k, x in lustig_values(3).items() if k not in LUSTIG_UNKNOWNS}
    >>> d = synthesize(2, LUSTIG_TOPOLOGY, v, LUSTIG_UNKNOWNS)
    >>> d.balance_report().balanced
    True
    """
    if not isinstance(values, Mapping):
        raise TypeError(f"values must be a mapping of parameter names to numbers, got {values!r}"[:300])
    n, topology = check_topology(n, topology)
    if values.get("g", G) != G:
        raise ValueError("a Design uses g = 9.81 m/s^2; leave g out of values (or set it to 9.81)")
    sol = solve(n, topology, values, unknowns)
    allv = {k: v for k, v in values.items() if k not in sol}
    allv.update(sol)
    chain = SerialChain.from_values(n, topology, allv)
    return chain.design(name, symbolic=symbolic)
