"""The one transform kernel (balancelab.core.frames) and the one finite-difference loop: exact
properties, and a scan of the package for rotations written anywhere else."""
from __future__ import annotations

import ast
import math
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import balancelab as bl
from balancelab.core import frames
from balancelab.core.kinematics import central_difference

PACKAGE = Path(bl.__file__).parent
KERNEL = PACKAGE / "core" / "frames.py"

#: places that combine a cosine and a sine without carrying a body point to the world, and why
NOT_A_TRANSFORM = {
    # a closed-form minimum energy A sin + B cos of Singh's 2R (a number of the paper, eq. 49)
    ("methods/singh/serial.py", "serial_2r_min_preload"),
}


def _trig_names(fn: ast.AST) -> tuple[set, set]:
    """Names bound to a cosine and to a sine inside ``fn`` (``c, s = np.cos(a), np.sin(a)`` ...)."""
    cos, sin = set(), set()
    for node in ast.walk(fn):
        if not isinstance(node, ast.Assign):
            continue
        for target in node.targets:
            pairs = (zip(target.elts, node.value.elts) if isinstance(target, ast.Tuple)
                     and isinstance(node.value, ast.Tuple) else [(target, node.value)])
            for t, v in pairs:
                if isinstance(t, ast.Name) and _trig_call(v):
                    (cos if _trig_call(v) == "cos" else sin).add(t.id)
    return cos, sin


def _trig_call(node) -> str | None:
    if isinstance(node, ast.Call):
        f = node.func
        name = f.attr if isinstance(f, ast.Attribute) else getattr(f, "id", "")
        return name if name in ("cos", "sin") else None
    return None


def _factors(node) -> list:
    """The factors of a product (through unary minus)."""
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        return _factors(node.operand)
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Mult):
        return _factors(node.left) + _factors(node.right)
    return [node]


def _kind(node, cos: set, sin: set) -> str | None:
    if isinstance(node, ast.Name):
        return "cos" if node.id in cos else "sin" if node.id in sin else None
    return _trig_call(node)


def _rotations(source: str) -> list[tuple[str, int]]:
    """``(function, line)`` of every ``c * x -+ s * y``-like sum in ``source``: a cosine times one
    thing plus or minus a sine times another, with the cosine and sine called or bound to names."""
    found = []
    for fn in [n for n in ast.walk(ast.parse(source)) if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))]:
        cos, sin = _trig_names(fn)
        for node in ast.walk(fn):
            if not (isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Add, ast.Sub))):
                continue
            left, right = _factors(node.left), _factors(node.right)
            if len(left) < 2 or len(right) < 2:
                continue
            kl, kr = {_kind(f, cos, sin) for f in left}, {_kind(f, cos, sin) for f in right}
            if ("cos" in kl and "sin" in kr) or ("sin" in kl and "cos" in kr):
                found.append((fn.name, node.lineno))
    return found


def test_no_module_writes_a_rotation_outside_the_kernel():
    offenders = []
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE).as_posix()
        if path != KERNEL:
            offenders += [f"{rel}:{line} in {name}" for name, line in _rotations(path.read_text(encoding="utf-8"))
                          if (rel, name) not in NOT_A_TRANSFORM]
    assert not offenders, "rotations written outside balancelab.core.frames:\n" + "\n".join(offenders)
    for rel, name in NOT_A_TRANSFORM:   # every exception still names a place the scan would flag
        assert any(fn == name for fn, _ in _rotations((PACKAGE / rel).read_text(encoding="utf-8"))), (rel, name)


@pytest.mark.parametrize("source", [
    "def f(a, p):\n    c, s = np.cos(a), np.sin(a)\n    return c * p[0] - s * p[1]\n",
    "def f(a, x, y):\n    return np.cos(a) * x + np.sin(a) * y\n",
    "def f(P, D):\n    sb = np.sin(P)\n    cb = np.cos(P)\n    return -D[0] * sb + D[1] * cb\n",
    "def f(t, p):\n    c, s = math.cos(t), math.sin(t)\n    return (s * p[0] + c * p[1],)\n",
])
def test_the_scan_sees_a_rotation_written_by_hand(source):
    assert _rotations(source)


def test_the_scan_leaves_polar_points_and_the_kernels_calls_alone():
    assert not _rotations("def f(a, r, x):\n    return x + r * np.cos(a), r * np.sin(a)\n")
    assert not _rotations("def f(a, p):\n    return frames.turn(np.cos(a), np.sin(a), p)\n")


# ------------------------------------------------------------------ the kernel's physics
ANGLES = np.linspace(-7.0, 7.0, 29)
POINTS = [(0.3, -1.2), (0.0, 0.0), (2.5, 0.0), (-1e-3, 4.0)]


