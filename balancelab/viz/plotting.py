"""Figures of any design: the mechanism, its energy, and views of a design space.

Everything here takes a :class:`balancelab.Design` (or a callable returning one), so a
figure is drawn from the same object the physics uses and cannot disagree with it.

* :func:`draw` draws a design in one configuration: links as bars or plates through
  all their joint and attachment points, the ground hatched at its pivots and
  anchors, ZFL springs as solid coils, springs with a free length as dashed coils of
  another colour, string-over-pulley springs with their pulley, weights and forces as
  arrows, counterweights as discs, and the papers' point names.
* :func:`energy_plot` draws the load, spring and total potential energy over the
  configuration range (curves for one degree of freedom, maps for two).
* :func:`lever_valley`, :func:`family_plot` and :func:`cognates_plot` show design
  spaces: the valley of minimum-energy levers, a one-parameter family of designs, and
  cognate linkages tracing one coupler curve.

The artists are kept (:class:`Drawing`, :class:`EnergyView`) so that animations and
explorers move them in place instead of redrawing the figure. One style is used across
the course: the colour-blind-safe Okabe-Ito palette and equal aspect for mechanisms.
"""
from __future__ import annotations

import math
from typing import Callable, Mapping, Sequence

import numpy as np

from ..core.kinematics import body_to_world
from ..core.design import Design, UnreachableConfiguration

__all__ = [
    "PALETTE",
    "Drawing",
    "EnergyView",
    "draw",
    "energy_plot",
    "default_q",
    "report_summary",
    "lever_valley",
    "family_plot",
    "cognates_plot",
]

#: Okabe-Ito colour-blind-safe palette (Okabe & Ito 2008), by name.
PALETTE = {
    "black": "#000000",
    "orange": "#E69F00",
    "sky": "#56B4E9",
    "green": "#009E73",
    "yellow": "#F0E442",
    "blue": "#0072B2",
    "vermillion": "#D55E00",
    "purple": "#CC79A7",
    "grey": "#7F7F7F",
}

#: The role each colour plays in every figure of the course.
STYLE = {
    "link": PALETTE["blue"],
    "ground": PALETTE["grey"],
    "zfl": PALETTE["vermillion"],
    "spring": PALETTE["purple"],
    "string": PALETTE["black"],
    "load": PALETTE["green"],
    "counterweight": PALETTE["orange"],
    "total": PALETTE["black"],
    "label": PALETTE["black"],
}


# --------------------------------------------------------------------------- helpers
def _plt():
    import matplotlib.pyplot as plt

    return plt


def _new_axes(ax, figsize=(5.0, 4.0)):
    if ax is not None:
        return ax
    plt = _plt()
    fig, ax = plt.subplots(figsize=figsize, layout="constrained")
    return ax


def _check_design(design) -> Design:
    if not isinstance(design, Design):
        raise TypeError(f"design must be a balancelab.Design, got {type(design).__name__}")
    return design


def default_q(design: Design) -> np.ndarray:
    """A representative reachable configuration of ``design`` (rad), shape ``(dof,)``.

    Three fifths of the way through each coordinate's range when that is reachable,
    otherwise the first sampled reachable configuration.

    Parameters
    ----------
    design : Design

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3)
    >>> round(float(np.degrees(default_q(d)[0])), 1)
    36.0
    """
    _check_design(design)
    lo, hi = design.q_range[:, 0], design.q_range[:, 1]
    q = lo + 0.6 * (hi - lo)
    if bool(design.reachable(q)):
        return q
    return design.sample(1, seed=0)[0]


def _count(name: str, n, minimum: int = 2) -> int:
    """``n`` as an int >= ``minimum``, or a ValueError naming ``name``."""
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < minimum:
        raise ValueError(f"{name} must be an integer >= {minimum}, got {n!r}")
    return int(n)


def _as_config(design: Design, q) -> np.ndarray:
    if q is None:
        return default_q(design)
    q = np.asarray(q, dtype=float).reshape(-1)
    if q.shape != (design.dof,):
        raise ValueError(f"q must hold {design.dof} angle(s) (rad) for the coordinates "
                         f"{design.q_names}, got shape {q.shape}")
    return q


def _range_grid(design: Design, n: int) -> np.ndarray:
    """Configurations spread over the range: a line for 1 dof, a grid for 2, samples beyond."""
    lo, hi = design.q_range[:, 0], design.q_range[:, 1]
    if design.dof == 1:
        return np.linspace(lo[0], hi[0], n)[:, None]
    if design.dof == 2:
        m = max(2, int(round(math.sqrt(n))))
        a, b = np.meshgrid(np.linspace(lo[0], hi[0], m), np.linspace(lo[1], hi[1], m))
        return np.stack([a.ravel(), b.ravel()], axis=-1)
    return design.sample(n, seed=0)


def report_summary(report) -> str:
    """One line for a title or a widget: the verdict and how far from balanced.

    Parameters
    ----------
    report : BalanceReport

    Returns
    -------
    str

    Examples
    --------
    >>> import balancelab as bl
    >>> report_summary(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3).balance_report())[:8]
    'balanced'
    """
    if not all(hasattr(report, a) for a in ("balanced", "variation", "residual", "scale", "worst_q")):
        raise TypeError(f"report must be a BalanceReport (design.balance_report()), got {type(report).__name__}")
    if report.balanced:
        return f"balanced (energy constant to {report.variation:.1e} of its scale)"
    q = ", ".join(f"{np.degrees(v):.0f}°" for v in np.atleast_1d(report.worst_q))
    return (f"NOT balanced: energy varies by {report.variation:.2g} of its scale; "
            f"largest |dV/dq| = {report.residual * report.scale:.3g} J/rad at ({q})")


def _safe_report(design: Design, n: int = 1000):
    try:
        return design.balance_report(n=n)
    except (ValueError, RuntimeError):
        return None


# ---------------------------------------------------------------------- geometry
def _hull(points: np.ndarray) -> np.ndarray:
    """Convex hull (counter-clockwise) of 2-D points; two extremes for collinear points."""
    pts = np.unique(np.round(points, 12), axis=0)
    if len(pts) <= 2:
        return pts
    order = np.lexsort((pts[:, 1], pts[:, 0]))
    pts = pts[order]

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    scale = float(np.ptp(pts, axis=0).max()) or 1.0
    eps = 1e-9 * scale * scale
    lower: list = []
    for p in pts:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= eps:
            lower.pop()
        lower.append(p)
    upper: list = []
    for p in pts[::-1]:
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= eps:
            upper.pop()
        upper.append(p)
    hull = np.array(lower[:-1] + upper[:-1])
    return hull


