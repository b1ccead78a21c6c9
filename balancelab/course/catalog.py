"""Every worked example of the course, by short name (the pattern of sympy's ``models``).

The examples are declared by the methods themselves (:mod:`balancelab.methods.registry`);
``catalog()`` lists them in the order of the course. The gallery, the book, the figures'
tests and the answer checks iterate it. A few entries are counter-examples kept on
purpose (an ordinary spring where a ZFL spring is needed): their
``expected_balanced`` is ``False``.
"""
from __future__ import annotations

from collections import OrderedDict

from ..methods.registry import Example, examples

__all__ = ["catalog", "Example"]


def catalog() -> OrderedDict[str, Example]:
    """Every worked example of the course, in the order of the course.

    Returns
    -------
    collections.OrderedDict
        Short name -> zero-argument :class:`~balancelab.methods.registry.Example`
        returning a :class:`~balancelab.Design`.

    Examples
    --------
    >>> import balancelab as bl
    >>> cat = bl.catalog()
    >>> cat["singh_fourbar"]().balance_report().balanced
    True
    """
    return OrderedDict(examples())
