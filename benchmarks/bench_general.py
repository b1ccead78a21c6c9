"""The linkage builder and the general balancer (issue 11): speed targets."""
from __future__ import annotations

import numpy as np

from timing import best_time


def run() -> list[tuple[str, float, str, str]]:
    import balancelab as bl
    from balancelab.methods.general.examples import all_pairs, arm_3r, fourbar_issue11, watt_sixbar

    rows = []
    arm = arm_3r()
    cands = all_pairs(arm)
    t = best_time(lambda: bl.balance(arm, springs=cands, objective="min_stiffness"), repeat=7)
    rows.append(("balance a 3R arm, all-pairs ZFL springs (6, distal ends free)", t * 1e3, "ms", "< 100"))
    six = watt_sixbar()
    names = six.bodies
    free = [((names[i], None), (names[j], (0.1, 0.0))) for i in range(6) for j in range(i + 1, 6)]
    t = best_time(lambda: bl.balance(six, springs=free, objective="min_stiffness"), repeat=3)
    rows.append(("balance a Watt six-bar, 15 springs with free anchor points", t * 1e3, "ms", "< 1000"))
    t = best_time(watt_sixbar, repeat=3)
    rows.append(("build a Watt six-bar (assembly, dof, circuit)", t * 1e3, "ms", ""))
    kin = fourbar_issue11().kinematics
    q = np.random.default_rng(0).uniform(-np.pi, np.pi, (100_000, 1))
    t = best_time(lambda: kin.poses(q), repeat=3)
    rows.append(("builder kinematics: 1e5 four-bar configurations", t * 1e3, "ms", "< 1000"))
    return rows