def _coil(a: np.ndarray, b: np.ndarray, width: float, turns: int = 7, lead: float = 0.15):
    """Polyline (x, y) of a zig-zag coil from ``a`` to ``b`` with straight leads."""
    d = b - a
    length = float(np.hypot(*d))
    if length < 1e-12:
        return np.array([a[0], b[0]]), np.array([a[1], b[1]])
    u = d / length
    n = np.array([-u[1], u[0]])
    s = np.concatenate([[0.0], lead + (1 - 2 * lead) * np.linspace(0, 1, 2 * turns + 1), [1.0]])
    w = np.zeros_like(s)
    w[2:-2:2] = 1.0
    w[3:-2:2] = -1.0
    w = w * min(width, 0.35 * length)
    pts = a[None, :] + s[:, None] * length * u[None, :] + w[:, None] * n[None, :]
    return pts[:, 0], pts[:, 1]


def _body_points(design: Design) -> list[list[tuple[float, float]]]:
    """Local points of each body that its drawn shape must pass through."""
    pts: list[list] = [[] for _ in design.bodies]
    for j in design.joints:
        pts[j.body_i].append(tuple(j.point_i))
        pts[j.body_j].append(tuple(j.point_j))
    for s in design.springs:
        pts[s.a.body].append(tuple(s.a.point))
        pts[s.b.body].append(tuple(s.b.point))
    for ld in design.loads:
        pts[ld.body].append(tuple(ld.point))
    for body, point in design.labels.values():
        if 0 <= int(body) < len(pts):
            pts[int(body)].append((float(point[0]), float(point[1])))
    for b in range(1, len(pts)):
        pts[b].append((0.0, 0.0))
    return [list(dict.fromkeys(p)) for p in pts]


def _ground_points(design: Design) -> list[tuple[float, float]]:
    out = []
    for j in design.joints:
        if j.body_i == 0:
            out.append(tuple(j.point_i))
        if j.body_j == 0:
            out.append(tuple(j.point_j))
    for s in design.springs:
        for at in (s.a, s.b):
            if at.body == 0:
                out.append(tuple(at.point))
    return list(dict.fromkeys(out))


def _structure(design: Design):
    return (len(design.bodies), tuple((j.body_i, j.body_j) for j in design.joints),
            tuple((s.a.body, s.b.body, s.realization, s.is_zfl) for s in design.springs),
            tuple((ld.body, ld.kind) for ld in design.loads), tuple(design.labels),
            tuple(len(p) for p in _body_points(design)), len(_ground_points(design)))


class _Geometry:
    """Every point a drawing needs, gathered for one vectorized world transform."""

    def __init__(self, design: Design):
        self.design = design
        self.body_pts = _body_points(design)
        att: list = []
        self.body_idx = []
        for b, pts in enumerate(self.body_pts):
            self.body_idx.append(list(range(len(att), len(att) + len(pts))))
            att += [(b, p) for p in pts]
        self.joint_idx = []
        for j in design.joints:
            self.joint_idx.append(len(att))
            att.append((j.body_i, tuple(j.point_i)))
        self.spring_idx = []
        for s in design.springs:
            self.spring_idx.append((len(att), len(att) + 1))
            att += [(s.a.body, tuple(s.a.point)), (s.b.body, tuple(s.b.point))]
        self.load_idx = []
        for ld in design.loads:
            self.load_idx.append(len(att))
            att.append((ld.body, tuple(ld.point)))
        self.label_idx = {}
        for name, (body, point) in design.labels.items():
            self.label_idx[name] = len(att)
            att.append((int(body), (float(point[0]), float(point[1]))))
        self.bodies = np.array([a[0] for a in att], dtype=int)
        self.points = np.array([a[1] for a in att], dtype=float).reshape(-1, 2)

    def world(self, q) -> np.ndarray:
        poses = self.design.poses(q)
        x, y = body_to_world(poses, self.bodies, self.points)
        return np.stack([x, y], axis=-1)


def _extent(design: Design, geom: _Geometry, n: int = 64):
    """Bounding box (xmin, xmax, ymin, ymax) of the mechanism over its range, and its size."""
    q = _range_grid(design, n)
    ok = design.reachable(q)
    q = q[ok] if ok.any() else design.sample(8, seed=0)
    W = geom.world(q).reshape(-1, 2)
    xmin, ymin = W.min(axis=0)
    xmax, ymax = W.max(axis=0)
    size = max(xmax - xmin, ymax - ymin, 1e-9)
    return np.array([xmin, xmax, ymin, ymax]), float(size)


