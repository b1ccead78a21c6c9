"""The linkage builder and the general balancer (issues 11 and 19): speed targets.

Each balance is timed with the default objective (``min_preload``) as well as ``min_stiffness``,
once with BLAS limited to one thread around the call and once with the BLAS libraries' own
default (multi-threaded): ``bl.balance`` limits small problems to one thread itself, so both
should meet the target on a loaded two-core machine.
"""
from __future__ import annotations

import numpy as np

from timing import best_time


def _threads(label: str):
    from threadpoolctl import threadpool_limits

    return threadpool_limits(limits=1) if label == "1 BLAS thread" else threadpool_limits(limits=None)


def run() -> list[tuple[str, float, str, str]]:
    import balancelab as bl
    from balancelab.methods.general.examples import all_pairs, arm_3r, fourbar_issue11, watt_sixbar

    rows = []
    arm = arm_3r()
    cands = all_pairs(arm)
    six = watt_sixbar()
    names = six.bodies
    free = [((names[i], None), (names[j], (0.1, 0.0))) for i in range(6) for j in range(i + 1, 6)]
    for label in ("1 BLAS thread", "default BLAS threads"):
        with _threads(label):
            for objective, target in (("min_preload", "< 50"), ("min_stiffness", "< 50")):
                t = best_time(lambda: bl.balance(arm, springs=cands, objective=objective), repeat=5)  # noqa: B023 (called at once)
                rows.append((f"balance a 3R arm, all-pairs ZFL springs (6, distal ends free), {objective}, {label}",
                             t * 1e3, "ms", target))
            for objective in ("min_preload", "min_stiffness"):
                t = best_time(lambda: bl.balance(six, springs=free, objective=objective), repeat=2)  # noqa: B023 (called at once)
                rows.append((f"balance a Watt six-bar, 15 springs with free anchor points, {objective}, {label}",
                             t * 1e3, "ms", "< 1000"))
    t = best_time(watt_sixbar, repeat=3)
    rows.append(("build a Watt six-bar (assembly, dof, circuit)", t * 1e3, "ms", ""))
    kin = fourbar_issue11().kinematics
    q = np.random.default_rng(0).uniform(-np.pi, np.pi, (100_000, 1))
    t = best_time(lambda: kin.poses(q), repeat=3)
    rows.append(("builder kinematics: 1e5 four-bar configurations", t * 1e3, "ms", "< 1000"))
    return rows
