"""Answer checks for the labs: ``check("2.1", k)`` tells a student whether an answer is right.

Every task of every lab is registered with the name of the variable that holds its
answer in the notebook (:func:`tasks`), so the grader (:mod:`balancelab.course.grading`) can
check a whole notebook at once. Three kinds of checks:

* **numeric**: a number in the stated SI unit, or a string or ``(value, "unit")`` pair
  with a unit (``"12 cm"``, ``(0.12, "m")``), within a stated relative tolerance;
* **symbolic**: a sympy expression (or a string sympy can parse) accepted when it is
  *equivalent* to the expected one: the difference simplifies to zero (with a numeric
  spot check at random positive values as a fallback);
* **design**: the student's design is built and its
  :meth:`~balancelab.Design.balance_report` is run; the check passes when the energy is
  constant (within the stated tolerance) and the task's constraints hold, so many
  designs are right.

A check never reveals the expected value and never raises: wrong types, NaN, a missing
unit or a wrong shape give a friendly :class:`Verdict` instead of a traceback.

Layout: ``core`` (verdicts, the task registry, :func:`check`), ``answers`` (reading and
judging answers) and one module per lab, ``lab1`` ... ``lab9``, holding that lab's data,
builders and tasks. Expected values come from the library's methods and designs, never
from formulas repeated here. A new task goes in its lab's module: a judge decorated with
:func:`~.core.register_task` (id, title, answer variable, kind, what an answer looks
like), built from the helpers of ``answers``; a new lab gets a new module imported below.

Examples
--------
>>> from balancelab.course.check import check
>>> print(check("1.2", "(m*r + m_l*r/2)/m_c"))
Task 1.2: ✔ correct. Your r_c is equivalent to the expected one.
"""
from .answers import (DESIGN_TOLERANCE, as_mapping, design_balanced, numeric, numeric_vector, point, quantity,
                      symbolic, vector)
# importing a lab module registers its tasks
from .core import (AnswerError, Task, Verdict, check, check_data, explain, lab_tasks, register_task, set_student,
                   task_numbers, tasks)
from .data import DesignData, decode_answer, encode_answer
from .lab1 import LAB1_FOURBAR, LAMP_ARM, lab1_fourbar
from .lab2 import LAB2_LEVER, LACOSTE, LAMP_SPRING, lab2_lever
from .lab3 import LAB3_LEVER, PARTNER_SPRINGS, lab3_torque_error
from .lab4 import LAB4_PARALLELOGRAM, LAB4_SINGH, lab4_singh_arm
from .lab5 import LAB5_TECHNIQUE2, lab5_technique2
from .lab6 import LAB6_BOARD, LAB6_LIFT, LAB6_SCISSORS, lab6_scissors
from .lab7 import LAB7_LAMP, lamp_with_springs
from .lab8 import LAB8_ARM, LAB8_QUANTILE_LIMIT, LAB8_TOLERANCES, built_arm, lab8_arm
from .lab9 import LAB9_LINK, lab9_spring

__all__ = ["Verdict", "Task", "check", "check_data", "set_student", "task_numbers", "encode_answer", "decode_answer", "DesignData", "tasks", "lab_tasks", "explain", "AnswerError", "register_task",
           "lab1_fourbar", "lab2_lever", "lab3_torque_error", "lab4_singh_arm", "lab5_technique2",
           "lab6_scissors", "lamp_with_springs", "lab8_arm", "built_arm", "lab9_spring",
           "quantity", "vector", "point", "numeric", "numeric_vector", "symbolic",
           "as_mapping", "DESIGN_TOLERANCE", "design_balanced",
           "LAMP_ARM", "LAB1_FOURBAR", "LAMP_SPRING", "LACOSTE", "LAB2_LEVER", "LAB3_LEVER", "PARTNER_SPRINGS",
           "LAB4_PARALLELOGRAM", "LAB4_SINGH", "LAB5_TECHNIQUE2", "LAB6_SCISSORS", "LAB6_LIFT", "LAB6_BOARD",
           "LAB7_LAMP", "LAB8_ARM", "LAB8_TOLERANCES", "LAB8_QUANTILE_LIMIT", "LAB9_LINK"]