# ----------------------------------------------------------------------- drawing
class Drawing:
    """The artists of a drawn design, updated in place by :meth:`update`.

    Created by :func:`draw` (and available as ``ax.drawing`` on the Axes it returns).

    Attributes
    ----------
    ax : matplotlib.axes.Axes
    design : Design
    q : numpy.ndarray
        The configuration drawn (rad).
    links : dict of int to matplotlib.patches.Polygon
        One artist per moving body: the convex outline through all its joint,
        attachment, load and label points (a bar for a binary link, a plate for a
        ternary one).
    joints : matplotlib.collections.PathCollection
        One marker per joint.
    ground : list of matplotlib.patches.Rectangle
        A hatched block under every ground pivot and spring anchor.
    springs : list of matplotlib.lines.Line2D
        One artist per spring: a solid coil for a ZFL spring, a dashed coil of another
        colour for a spring with a free length, a string over a pulley for
        ``realization == "pulley"`` (pulley circles are in ``extras``).
    loads : list of matplotlib.patches.Patch
        One artist per load: an arrow for a weight or force, a disc for a counterweight.
    load_segments : list of (numpy.ndarray, numpy.ndarray)
        Tail (the point of action) and head of each load's arrow (m); both the centre
        for a counterweight.
    labels : dict of str to matplotlib.text.Text
    label_dots : matplotlib.collections.PathCollection or None
        A small dot at every named point.
    extras : list
        Pulley circles and load points.
    """

    def __init__(self, design: Design, q=None, ax=None, *, labels: bool = True, color: str | None = None,
                 limits: bool = True, linewidth: float = 3.0, alpha: float = 1.0):
        self.ax = _new_axes(ax)
        self.show_labels = bool(labels)
        self.color = color or STYLE["link"]
        self.linewidth = float(linewidth)
        self.alpha = float(alpha)
        self.set_limits = bool(limits)
        self._artists: list = []
        self._build(_check_design(design), _as_config(design, q))

    # -- construction
    def _build(self, design: Design, q: np.ndarray) -> None:
        from matplotlib.patches import Circle, FancyArrowPatch, Polygon, Rectangle

        ax = self.ax
        for a in self._artists:
            a.remove()
        self._artists = []
        self.design = design
        self.q = q
        self.geom = _Geometry(design)
        self._struct = _structure(design)
        self._box, self.size = _extent(design, self.geom)
        L = self.size
        W = self.geom.world(q)
        a = self.alpha

        self.ground = []
        for p in _ground_points(design):
            r = Rectangle((p[0] - 0.04 * L, p[1] - 0.035 * L), 0.08 * L, 0.035 * L, facecolor="none",
                          edgecolor=STYLE["ground"], hatch="////", linewidth=0.8, alpha=a, zorder=1)
            ax.add_patch(r)
            self.ground.append(r)

        self.links = {}
        for b in range(1, len(design.bodies)):
            xy = _hull(W[self.geom.body_idx[b]])
            poly = Polygon(xy, closed=True, facecolor=_with_alpha(self.color, 0.15 * a),
                           edgecolor=_with_alpha(self.color, a), linewidth=self.linewidth,
                           joinstyle="round", capstyle="round", zorder=3)
            ax.add_patch(poly)
            self.links[b] = poly

        self.springs, self.extras = [], []
        self._pulleys = {}
        for i, s in enumerate(design.springs):
            zfl = s.is_zfl
            colour = STYLE["zfl"] if zfl else STYLE["spring"]
            style = "-" if zfl else (0, (3, 1.5))
            if s.realization == "pulley":
                colour, style = STYLE["string"], "-"
            line, = ax.plot([], [], color=colour, linestyle=style, linewidth=1.6, alpha=a, zorder=4,
                            solid_joinstyle="round", label=None)
            line.set_gid(f"spring:{s.name or i}")
            self.springs.append(line)
            if s.realization == "pulley":
                c = Circle((0, 0), 0.03 * L, facecolor="white", edgecolor=STYLE["string"],
                           linewidth=1.4, alpha=a, zorder=5)
                ax.add_patch(c)
                self._pulleys[i] = c
                self.extras.append(c)

        self.loads = []
        fmax = max([float(np.hypot(*ld.force)) for ld in design.loads] + [1e-300])
        self._load_len = []
        for ld in design.loads:
            f = float(np.hypot(*ld.force))
            if ld.kind == "counterweight":
                r = 0.025 * L + 0.035 * L * math.sqrt(f / fmax)
                art = Circle((0, 0), r, facecolor=STYLE["counterweight"], edgecolor="black",
                             linewidth=0.8, alpha=a, zorder=6)
                ax.add_patch(art)
                self._load_len.append(r)
            else:
                length = 0.06 * L + 0.09 * L * f / fmax
                art = FancyArrowPatch((0, 0), (0, -length), arrowstyle="-|>", mutation_scale=12,
                                      color=STYLE["load"], linewidth=2.0, alpha=a, zorder=6,
                                      shrinkA=0, shrinkB=0)
                ax.add_patch(art)
                self._load_len.append(length)
            art.set_gid(f"load:{ld.name}")
            self.loads.append(art)

        self.joints = ax.scatter(np.zeros(len(design.joints)), np.zeros(len(design.joints)), s=30,
                                 facecolor="white", edgecolor="black", linewidths=1.2, alpha=a,
                                 zorder=7)
        self.labels = {}
        self.label_dots = None
        if self.show_labels and design.labels:
            n = len(design.labels)
            self.label_dots = ax.scatter(np.zeros(n), np.zeros(n), s=6, color=STYLE["label"], alpha=a,
                                         zorder=7.5)
            for name in design.labels:
                t = ax.annotate(_tex_label(name), (0, 0), xytext=(5, 5), textcoords="offset points",
                                fontsize=9, color=STYLE["label"], alpha=a, zorder=8)
                self.labels[name] = t
        self._artists = (self.ground + list(self.links.values()) + self.springs + self.extras
                         + self.loads + [self.joints] + list(self.labels.values())
                         + ([self.label_dots] if self.label_dots is not None else []))
        if self.set_limits:
            self._apply_limits()
        ax.set_aspect("equal", adjustable="box" if self.set_limits else "datalim")
        ax.set_xlabel("x (m)")
        ax.set_ylabel("y (m)")
        self._place(W)

    def _apply_limits(self) -> None:
        x0, x1, y0, y1 = self._box
        pad = 0.05 * self.size + (max(self._load_len) if self._load_len else 0.0)
        self.ax.set_xlim(x0 - pad, x1 + pad)
        self.ax.set_ylim(y0 - pad, y1 + pad)

    # -- placing
    def _place(self, W: np.ndarray) -> None:
        g, d, L = self.geom, self.design, self.size
        for b, poly in self.links.items():
            poly.set_xy(_hull(W[g.body_idx[b]]))
        if d.joints:
            self.joints.set_offsets(W[g.joint_idx])
        for i, (s, line) in enumerate(zip(d.springs, self.springs)):
            ia, ib = g.spring_idx[i]
            pa, pb = W[ia], W[ib]
            if s.realization == "pulley":
                # the string runs from the moving end over a pulley at the other end, and on
                # to a coil hanging below the pulley whose stretch equals the string's run
                run = float(np.hypot(*(pb - pa)))
                drop = 0.15 * L + 0.5 * run
                c = np.array([pa[0] + 0.03 * L, pa[1]])
                top = np.array([c[0], c[1] - 0.25 * drop])
                cx, cy = _coil(top, np.array([c[0], c[1] - drop]), 0.02 * L)
                line.set_data(np.concatenate([[pb[0], pa[0], c[0]], cx]),
                              np.concatenate([[pb[1], pa[1] + 0.03 * L, c[1]], cy]))
                self._pulleys[i].center = (pa[0], pa[1])
            elif s.realization == "gas":
                m = pa + 0.55 * (pb - pa)
                u = pb - pa
                nrm = np.array([-u[1], u[0]]) / max(float(np.hypot(*u)), 1e-12) * 0.025 * L
                xs = [pa[0] + nrm[0], m[0] + nrm[0], m[0] - nrm[0], pa[0] - nrm[0], pa[0] + nrm[0],
                      np.nan, m[0], pb[0]]
                ys = [pa[1] + nrm[1], m[1] + nrm[1], m[1] - nrm[1], pa[1] - nrm[1], pa[1] + nrm[1],
                      np.nan, m[1], pb[1]]
                line.set_data(xs, ys)
            else:
                length = float(np.hypot(*(pb - pa)))
                turns = int(np.clip(round(length / (0.035 * L)), 2, 8))
                line.set_data(*_coil(pa, pb, 0.025 * L, turns=turns))
        self.load_segments = []
        for ld, art, ln, i in zip(d.loads, self.loads, self._load_len, g.load_idx):
            p = W[i]
            if ld.kind == "counterweight":
                art.center = (p[0], p[1])
                self.load_segments.append((p.copy(), p.copy()))
            else:
                f = np.asarray(ld.force, dtype=float)
                u = f / max(float(np.hypot(*f)), 1e-300)
                head = p + ln * u
                art.set_positions((p[0], p[1]), (head[0], head[1]))
                self.load_segments.append((p.copy(), head))
        for name, t in self.labels.items():
            t.xy = tuple(W[g.label_idx[name]])
        if self.label_dots is not None:
            self.label_dots.set_offsets(W[[g.label_idx[name] for name in self.labels]])

    def update(self, q=None, design: Design | None = None, *, rescale: bool = True) -> "Drawing":
        """Move the artists to configuration ``q`` (rad), optionally of another design.

        A design with the same structure (bodies, joints, springs, loads, labels) as
        the drawn one only moves the artists; otherwise they are rebuilt on the same
        Axes.

        Parameters
        ----------
        q : array_like, shape (dof,), optional
            Configuration (rad); the current one by default.
        design : Design, optional
            A new design to show (for example the same method with another parameter).
        rescale : bool
            Recompute the axis limits when the design changes.

        Returns
        -------
        Drawing
            ``self``.

        Raises
        ------
        UnreachableConfiguration
            If ``q`` cannot be reached; nothing is changed then.
        """
        if design is None:
            design = self.design
        _check_design(design)
        q = self.q if q is None else _as_config(design, q)
        if design is not self.design:
            if _structure(design) != self._struct:
                design.poses(q)  # raise before touching anything
                self._build(design, q)
                return self
            geom = _Geometry(design)
            W = geom.world(q)
            self.design, self.geom = design, geom
            if rescale:
                self._box, self.size = _extent(design, geom)
                if self.set_limits:
                    self._apply_limits()
        else:
            W = self.geom.world(q)
        self.q = q
        self._place(W)
        return self

    @property
    def artists(self) -> list:
        """Every artist of the drawing (for blitting and for removal)."""
        return list(self._artists)

    def set_visible(self, visible: bool) -> None:
        """Show or hide the whole mechanism."""
        for a in self._artists:
            a.set_visible(visible)


