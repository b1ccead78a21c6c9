"""One live explorer for any design: sliders for its parameters and its configuration.

``explore(factory, params)`` shows the mechanism beside its energy curve (or map),
the balance report and the spring constants, with a slider for every named design
parameter and for every configuration coordinate. A lab adds sliders by naming
parameters; it never writes a callback.

The figure is an ordinary matplotlib figure rendered off screen (Agg) into an
``ipywidgets.Image``: no ipympl, no running kernel-side event loop, and the picture a
test reads is exactly the one a student sees. Only the artists that change are
redrawn over a cached background, so a slider change costs a few tens of
milliseconds (see ``benchmarks/bench_explore.py``).

Invalid slider combinations (a four-bar that cannot assemble, a singular free choice,
an unreachable configuration) show a message and keep the last valid picture; no
traceback ever reaches the notebook.
"""
from __future__ import annotations

import dataclasses
import html
import inspect
import math
from io import BytesIO
from typing import Any, Callable, Mapping

import numpy as np

from ..core.design import Design
from ..core.report import format_q, q_units
from .drawing import Drawing, extent
from .energy import EnergyView, report_summary
from .style import FONT
from .frame import Blitter, check_design, default_q
from .explorer_sliders import ExplorerSliders

__all__ = ["Explorer", "explore", "scaled_design_factory"]

FIGSIZE = (8.0, 3.3)
DPI = 72


def scaled_design_factory(design: Design):
    """A factory that rebuilds ``design`` with its springs (or counterweights) scaled.

    Gives any fixed design one slider: ``stiffness`` multiplies every spring constant
    (or, for a design without springs, ``counterweight`` multiplies every
    counterweight). At 1 the design is unchanged, so its balance can be watched
    breaking as the slider moves away.

    Parameters
    ----------
    design : Design

    Returns
    -------
    (callable, dict)
        The factory and its ``params`` entry for :func:`explore`.

    Examples
    --------
    >>> import balancelab as bl
    >>> f, params = scaled_design_factory(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3))
    >>> params
    {'stiffness': (0.5, 1.5, 0.01, 1.0)}
    >>> round(f(stiffness=2.0).springs[0].k, 3)
    166.667
    """
    check_design(design)
    if design.springs:
        def by_stiffness(stiffness: float = 1.0) -> Design:
            if not stiffness > 0:
                raise ValueError(f"stiffness factor must be > 0, got {stiffness}")
            return design.replace(springs=[dataclasses.replace(s, k=s.k * stiffness)
                                           for s in design.springs])

        return by_stiffness, {"stiffness": (0.5, 1.5, 0.01, 1.0)}
    if any(ld.kind == "counterweight" for ld in design.loads):
        def by_counterweight(counterweight: float = 1.0) -> Design:
            if not counterweight > 0:
                raise ValueError(f"counterweight factor must be > 0, got {counterweight}")
            loads = [dataclasses.replace(ld, force=(ld.force[0] * counterweight,
                                                    ld.force[1] * counterweight))
                     if ld.kind == "counterweight" else ld for ld in design.loads]
            return design.replace(loads=loads)

        return by_counterweight, {"counterweight": (0.5, 1.5, 0.01, 1.0)}

    def unchanged() -> Design:
        return design

    return unchanged, {}


def _normalize_params(factory, params: Mapping) -> dict:
    out = {}
    try:
        sig = inspect.signature(factory)
    except (TypeError, ValueError):
        sig = None
    for name, spec in dict(params).items():
        if not isinstance(name, str) or not name.isidentifier():
            raise ValueError(f"parameter names must be identifiers, got {name!r}")
        try:
            spec = tuple(float(v) for v in spec)
        except (TypeError, ValueError):
            raise TypeError(f"params[{name!r}] must be (min, max), (min, max, step) or "
                            f"(min, max, step, value), got {spec!r}") from None
        if len(spec) not in (2, 3, 4):
            raise ValueError(f"params[{name!r}] must be (min, max), (min, max, step) or "
                             f"(min, max, step, value), got {spec!r}")
        lo, hi = spec[0], spec[1]
        if not (math.isfinite(lo) and math.isfinite(hi) and hi > lo):
            raise ValueError(f"params[{name!r}]: need finite min < max, got {lo}, {hi}")
        step = spec[2] if len(spec) >= 3 else (hi - lo) / 100
        if not step > 0:
            raise ValueError(f"params[{name!r}]: step must be > 0, got {step}")
        if len(spec) == 4:
            value = spec[3]
        else:
            value = None
            if sig is not None and name in sig.parameters:
                default = sig.parameters[name].default
                if isinstance(default, (int, float)) and not isinstance(default, bool) \
                        and lo <= default <= hi:
                    value = float(default)
            if value is None:
                value = lo + round((hi - lo) / 2 / step) * step
        if not lo <= value <= hi:
            raise ValueError(f"params[{name!r}]: initial value {value} is outside [{lo}, {hi}]")
        out[name] = (lo, hi, step, float(value))
    return out


