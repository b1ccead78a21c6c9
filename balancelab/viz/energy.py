"""The energy of a design over its range: :func:`energy_plot` and its :class:`EnergyView`.

One degree of freedom: the load, spring and total potential energy against the
coordinate, the total flat for a balanced design. Two degrees of freedom: a map of the
total energy's deviation from its mean, in units of the design's energy scale, and of
the residual generalized force. More: the three curves along a closed path through the
configuration space that sweeps every coordinate over its range (:func:`sweep_path`). Every number plotted is the design's own
(:meth:`balancelab.Design.potential_energy`, :meth:`~balancelab.Design.generalized_force`,
:meth:`~balancelab.Design.balance_report`). Layer: viz.
"""
from __future__ import annotations

import math

from typing import TYPE_CHECKING

import numpy as np

from ..core.design import Design
from ..core.report import MAX_CONFIGURATIONS, format_q, q_shown, q_units
from ..core.validation import finite_real
from .style import FONT, fit_title
from .frame import PALETTE, STYLE, angle_label, check_design, count, new_axes, range_grid

if TYPE_CHECKING:
    from matplotlib.image import AxesImage
    from numpy.typing import ArrayLike

__all__ = ["EnergyView", "describe_energy", "energy_limits", "energy_plot", "marked_q", "q_symbol", "report_summary",
           "sweep_path"]


def sweep_path(design: Design, n: int) -> tuple[np.ndarray, np.ndarray]:
    """A closed path of ``n`` configurations through a design's range, and its parameter in [0, 1].

    Coordinate ``i`` runs ``centre_i + half_i sin(2 pi (i + 1) t + i)`` (a Lissajous figure with
    frequencies 1, 2, 3, ...), so that every coordinate sweeps 96 % of its range and every pair of
    coordinates varies together.

    Examples
    --------
    >>> import balancelab as bl
    >>> q, t = sweep_path(bl.catalog()["general_3r_arm"](), 5)
    >>> q.shape, t.tolist()
    ((5, 3), [0.0, 0.25, 0.5, 0.75, 1.0])
    """
    t = np.linspace(0.0, 1.0, n)
    lo, hi = design.q_range[:, 0], design.q_range[:, 1]
    i = np.arange(design.dof)
    q = (lo + hi) / 2 + 0.48 * (hi - lo) * np.sin(2 * np.pi * (i + 1) * t[:, None] + i)
    return q, t


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
    units = getattr(report, "q_units", ()) or ("rad",) * len(np.atleast_1d(report.worst_q))
    q = format_q(units, report.worst_q)
    per = "J/rad" if set(units) == {"rad"} else "N" if set(units) == {"m"} else "J/rad or N"
    return (f"NOT balanced: energy varies by {report.variation:.2g} of its scale; "
            f"largest |dV/dq| = {report.residual * report.scale:.3g} {per} at ({q})")


_GREEK = {"theta": "θ", "phi": "φ", "psi": "ψ", "alpha": "α", "beta": "β", "gamma": "γ"}


def q_symbol(design: Design, i: int = 0) -> str:
    """Coordinate ``i`` of a design as a screen reader can say it: ``theta_1`` -> ``θ1``.

    Examples
    --------
    >>> import balancelab as bl
    >>> q_symbol(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3))
    'θ'
    """
    name = design.q_names[i]
    base, _, sub = name.partition("_")
    return _GREEK.get(base, base) + sub


def _j(x: float, scale: float) -> str:
    """An energy in joules for words: 3 significant digits, round-off (< 1e-9 of ``scale``) shown as 0."""
    return f"{x:.3g}" if abs(x) > 1e-9 * scale else "0"


def _j_range(lo: float, hi: float, scale: float) -> tuple[str, str]:
    """``lo`` and ``hi`` (J) for words, with as many digits (3 to 9) as it takes to tell them apart.

    >>> _j_range(23.041, 23.046, 10.0)
    ('23.04', '23.05')
    """
    for digits in range(3, 10):
        a, b = (f"{x:.{digits}g}" if abs(x) > 1e-9 * scale else "0" for x in (lo, hi))
        if a != b:
            break
    return a, b


def _span(design: Design, grid: np.ndarray, i: int) -> str:
    unit = q_units(design)[i]
    lo, hi = q_shown(unit, grid[0, i]), q_shown(unit, grid[-1, i])
    if unit == "m":
        return f"{q_symbol(design, i)} from {lo:.3g} m to {hi:.3g} m"
    return f"{q_symbol(design, i)} from {lo:.0f}° to {hi:.0f}°"


