"""Where free points may go by default: a box per body that follows the linkage, not the origin.

Each body's box is a square in its local frame, centred on the body's *proximal joint point*
(its end of the joint that first reaches it from the ground, walking the joints breadth first;
for the ground, the ground end of its first joint) and of half-width the linkage's *size*: the
largest distance of a joint, load or spring end point from its body's centre (or half a
slide's range). Translating every point of a drawing translates each box, scaling every length
scales it, and turning the drawing keeps its size. A linkage drawn the usual way (each body's
proximal joint at its local origin, its points on the axes) gets the square ``[-size, size]^2``
about the origin. Layer: methods.
"""
from __future__ import annotations


import numpy as np

from ...core.design import Design

__all__ = ["centres", "linkage_size", "default_boxes"]


def centres(design: Design) -> list[tuple[float, float]]:
    """Each body's proximal joint point (m, local frame); ``(0, 0)`` for a body no revolute joint
    reaches (a slider's block, say).

    Examples
    --------
    >>> import balancelab as bl
    >>> lk = bl.Linkage("lever far away")
    >>> lk.revolute("ground", (1000.0, 5.0), "arm", (1000.0, 5.0))
    >>> lk.mass("arm", 2.0, com=(1000.5, 5.0))
    >>> centres(lk.build())
    [(1000.0, 5.0), (1000.0, 5.0)]
    """
    out: list[tuple[float, float] | None] = [None] * len(design.bodies)
    ground = [j.point_i if j.body_i == 0 else j.point_j for j in design.joints if 0 in (j.body_i, j.body_j)]
    out[0] = (float(ground[0][0]), float(ground[0][1])) if ground else (0.0, 0.0)
    reached, frontier = {0}, [0]
    while frontier:
        nxt = []
        for j in design.joints:
            for a, b, pb in ((j.body_i, j.body_j, j.point_j), (j.body_j, j.body_i, j.point_i)):
                if a in frontier and b not in reached:
                    reached.add(b)
                    out[b] = (float(pb[0]), float(pb[1]))
                    nxt.append(b)
        frontier = nxt
    return [c if c is not None else (0.0, 0.0) for c in out]


def linkage_size(design: Design) -> float:
    """The linkage's size (m): the largest distance of a joint, load or spring end point from its
    body's centre (:func:`centres`), or half a slide's range if larger (the same however the drawing
    is turned); 0 only for a linkage drawn as one point that does not slide.

    Examples
    --------
    >>> import balancelab as bl
    >>> lk = bl.Linkage("lever")
    >>> lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    >>> lk.mass("arm", 2.0, com=(0.5, 0.0))
    >>> linkage_size(lk.build())
    0.5
    """
    c = centres(design)
    pts = [(j.body_i, j.point_i) for j in design.joints] + [(j.body_j, j.point_j) for j in design.joints]
    pts += [(ld.body, ld.point) for ld in design.loads]
    pts += [(e.body, e.point) for sp in design.springs for e in (sp.a, sp.b)]
    slides = [(hi - lo) / 2 for (lo, hi), unit in zip(np.asarray(design.q_range, dtype=float).reshape(-1, 2),
                                                       getattr(design.kinematics, "units", ())) if unit == "m"]
    return float(max([float(np.hypot(p[0] - c[b][0], p[1] - c[b][1])) for b, p in pts] + slides, default=0.0))


def default_boxes(design: Design, factor: float = 1.0) -> list[tuple]:
    """The default box of each body, ``((x_lo, x_hi), (y_lo, y_hi))`` (m, local frame): the square
    of half-width ``factor`` times :func:`linkage_size` about the body's centre (:func:`centres`).

    Examples
    --------
    >>> import balancelab as bl
    >>> lk = bl.Linkage("lever")
    >>> lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    >>> lk.mass("arm", 2.0, com=(0.5, 0.0))
    >>> default_boxes(lk.build())[1]
    ((-0.5, 0.5), (-0.5, 0.5))
    """
    w = factor * linkage_size(design)  # 0 for a linkage drawn as one point: balance then asks for a box
    return [((x - w, x + w), (y - w, y + w)) for x, y in centres(design)]


def scaled(box: tuple, factor: float) -> tuple:
    """``box`` widened ``factor`` times about its centre.

    Examples
    --------
    >>> scaled(((0.0, 2.0), (-1.0, 1.0)), 2.0)
    ((-1.0, 3.0), (-2.0, 2.0))
    """
    out = []
    for lo, hi in box:
        mid, half = (lo + hi) / 2, (hi - lo) / 2 * factor
        out.append((mid - half, mid + half))
    return tuple(out)
