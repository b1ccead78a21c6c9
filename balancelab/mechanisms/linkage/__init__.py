"""Any planar linkage of revolute joints: the `Linkage` builder and its numeric kinematics.

``topology`` writes every body point and every loop-closure gap as a fixed combination
of rotated vectors in the absolute body angles; ``kinematics`` assembles the linkage,
counts its degrees of freedom, follows its circuit and solves poses for many
configurations at once (:class:`LinkageKinematics`); ``builder`` is the user-facing
:class:`Linkage`. Layer: mechanisms.
"""
from .builder import Linkage
from .kinematics import LinkageKinematics
from .topology import Topology

__all__ = ["Linkage", "LinkageKinematics", "Topology"]
