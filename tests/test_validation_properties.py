"""Property tests of the input checks in ``balancelab.core.validation``, one per validator.

Each property states, independently of the code, which values a check accepts (and what it returns
for them) and which it refuses, with ``TypeError`` for the wrong kind of value and ``ValueError``
for a value out of range, the message naming the parameter. The builders' junk-input test
(``tests/test_junk_input.py``) shows that every public builder routes its parameters through these
checks; the checks' behaviour on every kind of junk is proved here, once.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from balancelab.core import validation as v

NAME = "size (m)"
#: anything a user might pass where a number is expected
ANYTHING = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**20, 10**20),
                     st.booleans(), st.none(), st.text(max_size=4), st.complex_numbers(allow_nan=False, max_magnitude=10),
                     st.lists(st.floats(-10, 10), max_size=3), st.dictionaries(st.text(max_size=2), st.integers(), max_size=2),
                     st.floats(-10, 10).map(np.float64), st.integers(-10, 10).map(np.int64))


def _is_real(x) -> bool:
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, (bool, np.bool_))


def _refused(fn, *args, **kwargs):
    """The exception type a call raises (``None`` if it returns), checking the message names NAME."""
    try:
        fn(*args, **kwargs)
    except (TypeError, ValueError) as err:
        assert NAME.split(" (")[0] in str(err), str(err)
        return type(err)
    return None


@settings(max_examples=400, deadline=None)
@given(value=ANYTHING, positive=st.booleans(), nonnegative=st.booleans())
def test_finite_real(value, positive, nonnegative):
    if not _is_real(value):
        assert _refused(v.finite_real, NAME, value) is TypeError
        return
    x = float(value) if abs(value) < 1e308 else math.inf
    ok = math.isfinite(x) and abs(x) <= v.MAX_MAGNITUDE
    ok = ok and (not positive or x >= v.MIN_POSITIVE) and (not nonnegative or x >= 0)
    if ok:
        out = v.finite_real(NAME, value, positive=positive, nonnegative=nonnegative)
        assert type(out) is float and out == x
    else:
        assert _refused(v.finite_real, NAME, value, positive=positive, nonnegative=nonnegative) is ValueError


@settings(max_examples=300, deadline=None)
@given(value=st.one_of(ANYTHING, st.tuples(ANYTHING, ANYTHING), st.lists(st.floats(allow_nan=True), max_size=4)))
def test_planar_point(value):
    items = list(value) if isinstance(value, (tuple, list)) else None
    if items is None or not all(_is_real(i) for i in items):
        assert _refused(v.planar_point, NAME, value) in (TypeError, ValueError)
        if isinstance(value, (str, dict)) or value is None:   # not numbers at all (a lone number is a
            assert _refused(v.planar_point, NAME, value) is TypeError  # point of the wrong shape: ValueError)
        return
    good = len(items) == 2 and all(math.isfinite(float(i)) and abs(float(i)) <= v.MAX_MAGNITUDE for i in items)
    if good:
        assert v.planar_point(NAME, value) == (float(items[0]), float(items[1]))
    else:
        assert _refused(v.planar_point, NAME, value) is ValueError


@settings(max_examples=300, deadline=None)
@given(value=ANYTHING, nbodies=st.one_of(st.none(), st.integers(1, 6)), moving=st.booleans())
def test_body_index(value, nbodies, moving):
    is_int = isinstance(value, (int, np.integer)) and not isinstance(value, bool)
    if not is_int:
        assert _refused(v.body_index, NAME, value, nbodies, moving=moving) is TypeError
        return
    ok = value >= 0 and (nbodies is None or value < nbodies) and (nbodies is None or not moving or value >= 1)
    if ok:
        assert v.body_index(NAME, value, nbodies, moving=moving) == int(value)
    else:
        assert _refused(v.body_index, NAME, value, nbodies, moving=moving) is ValueError


@settings(max_examples=300, deadline=None)
@given(items=st.one_of(st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=4), ANYTHING),
       n=st.one_of(st.none(), st.integers(0, 4)))
def test_finite_reals(items, n):
    if not isinstance(items, list):
        if isinstance(items, (str, bytes, dict)) or items is None or not hasattr(items, "__iter__"):
            assert _refused(v.finite_reals, NAME, items, n) is TypeError
        return
    count_ok = len(items) == n if n is not None else len(items) > 0
    each_ok = all(math.isfinite(x) and abs(x) <= v.MAX_MAGNITUDE for x in items)
    if count_ok and each_ok:
        assert v.finite_reals(NAME, items, n) == tuple(float(x) for x in items)
    else:
        assert _refused(v.finite_reals, NAME, items, n) is ValueError


@settings(max_examples=200, deadline=None)
@given(points=st.lists(st.tuples(st.floats(-1e13, 1e13), st.floats(-1e13, 1e13)), max_size=4),
       n=st.one_of(st.none(), st.integers(0, 4)))
def test_planar_points(points, n):
    count_ok = len(points) == n if n is not None else len(points) > 0
    each_ok = all(abs(c) <= v.MAX_MAGNITUDE for p in points for c in p)
    if count_ok and each_ok:
        assert v.planar_points(NAME, points, n) == tuple(points)
    else:
        assert _refused(v.planar_points, NAME, points, n) is ValueError


@settings(max_examples=200, deadline=None)
@given(value=ANYTHING, maximum=st.sampled_from([1e-3, 1e-6, 0.1]))
def test_step_size(value, maximum):
    if not _is_real(value):
        assert _refused(v.step_size, NAME, value, maximum) is TypeError
        return
    x = float(value) if abs(value) < 1e308 else math.inf
    if math.isfinite(x) and v.MIN_POSITIVE <= x <= maximum:
        assert v.step_size(NAME, value, maximum) == x
    else:
        assert _refused(v.step_size, NAME, value, maximum) is ValueError


@settings(max_examples=200, deadline=None)
@given(value=st.one_of(ANYTHING, st.sampled_from(["A", "B", "a", 1, 1.0, True])))
def test_option(value):
    choices = ("A", "B", 1)
    if any(value == c and type(value) is type(c) for c in choices) and not isinstance(value, bool):
        assert v.option(NAME, value, choices) == value
    else:
        assert _refused(v.option, NAME, value, choices) is ValueError


@settings(max_examples=200, deadline=None)
@given(value=st.one_of(ANYTHING, st.lists(st.lists(st.floats(allow_nan=True), min_size=2, max_size=2), max_size=3)),
       ndim_min=st.integers(0, 2))
def test_real_array(value, ndim_min):
    if isinstance(value, (str, bytes, dict)) or value is None or isinstance(value, (bool, complex)):
        assert _refused(v.real_array, NAME, value, ndim_min=ndim_min) is TypeError
        return
    arr = np.asarray(value)
    if arr.dtype.kind not in "iuf":
        assert _refused(v.real_array, NAME, value, ndim_min=ndim_min) is TypeError
        return
    arr = arr.astype(float)
    ok = arr.ndim >= ndim_min and np.all(np.isfinite(arr)) and (arr.size == 0 or np.abs(arr).max() <= v.MAX_MAGNITUDE)
    if ok:
        np.testing.assert_array_equal(v.real_array(NAME, value, ndim_min=ndim_min), arr)
    else:
        assert _refused(v.real_array, NAME, value, ndim_min=ndim_min) is ValueError


@settings(max_examples=150, deadline=None)
@given(items=st.one_of(st.lists(st.one_of(st.floats(-1, 1), st.integers(-3, 3)), max_size=4), ANYTHING))
def test_sequence_of_and_instance_of(items, ):
    if isinstance(items, list):
        if all(isinstance(i, float) for i in items):
            assert v.sequence_of(NAME, items, float) == tuple(items)
        else:
            assert _refused(v.sequence_of, NAME, items, float) is TypeError
    elif isinstance(items, (str, bytes, dict, float)) or not hasattr(items, "__iter__"):
        assert _refused(v.sequence_of, NAME, items, float) is TypeError
    if isinstance(items, float):
        assert v.instance_of(NAME, items, float, "a float") is items
    else:
        assert _refused(v.instance_of, NAME, items, float, "a float") is TypeError


def test_every_validator_has_a_property():
    """A new validator gets its property here (``positive_int``'s is in test_junk_input)."""
    covered = {"finite_real", "planar_point", "body_index", "finite_reals", "planar_points", "step_size",
               "option", "real_array", "sequence_of", "instance_of", "positive_int", "length_or_symbol"}
    constants = {"MAX_MAGNITUDE", "MIN_POSITIVE"}
    assert set(v.__all__) - constants <= covered, set(v.__all__) - constants - covered


@pytest.mark.parametrize("value", [2.0, 1e-12, 1e12])
def test_length_or_symbol_checks_numbers_and_keeps_symbols(value):
    import sympy as sp

    assert v.length_or_symbol(NAME, value) == value
    r = sp.Symbol("r", positive=True)
    assert v.length_or_symbol(NAME, r) is r
    for bad in (-value, 0.0, math.nan, "2.0", None):
        assert _refused(v.length_or_symbol, NAME, bad) in (TypeError, ValueError)
