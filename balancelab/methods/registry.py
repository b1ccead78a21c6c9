"""The registry of worked examples: each method declares its examples next to its code.

A method module registers an example with the :func:`example` decorator (the
decorated function called with fixed arguments) or, for an example that needs a
little set-up, with :func:`register` and a zero-argument factory. The catalog, the
gallery, the course order and the marks of the deliberately unbalanced examples all
come from here. Layer: methods; imports only ``core``.

Course order: examples are sorted by ``chapter`` (of the course book), then by the
order of the method families in :data:`FAMILIES`, then by the order in which the
declarations run: the modules in the order the family's ``__init__`` imports them, and
within a module from top to bottom (stacked decorators included: the decorator calls run
top to bottom, before the decorations).
"""
from __future__ import annotations

import dataclasses
import itertools
from dataclasses import dataclass, field
from typing import Callable

from ..core.design import Design
from ..core.validation import positive_int

__all__ = ["Example", "example", "register", "examples", "FAMILIES"]

#: The method families, in the order the course meets them within a chapter.
FAMILIES = ("lecture", "singh", "realize", "lustig", "deepak", "general", "practice")

_REGISTRY: dict[str, Example] = {}
_DECLARED = itertools.count()        # declarations, in the order they run


@dataclass(frozen=True)
class Example:
    """A worked example: a zero-argument callable returning a :class:`Design`.

    Attributes
    ----------
    name : str
        Short name, unique across the library (the catalog key).
    title : str
        One line: what it is and where it comes from.
    chapter : int
        Chapter of the course book that presents it.
    function : callable
        The method (or factory) that builds it.
    expected_balanced : bool
        ``False`` for the deliberate counter-examples (an ordinary spring where a ZFL
        spring is needed, an approximate balance).
    """

    name: str
    title: str
    chapter: int
    function: Callable[..., Design]
    expected_balanced: bool = True
    args: tuple = ()
    kwargs: dict = field(default_factory=dict)
    family: str = ""
    index: int = 0

    def __call__(self) -> Design:
        return self.function(*self.args, **self.kwargs)

    def __repr__(self) -> str:
        return f"<example {self.name!r}: {self.title}>"


def _family(module: str) -> str:
    parts = module.split(".")
    for fam in FAMILIES:
        if fam in parts:
            return fam
    raise ValueError(f"examples must be registered from a method family module {FAMILIES}, "
                     f"not {module!r}")


def register(name: str, title: str, factory: Callable[..., Design], *, chapter: int,
             expected_balanced: bool = True, args: tuple = (), kwargs: dict | None = None) -> None:
    """Register a worked example built by ``factory(*args, **kwargs)``.

    Parameters
    ----------
    name : str
        Unique short name.
    title : str
        One line for the gallery and the catalog.
    factory : callable
        Returns a :class:`Design`.
    chapter : int
        Chapter of the course book (1-6).
    expected_balanced : bool
        ``False`` for a deliberate counter-example.
    args, kwargs
        Fixed arguments of ``factory``.

    Raises
    ------
    ValueError
        If ``name`` is already registered for another example.
    """
    if not name or not isinstance(name, str):
        raise TypeError(f"name must be a non-empty str, got {name!r}")
    chapter = positive_int("chapter", chapter)
    entry = Example(name, title, chapter, factory, bool(expected_balanced), tuple(args),
                    dict(kwargs or {}), _family(factory.__module__), next(_DECLARED))
    old = _REGISTRY.get(name)
    if old is not None and (old.function, old.args, old.kwargs) != (factory, entry.args, entry.kwargs):
        raise ValueError(f"a worked example named {name!r} is already registered")
    if old is None:
        _REGISTRY[name] = entry


def example(name: str, title: str, *, chapter: int, expected_balanced: bool = True, **kwargs):
    """Decorator: register the decorated method, called with ``kwargs``, as a worked example.

    Stack several to register several examples of one method.

    Examples
    --------
    >>> from balancelab.methods.registry import examples
    >>> examples()["lacoste_lever"].kwargs
    {'weight': 10.0, 'length': 0.5, 'a_x': 0.2, 'b_y': 0.3}
    """
    order = next(_DECLARED)   # the decorator line runs now, top to bottom; the decoration later

    def decorate(fn):
        register(name, title, fn, chapter=chapter, expected_balanced=expected_balanced, kwargs=kwargs)
        _REGISTRY[name] = dataclasses.replace(_REGISTRY[name], index=order)
        return fn

    return decorate


def examples() -> dict[str, Example]:
    """Every registered example, in course order (see the module docstring).

    Importing the method families registers their examples; ``balancelab.methods`` imports
    every family of :data:`FAMILIES` before this module can be reached, so the registry is
    complete whenever this runs (no import here: the families import the registry, never
    the other way round).

    Returns
    -------
    dict
        Short name -> :class:`Example`.
    """
    order = sorted(_REGISTRY.values(), key=lambda e: (e.chapter, FAMILIES.index(e.family), e.index))
    return {e.name: e for e in order}
