"""`balance`: ZFL springs and counterweights that balance any design, from candidates you name.

Layer: methods. See the package docstring for the method and its justification.
"""
from __future__ import annotations

import contextlib
import warnings
from typing import Sequence

import numpy as np

from ...core.design import Design
from ...core.elements import Load, Spring, G
from ...core.validation import MAX_MAGNITUDE, MIN_POSITIVE, planar_point, positive_int
from ...core.errors import InfeasibleDesign
from ...core.report import MAX_CONFIGURATIONS
from .problem import Block, columns
from .bilinear import search
from .solver import OBJECTIVES, Solution, column_norms, rank_of, solve
from .verdicts import limit
from .box import default_boxes, linkage_size

__all__ = ["balance", "InfeasibleDesign", "OBJECTIVES", "free_choices"]

_CONTROLLER = None  # threadpoolctl's view of the loaded BLAS libraries, made on first use


def _body(design: Design, body, what: str) -> int:
    if isinstance(body, bool):
        raise TypeError(f"{what} must be a body name or index, got {body!r}")
    if isinstance(body, (int, np.integer)):
        if not 0 <= body < len(design.bodies):
            raise ValueError(f"{what} must be a body index in 0..{len(design.bodies) - 1}, got {body}")
        return int(body)
    if body not in design.bodies:
        raise ValueError(f"{what} must name a body of the design {design.bodies}, got {body!r}")
    return design.bodies.index(body)


def _end(design: Design, value, what: str):
    try:
        body, point = value
    except (TypeError, ValueError):
        raise TypeError(f"{what} must be a pair (body, point or None), got {value!r}") from None
    return (_body(design, body, f"{what} body"), None if point is None else planar_point(f"{what} point (m)", point))


def _size(design: Design) -> float:
    """The linkage's size (m, :func:`.box.linkage_size`), never zero."""
    return max(linkage_size(design), 1e-300)


def _box(box, design: Design) -> list:
    """The box of each body: the default boxes (:func:`.box.default_boxes`) or the given box for all."""
    if box is None:
        return default_boxes(design)
    try:
        (xl, xh), (yl, yh) = box
    except (TypeError, ValueError):
        raise TypeError(f"box must be ((x_lo, x_hi), (y_lo, y_hi)) in metres, got {box!r}") from None
    (xl, xh), (yl, yh) = planar_point("box x-range (m)", (xl, xh)), planar_point("box y-range (m)", (yl, yh))
    if xl > xh or yl > yh:
        raise ValueError(f"box must have lo <= hi on each axis, got {box!r}")
    return [((xl, xh), (yl, yh))] * len(design.bodies)


def _blocks(design: Design, springs, counterweights, boxes) -> list[Block]:
    """The candidates as blocks; ``boxes``: one box per body, or one box ``((x_lo, x_hi), (y_lo, y_hi))`` for all."""
    if isinstance(boxes, tuple):
        boxes = [boxes] * len(design.bodies)
    blocks = []
    for i, cand in enumerate(springs):
        try:
            a, b = cand
        except (TypeError, ValueError):
            raise TypeError(f"springs[{i}] must be a pair of ends ((body, point or None), (body, point or None)), "
                            f"got {cand!r}") from None
        ends = [_end(design, a, f"springs[{i}][0]"), _end(design, b, f"springs[{i}][1]")]
        if ends[0][0] == ends[1][0]:
            raise ValueError(f"springs[{i}] joins body {design.bodies[ends[0][0]]!r} to itself")
        free = 0 if ends[0][1] is None else 1 if ends[1][1] is None else None
        end_boxes = [boxes[ends[0][0]], boxes[ends[1][0]]]  # each end boxed by its own body's box
        box = end_boxes[free if free is not None else 1 if ends[0][1] is not None else 0]
        blocks.append(Block("spring", ends, free, box=box, end_boxes=end_boxes))
    for i, cand in enumerate(counterweights):
        body, point = _end(design, cand, f"counterweights[{i}]")
        if body == 0:
            raise ValueError(f"counterweights[{i}] is on the ground, where it cannot balance anything")
        blocks.append(Block("mass", [(body, point)], None if point is not None else 0, box=boxes[body]))
    if not blocks:
        raise ValueError("give at least one candidate spring or counterweight")
    return blocks


