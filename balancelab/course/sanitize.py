"""Student text made safe to show: the one place that shortens and cleans what a notebook chose.

What lives here: :func:`excerpt`, used by the grader's rows, notes and terminal summary (a
submission's name, an exception, a verdict echoing an answer never reaches a row or a terminal
longer than a few words or with control characters).
"""
from __future__ import annotations

__all__ = ["excerpt"]


def excerpt(text, n: int = 40) -> str:
    """Student text as it may appear in a row: printable characters only, at most ``n`` of them.

    Parameters
    ----------
    text : object
        Anything a notebook chose (an exception name, a lab name, a verdict echoing an answer).
    n : int
        Longest excerpt.

    Returns
    -------
    str

    Examples
    --------
    >>> excerpt("line one\\nline two " + "x" * 80, 20)
    'line one line two x…'
    """
    s = " ".join("".join(c if c.isprintable() else " " for c in str(text)[:4 * n + 100]).split())
    return s if len(s) <= n else s[:n - 1] + "…"
