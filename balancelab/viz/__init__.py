"""Viz: pictures of a design: drawings, energy plots, design spaces, animations, explorers.

What lives here: ``plotting`` (static figures: :func:`draw`, :func:`energy_plot`, the
design-space and family views), ``animation`` (offline HTML animations) and
``explorer`` (live ipywidgets explorers, imported on first use). No physics is computed
here: geometry and energies come from the :class:`balancelab.Design` being drawn, so a
picture cannot disagree with the numbers.

A new figure goes in ``plotting`` (or a new module here) as a function that takes a
``Design``. What it may import: ``core``, ``mechanisms``, ``methods`` (for the
quantities a method defines), matplotlib; never ``course``.
"""
import importlib

from .animation import animate, animate_parameter, configuration_path
from .plotting import (Drawing, EnergyView, cognates_plot, default_q, draw, energy_plot,
                       family_plot, lever_valley, report_summary)

__all__ = ["animate", "animate_parameter", "configuration_path", "Drawing", "EnergyView", "cognates_plot",
           "default_q", "draw", "energy_plot", "family_plot", "lever_valley", "report_summary", "explore",
           "Explorer"]

_LAZY = {"explore": "explorer", "Explorer": "explorer"}


def __getattr__(name: str):
    """``explore`` and ``Explorer`` need ipywidgets: imported on first use."""
    if name in _LAZY:
        return getattr(importlib.import_module(f"{__name__}.{_LAZY[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(__all__))