class Explorer(ExplorerSliders):
    """A live explorer of a family of designs (see :func:`explore`).

    Drive it from code exactly as the sliders do: :meth:`set` changes parameters or
    configuration coordinates and redraws. After every call, :attr:`message` is
    ``""`` when the request was valid, or says why it was not (the picture then keeps
    the last valid design and configuration).

    Attributes
    ----------
    design : Design
        The last valid design.
    q : numpy.ndarray
        The last valid configuration (rad).
    values : dict
        The requested parameter values (those of the sliders).
    valid_values : dict
        The parameter values of :attr:`design`.
    message : str
        Why the last request could not be shown, or ``""``.
    report : BalanceReport or None
    drawing : Drawing
    energy : EnergyView or None
    figure : matplotlib.figure.Figure
    png : bytes
        The last rendered picture.
    renders : int
        Number of pictures rendered.
    widget : ipywidgets.VBox
        The sliders, the picture, the report and the message (built on first use).
    """

    def __init__(self, factory: Callable, params: Mapping | None = None, q=True, *,
                 fixed: Mapping | None = None, figsize=FIGSIZE, dpi: float = DPI,
                 labels: bool = True, report_samples: int = 1000) -> None:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        if isinstance(factory, Design):
            factory, auto = scaled_design_factory(factory)
            params = auto if params is None else params
        if not callable(factory):
            raise TypeError("factory must be callable (factory(**params) -> Design) or a Design")
        self.factory = factory
        self.fixed = dict(fixed or {})
        self.params = _normalize_params(factory, params or {})
        self.values = {n: spec[3] for n, spec in self.params.items()}
        self.report_samples = int(report_samples)
        self.message = ""
        self.renders = 0
        self.png = b""
        self._widget: Any = None  # the ipywidgets VBox, made on first display
        self._syncing = False
        design = self._build(self.values)
        if q is True or q is None or q is False:
            q0 = default_q(design)
        else:
            q0 = np.asarray(q, dtype=float).reshape(-1)
            design.poses(q0)
        self.show_q = q is not False
        self.design = design
        self.valid_values = dict(self.values)
        self.q = q0
        self.report = self._report(design)

        fig = Figure(figsize=figsize, dpi=dpi, layout="constrained")
        FigureCanvasAgg(fig)
        self.figure = fig
        show_energy = design.dof <= 2
        if show_energy:
            ax_m, ax_e = fig.subplots(1, 2, width_ratios=(1, 1.2))
        else:
            ax_m, ax_e = fig.subplots(1, 1), None
        self.drawing = Drawing(design, q0, ax_m, labels=labels)
        ax_m.set_title(design.name, fontsize=FONT["title"], y=1.0)
        self.energy = None
        if show_energy:
            self.energy = EnergyView(design, ax_e, q=q0, report=self.report, title=False)
            ax_e.set_title(self._verdict(), fontsize=FONT["title"], y=1.0)
            self._fit_energy_limits()
        fig.canvas.draw()
        fig.set_layout_engine("none")
        self._blitter: Blitter | None = None
        self._render(full=True)

    # ------------------------------------------------------------------ building
    def _build(self, values) -> Design:
        d = self.factory(**{**self.fixed, **values})
        if not isinstance(d, Design):
            raise TypeError(f"the factory must return a balancelab.Design, got {type(d).__name__}")
        return d

    def _report(self, design):
        try:
            return design.balance_report(n=self.report_samples)
        except (ValueError, RuntimeError):
            return None

    def _verdict(self) -> str:
        rep = self.report
        if rep is None:
            return "energy"
        return "balanced: total energy constant" if rep.balanced else "NOT balanced"

    # --------------------------------------------------------------- public API
    @property
    def q_names(self) -> tuple:
        """Names of the configuration coordinates."""
        return self.design.q_names

    def set(self, **changes) -> bool:
        """Change parameters and/or configuration coordinates, then redraw.

        Parameters
        ----------
        **changes
            Design parameters by name (their units) and configuration coordinates by
            name (radians; metres for a slide).

        Returns
        -------
        bool
            True if the new request was valid and is shown; False if it was refused
            (see :attr:`message`; the last valid picture stays).

        Examples
        --------
        >>> import balancelab as bl
        >>> ex = explore(lambda a_x: bl.singh.lacoste_lever(10.0, 0.5, a_x, 0.3),
        ...              {"a_x": (0.0, 0.5, 0.01, 0.2)})
        >>> ex.set(a_x=0.0), ex.message.startswith("a_x = 0")
        (False, True)
        >>> ex.set(a_x=0.3), ex.message
        (True, '')
        """
        q = self._requested_q()
        for name, value in changes.items():
            if name in self.params:
                self.values[name] = float(value)
            elif name in self.q_names:
                q[self.q_names.index(name)] = float(value)
            else:
                raise KeyError(f"unknown slider {name!r}; parameters: {list(self.params)}, "
                               f"configuration: {list(self.q_names)}")
        self._q_request = q
        ok = self.update()
        self._sync_sliders()
        return ok

    def _requested_q(self) -> np.ndarray:
        return np.array(getattr(self, "_q_request", self.q), dtype=float).copy()

    def update(self) -> bool:
        """Rebuild the design from :attr:`values` if they changed and redraw.

        Returns
        -------
        bool
            As :meth:`set`.
        """
        try:
            return self._update()
        except Exception as exc:  # never let a traceback reach the notebook
            self._fail(f"unexpected error ({type(exc).__name__}): {exc}")
            return False

    def _update(self) -> bool:
        q = self._requested_q()
        new_params = self.values != self.valid_values
        design = self.design
        if new_params:
            try:
                design = self._build(self.values)
            except (ValueError, ArithmeticError, RuntimeError) as exc:
                self._fail(self._describe(exc))
                return False
            if design.dof != self.design.dof:
                self._fail(f"{self._where()}: the design changed its number of coordinates "
                           f"({self.design.dof} -> {design.dof}); the explorer cannot follow")
                return False
            lo, hi = design.q_range[:, 0], design.q_range[:, 1]
            q = np.clip(q, lo, hi)
        if not bool(design.reachable(q)):
            where = format_q(q_units(design), q, design.q_names)
            self._fail(f"{self._where()}: the configuration {where} cannot be reached by this "
                       "design (it does not assemble there); showing the last valid picture")
            return False
        full = False
        if new_params:
            report = self._report(design)
            rebuilt_before = self.drawing.artists
            self.drawing.update(q, design, rescale=False)
            if self.drawing.artists != rebuilt_before:
                full = True
            full |= self._fit_mechanism_limits(design)
            self.design, self.report = design, report
            if self.energy is not None:
                clim = self.energy.image.get_clim() if self.energy.image is not None else None
                xlim, ylim = self.energy.ax.get_xlim(), self.energy.ax.get_ylim()
                self.energy.update(design, report=report)
                full |= self.energy.ax.get_xlim() != xlim
                full |= self._fit_energy_limits(previous=ylim)
                if clim is not None and self.energy.image is not None and self.energy.image.get_clim() != clim:
                    full = True
                self.energy.ax.set_title(self._verdict(), fontsize=FONT["title"], y=1.0)
            self.valid_values = dict(self.values)
        else:
            self.drawing.update(q)
        if self.energy is not None:
            self.energy.set_q(q)
        self.q = q
        self._q_request = q
        self.message = ""
        self._render(full=full)
        self._show_text()
        return True

    def _where(self) -> str:
        return ", ".join(f"{n} = {v:.4g}" for n, v in self.values.items()) or self.design.name

    def _describe(self, exc) -> str:
        return f"{self._where()}: {exc}"

    def _fail(self, text: str) -> None:
        self.message = text
        self._show_text()

    # ------------------------------------------------------------------ limits
    def _fit_mechanism_limits(self, design) -> bool:
        """Grow (or shrink a lot) the mechanism's limits to fit ``design``; True if changed."""
        want = self.drawing.padded(extent(design, self.drawing.geom)[0])
        ax = self.drawing.ax
        cur = np.array([*ax.get_xlim(), *ax.get_ylim()])
        inside = want[0] >= cur[0] and want[1] <= cur[1] and want[2] >= cur[2] and want[3] <= cur[3]
        span_cur = max(cur[1] - cur[0], cur[3] - cur[2])
        span_want = max(want[1] - want[0], want[3] - want[2])
        if inside and span_want > 0.6 * span_cur:
            return False
        grow = 0.1 * span_want
        ax.set_xlim(want[0] - grow, want[1] + grow)
        ax.set_ylim(want[2] - grow, want[3] + grow)
        return True

    def _fit_energy_limits(self, previous=None) -> bool:
        """Keep the energy axis unless the new curves leave it or shrink a lot; True if changed."""
        e = self.energy
        if e is None or self.design.dof != 1:
            return False
        vals = np.concatenate([v[np.isfinite(v)] for v in (e.load, e.spring, e.total)] + [[0.0]])
        lo, hi = float(vals.min()), float(vals.max())
        cur = previous
        if cur is not None and lo >= cur[0] and hi <= cur[1] and (hi - lo) > 0.15 * (cur[1] - cur[0]):
            e.ax.set_ylim(*cur)
            return False
        pad = 0.25 * (hi - lo or 1.0)  # room to move before the next (full) redraw
        e.ylim = None
        e.ax.set_ylim(lo - pad, hi + pad)
        return True

    # --------------------------------------------------------------- rendering
    def _dynamic(self) -> list:
        arts = self.drawing.artists + [self.drawing.ax.title]
        if self.energy is not None:
            arts += self.energy.artists + [self.energy.ax.title]
        return arts

    def _render(self, full: bool = False) -> None:
        if self._blitter is None:
            self._blitter = Blitter(self.figure, self._dynamic)
        rgb = self._blitter.render(full=full)
        from PIL import Image

        out = BytesIO()
        Image.fromarray(rgb).save(out, format="png", compress_level=1)
        self.png = out.getvalue()
        self.renders += 1
        if self._widget is not None:
            self._image.value = self.png

    # ---------------------------------------------------------------- the text
    @property
    def report_text(self) -> str:
        """The balance verdict and the spring constants of the shown design (plain text)."""
        lines = [f"{self.design.name}: " + (report_summary(self.report) if self.report is not None
                                            else "nothing stores energy as it moves")]
        for i, s in enumerate(self.design.springs):
            kind = "ZFL" if s.is_zfl else f"free length {s.free_length:.4g} m"
            lines.append(f"{s.name or f'spring {i + 1}'}: k = {s.k:.6g} N/m ({kind}, {s.pulley or s.realization})")
        for ld in self.design.loads:
            if ld.kind == "counterweight":
                lines.append(f"{ld.name or 'counterweight'}: {ld.mass:.6g} kg")
        return "\n".join(lines)

    def _show_text(self) -> None:
        if self._widget is None:
            return
        rows = self.report_text.split("\n")
        colour = "#009E73" if self.report is not None and self.report.balanced else "#D55E00"
        body = f"<b style='color:{colour}'>{html.escape(rows[0])}</b>"
        if len(rows) > 1:
            body += "<ul style='margin:0'>" + "".join(f"<li>{html.escape(r)}</li>" for r in rows[1:]) \
                    + "</ul>"
        self._report_html.value = body
        self._message_html.value = (f"<span style='color:#D55E00'>&#9888; {html.escape(self.message)}</span>"
                                    if self.message else "")

    def __repr__(self) -> str:
        return (f"<Explorer of {self.design.name!r}: parameters {list(self.params)}, "
                f"configuration {list(self.q_names)}>")


