"""Generic pieces live in the generic layers (issue 22, item 4): every error type in core/errors.py,
one serial chain in mechanisms, the string-over-pulley geometry in mechanisms.geometry, and the
LaCoste levers' energies in singh, not in viz."""
from __future__ import annotations

import ast
import inspect
from pathlib import Path

import numpy as np
import pytest

import balancelab as bl
from balancelab.core import errors
from balancelab.mechanisms import chain, geometry

PACKAGE = Path(bl.__file__).parent
ERRORS = PACKAGE / "core" / "errors.py"


def _exception_classes(path: Path) -> list[str]:
    """Classes of ``path`` that derive (by name) from an exception type, or are named ``...Error``
    without being a plain record (a NamedTuple of a model's error is a result, not an exception)."""
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ClassDef):
            bases = [ast.unparse(b) for b in node.bases]
            exceptional = any(b.split(".")[-1].endswith(("Error", "Exception", "Warning", "Interrupt"))
                              for b in bases)
            record = any(b.split(".")[-1] in ("NamedTuple", "object") for b in bases) or \
                any(isinstance(d, ast.Name) and d.id == "dataclass" for d in node.decorator_list)
            if exceptional or (node.name.endswith("Error") and not record):
                out.append(node.name)
    return out


def test_every_error_type_is_declared_in_core_errors():
    elsewhere = {path.relative_to(PACKAGE).as_posix(): found for path in sorted(PACKAGE.rglob("*.py"))
                 if path != ERRORS and (found := _exception_classes(path))}
    assert not elsewhere, f"error types defined outside core/errors.py: {elsewhere}"


def test_every_error_type_is_a_balancelab_error_and_a_builtin_one():
    for name in errors.__all__:
        cls = getattr(errors, name)
        assert issubclass(cls, errors.BalancelabError), name
        if cls is not errors.BalancelabError:
            assert issubclass(cls, (ValueError, RuntimeError, TypeError)), name


def test_old_import_paths_of_moved_errors_name_the_same_class():
    from balancelab.course import labtools
    from balancelab.course.check import AnswerError, core

    assert bl.realize.ProfileError is errors.ProfileError
    assert labtools.MarkerError is errors.MarkerError
    assert AnswerError is core.AnswerError is errors.AnswerError
    assert errors.AnswerError("k must be > 0", "a rate in N/m").hint == "a rate in N/m"


def test_the_scan_sees_an_error_class_and_leaves_records_alone(tmp_path):
    probe = tmp_path / "probe.py"
    probe.write_text("class BadError(ValueError):\n    pass\n\nclass Other(bl.BalancelabError):\n    pass\n\n"
                     "class FitError(NamedTuple):\n    x: float\n")
    assert _exception_classes(probe) == ["BadError", "Other"]


# ------------------------------------------------------------------ one serial chain
@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_the_serial_chain_places_each_joint_at_the_sum_of_the_links_before_it(n):
    rng = np.random.default_rng(n)
    lengths = rng.uniform(0.1, 2.0, n)
    q = rng.uniform(-np.pi, np.pi, (40, n))
    poses, ok = chain.serial_chain_kinematics(lengths).poses(q)
    assert ok.all()
    steps = lengths * np.exp(1j * q)                  # link i as a complex number L_i e^{i theta_i}
    origins = np.concatenate([np.zeros((40, 1)), np.cumsum(steps, axis=1)[:, :-1]], axis=1)
    assert np.allclose(poses[:, 1:, 0] + 1j * poses[:, 1:, 1], origins, atol=1e-12)
    assert np.allclose(poses[:, 1:, 2], q, atol=0)


def test_the_2r_arm_and_lustigs_chain_are_the_serial_chain():
    q = np.random.default_rng(0).uniform(-np.pi, np.pi, (30, 2))
    two = chain.serial_2r_kinematics(1.5).poses(q)[0]
    many = chain.serial_chain_kinematics((1.5, 0.7)).poses(q)[0]
    assert np.array_equal(two, many)
    assert bl.lustig.chain_kinematics is chain.serial_chain_kinematics
    assert "def chain_kinematics" not in inspect.getsource(bl.methods.lustig.chain)


def test_the_serial_chain_refuses_bad_lengths():
    with pytest.raises(ValueError, match="lengths"):
        chain.serial_chain_kinematics((0.3, -0.1))
    with pytest.raises(ValueError, match="lengths"):
        chain.serial_chain_joints(())


def test_lustigs_symbolic_energy_still_matches_its_numbers():
    """The symbolic chain (paper symbols for the lengths) and the numeric one give one energy."""
    import sympy as sp

    d = bl.catalog()["lustig_case1"]()
    q = d.sample(20, seed=4)
    V = d.potential_energy(q).total
    expr = d.potential_energy_symbolic(parametric=False)
    t1, t2 = sp.symbols("theta_1 theta_2", real=True)
    got = sp.lambdify((t1, t2), expr, "numpy")(q[:, 0], q[:, 1])
    assert np.allclose(got, V, atol=1e-9 * max(1.0, float(np.ptp(V)), float(np.abs(V).max())))


# ------------------------------------------------------------------ geometry out of realize and viz
def test_the_string_over_a_pulley_is_mechanisms_geometry():
    from balancelab.methods.practice import routing
    from balancelab.viz import springs

    assert bl.realize.pulley_string is geometry.pulley_string
    assert springs.pulley_string is geometry.pulley_string and routing.pulley_string is geometry.pulley_string
    s = geometry.pulley_string((0.0, 0.0), 0.1, [(0.0, -0.5), (0.3, 0.4)])
    d = np.hypot([0.0, 0.3], [-0.5, 0.4])
    assert np.allclose(s.free, np.sqrt(d * d - 0.01), atol=1e-15)          # tangent length
    assert np.allclose(s.passed_over, 0.1 * s.wrap + s.free, atol=1e-15)


def test_viz_imports_no_realize_and_builds_no_lever():
    """viz draws; the string's geometry and the levers' energies come from below."""
    for path in sorted((PACKAGE / "viz").glob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                assert "realize" not in (node.module or ""), f"{path.name} imports {node.module}"
                assert "lacoste_lever" not in [a.name for a in node.names], f"{path.name} builds levers"


def test_lacoste_energies_are_singhs_closed_form():
    a, b = np.meshgrid(np.linspace(0.05, 1.0, 7), np.linspace(0.05, 1.0, 5))
    W, length = 10.0, 0.5
    want = W * length / 2 * (a / b + b / a)           # Singh eq. 3: the preload energy k (a^2 + b^2) / 2
    assert np.allclose(bl.singh.lacoste_energies(W, length, a, b), want, rtol=1e-12)
