"""Every worked example of the course, by short name (the pattern of sympy's ``models``).

``catalog()`` returns an ordered mapping from a short name to a zero-argument function
that builds the example with its published numbers. The gallery, the book, the figures'
tests and the answer checks iterate it. A few entries are counter-examples kept on
purpose (an ordinary spring where a ZFL spring is needed): their factory's
``expected_balanced`` attribute is ``False``.
"""
from __future__ import annotations

import importlib
from collections import OrderedDict
from typing import Callable

from .design import Design

__all__ = ["catalog", "Entry"]


class Entry:
    """A zero-argument factory of a catalog example.

    Attributes
    ----------
    name : str
        Short name (the catalog key).
    title : str
        One line saying what it is and where it comes from.
    expected_balanced : bool
        ``False`` for the deliberate counter-examples.
    """

    def __init__(self, name: str, target, title: str = "", kwargs: dict | None = None,
                 expected_balanced: bool = True):
        self.name = name
        self.title = title
        self.expected_balanced = expected_balanced
        self._target = target
        self._kwargs = dict(kwargs or {})
        self.__doc__ = title

    @property
    def function(self) -> Callable[..., Design]:
        """The library function this entry calls."""
        if callable(self._target):
            return self._target
        module, name = self._target.rsplit(".", 1)
        return getattr(importlib.import_module(f"balancelab.{module}"), name)

    def __call__(self) -> Design:
        return self.function(**self._kwargs)

    def __repr__(self) -> str:
        return f"<catalog entry {self.name!r}: {self.title}>"


_ENTRIES = [
    Entry("single_link_counterweight", "lever.single_link_counterweight",
          "Single link balanced by a counterweight (lecture 35 recap)",
          dict(mass=2.0, r=0.5, counter_mass=4.0, link_mass=0.5)),
    Entry("single_link_zfl", "lever.single_link_spring",
          "Single link with a ZFL spring, k = m g r/(b c) (lecture 35)",
          dict(mass=2.0, r=0.5, b=0.3, c=0.2)),
    Entry("single_link_zfl_below", "lever.single_link_spring",
          "Single link with a ZFL spring below the pivot (lecture 35, second arrangement)",
          dict(mass=2.0, r=0.5, b=0.3, c=0.2, arrangement="below")),
    Entry("single_link_ordinary_spring", "lever.single_link_ordinary_spring",
          "The same link with an ordinary spring: not balanced (lecture 35)",
          dict(mass=2.0, r=0.5, b=0.3, c=0.2, free_length=0.05), expected_balanced=False),
    Entry("lacoste_lever", "lever.lacoste_lever", "LaCoste's lever (Singh eqs 1-3)",
          dict(weight=10.0, l=0.5, a_x=0.2, b_y=0.3)),
    Entry("generalized_lever", "lever.generalized_lever", "Generalized lever (Singh eqs 12-17)",
          dict(weight=10.0, l=0.5, a_x=0.2, b_x=0.1, b_y=0.3)),
    Entry("min_preload_lever", "lever.min_preload_lever",
          "Lever with minimum preload, Singh's rocker: k4 = 20 N/m (eqs 18-20)",
          dict(weight=10.0, l=0.5, a_x=0.5, a_y=0.0)),
    Entry("fourbar_counterweights", "fourbar.fourbar_counterweights",
          "Four-bar with counterweights on links 2 and 4 (lecture 35)"),
    Entry("fourbar_two_springs", "fourbar.fourbar_two_springs",
          "Four-bar with two ZFL springs on links 2 and 4 (lecture 35)"),
    Entry("serial_2r_parallelogram", "serial.serial_2r_parallelogram",
          "2R arm with a parallelogram of auxiliary links (lecture 35)"),
    Entry("serial_2r_base_springs", "serial.serial_2r_base_springs",
          "2R desk-lamp arm with both springs on the base (lecture 35)"),
    Entry("serial_2r_simplified", "serial.serial_2r_simplified",
          "Simplified 2R with three ZFL springs (Singh eqs 21-28)"),
    Entry("serial_2r_min_preload", "serial.serial_2r_min_preload",
          "General 2R with minimum preload (Singh eqs 35-49, Sec. III.A numbers)"),
    Entry("serial_2r_two_springs", "serial.serial_2r_two_springs",
          "General 2R with two ZFL springs (Singh eq. 50)"),
    Entry("lustig_case1", "stiffness.lustig_case1",
          "Stiffness-matrix 2R, Table 3e case 1: springs along the links (Lustig et al.)"),
    Entry("lustig_case2", "stiffness.lustig_case2",
          "Stiffness-matrix 2R, Table 3e case 2: A2 turned about J2 (Lustig et al.)"),
    Entry("lustig_case3", "stiffness.lustig_case3",
          "Stiffness-matrix 2R, Table 3e case 3: centre of mass of link 2 off its axis (Lustig et al.)"),
    Entry("lustig_case4", "stiffness.lustig_case4",
          "Stiffness-matrix 2R, Table 3e case 4: cases 2 and 3 combined (Lustig et al.)"),
    Entry("singh_fourbar", "fourbar.singh_fourbar",
          "Four-bar with minimum preload (Singh Sec. III.A: k1 = 17.81, k4 = 20 N/m)"),
    Entry("scissors_lift", "scissors.scissors_lift",
          "Projector scissors lift, one ZFL and one finite-free-length spring (Singh Sec. IV)"),
    Entry("peaucellier_board", "peaucellier.peaucellier_board",
          "Peaucellier-Lipkin writing board (Singh Sec. III.B: k1 = 45.88, k2 = k3 = 33.02 N/m)"),
]

