"""Issue 19: a report on configurations along one level set of an unbalanced design's energy
(a real spring, free length 0.3 m) must not say balanced."""
import numpy as np
import pytest
from scipy.optimize import brentq

import balancelab as bl

G = 9.81


def _arm() -> bl.Design:
    lk = bl.Linkage("2R")
    lk.revolute("ground", (0.0, 0.0), "upper", (0.0, 0.0))
    lk.revolute("upper", (1.0, 0.0), "fore", (0.0, 0.0))
    lk.mass("upper", 1.0, com=(0.5, 0.0))
    lk.mass("fore", 1.0, com=(0.5, 0.0))
    lk.spring("fore", (1.0, 0.0), "ground", (0.0, 0.8), k=40.0, free_length=0.3)
    return lk.build()


def _energy(t1: float, t2: float) -> float:
    """Independent energy (J): two 1 kg links, COM at mid-length, spring tip to (0, 0.8)."""
    e1, e2 = np.array([np.cos(t1), np.sin(t1)]), np.array([np.cos(t2), np.sin(t2)])
    height = 0.5 * e1[1] + e1[1] + 0.5 * e2[1]
    stretch = np.linalg.norm(e1 + e2 - np.array([0.0, 0.8])) - 0.3
    return G * height + 0.5 * 40.0 * stretch ** 2


def _level_set() -> np.ndarray:
    level = _energy(0.0, 0.0)
    ts = np.linspace(-np.pi, np.pi, 361)
    q = []
    for t1 in np.linspace(-np.pi, np.pi, 61):
        f = [_energy(t1, t) - level for t in ts]
        for i in range(len(ts) - 1):
            if f[i] * f[i + 1] < 0:
                q.append((t1, brentq(lambda t, a=t1: _energy(a, t) - level, ts[i], ts[i + 1], xtol=1e-14)))
    return np.array(q)


def test_level_set_of_real_spring_design_is_not_reported_balanced():
    design, q = _arm(), _level_set()
    energies = np.array([_energy(*x) for x in q])
    assert np.ptp(energies) < 1e-9  # the set is a level set (independent energy)
    assert np.ptp(design.potential_energy(q).total) < 1e-9
    spread = np.ptp([_energy(*x) for x in design.sample(400)])
    assert spread > 50.0  # and the design is far from balanced
    try:
        report = design.balance_report(q=q)
    except ValueError as error:
        assert "q must" in str(error)
    else:
        assert not report.balanced


def test_a_grid_or_sample_still_proves_balance_or_its_absence():
    design = _arm()
    t = np.linspace(-np.pi, np.pi, 13)
    grid = np.stack(np.meshgrid(t, t), -1).reshape(-1, 2)
    assert not design.balance_report(q=grid).balanced
    assert not design.balance_report(q=design.sample(300)).balanced


def test_fill_dimension_tells_a_curve_from_a_grid_of_any_aspect():
    from balancelab.core.samples import fill_dimension
    t, s = np.linspace(0.0, 1.0, 50), np.linspace(0.0, 1.0, 5)
    assert fill_dimension(np.stack(np.meshgrid(t, s), -1).reshape(-1, 2)) == pytest.approx(2.0)
    a = np.linspace(0.0, 2 * np.pi, 300)
    assert fill_dimension(np.c_[np.cos(a), np.sin(a)]) < 1.5