@pytest.mark.parametrize("point", POINTS)
def test_turn_keeps_lengths_and_turns_by_the_angle(point):
    x, y = frames.rotate(np, ANGLES, point)
    assert np.allclose(np.hypot(x, y), math.hypot(*point), rtol=0, atol=1e-14)
    if point != (0.0, 0.0):
        turned = np.angle((x + 1j * y) / complex(*point))
        assert np.allclose(np.exp(1j * turned), np.exp(1j * ANGLES), atol=1e-12)


@pytest.mark.parametrize("point", POINTS)
def test_turn_back_undoes_turn_and_turn_rate_is_the_derivative(point):
    c, s = np.cos(ANGLES), np.sin(ANGLES)
    back = frames.turn_back(c, s, frames.turn(c, s, point))
    assert np.allclose(back[0], point[0], atol=1e-14) and np.allclose(back[1], point[1], atol=1e-14)
    h = 1e-6
    plus, minus = frames.rotate(np, ANGLES + h, point), frames.rotate(np, ANGLES - h, point)
    rate = frames.turn_rate(c, s, point)
    for k in range(2):
        assert np.allclose((plus[k] - minus[k]) / (2 * h), rate[k], atol=1e-8)


def test_place_is_origin_plus_turn_with_numbers_arrays_and_symbols():
    X, Y = np.array([1.0, -2.0]), np.array([0.5, 3.0])
    c, s = np.cos([0.4, 2.0]), np.sin([0.4, 2.0])
    for point in POINTS:
        got = frames.place(X, Y, c, s, point)
        want = frames.turn(c, s, point)
        assert np.allclose(got[0], X + want[0], atol=1e-15) and np.allclose(got[1], Y + want[1], atol=1e-15)
    t, a, b = sp.symbols("t a b", real=True)
    px, py = frames.place(1, 2, sp.cos(t), sp.sin(t), (a, b))
    assert sp.simplify(px - (1 + a * sp.cos(t) - b * sp.sin(t))) == 0
    assert sp.simplify(py - (2 + a * sp.sin(t) + b * sp.cos(t))) == 0


def test_body_to_world_matches_a_complex_number_model():
    rng = np.random.default_rng(3)
    poses = rng.normal(size=(5, 4, 3))
    bodies, points = [1, 3, 0, 2], rng.normal(size=(4, 2))
    x, y = frames.body_to_world(poses, bodies, points)
    for m in range(5):
        for i, b in enumerate(bodies):
            z = complex(*poses[m, b, :2]) + complex(*points[i]) * np.exp(1j * poses[m, b, 2])
            assert abs(complex(x[m, i], y[m, i]) - z) < 1e-13


# ------------------------------------------------------------------ the one finite-difference loop
def test_central_difference_is_the_derivative_inside_and_one_sided_at_the_ends():
    q = np.array([[0.0, 0.3], [1.0, -0.2], [0.999_9999, 0.0]])
    value = lambda q: np.sin(q[..., 0]) * np.cos(q[..., 1])          # noqa: E731
    reachable = lambda q: q[..., 0] <= 1.0                             # noqa: E731
    d = central_difference(value, reachable, q, 1e-6)
    assert np.allclose(d[0], [np.cos(0.0) * np.cos(0.3), -np.sin(0.0) * np.sin(0.3)], atol=1e-9)
    assert d[1, 0] == pytest.approx((np.sin(1.0) - np.sin(1.0 - 1e-6)) * np.cos(-0.2) / 1e-6, rel=1e-8)
    assert np.isfinite(d).all()


def test_central_difference_never_asks_for_an_unreachable_configuration():
    asked = []

    def value(q):
        asked.append(q.copy())
        return q[..., 0] ** 2

    central_difference(value, lambda q: np.abs(q[..., 0]) <= 1.0, np.array([[1.0], [-1.0], [0.5]]), 1e-3)
    assert all(np.all(np.abs(q[..., 0]) <= 1.0) for q in asked)


def test_both_generalized_forces_go_through_the_same_loop():
    """The design's dV/dq and practice's analytic virtual work agree on every catalog design
    they both handle (two routes, one difference scheme)."""
    from balancelab.methods.practice import forces

    for name in ("single_link_zfl", "serial_2r_min_preload", "lacoste_lever", "lustig_case1"):
        d = bl.catalog()[name]()
        q = d.sample(25, seed=2)
        scale = max(1.0, float(np.abs(d.generalized_force(q)).max()))
        assert np.allclose(forces.batch_generalized_force(d, q)[0], d.generalized_force(q), atol=1e-5 * scale)
