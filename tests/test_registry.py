"""The registry of worked examples: declared next to the methods, ordered by the course."""
from __future__ import annotations

import pytest

import balancelab as bl
from balancelab.methods import registry


def test_catalog_is_the_registry_in_course_order():
    examples = registry.examples()
    assert list(bl.catalog()) == list(examples)
    chapters = [e.chapter for e in examples.values()]
    assert chapters == sorted(chapters)
    names = list(examples)
    # within a chapter, the lecture before the papers; within a module, top to bottom
    assert names.index("single_link_zfl") < names.index("single_link_zfl_below") < names.index("lacoste_lever")
    assert names.index("fourbar_counterweights") < names.index("singh_fourbar") < names.index("deepak_technique1")
    chapter6 = [n for n in names if examples[n].chapter == 6]
    assert chapter6[-2:] == ["scissors_lift", "peaucellier_board"]
    # chapter 7 (balance your own linkage): the general balancer's examples
    assert {e.family for e in examples.values() if e.chapter == 7} == {"general"}


def test_every_example_names_its_family_and_counter_examples_are_marked():
    for _name, ex in registry.examples().items():
        assert ex.family in registry.FAMILIES and ex.function.__module__.startswith("balancelab.methods")
    unbalanced = {n for n, e in registry.examples().items() if not e.expected_balanced}
    assert unbalanced == {"single_link_ordinary_spring", "approximate_spring_lever",
                          "deepak_spring_loaded_fourbar"}


def test_registering_a_name_twice_for_another_example_is_refused():
    with pytest.raises(ValueError, match="already registered"):
        registry.register("lacoste_lever", "again", bl.singh.generalized_lever, chapter=2)


def test_an_example_outside_a_method_family_is_refused():
    def factory():
        return bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)

    with pytest.raises(ValueError, match="method family"):
        registry.register("outsider", "not a method", factory, chapter=2)
    with pytest.raises(ValueError, match="chapter"):
        registry.register("outsider", "no chapter", bl.singh.lacoste_lever, chapter=0)
    assert "outsider" not in registry.examples()


def test_course_order_within_a_module_is_its_source_order_without_frame_inspection():
    """Stacked and consecutive ``@example`` decorators keep their top-to-bottom order; the registry
    reads no call frames and imports every family explicitly."""
    import importlib
    import inspect
    import re

    source = inspect.getsource(registry)
    assert "_getframe" not in source and "importlib" not in source
    # every family, by name: in the package that holds the registry, which Python runs before it
    # (the registry itself imports none, so no family -> registry -> family cycle hides in a function)
    package = inspect.getsource(importlib.import_module("balancelab.methods"))
    assert f"from . import {', '.join(sorted(registry.FAMILIES))}" in package
    names = list(registry.examples())
    by_module: dict[str, list[str]] = {}
    for name, ex in registry.examples().items():
        by_module.setdefault(ex.function.__module__, []).append(name)
    checked = 0
    for module, members in by_module.items():
        text = inspect.getsource(__import__(module, fromlist=["_"]))
        declared = [m for m in re.findall(r'@example\(\s*"(\w+)"', text) if m in members]
        if len(declared) > 1:
            chapters = [registry.examples()[m].chapter for m in declared]
            same = [m for m, c in zip(declared, chapters) if c == chapters[0]]
            assert sorted(same, key=names.index) == same, module
            checked += len(same) > 1
    assert checked >= 3