class _Blitter:
    """Render a figure whose only changes are a known set of artists, off screen (Agg).

    The figure without the changing artists is drawn once and kept; each frame restores
    that background and draws the changing artists over it. A full redraw happens on
    request (limits or colour scales changed) or when the set of artists changes.
    """

    def __init__(self, fig, dynamic: Callable[[], list]):
        self.fig = fig
        self.dynamic = dynamic
        self._bg = None
        self._ids: list = []
        self.full_draws = 0

    def invalidate(self) -> None:
        self._bg = None

    def render(self, full: bool = False) -> np.ndarray:
        """Return the figure's pixels, shape (h, w, 3) uint8 (a view of the canvas buffer)."""
        canvas = self.fig.canvas
        dyn = self.dynamic()
        ids = [id(a) for a in dyn]
        if full or self._bg is None or ids != self._ids:
            vis = [a.get_visible() for a in dyn]
            for a in dyn:
                a.set_visible(False)
            try:
                canvas.draw()
                self._bg = canvas.copy_from_bbox(self.fig.bbox)
            finally:
                for a, v in zip(dyn, vis):
                    a.set_visible(v)
            self._ids = ids
            self.full_draws += 1
        else:
            canvas.restore_region(self._bg)
        renderer = canvas.get_renderer()
        for a in sorted(dyn, key=lambda a: a.get_zorder()):
            if a.get_visible():
                a.draw(renderer)
        return np.asarray(canvas.buffer_rgba())[..., :3]


def _with_alpha(colour: str, alpha: float):
    from matplotlib.colors import to_rgba

    r, g, b, _ = to_rgba(colour)
    return (r, g, b, alpha)


_GREEK = {"alpha", "beta", "gamma", "delta", "theta", "phi", "psi", "varphi", "chi", "eta", "mu", "nu",
          "rho", "sigma", "tau", "omega", "xi", "zeta", "lambda", "kappa", "epsilon"}


def _tex_label(name: str) -> str:
    """``a1`` -> ``$a_{1}$``, ``k_b`` -> ``$k_{b}$``, ``theta_2`` -> ``$\\theta_{2}$``."""
    import re

    m = re.fullmatch(r"([A-Za-z]+?)_?(\d+|(?<=_)[A-Za-z]\w*)?", name)
    if not m:
        return name
    base, sub = m.group(1), m.group(2)
    if base in _GREEK:
        base = "\\" + base
    elif len(base) > 1:
        return name
    if sub:
        return f"${base}_{{{sub}}}$"
    return f"${base}$" if (base.startswith("\\") or base.islower()) else name


def draw(design: Design, q=None, ax=None, labels: bool = True, *, color: str | None = None,
         limits: bool = True, title: bool | str = True, alpha: float = 1.0):
    """Draw a design in one configuration.

    Parameters
    ----------
    design : Design
        Any design of the course.
    q : array_like, shape (dof,), optional
        Configuration (rad); :func:`default_q` by default.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on; a new figure by default.
    labels : bool
        Write the design's named points (``design.labels``).
    color : str, optional
        Colour of the links (to tell several designs apart on one Axes).
    limits : bool
        Set the axis limits to hold the mechanism over its whole range.
    title : bool or str
        ``True`` for the design's name, a string for a custom title, ``False`` for none.
    alpha : float
        Opacity of the whole drawing (0-1).

    Returns
    -------
    matplotlib.axes.Axes
        The Axes; its ``drawing`` attribute is the :class:`Drawing` holding the artists.

    Raises
    ------
    UnreachableConfiguration
        If ``q`` cannot be reached.

    Examples
    --------
    >>> import balancelab as bl
    >>> ax = draw(bl.singh.lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3), q=[0.5])
    >>> len(ax.drawing.links), len(ax.drawing.springs), len(ax.drawing.loads)
    (1, 1, 1)
    """
    _check_design(design)
    q = _as_config(design, q)
    design.poses(q)
    drawing = Drawing(design, q, ax, labels=labels, color=color, limits=limits, alpha=alpha)
    ax = drawing.ax
    if title:
        ax.set_title(design.name if title is True else str(title), fontsize=10)
    ax.drawing = drawing
    return ax