#: deliberate counter-examples among the entries other modules provide
_NOT_BALANCED = {"deepak_spring_loaded_fourbar", "approximate_spring_lever"}


_TITLES = {
    "deepak_basic_balancer": "Basic spring force balancer (Deepak & Ananthasuresh, Fig. 4)",
    "deepak_balanced_parallelogram": "Balanced parallelogram (Deepak & Ananthasuresh, Figs 6-7)",
    "deepak_composed_springs": "Two ZFL springs composed into one (Deepak & Ananthasuresh, Sec. 2.1.1)",
    "deepak_plagiograph": "Balanced plagiograph (Deepak & Ananthasuresh, Sec. 2.1.2, eq. 1)",
    "deepak_gravity_fourbar": "Gravity load as the limit of a spring load (Deepak & Ananthasuresh, Sec. 4)",
}


def _module_entries(module: str) -> list[Entry]:
    """Entries from a module's ``catalog_entries()`` (name -> zero-argument factory)."""
    mod = importlib.import_module(f"balancelab.{module}")
    out = []
    for name, factory in mod.catalog_entries().items():
        title = _TITLES.get(name) or (factory.__doc__ or name).strip().splitlines()[0]
        out.append(Entry(name, factory, title, expected_balanced=name not in _NOT_BALANCED))
    return out


def _course_order() -> list[Entry]:
    """Part-1 entries with the other modules' entries placed where the course meets them."""
    names = [e.name for e in _ENTRIES]
    at = {"realize": names.index("min_preload_lever") + 1,
          "spring_fourbar": names.index("singh_fourbar") + 1}
    entries = list(_ENTRIES)
    inserted = 0
    for module in ("realize", "spring_fourbar"):
        extra = _module_entries(module)
        pos = at[module] + inserted
        entries[pos:pos] = extra
        inserted += len(extra)
    pos = [e.name for e in entries].index("scissors_lift")
    entries[pos:pos] = _module_entries("cognates")
    return entries


def catalog() -> "OrderedDict[str, Entry]":
    """Every worked example of the course, in the order of the course.

    Returns
    -------
    collections.OrderedDict
        Short name -> zero-argument :class:`Entry` returning a :class:`Design`.

    Examples
    --------
    >>> import balancelab as bl
    >>> cat = bl.catalog()
    >>> cat["singh_fourbar"]().balance_report().balanced
    True
    """
    return OrderedDict((e.name, e) for e in _course_order())
