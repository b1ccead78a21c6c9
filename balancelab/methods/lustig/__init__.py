"""Lustig, Dunning & Herder: the stiffness-matrix method for serial linkages (IFToMM 2015).

The potential energy of a serial chain with ZFL springs and gravity written as a
quadratic form of Cartesian joint coordinates; balance is the vanishing of the
off-diagonal and gravity terms (eqs 1-17), solved numerically or symbolically; the
paper's Table 3e cases and design-space relations (eqs 18-20).
"""
from .stiffness import (SerialChain, InfeasibleDesign, chain_kinematics, chain_parameter_names,
                        stiffness_matrix, stiffness_matrix_symbolic, constraint_equations,
                        constraint_residuals, gravity_conditions, diagonal_residual,
                        quadratic_energy, solve, solve_symbolic, synthesize, balance_all_pairs,
                        LUSTIG_TOPOLOGY, LUSTIG_UNKNOWNS, lustig_values, lustig_table3e_case,
                        lustig_case1, lustig_case2, lustig_case3, lustig_case4, lustig_alpha,
                        lustig_b1, lustig_a1, lustig_min_energy_pose, spring2_invariant)

__all__ = ["SerialChain", "InfeasibleDesign", "chain_kinematics", "chain_parameter_names",
           "stiffness_matrix", "stiffness_matrix_symbolic", "constraint_equations",
           "constraint_residuals", "gravity_conditions", "diagonal_residual", "quadratic_energy",
           "solve", "solve_symbolic", "synthesize", "balance_all_pairs", "LUSTIG_TOPOLOGY",
           "LUSTIG_UNKNOWNS", "lustig_values", "lustig_table3e_case", "lustig_case1",
           "lustig_case2", "lustig_case3", "lustig_case4", "lustig_alpha", "lustig_b1", "lustig_a1",
           "lustig_min_energy_pose", "spring2_invariant"]
