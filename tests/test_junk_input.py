"""Junk input to every public builder: a clean ValueError/TypeError that names the parameter.

Every public builder of ``balancelab.mechanisms`` and ``balancelab.methods`` (the registry's
worked examples, the subpackages' ``__all__``) and the core constructors is called once with
valid arguments (its *baseline*), then with one parameter replaced by junk: wrong tuple
lengths (too few and too many items), numeric strings, ``None``, out-of-range branches and
indices, unknown dict keys, ``h = 0``, NaN and 1e+-300 magnitudes. A junk call must
either raise ``ValueError``/``TypeError`` whose message contains the parameter's name, or (for
a magnitude that is merely extreme) succeed; never ``OverflowError``, ``ZeroDivisionError`` or
a ``RuntimeWarning``. A public callable with no baseline must be listed in ``EXEMPT`` with the
reason, so a new builder cannot be forgotten. A ``Load`` or ``Spring`` cannot know how many
bodies there are: the ``Design`` refuses an out-of-range body index (tested below). Angles of a
fully rotating linkage are accepted modulo 2 pi.

The junk cases (about 2,700) are not each a test: one test shows that every parameter of every
builder goes through a check (its first junk value is refused by name), a property test draws
cases from the whole list on every run, and the validators' own properties
(``tests/test_validation_properties.py``) prove what each check does with every kind of junk.
``BALANCELAB_JUNK_ALL=1`` runs every enumerated case as its own test.
"""
from __future__ import annotations

import inspect
import math
import os
import tempfile
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import balancelab as bl
import balancelab.mechanisms as mech
from balancelab.methods import deepak, lecture, lustig, realize, singh
from balancelab.methods.practice.springs import ExtensionSpring
from balancelab.methods.registry import examples

FB = deepak.example_fourbar
LEVER = lambda: singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)  # noqa: E731
FBK = lambda: mech.FourBarKinematics((0.0, 0.0), (0.7, 0.0), 0.3, 0.8, 0.6)  # noqa: E731
LV1 = lambda: {k: v for k, v in lustig.lustig_values(1).items() if k not in lustig.LUSTIG_UNKNOWNS}  # noqa: E731
CHAIN = lambda: lustig.SerialChain((0.3, 0.3), (2.0, 2.0), ((0.1, 0.0), (0.15, 0.0)),  # noqa: E731
                                   (bl.Spring(261.6, 0.0, (0, (0.0, 0.1)), (2, (0.1125, 0.0))),))

#: public callables outside the registry: name -> (callable, args, kwargs) of a valid call
_LEVER = lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
_REAL_SPRING = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0)
_NONCIRCULAR = realize.noncircular_pulley(_LEVER, spring_model=_REAL_SPRING, angle_range=(-1.0, 1.0), min_tension=45.0)


def _export_profile(design, path="pulley.csv", spring=0, *, n=None, tolerance=1e-3):
    """``realize.export_profile`` into a folder of its own that is removed afterwards (a file name
    is placed there; anything else, junk included, is passed on as given)."""
    with tempfile.TemporaryDirectory(prefix="balancelab-junk-") as folder:
        where = Path(folder) / path if isinstance(path, str) and path and "/" not in path else path
        return realize.export_profile(design, where, spring, n=n, tolerance=tolerance)


