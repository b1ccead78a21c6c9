"""Methods: ways to balance a mechanism, one subpackage per source.

What lives here: ``lecture`` (lecture 35: counterweights, the basic ZFL balancer,
parallelogram arms, the four-bar's equivalent masses), ``singh`` (Singh &
Ananthasuresh: levers, 2R arms and a four-bar with minimum preload, the scissors lift,
the Peaucellier-Lipkin board), ``lustig`` (Lustig, Dunning & Herder's stiffness-matrix
method), ``deepak`` (Deepak & Ananthasuresh: spring-loaded four-bars, techniques 1-3,
cognates), ``realize`` (making a ZFL spring real), ``general`` (balancing any linkage a user
draws: ``balance``), ``practice`` (real springs, tolerances, friction, joint forces) and
``registry`` (the worked examples).

Every method returns a :class:`balancelab.Design`. A new method goes in the module of
its source (or a new subpackage for a new source, added to
:data:`registry.FAMILIES`), and declares its worked examples there with
:func:`registry.example`.

What it may import: ``balancelab.core`` and ``balancelab.mechanisms``; a family may use
another family's building blocks (``singh`` uses ``lecture``'s basic balancer) but never
``viz`` or ``course``.
"""
from . import deepak, general, lecture, lustig, practice, realize, singh
from .registry import Example, example, examples, register

__all__ = ["deepak", "general", "lecture", "lustig", "practice", "realize", "singh", "Example", "example",
           "examples", "register"]