def describe_energy(design: Design, report, grid, total, load, spring) -> str:
    """What an energy plot shows, in words: is the total flat, at what energy, and what trades.

    Parameters
    ----------
    design : Design
    report : BalanceReport or None
        Its balance report (``None``: nothing stores energy).
    grid : numpy.ndarray, shape (m, dof)
        Configurations (rad).
    total, load, spring : numpy.ndarray, shape (m,)
        The design's energies there (J, NaN where unreachable).

    Returns
    -------
    str
        One sentence, numbers in joules and degrees.

    Examples
    --------
    >>> import balancelab as bl
    >>> view = EnergyView(bl.lecture.single_link_spring(mass=2.0, length=0.5, b=0.3, c=0.2))
    >>> print(view.description)  # doctest: +ELLIPSIS
    the total energy is flat at ... J over θ from ...° to ...° while the springs' energy (...) and the loads' energy (...) trade
    """
    ok = np.isfinite(total)
    if report is None or not ok.any():
        return "nothing stores energy as the design moves"
    t, l_, s = total[ok], load[ok], spring[ok]
    sc = report.scale
    where = _span(design, grid, 0) + (f" and {_span(design, grid, 1)}" if design.dof == 2 else "")
    parts = []
    for name, v in (("springs'", s), ("loads'", l_)):
        if np.ptp(v) > 1e-9 * max(report.scale, 1e-300):
            parts.append(f"the {name} energy ({_j(v.min(), sc)} to {_j(v.max(), sc)} J)")
    if report.balanced:
        trade = (" while " + " and ".join(parts) + (" trade" if len(parts) == 2 else " varies")) if parts else ""
        return f"the total energy is flat at {_j(float(np.mean(t)), sc)} J over {where}{trade}"
    units = q_units(design)
    at = format_q(units, report.worst_q, [q_symbol(design, i) for i in range(design.dof)])
    per = "J/rad" if set(units) == {"rad"} else "N" if set(units) == {"m"} else "J/rad or N"
    lo, hi = _j_range(float(t.min()), float(t.max()), sc)
    return (f"the total energy is not flat: it varies from {lo} to {hi} J over {where} "
            f"({report.variation:.2g} of the energy scale); the largest residual |dV/dq| is "
            f"{report.residual * report.scale:.3g} {per} at {at}")


