"""Lustig, Dunning & Herder: the stiffness-matrix method for serial linkages (IFToMM 2015).

Source: M. P. Lustig, A. G. Dunning, J. L. Herder, *Parameter analysis for the design of
statically balanced serial linkages using a stiffness matrix approach with Cartesian
coordinates*, 14th IFToMM World Congress (2015), eqs 1-20 and Table 3e; it recasts the
stiffness-matrix approach of Lin, Shieh & Chen (Mechanism and Machine Theory 45, 2010)
in Cartesian coordinates.

The idea
--------
Describe the state of every link by the unit vector ``q_u = (cos theta_u, sin theta_u)``
along its x-axis and stack them, ground first, into ``Q = (q_1, ..., q_N)`` with the
constant ``q_1 = (1, 0)``. Every point of the chain is then *linear* in ``Q``, so the
energy of ZFL springs (quadratic in the spring vector) and of gravity (linear in a
height, written ``(R q_1)^T S``) is one quadratic form ``U = 1/2 Q^T K_t Q`` (eqs 5-13).
The chain is balanced, for every pose, exactly when all off-diagonal entries of ``K_t``
vanish: ``N (N - 1)`` scalar equations for ``N`` links (the ground counted), solved
numerically or symbolically.

What lives here
---------------
``chain``
    :class:`SerialChain` (links, weights, ZFL springs), its kinematics, the paper's
    parameter names and its :class:`balancelab.Design`.
``matrix``
    ``K_t`` numerically and in the paper's symbols; the quadratic-form energy.
``conditions``
    the balance conditions (the off-diagonal entries), the gravity conditions.
``solving``
    solving the conditions for chosen unknowns (cached symbolic solution), the
    balanced design; a choice that leaves unknowns free reports its family of solutions
    (``SingularChoice``, ``solve_family``).
``all_pairs``
    a chain with a spring between every pair of links, balanced without sympy.
``paper``
    the paper's Table 3e cases (registered worked examples) and design-space
    relations (eqs 18-20).
"""
from .chain import SerialChain, chain_kinematics, chain_parameter_names
from .matrix import quadratic_energy, stiffness_matrix, stiffness_matrix_symbolic
from .conditions import constraint_equations, constraint_residuals, diagonal_residual, gravity_conditions
from .solving import (InfeasibleDesign, SingularChoice, SolutionFamily, solve, solve_family, solve_symbolic,
                      synthesize)
from .all_pairs import balance_all_pairs
from .paper import (LUSTIG_TOPOLOGY, LUSTIG_UNKNOWNS, lustig_a1, lustig_alpha, lustig_b1, lustig_case1,
                    lustig_case2, lustig_case3, lustig_case4, lustig_min_energy_pose, lustig_table3e_case,
                    lustig_values, spring2_invariant)

__all__ = ["SerialChain", "InfeasibleDesign", "chain_kinematics", "chain_parameter_names",
           "stiffness_matrix", "stiffness_matrix_symbolic", "constraint_equations",
           "constraint_residuals", "gravity_conditions", "diagonal_residual", "quadratic_energy",
           "solve", "solve_family", "SingularChoice", "SolutionFamily", "solve_symbolic", "synthesize",
           "balance_all_pairs", "LUSTIG_TOPOLOGY",
           "LUSTIG_UNKNOWNS", "lustig_values", "lustig_table3e_case", "lustig_case1",
           "lustig_case2", "lustig_case3", "lustig_case4", "lustig_alpha", "lustig_b1", "lustig_a1",
           "lustig_min_energy_pose", "spring2_invariant"]
