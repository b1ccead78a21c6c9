"""Mechanisms: the linkages themselves, with no springs and no loads.

What lives here: the one geometry kernel (``geometry``: rigid-body points, circle
intersection; rotations are ``core.frames``'), generic kinematics (``base``: explicit pose functions, trees of
revolute joints), and one module per mechanism of the course: ``lever``, ``chain`` (serial
chains of any number of links, the 2R arm among them), ``fourbar``, ``scissors``, ``peaucellier``. Each mechanism implements
:class:`balancelab.core.Kinematics` and names its joints.

A new mechanism goes in a new module here: a `Kinematics` subclass (or a function
returning one) and a function returning its joints.

What it may import: ``balancelab.core``.
"""
from .base import ExplicitKinematics, TreeKinematics
from .chain import (SymbolicChainKinematics, serial_2r_joints, serial_2r_kinematics, serial_chain_joints,
                    serial_chain_kinematics)
from .fourbar import (FourBar, FourBarKinematics, check_assembly, coupler_curve, fourbar_design, fourbar_joints,
                      fourbar_labels)
from .geometry import as_complex, as_point, binary_link_point, circle_intersection, rotate
from .lever import lever_design, lever_kinematics
from .peaucellier import PeaucellierKinematics
from .scissors import scissors_joints, scissors_kinematics

__all__ = ["ExplicitKinematics", "TreeKinematics", "serial_2r_joints", "serial_2r_kinematics",
           "serial_chain_joints", "serial_chain_kinematics", "SymbolicChainKinematics",
           "FourBar", "FourBarKinematics", "check_assembly", "coupler_curve", "fourbar_design", "fourbar_joints",
           "fourbar_labels", "as_complex", "as_point", "binary_link_point", "circle_intersection", "rotate",
           "lever_design", "lever_kinematics", "PeaucellierKinematics", "scissors_joints",
           "scissors_kinematics"]
