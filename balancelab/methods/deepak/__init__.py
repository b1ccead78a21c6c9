"""Deepak & Ananthasuresh: static balancing of a spring-loaded four-bar and its cognates (MMT 48, 2012).

Modules, lowest first: ``blocks`` (basic balancer, balanced parallelogram, composition
of springs, plagiograph and the balancing step every technique repeats),
``techniques`` (the spring-loaded four-bar, techniques 2 and 3, Herder's, their
families), ``technique1`` (two auxiliary links), ``gravity`` (gravity as the limit of a
spring load, the 2R arm and the slider-crank), ``watt`` (the 1:1:2 prototype),
``roberts`` (the Roberts-Chebyshev cognates), ``cognate_balance`` (the three cognates
balanced at once through the focal pivot) and ``examples`` (the example four-bar and
the worked examples of the registry). The four-bar itself is
:class:`balancelab.FourBar` (:mod:`balancelab.mechanisms.fourbar`).
"""
from ...mechanisms.fourbar import coupler_curve, fourbar_positions, loop_closure_error
from .blocks import (balanced_parallelogram, balanced_plagiograph, basic_balancer, compose_zfl_springs,
                     composed_springs_lever, composing_anchor, plagiograph_map)
from .techniques import (Technique2Parameters, Technique3Parameters, herder, spring_loaded_fourbar,
                         technique2, technique2_family, technique2_parameters, technique3, technique3_family,
                         technique3_parameters)
from .technique1 import technique1, technique1_family, technique1_feasible
from .gravity import (gravity_as_spring_limit, gravity_technique2, serial_2r_technique2,
                      slider_crank_technique2)
from .watt import watt_fourbar, watt_prototype
from .roberts import cognate_crank_angles, cognate_design, cognate_designs, cognate_triangle, cognates
from .cognate_balance import (CognateFamily, balance_cognates, cognate_family, focal_pivot_circles,
                              kb_ratio_from_triangle, similar_triangle_family)
from .examples import example_fourbar

__all__ = ["cognates", "cognate_triangle", "cognate_crank_angles", "cognate_design",
           "cognate_designs", "focal_pivot_circles", "CognateFamily", "cognate_family",
           "kb_ratio_from_triangle", "balance_cognates", "similar_triangle_family",
           "coupler_curve", "fourbar_positions", "loop_closure_error", "spring_loaded_fourbar",
           "basic_balancer", "balanced_parallelogram", "compose_zfl_springs", "composing_anchor",
           "composed_springs_lever", "plagiograph_map", "balanced_plagiograph",
           "Technique2Parameters", "technique1", "technique1_feasible", "technique1_family",
           "technique2_parameters", "technique2", "technique2_family", "Technique3Parameters",
           "technique3_parameters", "technique3", "technique3_family", "herder",
           "gravity_technique2", "gravity_as_spring_limit", "serial_2r_technique2",
           "slider_crank_technique2", "watt_fourbar", "watt_prototype", "example_fourbar"]
