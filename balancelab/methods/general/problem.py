"""The balance problem of a design and candidate ZFL springs and counterweights, as linear algebra.

Every unknown enters the energy linearly once the right variables are chosen:

* a ZFL spring between two fixed points: its rate ``k``; energy ``k/2 |w_a - w_b|^2``;
* a ZFL spring with one free end ``p`` on body ``c`` (the other end at ``w``): ``k`` and
  the moment ``m = k p``. With ``u = w - o_c`` (``o_c`` the origin of body ``c``),
  ``k/2 |u - R_c p|^2 = k/2 |u|^2 - (R_c^T u) . m + k/2 |p|^2`` and the last term is a
  constant: the energy is linear in ``(k, m)`` (the stiffness-matrix observation of
  Lustig et al., written for one end at a time);
* a counterweight of mass ``M`` at a fixed point: ``M g y``; at a free point ``p`` of body
  ``c``: ``g (M y_c + (R_c (M p))_y)``, linear in ``(M, M p)``.

A point kept inside a box ``lo <= p <= hi`` is the linear constraint ``k lo <= m <= k hi``.
:func:`columns` evaluates each variable's energy (its *column*) at sampled configurations
of the design's own kinematics; balance is ``A x + v = const`` with ``v`` the energy of
what the design carries already. :func:`harmonics` names the terms of an energy residual
(``cos theta_b``, ``sin(theta_c - theta_b)`` ...), for the message of an infeasible design.
Layer: methods.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ...core.elements import G
from ...core.frames import turn_back
from ...core.kinematics import body_to_world
from ...core.report import balanced_at, reference_point
from .box import linkage_size

__all__ = ["Block", "Problem", "columns", "harmonics", "lp_constraints"]


@dataclass
class Block:
    """One candidate: its kind, its ends and where its variables sit in ``x``.

    ``kind`` is ``"spring"`` or ``"mass"``; ``ends`` the attachments ``(body, point or
    None)`` (one for a counterweight); ``free`` the index of the free end (``None`` if
    both ends are fixed); ``cols`` the indices of ``(k or M, m_x, m_y)`` in ``x``; ``box``
    the local box ``((x_lo, x_hi), (y_lo, y_hi))`` (m) of the free point; ``end_boxes`` a spring's
    box for each end, that of the body the end is on (the box of whichever end is free, and of
    both ends of a spring whose two ends are free: ``free == "both"``).
    """

    kind: str
    ends: list
    free: int | None = None
    cols: list = field(default_factory=list)
    box: tuple = ((-1.0, 1.0), (-1.0, 1.0))
    end_boxes: list | None = None

    def box_of(self, end: int) -> tuple:
        """The box (m, local frame) of end ``end`` (0 or 1): its body's box, else the block's box."""
        return self.end_boxes[end] if self.end_boxes is not None else self.box

    def set_free(self, end: int | str | None) -> None:
        """Free end ``end`` (0, 1, ``"both"`` or None); the block's box becomes that end's box."""
        self.free = end  # type: ignore[assignment]  # "both" only while a spring's two ends are lifted
        if end == "both":
            self.box = self.box_of(0)
        elif isinstance(end, int):
            self.box = self.box_of(end)


@dataclass
class Problem:
    """Sampled balance problem: ``A`` (centred columns), ``v`` (centred known energy), and extras."""

    A: np.ndarray
    v: np.ndarray
    mean: np.ndarray  # mean of each uncentred spring column (J per unit variable): the preload's linear part
    blocks: list
    q: np.ndarray
    poses: np.ndarray
    load_spread: float
    design: object = None
    size: float = 0.0  # the linkage's size (m, :func:`.box.linkage_size`): the scale of the wider boxes tried

    @property
    def nvar(self) -> int:
        """Number of unknowns."""
        return self.A.shape[1]


def _world(poses, body, point):
    x, y = body_to_world(poses, [body], [point])
    return np.stack([x[..., 0], y[..., 0]], -1)


def _lifted_columns(poses, block):
    """Columns of a spring with both ends free, lifted: ``[k, k p_a, k p_b, k p_a p_b^T]`` (9 columns).

    With ``d = o_a - o_b`` (the bodies' origins), ``k/2 |d + R_a p_a - R_b p_b|^2`` is, up to
    constants, ``k |d|^2 / 2 + (R_a^T d) . k p_a - (R_b^T d) . k p_b - sum_ij W_ij (R_a^T R_b)_ij``
    with ``W = k p_a p_b^T``: linear in the nine unknowns, which relax the rank-one ``W``."""
    (ba, _), (bb, _) = block.ends
    d = poses[:, ba, :2] - poses[:, bb, :2]
    da = turn_back(np.cos(poses[:, ba, 2]), np.sin(poses[:, ba, 2]), (d[:, 0], d[:, 1]))   # R_a^T d
    db = turn_back(np.cos(poses[:, bb, 2]), np.sin(poses[:, bb, 2]), (d[:, 0], d[:, 1]))   # R_b^T d
    c, s = np.cos(poses[:, bb, 2] - poses[:, ba, 2]), np.sin(poses[:, bb, 2] - poses[:, ba, 2])
    return [0.5 * (d * d).sum(-1), da[0], da[1], -db[0], -db[1], -c, s, -s, -c]


def _spring_columns(poses, block):
    """Columns of one spring: ``[k]`` or ``[k, m_x, m_y]`` (J per N/m and per N)."""
    (ba, pa), (bb, pb) = block.ends
    if block.free == "both":
        return _lifted_columns(poses, block)
    if block.free is None:
        d = _world(poses, ba, pa) - _world(poses, bb, pb)
        return [0.5 * (d * d).sum(-1)]
    (bf, _), (bx, px) = (block.ends[1], block.ends[0]) if block.free == 1 else (block.ends[0], block.ends[1])
    cx, cy = box_centre(block.box)  # measured from the free point's box centre c: a far box costs no digits
    u = _world(poses, bx, px) - _world(poses, bf, (cx, cy))
    ux, uy = turn_back(np.cos(poses[:, bf, 2]), np.sin(poses[:, bf, 2]), (u[:, 0], u[:, 1]))   # R_c^T u
    # 0.5 |u + R c|^2 and -(R^T u + c), less their constants 0.5 |c|^2 and -c (see columns)
    return [0.5 * (u * u).sum(-1) + ux * cx + uy * cy, -ux, -uy]


def box_centre(box: tuple) -> tuple[float, float]:
    """The centre (m) of a box ``((x_lo, x_hi), (y_lo, y_hi))``.

    Examples
    --------
    >>> box_centre(((9996.0, 10004.0), (-30004.0, -29996.0)))
    (10000.0, -30000.0)
    """
    (xl, xh), (yl, yh) = box
    return ((xl + xh) / 2, (yl + yh) / 2)


def _constants(block) -> list[float]:
    """The constants left out of a spring's columns with one free end (``0.5 |c|^2`` and ``-c``, with
    ``c`` its box centre): they add to the means, the preload's linear part."""
    if block.kind != "spring" or block.free not in (0, 1):
        return []
    cx, cy = box_centre(block.box)
    return [0.5 * (cx * cx + cy * cy), -cx, -cy]


