"""The ipywidgets face of an :class:`~balancelab.viz.explorer.Explorer`: its sliders, kept in step
with the design, and what a screen reader is told about them.

The explorer's model (which design and configuration are valid, the picture, the report) lives in
:mod:`balancelab.viz.explorer`; this module only turns slider moves into :meth:`Explorer.update`
requests and shows the result. ``ipywidgets`` is imported on first use of :attr:`widget`.
"""
from __future__ import annotations

from typing import Any, Callable

import numpy as np

from ..core.report import q_units
from . import widget_access

__all__ = ["ExplorerSliders"]


class ExplorerSliders:
    """Sliders for an explorer's parameters and configuration (a base class of ``Explorer``).

    It reads the explorer's ``params``, ``values``, ``design``, ``q``, ``q_names``, ``show_q``,
    ``png`` and ``message``, and calls its ``update``, ``_requested_q`` and ``_show_text``.

    Examples
    --------
    >>> import balancelab as bl
    >>> ex = bl.explore(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3))
    >>> isinstance(ex, ExplorerSliders), len(ex.slider_descriptions) >= 1
    (True, True)
    """

    # what the explorer provides (annotations for type checkers; set by Explorer)
    params: dict[str, Any]
    values: dict[str, Any]
    design: Any
    q: Any
    q_names: Any
    show_q: bool
    png: Any
    message: Any
    _widget: Any
    update: Callable[..., Any]
    _requested_q: Callable[..., Any]
    _show_text: Callable[..., Any]

    # ----------------------------------------------------------------- widgets
    @property
    def widget(self):
        """The ipywidgets box: sliders, picture, report and message."""
        if self._widget is None:
            self._make_widgets()
        return self._widget

    def _make_widgets(self) -> None:
        import ipywidgets as w

        self._sliders = {}
        layout = w.Layout(width="420px")
        style = {"description_width": "110px"}
        for name, (lo, hi, step, _value) in self.params.items():
            s = w.FloatSlider(value=self.values[name], min=lo, max=hi, step=step, description=name,
                              continuous_update=True, readout_format=".4g", layout=layout, style=style)
            s.observe(self._on_param(name), names="value")
            self._sliders[name] = s
        self._q_sliders = {}
        if self.show_q:
            for i, (name, unit) in enumerate(zip(self.q_names, q_units(self.design))):
                suffix, factor, step, fmt, _ = widget_access.q_slider(unit)
                lo, hi = factor * np.asarray(self.design.q_range[i])
                s = w.FloatSlider(value=float(factor * self.q[i]), min=float(lo), max=float(hi),
                                  step=step, description=f"{name} ({suffix})", continuous_update=True,
                                  readout_format=fmt, layout=layout, style=style)
                s.observe(self._on_q(i), names="value")
                self._q_sliders[name] = s
        self._image = w.Image(value=self.png, format="png")
        self._report_html = w.HTML()
        self._message_html = w.HTML()
        self._widget = w.VBox(list(self._sliders.values()) + list(self._q_sliders.values())
                              + [self._image, self._report_html, self._message_html])
        self._label_widgets()
        self._widget.children += (widget_access.script_output(self._a11y_script()),)
        self._show_text()

    # ----------------------------------------------------------- accessibility
    @property
    def slider_descriptions(self) -> dict:
        """What each slider moves, in words (see :func:`~balancelab.viz.widget_access.slider_descriptions`)."""
        return widget_access.slider_descriptions(self)

    def _label_widgets(self) -> None:
        self._uid = widget_access.label_widgets(self._widget, self._report_html,
                                                list(self._sliders.values()) + list(self._q_sliders.values()),
                                                self.slider_descriptions)

    def _a11y_script(self) -> str:
        if self._widget is None:
            self._make_widgets()
        return widget_access.script(self._uid, self.design.name,
                                    list(self._sliders.values()) + list(self._q_sliders.values()),
                                    self.slider_descriptions)

    def _on_param(self, name):
        def callback(change):
            if self._syncing:
                return
            self.values[name] = float(change["new"])
            self.update()
            self._sync_sliders()

        return callback

    def _on_q(self, i):
        def callback(change):
            if self._syncing:
                return
            q = self._requested_q()
            q[i] = float(change["new"]) / self._q_factor(i)
            self._q_request = q
            self.update()
            self._sync_sliders()

        return callback

    def _q_factor(self, i: int) -> float:
        """Slider value per unit of coordinate ``i``: degrees per radian, or millimetres per metre."""
        return widget_access.q_slider(q_units(self.design)[i])[1]

    def _sync_sliders(self) -> None:
        """Keep the configuration sliders' ranges and values in step with the design."""
        if self._widget is None:
            return
        self._syncing = True
        try:
            for name, s in self._sliders.items():
                s.value = self.values[name]
            for i, s in enumerate(self._q_sliders.values()):
                lo, hi = (float(v) for v in self._q_factor(i) * np.asarray(self.design.q_range[i]))
                if (s.min, s.max) != (lo, hi):
                    if lo > s.max:
                        s.max, s.min = hi, lo
                    else:
                        s.min, s.max = lo, hi
                if not self.message:
                    s.value = float(self._q_factor(i) * self.q[i])
        finally:
            self._syncing = False

    def _ipython_display_(self):
        from IPython.display import display

        display(self.widget)

