"""Deepak & Ananthasuresh: static balancing of a spring-loaded four-bar and its cognates (MMT 48, 2012).

The building blocks (basic balancer, balanced parallelogram, composition of springs,
plagiograph), the four-bar loaded by a spring balanced by techniques 1-3 and Herder's,
their one-parameter families, the gravity four-bar as the limit of a spring load, and
the Roberts-Chebyshev cognates balanced through the focal pivot.
"""
from .roberts import (cognates, cognate_triangle, cognate_crank_angles, cognate_design,
                      cognate_designs, focal_pivot_circles, CognateFamily, cognate_family,
                      kb_ratio_from_triangle, balance_cognates)
from .spring_fourbar import (FourBar, coupler_curve, fourbar_positions, loop_closure_error,
                             spring_loaded_fourbar, basic_balancer, balanced_parallelogram,
                             compose_zfl_springs, composing_anchor, composed_springs_lever,
                             plagiograph_map, balanced_plagiograph, Technique2Parameters,
                             technique1, technique1_feasible, technique1_family,
                             technique2_parameters, technique2, technique2_family,
                             Technique3Parameters, technique3_parameters, technique3,
                             technique3_family, herder, gravity_technique2, gravity_as_spring_limit,
                             serial_2r_technique2, slider_crank_technique2, watt_fourbar,
                             watt_prototype, example_fourbar)

__all__ = ["cognates", "cognate_triangle", "cognate_crank_angles", "cognate_design",
           "cognate_designs", "focal_pivot_circles", "CognateFamily", "cognate_family",
           "kb_ratio_from_triangle", "balance_cognates", "FourBar", "coupler_curve",
           "fourbar_positions", "loop_closure_error", "spring_loaded_fourbar", "basic_balancer",
           "balanced_parallelogram", "compose_zfl_springs", "composing_anchor",
           "composed_springs_lever", "plagiograph_map", "balanced_plagiograph",
           "Technique2Parameters", "technique1", "technique1_feasible", "technique1_family",
           "technique2_parameters", "technique2", "technique2_family", "Technique3Parameters",
           "technique3_parameters", "technique3", "technique3_family", "herder",
           "gravity_technique2", "gravity_as_spring_limit", "serial_2r_technique2",
           "slider_crank_technique2", "watt_fourbar", "watt_prototype", "example_fourbar"]