def _default_point(design: Design, body: int, size: float, index: int = 0, start: int = 0) -> tuple[float, float]:
    """Where a both-free spring end starts. Start 0: half-way to the body's farthest joint, or above the
    ground (every candidate alike); start ``s > 0``: a point ``size / 2`` or less from there, in a
    direction that differs from candidate to candidate (golden-angle steps) and from start to start."""
    pts = [p for j in design.joints for (b, p) in ((j.body_i, j.point_i), (j.body_j, j.point_j)) if b == body]
    if body == 0:
        x, y = pts[0] if pts else (0.0, 0.0)
        x, y = x, y + size / 2
    else:
        far = max(pts, key=lambda p: np.hypot(*p), default=(0.0, 0.0))
        x, y = (far[0] / 2, far[1] / 2) if np.hypot(*far) > 0 else (size / 2, 0.0)
    if start == 0:
        return (x, y)
    angle = 2.399963 * (index + 1) * start
    r = size / 2 * (0.4 + 0.6 * ((index + start) % 3) / 2)
    return (x + r * np.cos(angle), y + r * np.sin(angle))


def _solve_alternating(design, blocks, q, objective):
    """Solve; springs with two free ends are bilinear: searched from many starts, the best kept
    (:func:`.bilinear.search`, which also gives the honest verdict when none balances)."""
    both = [b for b in blocks if b.kind == "spring" and b.ends[0][1] is None and b.ends[1][1] is None]
    if not both:
        p = columns(design, blocks, q)
        return p, solve(p, objective)
    return search(design, blocks, both, q, objective, _default_point, _size(design))


def _active(b, point, names) -> dict:
    """``{"active_<coordinate>": bound}`` for each coordinate of a solved free point at its box's edge."""
    out = {}
    for axis, ((lo, hi), name) in enumerate(zip(b.box, names)):
        tol = 1e-9 * max(hi - lo, abs(lo), abs(hi), 1e-12)
        for bound in (lo, hi):
            if abs(point[axis] - bound) <= tol:
                out[f"active_{name}"] = float(bound)
    return out


def _elements(design: Design, blocks, x: np.ndarray):
    """New springs and counterweights (zero rates and masses dropped), their parameters and the
    free coordinates that ended at their box's edge (``active_<coordinate>``: the bound, m)."""
    springs, loads, params = list(design.springs), list(design.loads), {}
    size = _size(design)
    active = {}
    for i, b in enumerate(blocks):
        value = float(x[b.cols[0]])
        if value <= 0:
            continue
        _check_limits(design, blocks, i, value)
        ends = list(b.ends)
        if b.free is not None:  # round-off (1e-12 of the linkage's size) becomes an exact zero
            point = [float(x[c] / value) for c in b.cols[1:]]
            ends[b.free] = (ends[b.free][0], tuple(0.0 if abs(v) < 1e-12 * size else v for v in point))
        if b.kind == "spring":
            j = len(springs) + 1
            springs.append(Spring(value, 0.0, ends[0], ends[1], name=f"k{j}"))
            # the naming table: parameters a_* on the moving body, b_* on the anchor (the ground, if
            # either end is), whichever order the candidate gave (the Spring keeps the given order)
            flip = ends[0][0] == 0 and ends[1][0] != 0
            a_end, b_end = (ends[1], ends[0]) if flip else (ends[0], ends[1])
            params.update({f"k{j}": value, f"a_x{j}": float(a_end[1][0]), f"a_y{j}": float(a_end[1][1]),
                           f"b_x{j}": float(b_end[1][0]), f"b_y{j}": float(b_end[1][1])})
            if b.free is not None:
                side = "ab"[1 - b.free if flip else b.free]
                active.update(_active(b, ends[b.free][1], (f"{side}_x{j}", f"{side}_y{j}")))
        else:
            j = sum(ld.kind == "counterweight" for ld in loads) + 1
            loads.append(Load(ends[0][0], ends[0][1], (0.0, -value * G), name=f"m_c{j}", kind="counterweight"))
            params.update({f"counter_mass{j}": value, f"c_x{j}": float(ends[0][1][0]), f"c_y{j}": float(ends[0][1][1])})
            if b.free is not None:
                active.update(_active(b, ends[0][1], (f"c_x{j}", f"c_y{j}")))
    return springs, loads, params, active


