"""balancelab: static balancing of planar linkages.

Build a mechanism in a line, balance it with springs or counterweights by any method of
the course, and let the design prove itself balanced::

    >>> import balancelab as bl
    >>> arm = bl.serial_2r_min_preload()            # Singh & Ananthasuresh's 2R
    >>> arm.balance_report().balanced
    True

Every method returns a :class:`Design`; plotting, animation, widgets and answer
checks all take that one type. ``catalog()`` lists every worked example of the course.
sympy is imported only when a symbolic method is first used.
"""
from .design import BALANCE_TOLERANCE, BalanceReport, Design, Energy, UnreachableConfiguration
from .elements import G, Attachment, Joint, Load, Spring, SymbolicParts, weight
from .kinematics import ExplicitKinematics, FourBarKinematics, Kinematics, TreeKinematics
from .lever import (generalized_lever, lacoste_lever, lever_kinematics, link_spring, min_preload_lever,
                    single_link_counterweight, single_link_ordinary_spring, single_link_spring)

from .serial import (free_choice_count, max_work_angle, serial_2r_base_springs, serial_2r_kinematics,
                     serial_2r_min_preload, serial_2r_parallelogram, serial_2r_simplified,
                     serial_2r_two_springs)
from .fourbar import (equivalent_masses, fourbar_counterweights, fourbar_joints, fourbar_two_springs,
                      singh_fourbar)
from .scissors import scissors_kinematics, scissors_lift
from .peaucellier import PeaucellierKinematics, peaucellier_board
from . import stiffness
from .stiffness import (InfeasibleDesign, SerialChain, balance_all_pairs, constraint_equations,
                        lustig_table3e_case, solve, stiffness_matrix, stiffness_matrix_symbolic, synthesize)
from .catalog import Entry, catalog

__version__ = "0.1.0"

_LAZY = ("plotting", "animation", "explore", "check", "grading", "labtools", "spring_fourbar",
         "cognates", "realize")


_LAZY_NAMES = {"draw": "plotting", "energy_plot": "plotting", "lever_valley": "plotting",
               "family_plot": "plotting", "cognates_plot": "plotting", "animate": "animation",
               "animate_parameter": "animation", "Explorer": "explore"}


def __getattr__(name: str):
    """Import the heavier submodules (matplotlib, ipywidgets, scipy) on first use."""
    import importlib

    if name in _LAZY:
        return importlib.import_module(f"{__name__}.{name}")
    if name in _LAZY_NAMES:
        return getattr(importlib.import_module(f"{__name__}.{_LAZY_NAMES[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