# ------------------------------------------------------------------------ energy
def energy_limits(lo: float, hi: float, scale: float = 0.0) -> tuple[float, float]:
    """y-limits (J) for energy curves spanning ``lo``..``hi``, never narrower than ``scale``.

    A balanced design whose energies are all constant would otherwise zoom in on
    round-off noise.

    Parameters
    ----------
    lo, hi : float
        Smallest and largest energy shown (J).
    scale : float
        The design's energy scale (J), see :class:`balancelab.BalanceReport`.

    Returns
    -------
    (float, float)

    Examples
    --------
    >>> energy_limits(-1e-15, 1e-15, 40.0)
    (-23.2, 23.2)
    """
    from ..core.validation import finite_real

    lo, hi = finite_real("lo (J)", lo), finite_real("hi (J)", hi)
    scale = finite_real("scale (J)", scale, nonnegative=True)
    if hi < lo:
        raise ValueError(f"need lo <= hi, got lo = {lo}, hi = {hi}")
    span = max(hi - lo, scale, 1e-12)
    mid = 0.5 * (lo + hi)
    lo, hi = min(lo, mid - span / 2), max(hi, mid + span / 2)
    pad = 0.08 * (hi - lo)
    return lo - pad, hi + pad


class EnergyView:
    """Energy curves (1 dof) or map (2 dof) of a design, updated in place.

    Created by :func:`energy_plot` (available as ``ax.energy``).

    Attributes
    ----------
    ax : matplotlib.axes.Axes
    design : Design
    report : BalanceReport or None
    lines : dict of str to Line2D
        ``"load"``, ``"spring"``, ``"total"`` (one degree of freedom).
    image : AxesImage
        Two degrees of freedom: the map of ``(total - mean) / scale`` (``mean`` and
        ``scale`` attributes, J), coloured over [-0.5, 0.5] for every design so a
        balanced design is one flat colour.
    marker : Line2D
        The current configuration.
    note : Text
        The balance verdict, and the residual when not balanced.
    """

    def __init__(self, design: Design, ax=None, *, n: int | None = None, report=None,
                 q=None, residual_ax=None, legend: bool = True, title: bool = True):
        _check_design(design)
        if design.dof > 2:
            raise ValueError(f"energy_plot draws 1 or 2 degrees of freedom; {design.name} has {design.dof}")
        self.ax = _new_axes(ax, figsize=(5.0, 3.4))
        self.n = _count("n", n) if n is not None else (241 if design.dof == 1 else 61)
        self.residual_ax = residual_ax
        self.show_title = title
        #: fixed energy-axis limits (J) for one dof; ``None`` to fit each design
        self.ylim: tuple | None = None
        self.lines: dict = {}
        self.image = None
        self.residual_image = None
        ax = self.ax
        if design.dof == 1:
            for key, label, colour, lw in (("load", "loads (gravity, forces)", STYLE["load"], 1.5),
                                           ("spring", "springs", STYLE["zfl"], 1.5),
                                           ("total", "total", STYLE["total"], 2.5)):
                self.lines[key], = ax.plot([], [], color=colour, linewidth=lw, label=label)
            self.worst, = ax.plot([], [], linestyle="none", marker="x", color=PALETTE["vermillion"],
                                  markersize=9, markeredgewidth=2)
            self.marker, = ax.plot([], [], linestyle="none", marker="o", color="black",
                                   markerfacecolor=PALETTE["yellow"], markersize=8, zorder=5)
            ax.set_xlabel(f"{_tex_label(design.q_names[0])} (deg)")
            ax.set_ylabel("potential energy (J)")
            if legend:
                ax.legend(loc="best", fontsize=8, framealpha=0.85)
        else:
            (x0, x1), (y0, y1) = np.degrees(design.q_range)
            extent = (x0, x1, y0, y1)
            self.image = ax.imshow(np.zeros((2, 2)), origin="lower", aspect="auto", cmap="cividis",
                                   extent=extent, interpolation="nearest")
            self.colorbar = ax.figure.colorbar(self.image, ax=ax,
                                               label="(total − mean) / energy scale")
            self.marker, = ax.plot([], [], linestyle="none", marker="o", color="black",
                                   markerfacecolor=PALETTE["yellow"], markersize=8)
            self.worst, = ax.plot([], [], linestyle="none", marker="x", color=PALETTE["vermillion"],
                                  markersize=9, markeredgewidth=2)
            ax.set_xlabel(f"{_tex_label(design.q_names[0])} (deg)")
            ax.set_ylabel(f"{_tex_label(design.q_names[1])} (deg)")
            if residual_ax is not None:
                self.residual_image = residual_ax.imshow(np.zeros((2, 2)), origin="lower", aspect="auto",
                                                         cmap="magma", extent=extent,
                                                         interpolation="nearest")
                self.residual_colorbar = residual_ax.figure.colorbar(
                    self.residual_image, ax=residual_ax, label="|dV/dq| / scale (1/rad)")
                residual_ax.set_xlabel(f"{_tex_label(design.q_names[0])} (deg)")
                residual_ax.set_ylabel(f"{_tex_label(design.q_names[1])} (deg)")
                residual_ax.set_title("residual generalized force", fontsize=10)
        self.note = ax.text(0.02, 0.03, "", transform=ax.transAxes, fontsize=8, va="bottom",
                            ha="left", color="black",
                            bbox=dict(boxstyle="round,pad=0.25", facecolor="white", alpha=0.8,
                                      edgecolor="none"))
        self.update(design, report=report, q=q)

    def update(self, design: Design | None = None, *, report=None, q=None) -> "EnergyView":
        """Recompute the curves (or map) for ``design`` and move the marker to ``q``.

        Parameters
        ----------
        design : Design, optional
            New design (same number of coordinates); the current one by default.
        report : BalanceReport, optional
            Its balance report, if already computed.
        q : array_like, optional
            Configuration (rad) to mark.

        Returns
        -------
        EnergyView
        """
        if design is not None:
            _check_design(design)
            self.design = design
            self.report = report if report is not None else _safe_report(design)
            self._compute()
        if q is not None:
            self.set_q(q)
        return self

    def _compute(self) -> None:
        d, ax = self.design, self.ax
        rep = self.report
        grid = _range_grid(d, self.n if d.dof == 1 else self.n * self.n)
        ok = d.reachable(grid)
        total = np.full(len(grid), np.nan)
        load = np.full(len(grid), np.nan)
        spring = np.full(len(grid), np.nan)
        if ok.any():
            e = d.potential_energy(grid[ok])
            total[ok], load[ok], spring[ok] = e.total, e.load, e.spring
        self.grid, self.total, self.load, self.spring = grid, total, load, spring
        if d.dof == 1:
            x = np.degrees(grid[:, 0])
            self.lines["load"].set_data(x, load)
            self.lines["spring"].set_data(x, spring)
            self.lines["total"].set_data(x, total)
            vals = np.concatenate([v[np.isfinite(v)] for v in (load, spring, total)] + [[0.0]])
            ax.set_xlim(x[0], x[-1])
            ax.set_ylim(*(self.ylim or energy_limits(vals.min(), vals.max(),
                                                     rep.scale if rep is not None else 0.0)))
        else:
            m = int(round(math.sqrt(len(grid))))
            Z = total.reshape(m, m)
            self.mean = float(np.nanmean(Z)) if np.isfinite(Z).any() else 0.0
            self.scale = rep.scale if rep is not None else float(np.nanmax(np.abs(Z - self.mean)) or 1.0)
            # deviation from the mean in units of the energy scale: one fixed colour range
            # for every design, a single flat colour when balanced
            self.image.set_data((Z - self.mean) / self.scale)
            self.image.set_clim(-0.5, 0.5)
            if self.residual_image is not None:
                gf = np.full(len(grid), np.nan)
                if ok.any():
                    gf[ok] = np.max(np.abs(d.generalized_force(grid[ok])), axis=-1)
                scale = rep.scale if rep is not None else 1.0
                R = (gf / scale).reshape(m, m)
                self.residual_image.set_data(R)
                top = float(np.nanmax(R)) if np.isfinite(R).any() else 1.0
                self.residual_image.set_clim(0.0, max(top, 1e-12))
        if rep is None:
            self.note.set_text("nothing stores energy as this design moves")
            self.worst.set_data([], [])
        elif rep.balanced:
            self.note.set_text(f"balanced: total constant to {rep.variation:.1e}\n"
                               f"of the energy scale ({rep.scale:.3g} J)")
            self.worst.set_data([], [])
        else:
            wq = np.atleast_1d(rep.worst_q)
            self.note.set_text(f"not balanced: total varies by {rep.variation:.2g} of the scale\n"
                               f"largest |dV/dq| = {rep.residual * rep.scale:.3g} J/rad (×)")
            if d.dof == 1:
                self.worst.set_data([np.degrees(wq[0])], [float(d.potential_energy(wq).total)])
            else:
                self.worst.set_data([np.degrees(wq[0])], [np.degrees(wq[1])])
        if self.show_title:
            ax.set_title(f"{d.name}: " + ("balanced" if rep is not None and rep.balanced else
                                          "not balanced"), fontsize=10)

    @property
    def artists(self) -> list:
        """The artists that change with the design or the configuration."""
        arts = list(self.lines.values()) + [self.marker, self.worst, self.note]
        return arts + [a for a in (self.image, self.residual_image) if a is not None]

    def set_visible(self, visible: bool) -> None:
        """Show or hide the curves, map, markers and note."""
        for a in self.artists:
            a.set_visible(visible)

    def set_q(self, q) -> None:
        """Move the marker to configuration ``q`` (rad)."""
        q = np.asarray(q, dtype=float).reshape(-1)
        if self.design.dof == 1:
            v = float(self.design.potential_energy(q).total)
            self.marker.set_data([np.degrees(q[0])], [v])
        else:
            self.marker.set_data([np.degrees(q[0])], [np.degrees(q[1])])


