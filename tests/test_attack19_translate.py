"""Issue 19: translating a drawing translates the designed springs (each free end stays in the default
box of its own body) and keeps their rates; checked with an independent energy."""
import warnings

import numpy as np
import pytest

import balancelab as bl

G = 9.81


def _lever(at: tuple[float, float]) -> bl.Design:
    lk = bl.Linkage("lever")
    lk.revolute("ground", at, "arm", (0.0, 0.0))
    lk.mass("arm", 2.0, com=(0.5, 0.0))
    return lk.build()


def _balance(design: bl.Design, **kw) -> bl.Design:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return bl.balance(design, springs=[(("arm", None), ("ground", None))], **kw)


def _spring_energy(design: bl.Design, at: tuple[float, float]) -> np.ndarray:
    """Independent spring energy (J) over a turn of the lever (pivot at ``at`` on the ground)."""
    spring = design.springs[0]
    ends = {spring.a.body: np.array(spring.a.point), spring.b.body: np.array(spring.b.point)}
    arm, ground = ends[1], ends[0] - np.array(at)
    t = np.linspace(-np.pi, np.pi, 720, endpoint=False)
    tip = np.c_[np.cos(t) * arm[0] - np.sin(t) * arm[1], np.sin(t) * arm[0] + np.cos(t) * arm[1]]
    return 0.5 * spring.k * np.sum((tip - ground) ** 2, axis=1)


def _mean_spring_energy(design: bl.Design, at: tuple[float, float]) -> float:
    return float(np.mean(_spring_energy(design, at)))


def _spread(design: bl.Design, at: tuple[float, float]) -> float:
    """Independent energy spread (J) over a turn of the lever (pivot at ``at`` on the ground)."""
    spring = design.springs[0]
    ends = {spring.a.body: np.array(spring.a.point), spring.b.body: np.array(spring.b.point)}
    arm, ground = ends[1], ends[0] - np.array(at)
    t = np.linspace(-np.pi, np.pi, 721)
    tip = np.c_[np.cos(t) * arm[0] - np.sin(t) * arm[1], np.sin(t) * arm[0] + np.cos(t) * arm[1]]
    return float(np.ptp(2.0 * G * 0.5 * np.sin(t) + 0.5 * spring.k * np.sum((tip - ground) ** 2, axis=1)))


@pytest.mark.parametrize("objective", ["min_stiffness", "min_preload"])
def test_translated_lever_keeps_rate_and_anchor_near_its_pivot(objective):
    at = (1e4, -3e4)
    home, far = _balance(_lever((0.0, 0.0)), objective=objective), _balance(_lever(at), objective=objective)
    if objective == "min_stiffness":
        assert far.springs[0].k == pytest.approx(home.springs[0].k, rel=1e-6)
    else:  # several springs share the least preload (mean spring energy): compare that, not the rate
        assert _mean_spring_energy(far, at) == pytest.approx(_mean_spring_energy(home, (0.0, 0.0)), rel=1e-6)
    spring = far.springs[0]
    ground = np.array(spring.a.point if spring.a.body == 0 else spring.b.point)
    assert np.all(np.abs(ground - np.array(at)) <= 0.5 + 1e-9)  # the ground's default box: half-width 0.5 m
    assert _spread(far, at) <= 1e-9 * 2.0 * G * 0.5
    assert _spread(home, (0.0, 0.0)) <= 1e-9 * 2.0 * G * 0.5


@pytest.mark.parametrize("at", [(0.0, 0.0), (1e3, 0.0), (1e4, -3e4)])
def test_far_lever_with_a_free_ground_anchor_finds_the_anchor_above_its_pivot(at):
    """Spring arm (0.25, 0) -> ground anchor free: min_stiffness puts it at the box's top, 0.5 m above
    the pivot, k = m g l / (a b) = 2 * 9.81 * 0.5 / (0.25 * 0.5); the same however far the drawing is."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        out = bl.balance(_lever(at), springs=[(("arm", (0.25, 0.0)), ("ground", None))], objective="min_stiffness")
    spring = out.springs[0]
    assert spring.k == pytest.approx(2.0 * G * 0.5 / (0.25 * 0.5), rel=1e-9)
    ground = np.array(spring.a.point if spring.a.body == 0 else spring.b.point) - np.array(at)
    assert ground == pytest.approx([0.0, 0.5], abs=1e-9)
    assert _spread(out, at) <= 1e-9 * 2.0 * G * 0.5
