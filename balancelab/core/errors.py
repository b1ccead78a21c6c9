"""The package's exceptions: one base class, and every error type a caller may catch.

Every error balancelab raises on purpose is a :class:`BalancelabError`; each also derives from
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
           "ApproximationError"]


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