MANUAL = {
    # core constructors
    "Spring": (bl.Spring, (100.0, 0.0, (0, (0.0, 0.2)), (1, (0.1, 0.0))), {}),
    "Load": (bl.Load, (1, (0.3, 0.0), (0.0, -9.81)), {}),
    "Attachment": (bl.Attachment, (1, (0.3, 0.0)), {}),
    "Pulley": (bl.Pulley, (0.01, (0.0, 1.0), 1), {}),
    "gravity_load": (bl.gravity_load, (1, (0.3, 0.0), 2.0), {}),
    "Design.generalized_force": (lambda q=((0.3,),), h=1e-6: LEVER().generalized_force(q, h=h), (), {}),
    "Design.replace": (lambda **kw: LEVER().replace(**kw), (), {"loads": [bl.Load(1, (0.5, 0.0), (0.0, -5.0))]}),
    # mechanisms
    "serial_2r_joints": (mech.serial_2r_joints, (0.5,), {}),
    "serial_2r_kinematics": (mech.serial_2r_kinematics, (0.5,), {}),
    "FourBar": (mech.FourBar, ((0.0, 0.0), (0.4, 0.0), 0.15, 0.35, 0.3, (0.2, 0.1)), {}),
    "FourBarKinematics": (mech.FourBarKinematics, ((0.0, 0.0), (0.7, 0.0), 0.3, 0.8, 0.6), {}),
    "check_assembly": (mech.check_assembly, (0.3, 0.8, 0.6, 0.7), {}),
    "coupler_curve": (mech.coupler_curve, (FB(),), {"n": 50}),
    "fourbar_joints": (mech.fourbar_joints, (FBK(),), {}),
    "fourbar_labels": (mech.fourbar_labels, (FBK(),), {}),
    "fourbar_design": (mech.fourbar_design, ("fb", FB(), [bl.Load(1, (0.1, 0.0), (0.0, -1.0))], []), {}),
    "as_complex": (mech.as_complex, ((1.0, 2.0),), {}),
    "lever_kinematics": (mech.lever_kinematics, (), {}),
    "lever_design": (mech.lever_design, ("lever", [bl.Load(1, (0.5, 0.0), (0.0, -1.0))], []), {}),
    "PeaucellierKinematics": (mech.PeaucellierKinematics, (0.22326, 0.7505, 0.363), {}),
    "scissors_joints": (mech.scissors_joints, (0.5,), {}),
    "scissors_kinematics": (mech.scissors_kinematics, (0.5,), {}),
    "fourbar_positions": (deepak.fourbar_positions, (FB(), [0.1, 0.2]), {}),
    "loop_closure_error": (deepak.loop_closure_error, (FB(), [0.1, 0.2]), {}),
    # lecture
    "equivalent_masses": (lecture.equivalent_masses, (0.3, 0.8, 0.6, 2.0, (0.4, 0.1)), {}),
    "link_spring": (lecture.link_spring, ((1.0, 0.0), 0.2, 0.1), {}),
    # singh
    "free_choice_count": (singh.free_choice_count, (1,), {}),
    "max_work_angle": (singh.max_work_angle, ((10.0, 20.0), ((1.0, 0.5), (2.0, 0.0)), 1.5), {}),
    "chain_conditions": (singh.chain_conditions, (1,), {}),
    "chain_solution_point": (singh.chain_solution_point, (1,), {}),
    "conditions_rank": (singh.conditions_rank, (1,), {}),
    "design_point": (singh.design_point, (singh.serial_2r_min_preload(),), {}),
    # lustig
    "SerialChain": (lustig.SerialChain, ((0.3, 0.3), (2.0, 2.0), ((0.1, 0.0), (0.15, 0.0))), {}),
    "chain_kinematics": (lustig.chain_kinematics, ((0.3, 0.2),), {}),
    "serial_chain_kinematics": (mech.serial_chain_kinematics, ((0.3, 0.2),), {}),
    "serial_chain_joints": (mech.serial_chain_joints, ((0.3, 0.2),), {}),
    "lacoste_energies": (singh.lacoste_energies, (10.0, 0.5, 0.2, 0.3), {}),
    "chain_parameter_names": (lustig.chain_parameter_names, (2, lustig.LUSTIG_TOPOLOGY), {}),
    "stiffness_matrix": (lustig.stiffness_matrix, (CHAIN(),), {}),
    "quadratic_energy": (lustig.quadratic_energy, (CHAIN(), [0.1, 0.2]), {}),
    "constraint_residuals": (lustig.constraint_residuals, (CHAIN(),), {}),
    "diagonal_residual": (lustig.diagonal_residual, (np.eye(2),), {}),
    "constraint_equations": (lustig.constraint_equations, (2, lustig.LUSTIG_TOPOLOGY), {}),
    "gravity_conditions": (lustig.gravity_conditions, (2, lustig.LUSTIG_TOPOLOGY), {}),
    "stiffness_matrix_symbolic": (lustig.stiffness_matrix_symbolic, (2, lustig.LUSTIG_TOPOLOGY), {}),
    "solve": (lustig.solve, (2, lustig.LUSTIG_TOPOLOGY, LV1(), lustig.LUSTIG_UNKNOWNS), {}),
    "solve_family": (lustig.solve_family, (2, lustig.LUSTIG_TOPOLOGY, LV1(), lustig.LUSTIG_UNKNOWNS), {}),
    "solve_symbolic": (lustig.solve_symbolic, (2, ((0, 2), (1, 2)), ("ax1", "ay1")), {}),
    "synthesize": (lustig.synthesize, (2, lustig.LUSTIG_TOPOLOGY, LV1(), lustig.LUSTIG_UNKNOWNS), {}),
    "lustig_values": (lustig.lustig_values, (1,), {}),
    "lustig_table3e_case": (lustig.lustig_table3e_case, (1,), {}),
    "lustig_alpha": (lustig.lustig_alpha, (lustig.lustig_values(1),), {}),
    "lustig_b1": (lustig.lustig_b1, (lustig.lustig_values(1),), {}),
    "lustig_a1": (lustig.lustig_a1, (lustig.lustig_values(1),), {}),
    "lustig_min_energy_pose": (lustig.lustig_min_energy_pose, (lustig.lustig_values(1),), {}),
    "spring2_invariant": (lustig.spring2_invariant, (lustig.lustig_values(1),), {}),
    "balance_all_pairs": (lustig.balance_all_pairs, ((0.3, 0.3), (2.0, 2.0), ((0.1, 0.0), (0.15, 0.0))), {}),
    # deepak
    "cognates": (deepak.cognates, (FB(),), {}),
    "cognate_triangle": (deepak.cognate_triangle, (FB(),), {}),
    "cognate_crank_angles": (deepak.cognate_crank_angles, (FB(), [0.1, 0.2]), {}),
    "cognate_design": (deepak.cognate_design, (FB(), 1), {}),
    "cognate_designs": (deepak.cognate_designs, (FB(), (0.1, -0.2), 100.0), {}),
    "focal_pivot_circles": (deepak.focal_pivot_circles, (((0.0, 0.0), (1.0, 0.0), (0.0, 1.0)),
                                                          ((1.0, 0.0), (0.0, 1.0), (1.0, 1.0))), {}),
    "cognate_family": (deepak.cognate_family, (FB(), (0.1, -0.2), 100.0), {}),
    "kb_ratio_from_triangle": (deepak.kb_ratio_from_triangle, (((0.0, 0.0), (1.0, 0.0), (0.3, 0.8)), (0.1, -0.2)), {}),
    "balance_cognates": (deepak.balance_cognates, (FB(), (0.1, -0.2), 100.0), {}),
    "similar_triangle_family": (deepak.similar_triangle_family, ((1 + 0j, 1j, -1 + 0j), (1 + 1j, 0.5 + 0j, 1j)), {}),
    "spring_loaded_fourbar": (deepak.spring_loaded_fourbar, (FB(), (0.1, -0.2), 100.0), {}),
    "compose_zfl_springs": (deepak.compose_zfl_springs, (10.0, (0.0, 1.0), 20.0, (1.0, 0.0)), {}),
    "composing_anchor": (deepak.composing_anchor, (10.0, (0.0, 1.0), (0.5, 0.5), 20.0), {}),
    "plagiograph_map": (deepak.plagiograph_map, (1.5, 0.4, (0.0, 0.0), (0.1, 0.2)), {}),
    "technique1": (deepak.technique1, (FB(), (0.1, -0.2), 100.0, 0.3, 0.3), {}),
    "technique1_feasible": (deepak.technique1_feasible, (FB(), (0.1, -0.2), 0.3, 0.3), {}),
    "technique1_family": (deepak.technique1_family, (FB(), (0.1, -0.2), 100.0, [0.3, 0.4], [0.3, 0.4]), {}),
    "technique2_parameters": (deepak.technique2_parameters, (FB(), (0.1, -0.2), 100.0), {}),
    "technique2": (deepak.technique2, (FB(), (0.1, -0.2), 100.0, "A", 0.1), {}),
    "technique2_family": (deepak.technique2_family, (FB(), (0.1, -0.2), 100.0, "A", [0.1, 0.2]), {}),
    "technique3_parameters": (deepak.technique3_parameters, (FB(), (0.1, -0.2), 100.0), {}),
    "technique3": (deepak.technique3, (FB(), (0.1, -0.2), 100.0), {}),
    "technique3_family": (deepak.technique3_family, (FB(), (0.1, -0.2), 100.0, "A", "A", [0.1, 0.2]), {}),
    "herder": (deepak.herder, (FB(), (0.1, -0.2), 100.0), {}),
    "gravity_technique2": (deepak.gravity_technique2, (FB(), 2.0, 100.0), {}),
    "gravity_as_spring_limit": (deepak.gravity_as_spring_limit, (FB(), 2.0, 100.0, 10.0), {}),
    "serial_2r_technique2": (deepak.serial_2r_technique2, ((0.05, 0.02), 0.2, 0.3, (0.2, 0.1), (0.1, -0.2), 100.0, 0.1), {}),
    "slider_crank_technique2": (deepak.slider_crank_technique2, (0.1, 0.3, 0.05, (0.1, 0.05), (0.2, -0.2), 100.0, 0.1), {}),
    "watt_fourbar": (deepak.watt_fourbar, (), {}),
    # realize
    "pulley_string": (realize.pulley_string, ((0.0, 0.3), 0.01, (0.2, 0.0)), {}),
    "pulley_energy": (realize.pulley_energy, (realize.pulley_lever(), [0.1, 0.2]), {}),
    "pulley_balance_error": (realize.pulley_balance_error, (realize.pulley_lever(),), {"n": 51}),
    "pulley_error_curve": (realize.pulley_error_curve, (realize.pulley_lever(), [0.0, 0.01]), {"n": 51}),
    "negative_free_length_partner": (realize.negative_free_length_partner, (100.0, -0.05, 50.0), {}),
    "noncircular_pulley": (realize.noncircular_pulley, (_LEVER,), {"spring_model": _REAL_SPRING,
                                                                    "angle_range": (-1.0, 1.0)}),
    "spring_limits": (realize.spring_limits, (_REAL_SPRING,), {}),
    "profile_part": (realize.profile_part, (_NONCIRCULAR,), {"n": 200}),
    "export_profile": (_export_profile, (_NONCIRCULAR, "pulley.csv"), {"tolerance": 1e-3}),
    "sleeve_lever": (realize.sleeve_lever, (), {"mass": 2.0, "length": 0.5, "b": 0.3, "c": 0.2, "free_length": 0.05}),
    "mount_normal_springs": (realize.mount_normal_springs, (_LEVER, 0.05), {"springs": [0], "margin": 0.1, "n": 50}),
    "balance_normal": (realize.balance_normal, (lecture.single_link_spring(2.0, 0.5, 0.3, 0.2).replace(springs=[]),),
                       {"springs": [((0, (0.0, 0.3)), (1, (0.2, 0.0)))], "free_length": 0.05}),
}

