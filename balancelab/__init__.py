"""balancelab: static balancing of planar linkages.

Build a mechanism, balance it with springs or counterweights by any method of the
course, and let the design prove itself balanced::

    >>> import balancelab as bl
    >>> arm = bl.singh.serial_2r_min_preload()     # Singh & Ananthasuresh's 2R
    >>> arm.balance_report().balanced
    True

The package is layered; each layer imports only the ones above it in this list:

``core``
    loads, springs, joints, the `Kinematics` contract and the immutable :class:`Design`.
``mechanisms``
    the linkages (lever, 2R chain, four-bar, scissors, Peaucellier-Lipkin) and the one
    geometry kernel.
``methods``
    the balancing methods, one namespace per source: :mod:`lecture <balancelab.methods.lecture>`,
    :mod:`singh <balancelab.methods.singh>`, :mod:`lustig <balancelab.methods.lustig>`,
    :mod:`deepak <balancelab.methods.deepak>`, :mod:`realize <balancelab.methods.realize>`,
    :mod:`practice <balancelab.methods.practice>` (real springs, tolerances, friction, forces);
    each declares its worked examples in the registry.
``viz``
    drawings, energy plots, animations and explorers of any design.
``course``
    the catalog of worked examples, the gallery, the labs' answer checks, the grader.

The top level re-exports the design types, the mechanisms' builders, the method
namespaces (``bl.lecture``, ``bl.singh``, ``bl.lustig``, ``bl.deepak``, ``bl.realize``,
``bl.practice``),
``catalog`` and the viz functions. matplotlib, scipy, sympy and ipywidgets are imported
only when something that needs them is first used.
"""
import importlib as _importlib

from .core import (BALANCE_TOLERANCE, Attachment, BalanceReport, BalancelabError, Design, Energy, G, Joint,
                   Kinematics, Load, Pulley, Spring, SymbolicParts, UnreachableConfiguration, gravity_load)
from .mechanisms import (ExplicitKinematics, FourBar, FourBarKinematics, PeaucellierKinematics, TreeKinematics,
                         fourbar_joints, lever_kinematics, scissors_kinematics, serial_2r_kinematics)
from .mechanisms.linkage import Linkage
from .methods import deepak, lecture, lustig, practice, realize, singh
from .methods.general import InfeasibleDesign, balance
from .course.catalog import catalog

__version__ = "0.2.0"

#: the names that need matplotlib or ipywidgets, imported on first use: name -> module that defines it
_LAZY = {
    "viz": "balancelab.viz", "course": "balancelab.course",
    **{name: "balancelab.viz" for name in ("draw", "energy_plot", "lever_valley", "family_plot",
                                           "cognates_plot", "animate", "animate_parameter", "explore",
                                           "Explorer")},
}

__all__ = [
    # core
    "BALANCE_TOLERANCE", "Attachment", "BalanceReport", "BalancelabError", "Design", "Energy", "G", "Joint", "Kinematics",
    "Load", "Pulley", "Spring", "SymbolicParts", "UnreachableConfiguration", "gravity_load",
    # mechanisms
    "ExplicitKinematics", "FourBar", "FourBarKinematics", "PeaucellierKinematics", "TreeKinematics",
    "fourbar_joints", "lever_kinematics", "scissors_kinematics", "serial_2r_kinematics", "Linkage",
    # methods
    "deepak", "lecture", "lustig", "practice", "realize", "singh", "balance", "InfeasibleDesign",
    # viz and course (imported on first use)
    "viz", "draw", "energy_plot", "lever_valley", "family_plot", "cognates_plot", "animate",
    "animate_parameter", "explore", "Explorer", "course", "catalog",
]


def __getattr__(name: str):
    """Import the parts that need matplotlib or ipywidgets on first use."""
    if name in _LAZY:
        module = _importlib.import_module(_LAZY[name])
        value = module if module.__name__.endswith("." + name) else getattr(module, name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted(set(__all__) | {n for n in globals() if n.startswith("__") or not n.startswith("_")})