def _mass_columns(poses, block):
    """Columns of one counterweight: ``[M]`` or ``[M, M p_x, M p_y]`` (J per kg and per kg m)."""
    body, point = block.ends[0]
    if block.free is None:
        return [G * _world(poses, body, point)[:, 1]]
    a = poses[:, body, 2]
    return [G * poses[:, body, 1], G * np.sin(a), G * np.cos(a)]


def columns(design, blocks, q) -> Problem:
    """The sampled problem of ``design`` with candidate ``blocks`` at configurations ``q``.

    Parameters
    ----------
    design : Design
    blocks : list of Block
        Their ``cols`` are set here. A spring whose ``free`` is ``"both"`` gets the nine lifted
        columns of :func:`_lifted_columns` (a linear relaxation of the bilinear problem).
    q : numpy.ndarray, shape (m, dof)
        Reachable configurations (rad).

    Returns
    -------
    Problem

    Examples
    --------
    A lever (2 kg at 0.5 m) and one ZFL spring between fixed points: one column.

    >>> import balancelab as bl
    >>> lk = bl.Linkage("lever")
    >>> lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    >>> lk.mass("arm", 2.0, com=(0.5, 0.0))
    >>> d = lk.build()
    >>> p = columns(d, [Block("spring", [(1, (0.25, 0.0)), (0, (0.0, 0.4))])], d.sample(50))
    >>> p.A.shape, round(float(np.ptp(p.v)), 6) <= 2 * 2.0 * 9.81 * 0.5
    ((50, 1), True)
    """
    poses = np.array(design.poses(q), dtype=float, copy=True)
    poses[..., :2] -= reference_point(design)  # about a ground point: a far origin costs no digits
    cols: list[np.ndarray] = []
    mean: list[float] = []
    for block in blocks:
        new = _spring_columns(poses, block) if block.kind == "spring" else _mass_columns(poses, block)
        block.cols = list(range(len(cols), len(cols) + len(new)))
        cols += new
        extra = _constants(block) or [0.0] * len(new)
        mean += [float(np.mean(c)) + e if block.kind == "spring" else 0.0 for c, e in zip(new, extra)]
    A = np.stack(cols, -1) if cols else np.zeros((len(q), 0))
    vl, vs = design.element_energies(q)
    v = vl.sum(-1) + vs.sum(-1)
    spread = float(np.ptp(vl, axis=0).sum() + np.ptp(vs, axis=0).sum()) if (vl.size or vs.size) else 0.0
    if np.ptp(v) <= 1e-6 * spread and balanced_at(design, q):
        v = np.zeros_like(v)  # balanced already by its report's own yardstick: what is left is round-off, no term to cancel
    return Problem(A - A.mean(0), v - v.mean(), np.array(mean), blocks, q, poses, spread, design, linkage_size(design))


