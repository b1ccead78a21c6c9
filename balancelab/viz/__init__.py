"""Viz: pictures of a design: drawings, energy plots, design spaces, animations, explorers.

What lives here: ``frame`` (the shared palette, input checks, configuration grids and
off-screen rendering), ``style`` (the house style: resolution, font sizes, titles that fit,
labels that avoid each other, figures shown as one image per panel), ``springs`` (how a
coil, a gas spring or a string over a pulley is drawn), ``drawing`` (:func:`draw` and
:class:`Drawing`), ``diagram`` (labelled diagrams: named points, dimension lines, angle
arcs), ``energy``
(:func:`energy_plot` and :class:`EnergyView`), ``spaces`` (:func:`lever_valley`,
:func:`family_plot`, :func:`cognates_plot`), ``animation`` (offline HTML animations),
``player`` (the page's accessible animation player), ``explorer`` (live ipywidgets
explorers, imported on first use) and ``widget_access`` (the explorers' slider names,
descriptions and live report for screen readers), ``formula`` (long SymPy results set
over lines that fit a phone's column). Every figure and animation says what it
shows in words computed from the design (its alt text). No physics is
computed here: geometry and energies come from the :class:`balancelab.Design` being
drawn (and a spring's realization from its ``realization``), so a picture cannot
disagree with the numbers.

A new figure goes in a module here (a new one for a new kind of view) as a function
that takes a ``Design``. What it may import: ``core``, ``mechanisms``, ``methods`` (for
the quantities a method defines), matplotlib; never ``course``.
"""
import importlib

from .animation import Player, animate, animate_parameter, configuration_path, player
from .diagram import diagram, point_positions
from .drawing import Drawing, draw
from .energy import EnergyView, energy_plot, report_summary
from .frame import default_q
from .spaces import cognates_plot, family_plot, lever_valley

__all__ = ["Player", "animate", "animate_parameter", "player", "configuration_path", "Drawing", "EnergyView", "cognates_plot",
           "default_q", "diagram", "draw", "energy_plot", "family_plot", "lever_valley", "point_positions", "report_summary", "explore",
           "Explorer"]

_LAZY = {"explore": "explorer", "Explorer": "explorer"}


def __getattr__(name: str):
    """``explore`` and ``Explorer`` need ipywidgets: imported on first use."""
    if name in _LAZY:
        return getattr(importlib.import_module(f"{__name__}.{_LAZY[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(globals()) | set(__all__))
