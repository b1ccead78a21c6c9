"""The picture of a design in one configuration: :func:`draw` and its :class:`Drawing`.

Links are drawn as bars or plates through all their joint and attachment points, the
ground hatched at its pivots and anchors, ZFL springs as solid coils, springs with a
free length as dashed coils of another colour, springs realized by a pulley as a
string over their pulley (:mod:`balancelab.viz.springs`), weights and forces as arrows,
counterweights as discs, and the papers' point names. Every position is the design's
own (:meth:`balancelab.Design.poses`), gathered by
:class:`~balancelab.viz.outline.Geometry` for one vectorized transform
(:mod:`balancelab.viz.outline`: what is drawn where; this module: how).

The artists are kept (:class:`Drawing`) so that animations and explorers move them in
place instead of redrawing the figure. Layer: viz.
"""
from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..core.design import Design
from .style import FONT, arrange_labels, fit_title
from .frame import STYLE, as_config, check_design, new_axes, tex_label
from .outline import Geometry, extent, hull
from .springs import cable_angle, profile_outline, pulley_drawn_radius, spring_path, spring_style

__all__ = ["Drawing", "Geometry", "draw", "extent"]


def _with_alpha(colour: str, alpha: float):
    from matplotlib.colors import to_rgba

    r, g, b, _ = to_rgba(colour)
    return (r, g, b, alpha)


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
        colour for a spring with a free length, and for a spring realized by a pulley
        (``spring.pulley``) a string from its attachment ``b`` over the pulley centred at
        ``a`` to a coil on the pulley's ``spring_direction`` side (pulley circles are in
        ``extras``).
    loads : list of matplotlib.patches.Patch
        One artist per load: an arrow for a weight or force, a disc for a counterweight.
    load_segments : list of (numpy.ndarray, numpy.ndarray)
        Tail (the point of action) and head of each load's arrow (m); both the centre
        for a counterweight.
    load_lengths : list of float
        Length of each load's arrow, or radius of its disc (m).
    labels : dict of str to matplotlib.text.Text
    label_dots : matplotlib.collections.PathCollection or None
        A small dot at every named point.
    extras : list
        Pulley circles.
    size : float
        Size of the mechanism over its range (m), which scales the symbols.

    Examples
    --------
    >>> import balancelab as bl
    >>> dr = Drawing(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3), [0.0])
    >>> [float(v) for v in dr.labels["p"].xy]
    [0.5, 0.0]
    >>> round(float(dr.update([np.pi / 2]).labels["p"].xy[1]), 12)
    0.5
    """

    def __init__(self, design: Design, q=None, ax=None, *, labels: bool = True, color: str | None = None,
                 limits: bool = True, linewidth: float = 3.0, alpha: float = 1.0) -> None:
        self.ax = new_axes(ax)
        self.show_labels = bool(labels)
        self.color = color or STYLE["link"]
        self.linewidth = float(linewidth)
        self.alpha = float(alpha)
        self.set_limits = bool(limits)
        self._artists: list = []
        self._build(check_design(design), as_config(design, q))

    # -- construction
    def _build(self, design: Design, q: np.ndarray) -> None:
        for a in self._artists:
            a.remove()
        self.design = design
        self.q = q
        self.geom = Geometry(design)
        self._box, self.size = extent(design, self.geom)
        W = self.geom.world(q)
        self._build_ground()
        self._build_links(W)
        self._build_springs()
        self._build_loads()
        self._build_marks()
        self._artists = (self.ground + list(self.links.values()) + self.springs + self.extras
                         + self.loads + [self.joints] + list(self.labels.values())
                         + ([self.label_dots] if self.label_dots is not None else []))
        if self.set_limits:
            self._apply_limits()
            self.ax.set_aspect("equal", adjustable="box")
        elif self.ax.get_aspect() != 1.0:  # a rebuild keeps the limits and adjustable its caller set
            self.ax.set_aspect("equal", adjustable="datalim")
        self.ax.set_xlabel("x (m)")
        self.ax.set_ylabel("y (m)")
        self._place(W)

    def _build_ground(self) -> None:
        from matplotlib.patches import Rectangle

        L = self.size
        self.ground = []
        for p in self.geom.ground:
            r = Rectangle((p[0] - 0.04 * L, p[1] - 0.035 * L), 0.08 * L, 0.035 * L, facecolor="none",
                          edgecolor=STYLE["ground"], hatch="////", linewidth=0.8, alpha=self.alpha, zorder=1)
            self.ax.add_patch(r)
            self.ground.append(r)

    def _build_links(self, W: np.ndarray) -> None:
        from matplotlib.patches import Polygon

        a = self.alpha
        self.links = {}
        for b in range(1, len(self.design.bodies)):
            poly = Polygon(hull(W[self.geom.body_idx[b]]), closed=True,
                           facecolor=_with_alpha(self.color, 0.15 * a), edgecolor=_with_alpha(self.color, a),
                           linewidth=self.linewidth, joinstyle="round", capstyle="round", zorder=3)
            self.ax.add_patch(poly)
            self.links[b] = poly

    def _build_springs(self) -> None:
        from matplotlib.patches import Circle

        self.springs, self.extras, self._pulleys = [], [], {}
        for i, s in enumerate(self.design.springs):
            colour, style = spring_style(s)
            line, = self.ax.plot([], [], color=colour, linestyle=style, linewidth=1.6, alpha=self.alpha,
                                 zorder=4, solid_joinstyle="round", label=None)
            line.set_gid(f"spring:{s.name or i}")
            self.springs.append(line)
            if s.cable is not None:   # the non-circular pulley, carried by the link
                prof, = self.ax.fill([], [], facecolor="#dddddd", edgecolor=STYLE["string"], linewidth=1.0,
                                     alpha=self.alpha, zorder=3.5)
                self._pulleys[i] = prof
                self.extras.append(prof)
            if s.pulley is not None:
                c = Circle((0, 0), pulley_drawn_radius(s.pulley, self.size), facecolor="white",
                           edgecolor=STYLE["string"], linewidth=1.4, alpha=self.alpha, zorder=5)
                self.ax.add_patch(c)
                self._pulleys[i] = c
                self.extras.append(c)

    def _build_loads(self) -> None:
        from matplotlib.patches import Circle, FancyArrowPatch

        L, a = self.size, self.alpha
        loads = self.design.loads
        fmax = max([float(np.hypot(*ld.force)) for ld in loads] + [1e-300])
        # a Circle for a counterweight, a FancyArrowPatch for any other load (see update)
        self.loads: list[Any] = []
        self.load_lengths: list[float] = []
        for ld in loads:
            f = float(np.hypot(*ld.force))
            art: Circle | FancyArrowPatch
            if ld.kind == "counterweight":
                length = 0.025 * L + 0.035 * L * math.sqrt(f / fmax)
                art = Circle((0, 0), length, facecolor=STYLE["counterweight"], edgecolor="black",
                             linewidth=0.8, alpha=a, zorder=6)
            else:
                length = 0.06 * L + 0.09 * L * f / fmax
                art = FancyArrowPatch((0, 0), (0, -length), arrowstyle="-|>", mutation_scale=12,
                                      color=STYLE["load"], linewidth=2.0, alpha=a, zorder=6,
                                      shrinkA=0, shrinkB=0)
            self.ax.add_patch(art)
            self.load_lengths.append(length)
            art.set_gid(f"load:{ld.name}")
            self.loads.append(art)

    def _build_marks(self) -> None:
        ax, a, design = self.ax, self.alpha, self.design
        self.joints = ax.scatter(np.zeros(len(design.joints)), np.zeros(len(design.joints)), s=30,
                                 facecolor="white", edgecolor="black", linewidths=1.2, alpha=a, zorder=7)
        self.labels = {}
        self.label_dots = None
        if self.show_labels and design.labels:
            n = len(design.labels)
            self.label_dots = ax.scatter(np.zeros(n), np.zeros(n), s=6, color=STYLE["label"], alpha=a,
                                         zorder=7.5)
            for name in design.labels:
                self.labels[name] = ax.annotate(tex_label(name), (0, 0), xytext=(5, 5),
                                                textcoords="offset points", fontsize=FONT["annotation"],
                                                color=STYLE["label"], alpha=a, zorder=8)

    def padded(self, box) -> np.ndarray:
        """Axis limits ``[x0, x1, y0, y1]`` (m) holding ``box`` with room for the load symbols.

        Parameters
        ----------
        box : array_like
            ``[xmin, xmax, ymin, ymax]`` (m), for example from :func:`extent`.

        Returns
        -------
        numpy.ndarray

        Examples
        --------
        >>> import balancelab as bl
        >>> dr = Drawing(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3), [0.0])
        >>> bool(np.all(dr.padded([0, 1, 0, 1]) == [-dr.load_lengths[0] - 0.05, 1.05 + dr.load_lengths[0],
        ...                                         -dr.load_lengths[0] - 0.05, 1.05 + dr.load_lengths[0]]))
        True
        """
        x0, x1, y0, y1 = (float(v) for v in box)
        pad = 0.05 * max(x1 - x0, y1 - y0, 1e-9) + max(self.load_lengths or [0.0])
        return np.array([x0 - pad, x1 + pad, y0 - pad, y1 + pad])

    def _apply_limits(self) -> None:
        x0, x1, y0, y1 = self.padded(self._box)
        self.ax.set_xlim(x0, x1)
        self.ax.set_ylim(y0, y1)

    # -- placing
    def _place(self, W: np.ndarray) -> None:
        g, d = self.geom, self.design
        for b, poly in self.links.items():
            poly.set_xy(hull(W[g.body_idx[b]]))
        if d.joints:
            self.joints.set_offsets(W[g.joint_idx])
        for i, (s, line) in enumerate(zip(d.springs, self.springs)):
            pa, pb = W[g.spring_idx[i][0]], W[g.spring_idx[i][1]]
            if s.pulley is not None:
                radius = pulley_drawn_radius(s.pulley, self.size)
                self._pulleys[i].center = (pa[0], pa[1])
                self._pulleys[i].set_radius(radius)
                line.set_data(*spring_path(s, pa, pb, self.size, radius))
            elif s.cable is not None:
                self._pulleys[i].set_xy(np.column_stack(profile_outline(s, cable_angle(s, pb))))
                line.set_data(*spring_path(s, pa, pb, self.size))
            else:
                line.set_data(*spring_path(s, pa, pb, self.size))
        self.load_segments = []
        for ld, art, ln, i in zip(d.loads, self.loads, self.load_lengths, g.load_idx):
            p = W[i]
            if ld.kind == "counterweight":
                art.center = (p[0], p[1])
                self.load_segments.append((p.copy(), p.copy()))
            else:
                f = np.asarray(ld.force, dtype=float)
                head = p + ln * f / max(float(np.hypot(*f)), 1e-300)
                art.set_positions((p[0], p[1]), (head[0], head[1]))
                self.load_segments.append((p.copy(), head))
        for name, t in self.labels.items():
            t.xy = tuple(W[g.label_idx[name]])
        if self.label_dots is not None:
            self.label_dots.set_offsets(W[[g.label_idx[name] for name in self.labels]])
        if self.labels:
            self._arrange_labels(W)

    def _arrange_labels(self, W: np.ndarray) -> None:
        """Labels of coincident points merged, each turned away from its neighbours (see style)."""
        g = self.geom
        points = {n: W[g.label_idx[n]] for n in self.labels}
        self._label_dirs = arrange_labels(self.labels, points, {n: tex_label(n) for n in self.labels},
                                          W[g.joint_idx] if self.design.joints else (),
                                          getattr(self, "_label_dirs", None))

    def update(self, q=None, design: Design | None = None, *, rescale: bool = True) -> Drawing:
        """Move the artists to configuration ``q`` (rad), optionally of another design.

        A design with the same structure (bodies, joints, springs and their
        realizations, loads, labels) as the drawn one only moves the artists;
        otherwise they are rebuilt on the same Axes.

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
        check_design(design)
        q = self.q if q is None else as_config(design, q)
        if design is not self.design:
            geom = Geometry(design)
            if geom.structure != self.geom.structure:
                design.poses(q)  # raise before touching anything
                self._build(design, q)
                return self
            W = geom.world(q)
            self.design, self.geom = design, geom
            if rescale:
                self._box, self.size = extent(design, geom)
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


def draw(design: Design, q=None, ax=None, labels: bool = True, *, color: str | None = None,
         limits: bool = True, title: bool | str = True, alpha: float = 1.0):
    """Draw a design in one configuration.

    Parameters
    ----------
    design : Design
        Any design of the course.
    q : array_like, shape (dof,), optional
        Configuration (rad); :func:`~balancelab.viz.default_q` by default.
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
    >>> ax = draw(bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3), q=[0.5])
    >>> len(ax.drawing.links), len(ax.drawing.springs), len(ax.drawing.loads)
    (1, 1, 1)
    """
    check_design(design)
    q = as_config(design, q)
    design.poses(q)
    drawing = Drawing(design, q, ax, labels=labels, color=color, limits=limits, alpha=alpha)
    ax = drawing.ax
    if title:
        fit_title(ax, design.name if title is True else str(title), fontsize=FONT["title"])
    ax.drawing = drawing
    return ax
