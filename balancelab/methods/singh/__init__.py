"""Singh & Ananthasuresh: static balancing with minimum spring preload.

LaCoste's lever, the generalized lever and the lever with minimum preload; 2R arms with
three (or two) ZFL springs from the ground; the four-bar of Sec. III.A; the
Peaucellier-Lipkin writing board (Sec. III.B); the scissors lift (Sec. IV).
"""
# imported in course order: the registry orders a family's examples by module import
from .lever import generalized_lever, lacoste_energies, lacoste_lever, min_preload_lever
from .counting import ChainConditions, chain_conditions, chain_solution_point, conditions_rank, design_point
from .serial import (free_choice_count, max_work_angle, serial_2r_min_preload, serial_2r_simplified,
                     serial_2r_two_springs)
from .fourbar import singh_fourbar
from .scissors import scissors_lift
from .peaucellier import peaucellier_board

__all__ = ["singh_fourbar", "generalized_lever", "lacoste_energies", "lacoste_lever", "min_preload_lever", "peaucellier_board",
           "scissors_lift", "free_choice_count", "max_work_angle", "serial_2r_min_preload",
           "serial_2r_simplified", "serial_2r_two_springs", "ChainConditions", "chain_conditions",
           "chain_solution_point", "conditions_rank", "design_point"]