def _safe_report(design: Design, n: int = 1000):
    try:
        return design.balance_report(n=n)
    except (ValueError, RuntimeError):
        return None


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
    grid, total, load, spring : numpy.ndarray
        The configurations (rad) and the design's energies there (J, NaN where
        unreachable), exactly as plotted.

    Examples
    --------
    >>> import balancelab as bl
    >>> view = EnergyView(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3), q=[0.5])
    >>> view.report.balanced, view.grid.shape
    (True, (241, 1))
    """

    def __init__(self, design: Design, ax=None, *, n: int | None = None, report=None,
                 q=None, residual_ax=None, legend: bool = True, title: bool = True) -> None:
        check_design(design)
        self.path = design.dof > 2  # curves along sweep_path instead of a map
        self.ax = new_axes(ax, figsize=(5.0, 3.4))
        _check_axes("ax", ax)
        self.n = _plot_count(design, n) if n is not None else (61 if design.dof == 2 else 241)
        self.residual_ax = residual_ax
        self.show_title = title
        #: fixed energy-axis limits (J) for one dof; ``None`` to fit each design
        self.ylim: tuple | None = None
        self.lines: dict = {}
        #: the legend (1 dof, when asked for); it also carries the verdict, which then never
        #: covers a curve or the legend
        self.legend = None
        self.image: AxesImage | None = None  # the energy map (2 dof)
        self.residual_image: AxesImage | None = None
        if design.dof != 2:
            self._init_curves(design, legend)
        else:
            self._init_map(design, residual_ax)
        self.note = self.ax.text(0.02, 0.03, "", transform=self.ax.transAxes, fontsize=FONT["note"], va="bottom",
                                 ha="left", color="black",
                                 bbox=dict(boxstyle="round,pad=0.25", facecolor="white", alpha=0.8,
                                           edgecolor="none"))
        self.update(design, report=report, q=q)

    def _init_curves(self, design: Design, legend: bool) -> None:
        ax = self.ax
        # the total dashed and beneath: a load or spring curve that coincides with it stays visible
        for key, label, colour, lw, dash, z in (
                ("load", "loads (gravity, forces)", STYLE["load"], 1.8, "-", 3),
                ("spring", "springs", STYLE["zfl"], 1.8, "-", 3),
                ("total", "total", STYLE["total"], 2.4, (0, (5, 2.5)), 2)):
            self.lines[key], = ax.plot([], [], color=colour, linewidth=lw, linestyle=dash, label=label,
                                       zorder=z)
        self.worst, = ax.plot([], [], linestyle="none", marker="x", color=PALETTE["vermillion"],
                              markersize=9, markeredgewidth=2)
        self.marker, = ax.plot([], [], linestyle="none", marker="o", color="black",
                               markerfacecolor=PALETTE["yellow"], markersize=8, zorder=5)
        ax.set_xlabel(f"position along a closed path that sweeps all {design.dof} coordinates (%)" if self.path
                      else angle_label(design, 0))
        ax.set_ylabel("potential energy (J)")
        if legend:
            self.legend = ax.legend(loc="best", fontsize=FONT["legend"], framealpha=0.85,
                                    title_fontsize=FONT["note"], alignment="left")

    def _init_map(self, design: Design, residual_ax) -> None:
        ax = self.ax
        u = q_units(design)
        (x0, x1), (y0, y1) = q_shown(u[0], design.q_range[0]), q_shown(u[1], design.q_range[1])
        extent = (x0, x1, y0, y1)
        self.image = ax.imshow(np.zeros((2, 2)), origin="lower", aspect="auto", cmap="cividis",
                               extent=extent, interpolation="nearest")
        self.colorbar = ax.figure.colorbar(self.image, ax=ax, label="(total − mean) / energy scale")
        self.marker, = ax.plot([], [], linestyle="none", marker="o", color="black",
                               markerfacecolor=PALETTE["yellow"], markersize=8)
        self.worst, = ax.plot([], [], linestyle="none", marker="x", color=PALETTE["vermillion"],
                              markersize=9, markeredgewidth=2)
        ax.set_xlabel(angle_label(design, 0))
        ax.set_ylabel(angle_label(design, 1))
        if residual_ax is not None:
            self.residual_image = residual_ax.imshow(np.zeros((2, 2)), origin="lower", aspect="auto",
                                                     cmap="magma", extent=extent, interpolation="nearest")
            self.residual_colorbar = residual_ax.figure.colorbar(
                self.residual_image, ax=residual_ax,
                label=f"|dV/dq| / scale ({' or '.join('1/' + v for v in sorted(set(u), reverse=True))})")
            residual_ax.set_xlabel(angle_label(design, 0))
            residual_ax.set_ylabel(angle_label(design, 1))
            residual_ax.set_title("residual generalized force", fontsize=FONT["title"])

    def update(self, design: Design | None = None, *, report=None, q=None) -> EnergyView:
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
            check_design(design)
            self.design = design
            self.report = report if report is not None else _safe_report(design)
            self._compute()
        if q is not None:
            self.set_q(q)
        return self

    def _compute(self) -> None:
        """The design's energies over the range grid, then the curves or maps and the verdict."""
        d = self.design
        if self.path:
            grid, self.t = sweep_path(d, self.n)
        else:
            grid = range_grid(d, self.n if d.dof == 1 else self.n * self.n)
        ok = d.reachable(grid)
        total = np.full(len(grid), np.nan)
        load = np.full(len(grid), np.nan)
        spring = np.full(len(grid), np.nan)
        if ok.any():
            e = d.potential_energy(grid[ok])
            total[ok], load[ok], spring[ok] = e.total, e.load, e.spring
        self.grid, self.total, self.load, self.spring = grid, total, load, spring
        if d.dof != 2:
            self._show_curves()
        else:
            self._show_maps(ok)
        self._show_verdict()

    def _show_curves(self) -> None:
        rep = self.report
        x = 100 * self.t if self.path else q_shown(q_units(self.design)[0], self.grid[:, 0])
        self.lines["load"].set_data(x, self.load)
        self.lines["spring"].set_data(x, self.spring)
        self.lines["total"].set_data(x, self.total)
        vals = np.concatenate([v[np.isfinite(v)] for v in (self.load, self.spring, self.total)] + [[0.0]])
        self.ax.set_xlim(x[0], x[-1])
        self.ax.set_ylim(*(self.ylim or energy_limits(vals.min(), vals.max(),
                                                      rep.scale if rep is not None else 0.0)))

    def _show_maps(self, ok: np.ndarray) -> None:
        d, rep, grid = self.design, self.report, self.grid
        m = int(round(math.sqrt(len(grid))))
        Z = self.total.reshape(m, m)
        self.mean = float(np.nanmean(Z)) if np.isfinite(Z).any() else 0.0
        self.scale = rep.scale if rep is not None else float(np.nanmax(np.abs(Z - self.mean)) or 1.0)
        # deviation from the mean in units of the energy scale: one fixed colour range
        # for every design, a single flat colour when balanced
        assert self.image is not None  # _show_maps draws a 2-dof design, whose map _build made
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

    def _show_verdict(self) -> None:
        d, rep = self.design, self.report
        if rep is None:
            verdict = "nothing stores energy as this design moves"
            self.worst.set_data([], [])
        elif rep.balanced:
            verdict = (f"balanced: total constant to {rep.variation:.1e}\n"
                       f"of the energy scale ({rep.scale:.3g} J)")
            self.worst.set_data([], [])
        else:
            wq = np.atleast_1d(rep.worst_q)
            verdict = (f"not balanced: total varies by {rep.variation:.2g} of the scale\n"
                       f"largest |dV/dq| = {rep.residual * rep.scale:.3g} "
                       f"{'N' if set(q_units(d)) == {'m'} else 'J/rad' if set(q_units(d)) == {'rad'} else 'J/rad or N'} (×)")
            if self.path:  # the worst configuration need not lie on the path: it is written, not marked
                self.worst.set_data([], [])
            elif d.dof == 1:
                self.worst.set_data([q_shown(q_units(d)[0], wq[0])], [float(d.potential_energy(wq).total)])
            else:
                u = q_units(d)
                self.worst.set_data([q_shown(u[0], wq[0])], [q_shown(u[1], wq[1])])
        self.note.set_text(verdict)   # shown in the legend's title when there is a legend
        if self.legend is not None:
            self.legend.set_title(verdict)
            self.note.set_visible(False)
        if self.show_title:
            fit_title(self.ax, f"{d.name}: " + ("balanced" if rep is not None and rep.balanced else
                                                "not balanced"), fontsize=FONT["title"])

    @property
    def description(self) -> str:
        """What the plot shows, in words, from the design's numbers (the figure's alt text).

        Examples
        --------
        >>> import balancelab as bl
        >>> EnergyView(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)).description[:27]
        'the total energy is flat at'
        """
        return describe_energy(self.design, self.report, self.grid, self.total, self.load, self.spring)

    @property
    def artists(self) -> list:
        """The artists that change with the design or the configuration."""
        arts = list(self.lines.values()) + [self.marker, self.worst, self.note]
        arts += [self.legend] if self.legend is not None else []
        return arts + [a for a in (self.image, self.residual_image) if a is not None]

    def set_visible(self, visible: bool) -> None:
        """Show or hide the curves, map, markers and note."""
        for a in self.artists:
            a.set_visible(visible)
        if self.legend is not None:   # the verdict is in the legend's title
            self.note.set_visible(False)

    def set_q(self, q) -> None:
        """Move the marker to configuration ``q`` (rad, or m for a slide), which must lie in the design's range."""
        q = marked_q(self.design, q)
        if self.path:  # the nearest point of the path
            k = int(np.argmin(np.sum((self.grid - q) ** 2, axis=-1)))
            self.marker.set_data([100 * self.t[k]], [float(self.total[k])])
        elif self.design.dof == 1:
            v = float(self.design.potential_energy(q).total)
            self.marker.set_data([q_shown(q_units(self.design)[0], q[0])], [v])
        else:
            u = q_units(self.design)
            self.marker.set_data([q_shown(u[0], q[0])], [q_shown(u[1], q[1])])


