"""Shared test helpers: the physics every design must satisfy."""
from __future__ import annotations

import os

import numpy as np

os.environ.setdefault("MPLBACKEND", "Agg")

from balancelab import Design, Spring  # noqa: E402


def spring_perturbations(design: Design, rel: float = 1e-3):
    """Yield ``(label, design)`` with one non-zero spring parameter changed by ``rel`` (relative).

    (A relative change of a parameter that is zero is no change.)
    """
    for i, s in enumerate(design.springs):
        fields = {"k": s.k, "free_length": s.free_length,
                  "a_x": s.a.point[0], "a_y": s.a.point[1], "b_x": s.b.point[0], "b_y": s.b.point[1]}
        for name, value in fields.items():
            if value == 0:
                continue
            new = value * (1 + rel)
            k, l0 = s.k, s.free_length
            a, b = list(s.a.point), list(s.b.point)
            if name == "k":
                k = new
            elif name == "free_length":
                l0 = new
            else:
                (a if name[0] == "a" else b)[0 if name[2] == "x" else 1] = new
            changed = Spring(k, l0, (s.a.body, tuple(a)), (s.b.body, tuple(b)), name=s.name,
                             realization=s.realization)
            springs = list(design.springs)
            springs[i] = changed
            yield f"spring {s.name or i} {name}", design.replace(springs=springs)


def assert_exactly_balanced(design: Design, n: int = 1000) -> None:
    """Energy constant over ``n`` samples to 1e-9, and every 1e-3 spring change detected."""
    report = design.balance_report(n=n)
    assert report.n == n
    assert report.balanced, f"{design.name}: {report}"
    assert report.variation <= 1e-9
    assert report.residual < 1e-6, report
    for label, bad in spring_perturbations(design):
        r = bad.balance_report(n=200)
        assert not r.balanced, f"{design.name}: perturbing {label} went unnoticed ({r})"
        assert r.variation > 1e-7, (label, r.variation)


def assert_symbolic_matches_numeric(design: Design, samples: int = 5) -> None:
    """The symbolic energy (with the design's values) equals the numeric one."""
    import sympy as sp

    expr = design.potential_energy_symbolic()
    values = design.symbolic.values if design.symbolic is not None else {}
    kin = design.kinematics
    if design.symbolic is not None and design.symbolic.kinematics is not None:
        kin = design.symbolic.kinematics
    syms = kin.symbols()
    f = sp.lambdify(syms, expr.subs(values), "numpy")
    q = design.sample(samples, seed=3)
    vals = kin.symbol_values(q)
    got = np.array([f(*v) for v in vals], dtype=float)
    want = design.potential_energy(q).total
    np.testing.assert_allclose(got, want, rtol=1e-9, atol=1e-9 * design.balance_report(n=100).scale)
