"""Course: what the book and the labs use on top of the library.

What lives here: ``catalog`` (every worked example, in course order, from the methods'
registry), ``gallery`` (``python -m balancelab.course.gallery`` prints their reports),
``check`` (the labs' answer checks, one module per lab, and ``check.data``: answers as
plain data), ``grading`` (the bulk grader, ``python -m balancelab.course.grading``: the
trusted half, which judges exported answers), ``gradetable`` (its CSV table), ``runner``
(the untrusted half: runs a submission and exports its answers), ``sandbox`` (bubblewrap
and resource limits), ``labtools`` (student versions, hand-out and autograder,
``python -m balancelab.course.labtools``) and ``launch`` (the student notebooks' set-up cell
for Colab and the labs' Binder, Colab and JupyterHub links).

A new lab check goes in ``check`` next to the checks of its lab. What it may import:
everything below it (``core``, ``mechanisms``, ``methods``, ``viz``).
"""
from .catalog import catalog

__all__ = ["catalog"]