#: public names that are not builders taking user input, with the reason
EXEMPT = {
    "ExplicitKinematics": "takes a pose function; its numeric arguments are checked by TreeKinematics' tests",
    "TreeKinematics": "built by the mechanisms from checked lengths; not a user-facing builder",
    "as_point": "takes a complex number (the kernel's output), returns its (x, y)",
    "binary_link_point": "geometry kernel: array in, array out (hot path, inputs come from checked designs)",
    "circle_intersection": "geometry kernel: array in, array out (hot path, inputs come from checked designs)",
    "rotate": "geometry kernel: array in, array out (hot path, inputs come from checked designs)",
    "InfeasibleDesign": "an exception", "SingularChoice": "an exception", "ApproximationError": "an exception",
    "SolutionFamily": "built by solve_family", "CognateFamily": "a result (NamedTuple)",
    "Technique2Parameters": "a result (NamedTuple)", "Technique3Parameters": "a result (NamedTuple)",
    "ChainConditions": "a result", "PulleyString": "a result (NamedTuple)", "PulleyError": "a result (NamedTuple)",
    "LUSTIG_TOPOLOGY": "a constant", "LUSTIG_UNKNOWNS": "a constant",
    "example_fourbar": "takes no argument", "lustig_case1": "takes no argument", "lustig_case2": "takes no argument",
    "lustig_case3": "takes no argument", "lustig_case4": "takes no argument",
    "NoncircularProfile": "built by noncircular_pulley from its synthesis (Chebyshev series); not a user-facing builder",
    "sleeve_derivation": "takes no argument", "normal_spring_derivation": "takes no argument",
    "SymbolicChainKinematics": "wraps a checked serial_chain_kinematics with sympy lengths (symbolic energy only)",
    "CableGeometry": "a result (NamedTuple)", "ProfilePart": "a result (NamedTuple)", "ProfileError": "an exception",
}