def _check_limits(design: Design, blocks, index: int, value: float) -> None:
    """InfeasibleDesign (verdict ``"limit"``) when a solved rate or counter mass is beyond what a design
    may hold (``MIN_POSITIVE <= k <= MAX_MAGNITUDE`` N/m, a weight up to ``MAX_MAGNITUDE`` N), never the
    validators' plain ValueError from inside ``balance``."""
    b = blocks[index]
    kind = "springs" if b.kind == "spring" else "counterweights"
    what = f"{kind}[{sum(c.kind == b.kind for c in blocks[:index])}] {'rate k' if b.kind == 'spring' else 'counter mass'}"
    if b.kind == "spring" and value > MAX_MAGNITUDE:
        raise limit(design.name, what, value, "N/m", MAX_MAGNITUDE, above=True)
    if b.kind == "spring" and value < MIN_POSITIVE:
        raise limit(design.name, what, value, "N/m", MIN_POSITIVE, above=False)
    if b.kind == "mass" and value * G > MAX_MAGNITUDE:
        raise limit(design.name, what, value, "kg", MAX_MAGNITUDE / G, above=True)


def _threads(p_size: int):
    """A context that limits BLAS to one thread for small problems (threads cost more than they
    save there: on a loaded two-core machine the minimum preload ran 100 times slower)."""
    global _CONTROLLER
    if p_size >= 4_000_000:
        return contextlib.nullcontext()
    if _CONTROLLER is None:  # finding the BLAS libraries takes tens of ms: once per process
        import scipy.optimize  # noqa: F401  (loads scipy's own BLAS, so that the controller sees it)
        from threadpoolctl import ThreadpoolController

        _CONTROLLER = ThreadpoolController()
    return _CONTROLLER.limit(limits=1)


def _any_free(springs, counterweights) -> bool:
    """Whether a (checked) candidate leaves a point to the solver."""
    return any(end[1] is None for c in springs for end in c) or any(c[1] is None for c in counterweights)


def _solve_growing(design, springs, counterweights, box, q, objective):
    """Solve with the given box; with the default box, grow it (as the verdict suggests, at most
    three times, up to 1000 times the linkage's size) while a point outside it would balance."""
    current, total = _box(box, design), 1.0
    if box is None and linkage_size(design) == 0 and _any_free(springs, counterweights):
        raise ValueError(f"{design.name}: every joint, load and spring end sits at one point: there is no size to "
                         "draw a default box from; pass box=((x_lo, x_hi), (y_lo, y_hi)) in metres")
    for attempt in range(4):
        blocks = _blocks(design, springs, counterweights, current)
        try:
            p, sol = _solve_alternating(design, blocks, q, objective)
            return p, sol, current
        except InfeasibleDesign as err:
            factor = getattr(err, "factor", None)
            grow = getattr(err, "verdict", None) == "box" and box is None and attempt < 3 and factor is not None
            if not grow or factor is None or factor <= 1.0 or total * factor > 1000:
                raise
            total *= factor
            current = default_boxes(design, total)