def marked_q(design: Design, q: ArrayLike) -> np.ndarray:
    """``q`` as one configuration of ``design`` inside its range ``design.q_range`` (an angle that
    differs from one inside by whole turns is brought inside), or a ValueError naming ``q`` and the range.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.scissors_lift()
    >>> marked_q(d, 0.5).tolist()
    [0.5]
    >>> marked_q(d, 2.0)
    Traceback (most recent call last):
    ...
    ValueError: q must lie in the design's range theta = 0.0°..90.0°, got theta = 114.6°
    """
    given = design.check_q(q).reshape(-1)
    if given.size != design.dof:
        raise ValueError(f"q must be one configuration ({design.dof} coordinates {design.q_names}), got {given.size} values")
    units = q_units(design)
    rng = np.asarray(design.q_range, dtype=float).reshape(-1, 2)
    out = given.copy()
    for i, (unit, v, (lo, hi)) in enumerate(zip(units, given, rng)):
        tol = 1e-9 * max(hi - lo, abs(lo), abs(hi), 1e-300)
        if unit == "rad":  # whole turns apart are the same pose; a range of a whole turn holds every angle
            x = lo + (v - lo) % (2 * np.pi)
            inside = hi - lo >= 2 * np.pi - tol or x <= hi + tol or x >= lo + 2 * np.pi - tol
            if hi - lo < 2 * np.pi - tol:  # the angle inside the range, as the kinematics takes it
                out[i] = x if x <= hi + tol else x - 2 * np.pi
        else:
            inside = lo - tol <= v <= hi + tol
        if not inside:
            names = design.q_names
            span = ", ".join(f"{n} = {format_q((u,), [a])}..{format_q((u,), [b])}"
                             for n, u, (a, b) in zip(names, units, rng))
            raise ValueError(f"q must lie in the design's range {span}, got {format_q(units, given, names)}")
    return out


