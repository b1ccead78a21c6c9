"""Issue 19: huge drawings (>= 3e3 m) and huge masses (1e9 kg) must solve or raise InfeasibleDesign,
never a ValueError from inside scipy; a returned design is balanced by an independent energy."""
import warnings

import numpy as np
import pytest

import balancelab as bl

G = 9.81


def _lever(mass: float, com: float) -> bl.Design:
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    lk.mass("arm", mass, com=(com, 0.0))
    return lk.build()


def _independent_spread(design: bl.Design, mass: float, com: float) -> float:
    """Energy spread (J) over a turn: gravity on the COM plus each spring, from its own attachments."""
    spring = design.springs[0]
    assert spring.free_length == 0.0
    ends = {spring.a.body: np.array(spring.a.point), spring.b.body: np.array(spring.b.point)}
    arm, ground = ends[1], ends[0]
    t = np.linspace(-np.pi, np.pi, 721)
    tip = np.c_[np.cos(t) * arm[0] - np.sin(t) * arm[1], np.sin(t) * arm[0] + np.cos(t) * arm[1]]
    energy = mass * G * com * np.sin(t) + 0.5 * spring.k * np.sum((tip - ground) ** 2, axis=1)
    return float(np.ptp(energy))


@pytest.mark.parametrize("mass, com", [(2.0, 1.5e3), (2.0, 5e3), (1e9, 0.5)])
def test_spring_free_at_both_ends_on_huge_lever_or_mass(mass, com):
    design = _lever(mass, com)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            out = bl.balance(design, springs=[(("arm", None), ("ground", None))])
        except bl.InfeasibleDesign as error:
            assert error.verdict in ("box", "limit", "impossible")
            return
    assert out.balance_report().balanced
    assert _independent_spread(out, mass, com) <= 1e-8 * mass * G * com
