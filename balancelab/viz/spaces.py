"""Views of a design space: the valley of balanced levers, a family of designs, cognates.

* :func:`lever_valley`: the balanced energy of LaCoste's lever over its two free
  choices, each point the energy of the lever :func:`balancelab.singh.lacoste_lever`
  builds there.
* :func:`family_plot`: loci of named points and spring constants along a
  one-parameter family of designs.
* :func:`cognates_plot`: several linkages and the curves one named point of each traces.

Every number shown is read from the designs (their energies, springs and points).
Layer: viz; imports ``balancelab.core``, ``balancelab.methods.singh`` (the levers and their
energies: :func:`balancelab.singh.lacoste_energies`).
"""
from __future__ import annotations

from typing import Any, Callable, Mapping, Sequence

import numpy as np

from ..core.design import Design, UnreachableConfiguration
from ..core.validation import finite_real
from ..methods.singh import lacoste_energies
from .drawing import Drawing, draw
from .style import FONT
from .frame import PALETTE, as_config, check_design, count, new_axes, range_grid, tex_label

__all__ = ["cognates_plot", "family_plot", "lever_valley"]

#: Colours of successive curves.
_COLOURS = [PALETTE[c] for c in ("blue", "vermillion", "green", "orange", "purple", "sky", "black")]


# ------------------------------------------------------------------ lever valley
def _valley_ranges(a_range, b_range) -> list:
    rngs = []
    for name, r in (("a_range", a_range), ("b_range", b_range)):
        lo, hi = (finite_real(f"{name} start (m)", r[0], positive=True),
                  finite_real(f"{name} end (m)", r[1], positive=True))
        if hi <= lo:
            raise ValueError(f"{name} must be increasing, got {r}")
        rngs.append((lo, hi))
    return rngs