def energy_plot(design: Design, ax=None, *, q=None, n: int | None = None, residual: bool | None = None,
                legend: bool = True):
    """Load, spring and total potential energy over the configuration range.

    One degree of freedom: three curves against the coordinate (in degrees), the
    total flat for a balanced design; when it is not balanced the spread and the
    largest residual ``|dV/dq|`` are written and the worst configuration marked.
    Two degrees of freedom: a map of the total energy's deviation from its mean in
    units of the design's energy scale (the sum of the spreads of every load and
    spring energy), so a balanced design is one flat colour, and optionally a map of
    the residual generalized force. The balance verdict is in the title.

    Parameters
    ----------
    design : Design
        A design with 1 or 2 coordinates.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (a new figure by default).
    q : array_like, optional
        A configuration (rad) to mark.
    n : int, optional
        Points (an integer >= 2) along the range (1 dof, default 241) or per side of the map (2 dof,
        default 61).
    residual : bool or matplotlib.axes.Axes, optional
        Two degrees of freedom only: draw the map of the residual generalized force
        ``|dV/dq| / scale`` too, on a second Axes of a new figure (``True``, the default
        when ``ax`` is not given) or on the Axes given.
    legend : bool
        Show the legend (1 dof).

    Returns
    -------
    matplotlib.axes.Axes
        The energy Axes; ``ax.energy`` is the :class:`EnergyView`.

    Examples
    --------
    >>> import balancelab as bl
    >>> ax = energy_plot(bl.singh.lacoste_lever(weight=10.0, l=0.5, a_x=0.2, b_y=0.3))
    >>> ax.energy.report.balanced
    True
    """
    _check_design(design)
    residual_ax = None
    if design.dof == 2:
        if residual is None:
            residual = ax is None
        if hasattr(residual, "imshow"):
            residual_ax = residual
        elif residual and ax is None:
            plt = _plt()
            fig, (ax, residual_ax) = plt.subplots(1, 2, figsize=(9.5, 3.6), layout="constrained")
        elif residual:
            raise ValueError("with ax given, pass the Axes for the residual map as residual=")
    view = EnergyView(design, ax, n=n, q=q, residual_ax=residual_ax, legend=legend)
    view.ax.energy = view
    return view.ax


