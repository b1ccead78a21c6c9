"""Core: the parts of a design and the design itself.

What lives here: the input checks (``validation``), loads, springs and joints
(``elements``), the package's exception types (``errors``), the one transform kernel (``frames``:
a body's local point carried to the world and back), the `Kinematics` contract every mechanism
implements and the one finite-difference loop over configurations (``kinematics``),
the immutable :class:`Design` with its numeric energy and balance report (``design``)
and its symbolic energy and balance conditions (``symbolic``).

What it may import: numpy (and sympy lazily), nothing else of balancelab. Everything
else imports core.
"""
from .design import BALANCE_TOLERANCE, BalanceReport, Design, Energy
from .errors import (AnswerError, ApproximationError, BalancelabError, InfeasibleDesign, MarkerError, ProfileError,
                     SingularChoice, UnreachableConfiguration)
from .elements import G, Attachment, CablePath, Joint, Load, Pulley, Spring, SymbolicParts, gravity_load
from .kinematics import Kinematics, body_to_world, joint_gaps

__all__ = ["BALANCE_TOLERANCE", "BalanceReport", "Design", "Energy", "BalancelabError", "UnreachableConfiguration",
           "InfeasibleDesign", "SingularChoice", "ApproximationError", "ProfileError", "MarkerError", "AnswerError", "G",
           "Attachment", "CablePath", "Joint", "Load", "Pulley", "Spring", "SymbolicParts", "gravity_load", "Kinematics",
           "body_to_world", "joint_gaps"]