def balance(design: Design, springs: Sequence = (), counterweights: Sequence = (), objective: str = "min_preload",
            *, box=None, n: int | None = None) -> Design:
    """Balance ``design`` with ZFL springs and counterweights chosen among candidates.

    Parameters
    ----------
    design : Design
        Any design (any kinematics, loads, springs of any free length); what it carries
        already is kept and balanced against.
    springs : sequence of ((body, point or None), (body, point or None))
        Candidate ZFL springs between two attachments (body name or index, local point in
        m); ``None`` lets the solver place that end.
    counterweights : sequence of (body, point or None)
        Candidate counterweights (kg, solved for) at local points, ``None`` to place them.
    objective : {"min_preload", "min_stiffness", "min_mass"}
        Which balanced solution to pick when there are free choices: the least spring
        energy (Singh's minimum preload: the constant total energy as low as it goes), the
        smallest total stiffness (N/m), or the smallest total counter mass (kg). Ties: an
        objective ignores the candidates it does not count (counterweights for the stiffness,
        springs for the mass; the minimum preload's counterweights are made the lightest among
        the designs of least preload, with fixed spring ends); when other designs reach the same value a UserWarning says so,
        and the design returned is simply the linear program's optimal vertex (HiGHS), picked
        by no further rule.
    box : ((x_lo, x_hi), (y_lo, y_hi)), optional
        Where free points may go, in their bodies' local frames (m). By default each body
        gets its own square, centred on the body's proximal joint point (its end of the joint
        that first reaches it from the ground; for the ground, its first joint) and of
        half-width the linkage's size (the largest distance of a joint, load or spring end point
        from its body's centre): it moves and scales with the drawing, wherever and however
        large it is drawn (:mod:`.box`). When a point outside it would balance, the default
        boxes grow about their centres (up to 1000 times) before ``balance`` gives up.
    n : int, optional
        Number of sampled configurations, ``20..MAX_CONFIGURATIONS`` (200 000; default: enough
        for the unknowns, at least 240).

    Returns
    -------
    Design
        A copy with the springs (``k > 0``; candidates that come out at zero are left out)
        and counterweights added; its ``parameters`` hold the rates ``k<j>``, the ends
        ``a_x<j>, a_y<j>, b_x<j>, b_y<j>`` (``a`` the end on the moving body, ``b`` the anchor:
        a candidate's ground end is ``b`` whichever order it was given in), the counter masses and points, and
        ``conditions_rank`` and ``free_choices`` (unknowns minus the rank). For a spring with
        both ends free the count is that of the last linear round (one end free).

    Raises
    ------
    InfeasibleDesign
        When no admissible solution exists; the message names the energy terms that
        cannot be cancelled and the candidates that would need a negative value; ``err.verdict``
        says which (``"limit"``: a rate outside ``1e-12..1e12`` N/m or a counter mass whose weight
        exceeds ``1e12`` N would be needed, named with the limit).

    Examples
    --------
    >>> import balancelab as bl
    >>> lk = bl.Linkage("lever")
    >>> lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    >>> lk.mass("arm", 2.0, com=(0.5, 0.0))
    >>> d = bl.balance(lk.build(), springs=[(("arm", (0.25, 0.0)), ("ground", (0.0, 0.4)))])
    >>> round(d.parameters["k1"], 6), d.balance_report().balanced   # k = m g l / (a b)
    (98.1, True)
    """
    if not isinstance(design, Design):
        raise TypeError(f"design must be a balancelab Design, got {type(design).__name__}")
    if objective not in OBJECTIVES:
        raise ValueError(f"objective must be one of {OBJECTIVES}, got {objective!r}")
    _blocks(design, list(springs), list(counterweights), _box(box, design))  # check the input first
    m = 240 if n is None else positive_int("n (number of configurations)", n, minimum=20, maximum=MAX_CONFIGURATIONS)
    q = design.sample(max(m, 6 * 3 * (len(springs) + len(counterweights))) if n is None else m, seed=0)
    vl, vs = design.element_energies(q)
    if not (np.ptp(vl, axis=0).sum() + np.ptp(vs, axis=0).sum()) > 0:
        raise ValueError(f"{design.name}: nothing to balance: its loads and springs exchange no energy as it "
                         "moves (keep at least one load, or the spring that loads a spring-loaded mechanism)")
    with _threads(len(q) * 9 * (len(springs) + len(counterweights))):
        p, sol, _ = _solve_growing(design, list(springs), list(counterweights), box, q, objective)
    new_springs, new_loads, params, active = _elements(design, p.blocks, sol.x)
    params.update(conditions_rank=int(sol.rank), free_choices=int(sol.free_choices), active_bounds=len(active),
                  **active)
    if any(b.free is not None for b in p.blocks):  # the box of the first free point (all alike but a far drawing's)
        (xl, xh), (yl, yh) = next(b.box for b in p.blocks if b.free is not None)
        params.update(box_x_lo=xl, box_x_hi=xh, box_y_lo=yl, box_y_hi=yh)
    if sol.unique is False:
        ignored = sorted({"springs" if b.kind == "spring" else "counterweights" for b in p.blocks
                          if objective == "min_mass" and b.kind == "spring"
                          or objective == "min_stiffness" and b.kind == "mass"
                          or objective == "min_preload" and b.kind == "mass"})
        warnings.warn(f"{design.name}: objective {objective!r} does not select a unique design: it ignores the "
                      f"{' and '.join(ignored) or 'candidates'} it does not count, and {sol.free_choices} free "
                      "choice(s) remain; the design returned is one of many (choose another objective, or fewer "
                      "candidates)", UserWarning, stacklevel=2)
    out = design.replace(name=f"{design.name}, balanced ({objective})", springs=new_springs, loads=new_loads,
                         parameters={**design.parameters, **params})
    _verify(out, design.sample(400, seed=1))
    return out


