"""Accessibility of the live explorers: slider names and descriptions, and a live report.

ipywidgets 8 draws a slider as a ``role="slider"`` handle (noUiSlider) without an accessible
name, and replaces the report's HTML on every change without telling a screen reader. The
notebook front end (JupyterLab, Notebook 7) runs a small script that the explorer's box carries in
an ``ipywidgets.Output`` (:func:`script`, :func:`script_output`) that names each handle after its slider, gives it a description
(``aria-describedby``: what it moves, its range and step, from :func:`slider_descriptions`),
makes the report a polite live region (``role="status"``) and gives the picture a text
alternative. Each slider also carries its description as a tooltip. Layer: viz.
"""
from __future__ import annotations

import json
import uuid

import numpy as np

from ..core.report import q_units

__all__ = ["label_widgets", "script", "script_output", "slider_descriptions", "q_slider"]


def q_slider(unit: str) -> tuple[str, float, float, str, str]:
    """How a coordinate's slider shows it: ``(suffix, factor, step, readout format, unit in words)``.

    An angle (``"rad"``) is shown in degrees, a slide (``"m"``) in millimetres; ``factor`` turns the
    coordinate (rad or m) into the slider's value.

    Examples
    --------
    >>> q_slider("rad")[:3], q_slider("m")[:3]
    (('deg', 57.29577951308232, 0.5), ('mm', 1000.0, 1.0))
    """
    if unit == "m":
        return "mm", 1000.0, 1.0, ".0f", "millimetres"
    if unit == "rad":
        return "deg", float(np.degrees(1.0)), 0.5, ".1f", "degrees"
    raise ValueError(f"unit must be 'rad' or 'm', got {unit!r}")

_A11Y_JS = """(function () {
  var spec = SPEC, tries = 0;
  function label() {
    var boxes = document.querySelectorAll("." + spec.box), missing = boxes.length === 0;
    boxes.forEach(function (box) {
      box.setAttribute("role", "group");
      box.setAttribute("aria-label", spec.name);
      spec.sliders.forEach(function (s, i) {
        var el = box.querySelector("." + s[0]), handle = el && el.querySelector(".noUi-handle");
        if (!handle) { missing = true; return; }
        if (handle.getAttribute("aria-label") !== s[1]) { handle.setAttribute("aria-label", s[1]); }
        var id = s[0] + "-description";
        if (!el.querySelector("#" + id)) {
          var d = document.createElement("span");
          d.id = id; d.hidden = true; d.textContent = s[2];
          el.appendChild(d);
        }
        handle.setAttribute("aria-describedby", id);
      });
      var report = box.querySelector("." + spec.report + " .widget-html-content");
      if (report) {
        report.setAttribute("role", "status");
        report.setAttribute("aria-live", "polite");
        report.setAttribute("aria-atomic", "true");
      } else { missing = true; }
      var img = box.querySelector("img");
      if (img && !img.getAttribute("alt")) { img.setAttribute("alt", spec.alt); }
      if (!box.blObserved && window.MutationObserver) {
        box.blObserved = true;
        new MutationObserver(function () { label(); }).observe(box, {childList: true, subtree: true});
      }
    });
    if (missing && ++tries < 600) { setTimeout(label, 100); }
  }
  label();
})();
"""


def slider_descriptions(explorer) -> dict:
    """What each slider of an explorer moves, in words: keyed by the slider's label.

    Parameters
    ----------
    explorer : Explorer

    Returns
    -------
    dict of str to str

    Examples
    --------
    >>> import balancelab as bl
    >>> ex = bl.viz.explore(bl.catalog()["lacoste_lever"]())
    >>> print(ex.slider_descriptions["theta (deg)"])  # doctest: +ELLIPSIS
    theta, ... from ... to ... degrees in steps of 0.5; moves the mechanism along its energy curve
    """
    out = {}
    design = explorer.design
    for name, (lo, hi, step, _) in explorer.params.items():
        out[name] = (f"{name}, a parameter of {design.name}: from {lo:.4g} to {hi:.4g} in steps of "
                     f"{step:.4g}; the picture and the balance report below follow it")
    if explorer.show_q:
        words = design.kinematics.describe()
        for i, (name, unit) in enumerate(zip(explorer.q_names, q_units(design))):
            suffix, factor, step, fmt, spoken = q_slider(unit)
            lo, hi = factor * np.asarray(design.q_range[i])
            what = f", {words[i]}," if words[i] else ""
            out[f"{name} ({suffix})"] = (f"{name}{what} from {lo:{fmt}} to {hi:{fmt}} {spoken} in steps of "
                                         f"{step:g}; moves the mechanism along its energy curve")
    return out


def label_widgets(box, report, sliders: list, descriptions: dict) -> str:
    """Give the explorer's widgets the DOM classes :func:`script` finds them by; return their id.

    Each slider's tooltip becomes its description.
    """
    uid = uuid.uuid4().hex[:12]
    box.add_class("bl-explorer")
    box.add_class(f"bl-explorer-{uid}")
    for i, s in enumerate(sliders):
        s.add_class(f"bl-slider-{uid}-{i}")
        s.tooltip = descriptions.get(s.description, s.description)
    report.add_class(f"bl-report-{uid}")
    return uid


def script(uid: str, name: str, sliders: list, descriptions: dict) -> str:
    """The JavaScript that labels one explorer's widgets in the page (see the module docstring).

    Examples
    --------
    >>> "aria-live" in script("abc", "a lever", [], {})
    True
    """
    spec = {"box": f"bl-explorer-{uid}", "name": f"Explorer of {name}", "report": f"bl-report-{uid}",
            "alt": f"{name} and its energy; the balance report below says what it shows",
            "sliders": [[f"bl-slider-{uid}-{i}", s.description, descriptions.get(s.description, "")]
                        for i, s in enumerate(sliders)]}
    return _A11Y_JS.replace("SPEC", json.dumps(spec, ensure_ascii=False).replace("</", "<\\/"))


def script_output(js: str):
    """An ``ipywidgets.Output`` that holds ``js`` as its one (invisible) output.

    A notebook front end renders it with the widget, wherever the widget is shown, and runs the
    script; a front end that runs no JavaScript shows nothing.

    Examples
    --------
    >>> script_output("1 + 1;").outputs[0]["data"]["application/javascript"]
    '1 + 1;'
    """
    import ipywidgets as w

    out = w.Output(layout=w.Layout(height="0px", overflow="hidden", margin="0", padding="0"))
    out.outputs = ({"output_type": "display_data", "metadata": {},
                    "data": {"application/javascript": js, "text/plain": ""}},)
    return out