def _registry_baselines() -> dict:
    """The public methods the worked examples call, with the examples' arguments."""
    out = {}
    for entry in examples().values():
        fn = entry.function
        if fn.__name__.startswith("_"):   # a factory around a public method listed in MANUAL
            continue
        out.setdefault(fn.__name__, (fn, entry.args, entry.kwargs))
    return out


BASELINES = {**_registry_baselines(), **MANUAL}
PUBLIC = {name: getattr(mod, name) for mod in (mech, lecture, singh, lustig, deepak)
          for name in mod.__all__} | {name: getattr(realize, name) for name in realize.__all__}


def test_every_public_builder_has_a_baseline_or_a_reason():
    missing = sorted(n for n in PUBLIC if n not in BASELINES and n not in EXEMPT)
    assert not missing, f"public callables with no junk-input baseline: {missing}"


@pytest.mark.parametrize("name", sorted(BASELINES))
def test_baseline_calls_are_valid(name):
    fn, args, kwargs = BASELINES[name]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fn(*args, **kwargs)


# ------------------------------------------------------------------ junk
_FREE_TEXT = {"name", "title", "label", "labels", "reference", "kind", "link"}
BIG, TINY = 1e300, 1e-300


def _junk_number(value, pname):
    if pname == "h":
        yield "zero step", 0.0
    yield "numeric string", str(float(value))
    yield "None", None
    yield "nan", math.nan
    yield "inf", math.inf
    for v in (BIG, -BIG, TINY, -TINY):
        yield f"magnitude {v:g}", v