def lever_valley(weight: float = 10.0, length: float = 0.5, a_range=(0.05, 1.0), b_range=(0.05, 1.0), *,
                 n: int = 60, ax=None, kind: str = "contour"):
    """Balanced potential energy of LaCoste's lever over its two free choices (Singh Fig. 2).

    Every grid point ``(a_x, b_y)`` is the lever :func:`balancelab.singh.lacoste_lever`
    builds there (``k = W l / (a_x b_y)``, balanced), and its value is that design's
    potential energy, constant over its range: ``PE = W l / (2 a_x b_y) (a_x^2 + b_y^2)``
    (Singh & Ananthasuresh, eq. 3). It is smallest, ``PE = W l``, all along the valley
    ``a_x = b_y`` (eqs 4-9), drawn dashed at the energies of the levers built on it.
    Building the ``n^2`` designs takes about 0.2 ms each.

    Parameters
    ----------
    weight : float
        W (N), > 0.
    length : float
        Length of the lever: the distance ``l`` of the load from the pivot (m), > 0.
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
    W = finite_real("weight W (N)", weight, positive=True)
    length = finite_real("length (m)", length, positive=True)
    rngs = _valley_ranges(a_range, b_range)
    if kind not in ("contour", "surface"):
        raise ValueError(f"kind must be 'contour' or 'surface', got {kind!r}")
    n = count("n", n)
    A, B = np.meshgrid(np.linspace(rngs[0][0], rngs[0][1], n), np.linspace(rngs[1][0], rngs[1][1], n))
    PE = lacoste_energies(W, length, A, B)
    v = np.linspace(max(rngs[0][0], rngs[1][0]), min(rngs[0][1], rngs[1][1]), 25)
    pe_v = lacoste_energies(W, length, v, v)
    label = f"valley $a_x = b_y$: PE = W l = {float(np.mean(pe_v)):.3g} J"
    if kind == "surface":
        ax = _valley_surface(ax, A, B, PE, v, pe_v, label)
    else:
        ax = _valley_contour(ax, A, B, PE, v, pe_v, label)
    ax.set_xlabel("$a_x$ (m)")
    ax.set_ylabel("$b_y$ (m)")
    ax.set_title(f"LaCoste lever, W = {W:g} N, l = {length:g} m", fontsize=FONT["title"])
    ax.valley = (A, B, PE)
    return ax


def _valley_surface(ax, A, B, PE, v, pe_v, label: str):
    if ax is None:
        import matplotlib.pyplot as plt

        fig = plt.figure(figsize=(5.5, 4.5), layout="constrained")
        ax = fig.add_subplot(projection="3d")
    top = np.minimum(PE, np.quantile(PE, 0.9))
    ax.plot_surface(A, B, top, cmap="cividis", linewidth=0, antialiased=True, alpha=0.9)
    ax.plot(v, v, pe_v, color=PALETTE["vermillion"], linewidth=2.5, label=label.replace("$", ""))
    ax.set_zlabel("PE (J)")
    ax.legend(fontsize=FONT["legend"])
    return ax


def _valley_contour(ax, A, B, PE, v, pe_v, label: str):
    from matplotlib.colors import LogNorm

    ax = new_axes(ax, figsize=(5.0, 4.2))
    floor = min(float(np.min(PE)), float(np.min(pe_v)))
    levels = floor * np.geomspace(1.0, float(PE.max()) / floor, 16)
    cs = ax.contourf(A, B, PE, levels=levels, cmap="cividis", norm=LogNorm())
    cb = ax.figure.colorbar(cs, ax=ax, label="balanced PE (J)")
    cb.set_ticks(levels[::3])
    cb.set_ticklabels([f"{x:.3g}" for x in levels[::3]])
    cb.minorticks_off()
    ax.plot(v[[0, -1]], v[[0, -1]], "--", color=PALETTE["vermillion"], linewidth=2, label=label)
    ax.set_aspect("equal")
    ax.legend(loc="upper left", fontsize=FONT["legend"])
    return ax


# -------------------------------------------------------------------- families
def _family_values(factory: Callable, name: str, values, fixed: Mapping | None):
    out: list[tuple[float, Any, Exception | None]] = []
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
        import matplotlib.pyplot as plt

        _, axes = plt.subplots(1, 2, figsize=(9.5, 3.8), layout="constrained")
    ax_l, ax_k = axes
    if isinstance(good[0][1], Design):
        ref = good[len(good) // 2] if reference is None else min(good, key=lambda t: abs(t[0] - reference))
        qq = as_config(ref[1], q)
        loci, consts = _design_family(good, qq, points)
        draw(ref[1], qq, ax=ax_l, title=f"{ref[1].name}, {name} = {ref[0]:.3g}")
        ylab = "spring constant (N/m)"
    else:
        loci, consts = _mapping_family(good, points)
        ax_l.set_aspect("equal", adjustable="datalim")
        ax_l.set_xlabel("x (m)")
        ax_l.set_ylabel("y (m)")
        ylab = "value"
    vs = np.array([v for v, _ in good])
    _plot_family(ax_l, ax_k, vs, loci, consts, name, ylab)
    skipped = len(rows) - len(good)
    ax_k.set_title(f"along the family ({len(good)} designs" +
                   (f", {skipped} invalid values skipped)" if skipped else ")"), fontsize=FONT["title"])
    ax_l.family = {"values": vs, "loci": loci, "constants": consts}
    return ax_l, ax_k


def _design_family(good, q, points) -> tuple[dict, dict]:
    """Loci (m) of the named points at ``q`` and the constant (N/m) of every spring, by name."""
    first = good[0][1]
    names = list(points) if points is not None else list(first.labels)
    loci: dict = {}
    for lab in names:
        rows = []
        for _, d in good:
            if lab not in d.labels:
                raise ValueError(f"point {lab!r} is not a label of {d.name}; labels: {list(d.labels)}")
            rows.append(d.world_points(q, [d.labels[lab]])[0])
        pts = np.array(rows)
        if points is not None or np.ptp(pts, axis=0).max() > 1e-12:
            loci[lab] = pts
    # spring constants by spring name (NaN where a design has no such spring)
    keys: dict = {}
    for _, d in good:
        for i, s in enumerate(d.springs):
            keys.setdefault(s.name or f"spring {i + 1}", None)
    consts = {key: np.array([next((s.k for i, s in enumerate(d.springs)
                                   if (s.name or f"spring {i + 1}") == key), np.nan) for _, d in good])
              for key in keys}
    return loci, consts


def _mapping_family(good, points) -> tuple[dict, dict]:
    """Loci of the pairs and values of the numbers of a family of mappings."""
    loci: dict = {}
    consts: dict = {}
    for key, val in good[0][1].items():
        arr = np.asarray(val, dtype=float)
        if arr.shape == (2,):
            if points is None or key in points:
                loci[key] = np.array([np.asarray(m[key], dtype=float) for _, m in good])
        elif arr.shape == ():
            consts[key] = np.array([float(m[key]) for _, m in good])
    return loci, consts


def _plot_family(ax_l, ax_k, vs, loci: dict, consts: dict, name: str, ylab: str) -> None:
    for i, (lab, pts) in enumerate(loci.items()):
        c = _COLOURS[i % len(_COLOURS)]
        ax_l.plot(pts[:, 0], pts[:, 1], ":", color=c, linewidth=1.8, label=f"locus of {lab}")
        ax_l.plot(pts[[0, -1], 0], pts[[0, -1], 1], linestyle="none", marker="o", markersize=4, color=c)
    if loci:
        ax_l.legend(fontsize=FONT["legend"], loc="best")
    for i, (lab, ks) in enumerate(consts.items()):
        ax_k.plot(vs, ks, color=_COLOURS[i % len(_COLOURS)], linewidth=2, label=tex_label(lab))
    ax_k.set_xlabel(tex_label(name))
    ax_k.set_ylabel(ylab)
    if consts:
        ax_k.legend(fontsize=FONT["legend"])


# --------------------------------------------------------------------- cognates
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
    n = count("n", n)
    ax = new_axes(ax, figsize=(5.5, 4.5))
    colours = [PALETTE[c] for c in ("blue", "vermillion", "green", "orange", "purple", "sky")]
    curves = []
    for i, d in enumerate(designs):
        check_design(d)
        if point not in d.labels:
            raise ValueError(f"{d.name} has no point named {point!r}; its labels are {list(d.labels)}")
        c = colours[i % len(colours)]
        grid = range_grid(d, n) if d.dof == 1 else d.sample(n, seed=0)
        ok = d.reachable(grid)
        pts = d.world_points(grid[ok], [d.labels[point]])[:, 0, :]
        curves.append(pts)
        ax.plot(pts[:, 0], pts[:, 1], "-" if i == 0 else "--", color=c, linewidth=2.2 - 0.4 * min(i, 3),
                label=f"{d.name}: path of {point}")
        if show:
            Drawing(d, None if q is None else q[i], ax, labels=(i == 0), color=c, limits=False, linewidth=2.5)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    # below the x label, where it can cover neither a pivot nor a path
    ax.legend(fontsize=FONT["legend"], loc="upper center", bbox_to_anchor=(0.5, -0.16), frameon=False)
    ax.autoscale_view()
    ax.curves = curves
    return ax