def energy_plot(design: Design, ax=None, *, q=None, n: int | None = None, residual: bool | None = None,
                legend: bool = True):
    """Load, spring and total potential energy over the configuration range.

    One degree of freedom: three curves against the coordinate (in degrees), the
    total flat for a balanced design; when it is not balanced the spread and the
    largest residual ``|dV/dq|`` are written and the worst configuration marked.
    Two degrees of freedom: a map of the total energy's deviation from its mean in
    units of the design's energy scale (the sum of the spreads of every load and
    spring energy), so a balanced design is one flat colour, and optionally a map of
    the residual generalized force. Three or more: the three curves along a closed path
    that sweeps every coordinate over its range (:func:`sweep_path`), with the design's
    variation written. The balance verdict is in the title.

    Parameters
    ----------
    design : Design
        Any design.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (a new figure by default).
    q : array_like, optional
        A configuration (rad, or m for a slide) to mark, inside ``design.q_range`` (an angle
        may differ by whole turns); outside it a ValueError names ``q`` and the range.
    n : int, optional
        Points (an integer >= 2) along the range (1 dof, default 241) or per side of the map (2 dof,
        default 61); at most :data:`~balancelab.core.report.MAX_CONFIGURATIONS` configurations in
        all (a map's ``n * n``), else a ValueError names ``n`` and its largest value.
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
    >>> ax = energy_plot(bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3))
    >>> ax.energy.report.balanced
    True
    """
    check_design(design)
    _check_axes("ax", ax)
    if n is not None:
        _plot_count(design, n)
    residual_ax = None
    if design.dof == 2:
        if residual is not None and not isinstance(residual, bool):
            _check_axes("residual", residual)
        if residual is None:
            residual = ax is None
        if hasattr(residual, "imshow"):
            residual_ax = residual
        elif residual and ax is None:
            import matplotlib.pyplot as plt

            fig, (ax, residual_ax) = plt.subplots(1, 2, figsize=(9.5, 3.6), layout="constrained")
        elif residual:
            raise ValueError("with ax given, pass the Axes for the residual map as residual=")
    view = EnergyView(design, ax, n=n, q=q, residual_ax=residual_ax, legend=legend)
    view.ax.energy = view
    return view.ax


def _plot_count(design: Design, n: int) -> int:
    """``n`` (points along the range, or per side of a 2-dof map) checked: an int >= 2 whose plot
    holds at most ``MAX_CONFIGURATIONS`` configurations, else a ValueError naming ``n`` and the range.

    Examples
    --------
    >>> import balancelab as bl
    >>> arm = bl.singh.serial_2r_min_preload()
    >>> _plot_count(arm, 400)
    400
    >>> _plot_count(arm, 10**6)
    Traceback (most recent call last):
    ...
    ValueError: n must be an integer from 2 to 447 for a design with 2 coordinates (a map of n * n configurations, at most 200000), got 1000000
    """
    n = count("n", n)
    grid = 2 if design.dof == 2 else 1
    largest = math.isqrt(MAX_CONFIGURATIONS) if grid == 2 else MAX_CONFIGURATIONS
    if n > largest:
        shape = "a map of n * n configurations" if grid == 2 else "n configurations"
        raise ValueError(f"n must be an integer from 2 to {largest} for a design with {design.dof} coordinate"
                         f"{'s' if design.dof > 1 else ''} ({shape}, at most {MAX_CONFIGURATIONS}), got {n}")
    return n


def _check_axes(name: str, ax) -> None:
    """Refuse an ``ax`` that is not a matplotlib Axes (``None`` is allowed: a new figure)."""
    if ax is None:
        return
    from matplotlib.axes import Axes

    if not isinstance(ax, Axes):
        raise TypeError(f"{name} must be a matplotlib Axes (or None for a new figure), got {type(ax).__name__}")