def harmonics(design, poses, residual, top: int = 4, q=None) -> list[tuple[str, float]]:
    """The largest trigonometric terms of an energy ``residual`` (J) sampled at ``poses``.

    Fits ``residual`` with ``cos theta_b``, ``sin theta_b`` and ``cos``/``sin`` of the
    differences of the body angles (every ZFL spring and weight energy is a combination
    of these) and returns the ``top`` terms with the largest amplitude, as
    ``(term, coefficient in J)``; for a linkage with loops the fit is the least-norm one.
    With the configurations ``q`` of a design with slides (coordinates in m), the terms also
    hold the slides ``s_k``, ``s_k^2`` and ``s_k cos theta_b``, ``s_k sin theta_b`` (J per m, m^2).

    Examples
    --------
    >>> import balancelab as bl
    >>> lk = bl.Linkage("lever")
    >>> lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    >>> d = lk.build()
    >>> q = d.sample(40)
    >>> [(name, round(c, 9)) for name, c in harmonics(d, d.poses(q), 3.0 * np.sin(q[:, 0]))]
    [('sin θ_1', 3.0)]
    """
    nb = len(design.bodies)
    th = poses[..., 2]
    feats, names = [], []
    for b in range(1, nb):
        feats += [np.cos(th[:, b]), np.sin(th[:, b])]
        names += [f"cos θ_{b}", f"sin θ_{b}"]
        for c in range(b + 1, nb):
            feats += [np.cos(th[:, c] - th[:, b]), np.sin(th[:, c] - th[:, b])]
            names += [f"cos(θ_{c} - θ_{b})", f"sin(θ_{c} - θ_{b})"]
    units = getattr(design.kinematics, "units", ())
    for i, unit in enumerate(units if q is not None else ()):
        if unit != "m":
            continue
        sv, sname = np.asarray(q)[:, i], design.q_names[i]
        feats += [sv, sv * sv]
        names += [sname, f"{sname}²"]
        for b in range(1, nb):
            if np.ptp(th[:, b]) > 1e-9:  # bodies that never turn have no harmonics
                feats += [sv * np.cos(th[:, b]), sv * np.sin(th[:, b])]
                names += [f"{sname} cos θ_{b}", f"{sname} sin θ_{b}"]
    keep: list[int] = []  # constant features name nothing; a feature equal to an earlier one (bodies turning alike) once
    for i, f in enumerate(feats):
        if np.ptp(f) > 1e-12 and not any(np.allclose(f, feats[j], atol=1e-9) for j in keep):
            keep.append(i)
    feats, names = [feats[i] for i in keep], [names[i] for i in keep]
    if not feats:
        return []
    F = np.stack(feats, -1)
    F = F - F.mean(0)
    coef = np.linalg.lstsq(F, residual - residual.mean(), rcond=1e-10)[0]
    order = np.argsort(-np.abs(coef))[:top]
    return [(names[i], float(coef[i])) for i in order if abs(coef[i]) > 1e-12 * max(np.abs(coef).max(), 1e-300)]


def lp_constraints(p: Problem, S: np.ndarray):
    """Bounds and box inequalities on the scaled variables ``y = x / S``."""
    n = p.nvar
    bounds: list[tuple[float | None, float | None]] = [(None, None)] * n
    rows = []
    for b in p.blocks:
        bounds[b.cols[0]] = (0.0, None)
        if b.free is None:
            continue
        k = b.cols[0]
        boxed = [(1, b.box)] + ([(3, b.box_of(1))] if b.free == "both" else [])  # (first column, box)
        for first, box in boxed:
            for axis, (lo, hi) in enumerate(box):
                m = b.cols[first + axis]
                for sign, lim in ((1.0, hi), (-1.0, lo)):  # sign (m - lim k) <= 0
                    row = np.zeros(n)
                    row[m], row[k] = sign * S[m], -sign * lim * S[k]
                    rows.append(row)
    A_ub = np.array(rows) if rows else None
    return bounds, A_ub, (np.zeros(len(rows)) if rows else None)
