"""The general balancer: ZFL springs and counterweights for any design, from named candidates.

Why this method
---------------
With zero-free-length springs and constant loads, the potential energy of any planar
linkage is a combination of ``cos theta_b``, ``sin theta_b`` and the cosines and sines
of the differences of the absolute body angles, with coefficients that are *linear* in
each spring rate and counter mass, and linear in the moments ``k p`` of a free
attachment point ``p`` when the spring's other end is known (:mod:`.problem`). Balance,
a constant energy, is therefore a linear system in these unknowns.

For an open chain the body angles are independent and the system is exactly the
harmonic (trigonometric) coefficients of the energy. For loops they are tied by the
closure equations, and the coefficients are no longer unique; instead of eliminating the
loops symbolically we sample the design's own numeric kinematics at a few hundred
configurations spread over its range and require the energy to be the same at all of
them. Since the energy lies in the finite span of those trigonometric functions, a
sample larger than that span is as good as the harmonic conditions (for trees it is
exactly equivalent), and the singular value decomposition of the sampled system gives
the *rank of the conditions* and the free choices left (:mod:`.solver`).
Non-negativity (``k >= 0``, masses ``>= 0``) and boxes for free points are linear
constraints, so an objective that is linear (smallest total stiffness, smallest counter
mass, minimum preload with fixed points) is a linear program; the minimum preload with
free points adds the convex term ``|k p|^2 / (2k)`` (SLSQP from the linear program's
answer). A spring whose two ends are both free is bilinear (``k p_a p_b``, the cross
term of Lustig et al.'s stiffness matrix); it is solved by alternating which end is
free, each round a linear problem whose previous answer stays admissible, so the
objective never increases. Every returned design is checked by its own balance report.

What lives here: ``problem`` (candidates as columns of the sampled energy), ``solver``
(rank, linear program, polish, infeasibility message), ``balancer`` (:func:`balance`),
``examples`` (worked examples in the registry, family ``"general"``). Layer: methods; it
may import ``core`` and ``mechanisms`` (its error types are in ``core.errors``).
"""
from .balancer import OBJECTIVES, InfeasibleDesign, balance, free_choices
from . import examples

__all__ = ["OBJECTIVES", "InfeasibleDesign", "balance", "free_choices", "examples"]
