"""The instructor's lab tools: student versions generated from the solution notebooks (the single
source), the students' hand-out and the autograder. They work from a checkout and from an installed
wheel (``pip install "balancelab[instructor]"``); the labs folder is an argument.

What lives here: ``markers`` (notebook surgery: solution markers, the student version of one
notebook), ``students`` (student versions on disk and the staleness check), ``execute`` (running a
notebook and storing stable outputs), ``handout`` (hand-out and autograder folders), ``folders``
(where the labs, the course's ``_config.yml`` and the package's build files are) and ``cli`` (the
command line). It may import ``balancelab.course.launch`` and the standard library (``nbformat``
and ``nbclient`` inside the functions that need them).

One command regenerates every student version, from the course folder (the one holding
``labs/``) or with ``--labs``/``--solutions``/``--student``::

    balancelab-labs generate                 # labs/solutions -> labs/student
    balancelab-labs check                    # exit 1 if a student version is stale
    balancelab-labs execute                  # re-run the solutions, store outputs
    balancelab-labs handout OUT              # what students get (no solutions)
    balancelab-labs autograder OUT           # what the instructor grades with

(``python -m balancelab.course.labtools ...`` is the same command.)
"""
from __future__ import annotations

from ..launch import GRADER_MODULES
from .cli import main
from .execute import WIDGET_MIME, WIDGET_TEXT, execute_notebook, stable_widget_id
from .folders import default_labs
from .handout import autograder, handout
from .markers import ANSWER_PLACEHOLDER, PLACEHOLDER, MarkerError, solution_texts, student_version
from .students import generate, stale, student_text

__all__ = ["PLACEHOLDER", "ANSWER_PLACEHOLDER", "MarkerError", "WIDGET_MIME", "WIDGET_TEXT", "GRADER_MODULES",
           "student_version", "student_text", "solution_texts", "generate", "stale", "execute_notebook",
           "stable_widget_id", "handout", "autograder", "default_labs", "main"]