# ----------------------------------------------------------------- design spaces
def lever_valley(weight: float = 10.0, l: float = 0.5, a_range=(0.05, 1.0), b_range=(0.05, 1.0), *,
                 n: int = 120, ax=None, kind: str = "contour"):
    """Balanced potential energy of LaCoste's lever over its two free choices (Singh Fig. 2).

    With ``k = W l / (a_x b_y)`` the lever is balanced for every ``(a_x, b_y)`` and its
    constant energy is ``PE = W l / (2 a_x b_y) (a_x^2 + b_y^2)`` (Singh &
    Ananthasuresh, eq. 3). It is smallest, ``PE = W l``, all along the valley
    ``a_x = b_y`` (eqs 4-9), which is drawn dashed.

    Parameters
    ----------
    weight : float
        W (N), > 0.
    l : float
        Distance of the load from the pivot (m), > 0.
    a_range, b_range : (float, float)
        Ranges of ``a_x`` and ``b_y`` (m), both ends > 0.
    n : int
        Grid points per side, >= 2.
    ax : matplotlib.axes.Axes, optional
        Axes (3-D Axes for ``kind="surface"``); a new figure by default.
    kind : {"contour", "surface"}
        Filled contour map or 3-D surface.

    Returns
    -------
    matplotlib.axes.Axes
        With ``ax.valley = (A, B, PE)``, the grid (m, m, J).

    Examples
    --------
    >>> ax = lever_valley(10.0, 0.5, n=40)
    >>> A, B, PE = ax.valley
    >>> bool(abs(PE.min() - 5.0) < 0.05)
    True
    """
    from ..core.validation import finite_real

    W = finite_real("weight W (N)", weight, positive=True)
    l = finite_real("l (m)", l, positive=True)
    rngs = []
    for name, r in (("a_range", a_range), ("b_range", b_range)):
        lo, hi = (finite_real(f"{name} start (m)", r[0], positive=True),
                  finite_real(f"{name} end (m)", r[1], positive=True))
        if hi <= lo:
            raise ValueError(f"{name} must be increasing, got {r}")
        rngs.append((lo, hi))
    if kind not in ("contour", "surface"):
        raise ValueError(f"kind must be 'contour' or 'surface', got {kind!r}")
    n = _count("n", n)
    a = np.linspace(*rngs[0], n)
    b = np.linspace(*rngs[1], n)
    A, B = np.meshgrid(a, b)
    PE = W * l / (2 * A * B) * (A ** 2 + B ** 2)
    lo_v = max(rngs[0][0], rngs[1][0])
    hi_v = min(rngs[0][1], rngs[1][1])
    if kind == "surface":
        if ax is None:
            plt = _plt()
            fig = plt.figure(figsize=(5.5, 4.5), layout="constrained")
            ax = fig.add_subplot(projection="3d")
        top = np.minimum(PE, np.quantile(PE, 0.9))
        ax.plot_surface(A, B, top, cmap="cividis", linewidth=0, antialiased=True, alpha=0.9)
        v = np.linspace(lo_v, hi_v, 50)
        ax.plot(v, v, np.full_like(v, W * l), color=PALETTE["vermillion"], linewidth=2.5,
                label=f"valley a_x = b_y, PE = W l = {W * l:.3g} J")
        ax.set_zlabel("PE (J)")
        ax.legend(fontsize=8)
    else:
        ax = _new_axes(ax, figsize=(5.0, 4.2))
        levels = W * l * np.geomspace(1.0, float(PE.max()) / (W * l), 16)
        from matplotlib.colors import LogNorm

        cs = ax.contourf(A, B, PE, levels=levels, cmap="cividis", norm=LogNorm())
        cb = ax.figure.colorbar(cs, ax=ax, label="balanced PE (J)")
        cb.set_ticks(levels[::3])
        cb.set_ticklabels([f"{v:.3g}" for v in levels[::3]])
        cb.minorticks_off()
        ax.plot([lo_v, hi_v], [lo_v, hi_v], "--", color=PALETTE["vermillion"], linewidth=2,
                label=f"valley $a_x = b_y$: PE = W l = {W * l:.3g} J")
        ax.set_aspect("equal")
        ax.legend(loc="upper left", fontsize=8)
    ax.set_xlabel("$a_x$ (m)")
    ax.set_ylabel("$b_y$ (m)")
    ax.set_title(f"LaCoste lever, W = {W:g} N, l = {l:g} m", fontsize=10)
    ax.valley = (A, B, PE)
    return ax


def _family_values(factory: Callable, name: str, values, fixed: Mapping | None):
    out = []
    for v in values:
        try:
            out.append((float(v), factory(**{**(fixed or {}), name: v}), None))
        except (ValueError, ArithmeticError, UnreachableConfiguration) as exc:
            out.append((float(v), None, exc))
    return out