def explore(factory, params: Mapping | None = None, q=True, *, fixed: Mapping | None = None,
            figsize=FIGSIZE, dpi: float = DPI, labels: bool = True) -> Explorer:
    """A live explorer with sliders for a design's parameters and configuration.

    Parameters
    ----------
    factory : callable or Design
        ``factory(**{name: value, ...}) -> Design``. A Design is explored through
        :func:`scaled_design_factory` (one stiffness or counterweight slider).
    params : mapping, optional
        ``{name: (min, max)}``, ``(min, max, step)`` or ``(min, max, step, value)``
        for every slider; the initial value is the factory's default when it has one
        in range, else the middle of the range.
    q : bool or array_like
        ``True``: sliders for the configuration (degrees; a slide in mm), from
        :func:`~balancelab.viz.default_q`; an array: the same, starting there
        (rad); ``False``: no configuration sliders.
    fixed : mapping, optional
        Keyword arguments always passed to the factory.
    figsize, dpi :
        Size (inches) and resolution of the picture.
    labels : bool
        Write the design's named points.

    Returns
    -------
    Explorer
        Displays itself in a notebook; drive it from code with :meth:`Explorer.set`.

    Raises
    ------
    ValueError
        If the initial parameter values do not give a valid design.

    Examples
    --------
    >>> import balancelab as bl
    >>> ex = explore(bl.singh.lacoste_lever, {"a_x": (0.05, 0.5), "b_y": (0.05, 0.5)},
    ...              fixed={"weight": 10.0, "length": 0.5})
    >>> ex.set(a_x=0.25, theta=0.3)
    True
    >>> ex.report.balanced
    True
    """
    return Explorer(factory, params, q, fixed=fixed, figsize=figsize, dpi=dpi, labels=labels)
