"""The package's exceptions: one base class, and every error type a caller may catch.

Every error balancelab raises on purpose is a :class:`BalancelabError` (the course tools' too:
a malformed answer, a broken solution marker); each also derives from
the built-in exception a caller would expect (bad values are ``ValueError``), so
``except ValueError`` keeps working. Modules raise these types; none defines its own.

Examples
--------
>>> issubclass(InfeasibleDesign, BalancelabError) and issubclass(InfeasibleDesign, ValueError)
True
"""
from __future__ import annotations

from typing import Any, Sequence

__all__ = ["BalancelabError", "UnreachableConfiguration", "InfeasibleDesign", "SingularChoice",
           "ApproximationError", "ProfileError", "MarkerError", "AnswerError"]


class BalancelabError(Exception):
    """Base class of every error that balancelab raises on purpose.

    Examples
    --------
    >>> import balancelab as bl
    >>> lever = bl.catalog()["pulley_lever"]()      # the string leaves the pulley past 90 degrees
    >>> try:
    ...     lever.potential_energy([2.2])
    ... except bl.BalancelabError as err:
    ...     print(type(err).__name__)
    UnreachableConfiguration
    """


class UnreachableConfiguration(BalancelabError, ValueError):
    """Raised when a configuration is outside what the linkage can reach (or has the wrong shape).

    Examples
    --------
    >>> issubclass(UnreachableConfiguration, ValueError)
    True
    """


class InfeasibleDesign(BalancelabError, ValueError):
    """Raised when the balance equations only have physically impossible solutions.

    For instance a negative spring stiffness, or a non-positive mass or length.

    Attributes
    ----------
    verdict : str or None
        Set by :func:`balancelab.balance`: ``"impossible"``, ``"negative"``, ``"box"`` or
        ``"not_found"`` (see :mod:`balancelab.methods.general.verdicts`); None otherwise.
    box : tuple or None
        Set by :func:`balancelab.balance` with the ``"box"`` verdict: the anchor box that would do.

    Examples
    --------
    >>> issubclass(InfeasibleDesign, ValueError)
    True
    """

    verdict: str | None = None
    box: Any = None


class SingularChoice(BalancelabError, ValueError):
    """Raised by :func:`balancelab.lustig.solve` when the conditions leave some unknowns free.

    ``families`` holds the solution families (:class:`balancelab.lustig.SolutionFamily`) when
    they could be computed for the given numbers, else is empty.

    Examples
    --------
    >>> issubclass(SingularChoice, ValueError)
    True
    """

    def __init__(self, message: str, families: Sequence[Any] = ()) -> None:
        super().__init__(message)
        self.families = tuple(families)


class ApproximationError(BalancelabError, RuntimeError):
    """Raised when an approximate (optimized) spring placement cannot reach its target.

    Examples
    --------
    >>> issubclass(ApproximationError, RuntimeError)
    True
    """


class ProfileError(BalancelabError, ValueError):
    """Raised when no wrappable non-circular profile exists, or when the cable leaves the profile.

    Raised by :mod:`balancelab.realize` (also importable from there).

    Examples
    --------
    >>> import balancelab as bl
    >>> bl.realize.ProfileError is ProfileError and issubclass(ProfileError, ValueError)
    True
    """


class MarkerError(BalancelabError, ValueError):
    """A solution marker of a lab notebook is missing its partner or nested.

    Raised by :mod:`balancelab.course.labtools` when it makes the student version of a lab.

    Examples
    --------
    >>> issubclass(MarkerError, ValueError)
    True
    """


class AnswerError(BalancelabError, ValueError):
    """A malformed answer to a lab task; its message is shown to the student as the verdict.

    Parameters
    ----------
    message : str
        What is wrong with the answer (shown as the verdict's message).
    hint : str
        How to write it instead (shown as the verdict's hint); the task's ``expects``
        text when empty.

    Examples
    --------
    >>> e = AnswerError("k must be positive.", "A spring rate is > 0 N/m.")
    >>> str(e), e.hint
    ('k must be positive.', 'A spring rate is > 0 N/m.')
    """

    def __init__(self, message: str, hint: str = "") -> None:
        super().__init__(message)
        self.hint = hint