def family_plot(factory: Callable, name: str, values: Sequence[float], *, q=None, points=None,
                fixed: Mapping | None = None, axes=None, reference: float | None = None):
    """A one-parameter family of designs: loci of points and spring constants along it.

    ``factory(**{name: v})`` is called for every value. When it returns a
    :class:`Design`, the design at ``reference`` is drawn at ``q``, the positions
    (at ``q``) of the named points that move along the family are traced as loci over
    it, and the stiffness of every spring (by its name) is plotted against ``v``.
    When it returns a mapping, every number in it is plotted against ``v`` and every
    pair ``(x, y)`` is traced as a locus. Values for which the factory raises
    ``ValueError`` are skipped (and counted in the title).

    Parameters
    ----------
    factory : callable
        ``factory(**{name: value, **fixed})`` -> Design or mapping.
    name : str
        The free parameter.
    values : sequence of float
        Its values.
    q : array_like, optional
        Configuration at which the loci are taken (designs only).
    points : sequence of str, optional
        Label names to trace (designs) or keys of point entries (mappings); by default
        every label or pair that moves.
    fixed : mapping, optional
        Other keyword arguments for ``factory``.
    axes : pair of Axes, optional
        Where to draw (loci, constants); a new figure by default.
    reference : float, optional
        The value whose design is drawn (default: the middle valid value).

    Returns
    -------
    (Axes, Axes)
        The locus Axes and the constants Axes; ``axes[0].family`` holds the computed
        ``{"values", "loci", "constants"}``.

    Examples
    --------
    >>> import balancelab as bl
    >>> ax1, ax2 = family_plot(lambda a_x: bl.singh.lacoste_lever(10.0, 0.5, a_x, 0.3), "a_x",
    ...                        [0.1, 0.2, 0.3])
    >>> [round(float(k), 2) for k in ax1.family["constants"]["k"]]
    [166.67, 83.33, 55.56]
    """
    if not callable(factory):
        raise TypeError("factory must be callable: factory(**{name: value}) -> Design or dict")
    values = list(values)
    if not values:
        raise ValueError("values must hold at least one parameter value")
    rows = _family_values(factory, name, values, fixed)
    good = [(v, d) for v, d, e in rows if e is None]
    if not good:
        raise ValueError(f"the factory failed for every value of {name}: {rows[0][2]}")
    if axes is None:
        plt = _plt()
        fig, axes = plt.subplots(1, 2, figsize=(9.5, 3.8), layout="constrained")
    ax_l, ax_k = axes
    vs = np.array([v for v, _ in good])
    loci: dict = {}
    consts: dict = {}
    first = good[0][1]
    if isinstance(first, Design):
        ref = good[len(good) // 2] if reference is None else min(good, key=lambda t: abs(t[0] - reference))
        qq = _as_config(ref[1], q)
        names = list(points) if points is not None else list(first.labels)
        for lab in names:
            pts = []
            for _, d in good:
                if lab not in d.labels:
                    raise ValueError(f"point {lab!r} is not a label of {d.name}; labels: {list(d.labels)}")
                pts.append(d.world_points(qq, [d.labels[lab]])[0])
            pts = np.array(pts)
            if points is not None or np.ptp(pts, axis=0).max() > 1e-12:
                loci[lab] = pts
        # spring constants by spring name (NaN where a design has no such spring)
        for _, d in good:
            for i, s in enumerate(d.springs):
                consts.setdefault(s.name or f"spring {i + 1}", None)
        for key in consts:
            consts[key] = np.array([next((s.k for i, s in enumerate(d.springs)
                                          if (s.name or f"spring {i + 1}") == key), np.nan)
                                    for _, d in good])
        draw(ref[1], qq, ax=ax_l, title=f"{ref[1].name}, {name} = {ref[0]:.3g}")
        ylab = "spring constant (N/m)"
    else:
        for key, val in first.items():
            arr = np.asarray(val, dtype=float)
            if arr.shape == (2,):
                if points is None or key in points:
                    loci[key] = np.array([np.asarray(m[key], dtype=float) for _, m in good])
            elif arr.shape == ():
                consts[key] = np.array([float(m[key]) for _, m in good])
        ax_l.set_aspect("equal", adjustable="datalim")
        ax_l.set_xlabel("x (m)")
        ax_l.set_ylabel("y (m)")
        ylab = "value"
    colours = [PALETTE[c] for c in ("blue", "vermillion", "green", "orange", "purple", "sky", "black")]
    for i, (lab, pts) in enumerate(loci.items()):
        c = colours[i % len(colours)]
        ax_l.plot(pts[:, 0], pts[:, 1], ":", color=c, linewidth=1.8, label=f"locus of {lab}")
        ax_l.plot(pts[[0, -1], 0], pts[[0, -1], 1], linestyle="none", marker="o", markersize=4, color=c)
    if loci:
        ax_l.legend(fontsize=8, loc="best")
    for i, (lab, ks) in enumerate(consts.items()):
        ax_k.plot(vs, ks, color=colours[i % len(colours)], linewidth=2, label=_tex_label(lab))
    ax_k.set_xlabel(_tex_label(name))
    ax_k.set_ylabel(ylab)
    if consts:
        ax_k.legend(fontsize=8)
    skipped = len(rows) - len(good)
    ax_k.set_title(f"along the family ({len(good)} designs" +
                   (f", {skipped} invalid values skipped)" if skipped else ")"), fontsize=10)
    ax_l.family = {"values": vs, "loci": loci, "constants": consts}
    return ax_l, ax_k


def cognates_plot(designs: Sequence[Design], point: str = "P", *, q=None, n: int = 361, ax=None,
                  show: bool = True):
    """Several linkages (cognates) and the curves traced by one named point of each.

    Every design is drawn in its own colour and the path of its label ``point`` over
    its whole reachable range is traced; for Roberts-Chebyshev cognates the curves
    coincide.

    Parameters
    ----------
    designs : sequence of Design
        One-degree-of-freedom designs, each with a label ``point``.
    point : str
        Name of the traced point (for example the coupler point ``"P"``).
    q : sequence of array_like, optional
        One configuration (rad) per design at which to draw it (default:
        :func:`default_q` of each).
    n : int
        Samples along each range, >= 2.
    ax : matplotlib.axes.Axes, optional
    show : bool
        Draw the mechanisms (otherwise only the curves).

    Returns
    -------
    matplotlib.axes.Axes
        With ``ax.curves`` = list of ``(n_i, 2)`` arrays (m), one per design.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)
    >>> ax = cognates_plot([d], point="p")
    >>> round(float(np.hypot(*ax.curves[0][0])), 3)
    0.5
    """
    designs = list(designs)
    if not designs:
        raise ValueError("designs must hold at least one Design")
    n = _count("n", n)
    ax = _new_axes(ax, figsize=(5.5, 4.5))
    colours = [PALETTE[c] for c in ("blue", "vermillion", "green", "orange", "purple", "sky")]
    curves = []
    for i, d in enumerate(designs):
        _check_design(d)
        if point not in d.labels:
            raise ValueError(f"{d.name} has no point named {point!r}; its labels are {list(d.labels)}")
        c = colours[i % len(colours)]
        grid = _range_grid(d, n) if d.dof == 1 else d.sample(n, seed=0)
        ok = d.reachable(grid)
        pts = d.world_points(grid[ok], [d.labels[point]])[:, 0, :]
        curves.append(pts)
        ax.plot(pts[:, 0], pts[:, 1], "-" if i == 0 else "--", color=c, linewidth=2.2 - 0.4 * min(i, 3),
                label=f"{d.name}: path of {point}")
        if show:
            Drawing(d, None if q is None else q[i], ax, labels=(i == 0), color=c, limits=False, linewidth=2.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.legend(fontsize=8, loc="best")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.autoscale_view()
    ax.curves = curves
    return ax