def _junk_int(value, pname, name):
    yield "numeric string", str(value)
    yield "None", None
    yield "negative", -7
    yield "fraction", value + 0.5
    if pname in ("branch", "index", "dof", "turn", "case", "technique"):
        yield "out of range", 99


def _is_number(v):
    return isinstance(v, (float, np.floating)) and not isinstance(v, bool)


def _is_int(v):
    return isinstance(v, (int, np.integer)) and not isinstance(v, bool)


#: sequences whose number of items is the caller's choice (one per link, per sample, per spring)
VARIABLE_LENGTH = {"lengths", "q", "h_values", "length_1_values", "length_2_values", "radii", "topology",
                   "loads", "springs", "unknowns", "theta"}


def _junk_sequence(value, pname):
    items = list(value)
    yield "None", None
    yield "a string", "1.0"
    if items and pname not in VARIABLE_LENGTH:
        yield "too few items", type(value)(items[:-1]) if isinstance(value, tuple) else items[:-1]
    if pname not in VARIABLE_LENGTH:
        yield "too many items", tuple(items) + (items[-1] if items else 0.0,)
    if items and all(_is_number(v) or _is_int(v) for v in items):
        yield "numeric strings", tuple(str(v) for v in items)
        yield "nan item", (math.nan,) + tuple(items[1:])
        yield "magnitude item", (BIG,) + tuple(items[1:])
    elif items and pname not in VARIABLE_LENGTH and isinstance(items[0], (tuple, list)) and all(_is_number(v) or _is_int(v) for v in items[0]):
        yield "point with three coordinates", (tuple(items[0]) + (0.0,),) + tuple(items[1:])
        yield "point of strings", (tuple(str(v) for v in items[0]),) + tuple(items[1:])
        yield "magnitude item", ((BIG,) + tuple(items[0][1:]),) + tuple(items[1:])


def junk_values(value, pname, name=""):
    """(label, junk) pairs for a parameter whose valid value is ``value``."""
    if isinstance(value, bool) or value is None or callable(value):
        return
    if pname in _FREE_TEXT:
        return
    if _is_number(value):
        yield from _junk_number(value, pname)
    elif _is_int(value):
        yield from _junk_int(value, pname, name)
    elif isinstance(value, str):
        yield "not an option", "no-such-option"
        yield "None", None
    elif isinstance(value, dict):
        yield "unknown key", {**value, "no_such_key": 1.0}
        yield "None", None
    elif isinstance(value, (tuple, list, np.ndarray)):
        if isinstance(value, tuple) and hasattr(value, "_fields"):
            return
        yield from _junk_sequence(tuple(value) if isinstance(value, np.ndarray) else value, pname)
    elif isinstance(value, complex):
        yield "None", None
        yield "numeric string", str(value)
    else:  # an object: a Design, a FourBar, a kinematics, a spring
        yield "None", None
        yield "a string", "1.0"


