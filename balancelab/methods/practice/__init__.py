"""From ideal to real: real extension springs, selection, tolerances, friction, payloads, forces.

What lives here: ``springs`` (helical extension springs from wire and coil data, the
materials table), ``selection`` (real springs for each ZFL spring of a balanced design),
``tolerance`` (Monte Carlo of built designs), ``friction`` (Coulomb joint friction: what
a balancer must do to stay where it is left), ``payload`` (re-balancing for a new payload,
the work of an adjustment) and ``forces`` (spring forces, generalized forces and joint
loads). Course chapter 8 ("From ideal to real") uses them.

What it may import: ``balancelab.core``, ``balancelab.mechanisms`` and the other method
families' building blocks (``lecture``, and ``realize`` for the exact string-over-pulley model
and the cable on a non-circular pulley); never ``viz`` or ``course``.
"""
from . import forces, friction, payload, routing, selection, springs, tolerance

__all__ = ["forces", "friction", "payload", "routing", "selection", "springs", "tolerance"]