def _verify(design: Design, q: np.ndarray) -> None:
    """The verdict of :meth:`Design.balance_report` (its default configurations, and the fresh ones
    ``q``): a design its own report calls unbalanced is never returned (InfeasibleDesign instead,
    verdict ``"not_found"``: the solution found does not pass the report, e.g. at round-off)."""
    for r in (design.balance_report(), design.balance_report(q)):
        if not r.balanced:
            err = InfeasibleDesign(f"{design.name}: the solution found does not pass its own balance report: the "
                                   f"energy varies by {r.load_variation:.3g} of the loads' {r.load_scale:.3g} J "
                                   f"over {r.n} configurations (round-off of large or cancelling terms, or a "
                                   "sample that missed part of the range: try a larger n); no design is returned")
            err.verdict, err.box = "not_found", None
            raise err


def free_choices(design: Design, springs: Sequence = (), counterweights: Sequence = (), *, n: int | None = None
                 ) -> Solution:
    """Rank of the balance conditions and free choices for these candidates (no sign constraints).

    Returns
    -------
    Solution
        Only ``rank``, ``nvar`` and ``free_choices`` are meaningful (``x`` is the least-norm
        unsigned solution).

    Examples
    --------
    A lever with one ZFL spring whose anchor is free: balance fixes ``k b_y`` and ``b_x = 0``,
    one choice is left.

    >>> import balancelab as bl
    >>> lk = bl.Linkage("lever")
    >>> lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    >>> lk.mass("arm", 2.0, com=(0.5, 0.0))
    >>> s = free_choices(lk.build(), springs=[(("arm", (0.25, 0.0)), ("ground", None))])
    >>> s.nvar, s.rank, s.free_choices
    (3, 2, 1)
    """
    blocks = _blocks(design, list(springs), list(counterweights), _box(None, design))
    q = design.sample(240 if n is None else positive_int("n (number of configurations)", n, minimum=20,
                                                         maximum=MAX_CONFIGURATIONS), seed=0)
    p = columns(design, blocks, q)
    r = rank_of(p.A / column_norms(p))[0]
    x = np.linalg.lstsq(p.A, -p.v, rcond=1e-12)[0]
    return Solution(x, r, p.nvar, float(np.ptp(p.A @ x + p.v)))