def _bound(name):
    fn, args, kwargs = BASELINES[name]
    try:
        sig = inspect.signature(fn)
    except (TypeError, ValueError):
        return fn, None
    if name == "Design.replace":
        return fn, dict(kwargs)
    try:
        ba = sig.bind(*args, **kwargs)
    except TypeError as err:
        raise TypeError(f"baseline of {name}: {err}") from None
    ba.apply_defaults()
    return fn, {k: v for k, v in ba.arguments.items()
                if sig.parameters[k].kind not in (inspect.Parameter.VAR_POSITIONAL, inspect.Parameter.VAR_KEYWORD)}


def _cases() -> list[tuple]:
    """``(builder, parameter, junk, label)`` for every junk value of every parameter of every builder."""
    out = []
    for name in sorted(BASELINES):
        fn, params = _bound(name)
        if not params:
            continue
        for pname, value in params.items():
            for label, junk in junk_values(value, pname, name):
                out.append((name, pname, junk, label))
    return out


CASES = _cases()


def _call(name, pname, junk):
    fn, params = _bound(name)
    return fn(**dict(params, **{pname: junk}))


def check_junk(name, pname, junk, label=""):
    magnitude = (isinstance(junk, float) and math.isfinite(junk) and junk != 0.0) or label.startswith("magnitude")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            _call(name, pname, junk)
        except (ValueError, TypeError) as err:
            assert pname in str(err), f"{name}({pname}={junk!r}): message does not name {pname!r}: {err}"
            return
    assert magnitude, f"{name}({pname}={junk!r}) was accepted"


def test_every_builder_checks_every_parameter():
    """The one coverage test: every parameter of every public builder refuses its first junk value
    (``None``, a string, a wrong option) with a message naming it, so each goes through a check of
    ``core.validation``, whose behaviour on every kind of junk the property tests prove
    (``tests/test_validation_properties.py``)."""
    failures, first = [], {}
    for name, pname, junk, label in CASES:
        first.setdefault((name, pname), (junk, label))
    for (name, pname), (junk, label) in first.items():
        try:
            check_junk(name, pname, junk, label)
        except AssertionError as err:
            failures.append(str(err).splitlines()[0])
    assert len(first) > 300 and not failures, failures


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=st.sampled_from(CASES))
def test_junk_is_refused_with_the_parameter_named(case):
    """A sample of every enumerated junk case (all of them: ``BALANCELAB_JUNK_ALL=1``)."""
    check_junk(*case)


ALL_CASES = CASES if os.environ.get("BALANCELAB_JUNK_ALL") else []


@pytest.mark.parametrize("name, pname, junk, label", ALL_CASES, ids=[f"{c[0]}-{c[1]}-{c[3]}" for c in ALL_CASES])
def test_every_junk_case_is_refused_with_the_parameter_named(name, pname, junk, label):
    """Every enumerated junk case (about 2,700 calls): only with ``BALANCELAB_JUNK_ALL=1``."""
    check_junk(name, pname, junk, label)


_PARAMS = [(n, p, v) for n in sorted(BASELINES) for p, v in (_bound(n)[1] or {}).items()
           if _is_number(v)]


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=st.sampled_from(_PARAMS),
       junk=st.one_of(st.floats(allow_nan=True, allow_infinity=True).filter(lambda v: not -1e6 < v < 1e6),
                      st.floats(-1e-200, 1e-200).filter(lambda v: v != 0.0),
                      st.sampled_from([math.nan, math.inf, -math.inf]),
                      st.text(max_size=3), st.none(), st.lists(st.floats(), max_size=3)))
def test_random_junk_numbers_are_refused_or_harmless(case, junk):
    name, pname, _ = case
    check_junk(name, pname, junk)


@pytest.mark.parametrize("load, spring", [((99, (0.5, 0.0)), None), (None, ((0, (0.0, 0.3)), (7, (0.2, 0.0))))])
def test_body_indices_out_of_range_are_refused_by_the_design(load, spring):
    """A Load or a Spring does not know how many bodies there are; the Design refuses them."""
    d = LEVER()
    with pytest.raises(ValueError, match="body (99|7); bodies are 0..1"):
        if load:
            d.replace(loads=[bl.Load(*load, (0.0, -1.0))])
        else:
            d.replace(springs=[bl.Spring(10.0, 0.0, *spring)])


def test_singh_fourbar_names_the_rockers_com():
    with pytest.raises(ValueError, match=r"coms\[2\]"):
        singh.singh_fourbar(coms=((1.0, 0.5), (2.0, 0.0), (0.0, 0.0)))


# ------------------------------------------------------------------ angles modulo 2 pi
_FULL_TURN = [name for name, e in bl.catalog().items()
              if np.all(np.ptp(e().q_range, axis=1) >= 2 * np.pi - 1e-9)]


def test_fully_rotating_fourbars_are_in_the_list():
    kinds = {type(bl.catalog()[n]().kinematics).__name__ for n in _FULL_TURN}
    assert "FourBarKinematics" in kinds and len(_FULL_TURN) >= 10


@pytest.mark.parametrize("name", _FULL_TURN)
def test_full_turn_angles_are_accepted_modulo_two_pi(name):
    d = bl.catalog()[name]()
    q = d.sample(30, seed=4)
    turns = np.random.default_rng(5).integers(-3, 4, q.shape) * 2 * np.pi
    assert d.reachable(q + turns).all()
    e, e_turned = d.potential_energy(q).total, d.potential_energy(q + turns).total
    np.testing.assert_allclose(e_turned, e, rtol=0, atol=1e-9 * (1 + np.abs(e).max()))
    world = d.world_points(q, [(b, (0.1, 0.05)) for b in range(1, len(d.bodies))])
    np.testing.assert_allclose(d.world_points(q + turns, [(b, (0.1, 0.05)) for b in range(1, len(d.bodies))]),
                               world, atol=1e-12)


def test_a_crank_that_cannot_turn_fully_keeps_its_range():
    d = singh.singh_fourbar()
    lo, hi = d.q_range[0]
    assert hi - lo < 2 * np.pi
    q = np.array([[0.5 * (lo + hi)]])
    assert d.reachable(q).all() and not d.reachable(q + 2 * np.pi).all()


@settings(max_examples=300, deadline=None)
@given(value=st.one_of(st.integers(-10**6, 10**6), st.floats(allow_nan=True), st.booleans(), st.none(),
                       st.text(max_size=3), st.integers(-5, 20).map(np.int64)),
       minimum=st.integers(0, 5), span=st.one_of(st.none(), st.integers(0, 10)))
def test_the_integer_validator_accepts_exactly_the_integers_in_range(value, minimum, span):
    """``positive_int``, the package's one integer check: an integer in range comes back as an ``int``;
    anything else raises, ``TypeError`` for a non-integer and ``ValueError`` for an integer out of
    range, and the message names the parameter and the range."""
    from balancelab.core.validation import positive_int

    maximum = None if span is None else minimum + span
    is_int = isinstance(value, (int, np.integer)) and not isinstance(value, bool)
    in_range = is_int and value >= minimum and (maximum is None or value <= maximum)
    if in_range:
        out = positive_int("count", value, minimum, maximum)
        assert type(out) is int and out == value
        return
    with pytest.raises(ValueError if is_int else TypeError) as err:
        positive_int("count", value, minimum, maximum)
    assert str(err.value).startswith("count must be an integer")
    assert (f">= {minimum}" if maximum is None else f"in {minimum}..{maximum}") in str(err.value)


def test_junk_tests_leave_no_folder_behind(tmp_path):
    """Importing this module (as every xdist worker does) and exporting a pulley profile with good and
    junk paths leave no ``balancelab-junk-*`` folder in the temporary folder."""
    import os
    import subprocess
    import sys

    code = ("import sys; sys.path.insert(0, 'tests'); import test_junk_input as t; "
            "t.test_baseline_calls_are_valid('export_profile'); "
            "[t.check_junk('export_profile', p, j, l) for p in ('path', 'tolerance') "
            "for l, j in t.junk_values(t._bound('export_profile')[1][p], p)]")
    env = dict(os.environ, TMPDIR=str(tmp_path))
    subprocess.run([sys.executable, "-c", code], cwd=Path(__file__).parents[1], env=env, check=True,
                   timeout=300, capture_output=True)
    assert not sorted(p.name for p in tmp_path.glob("balancelab-junk-*"))
