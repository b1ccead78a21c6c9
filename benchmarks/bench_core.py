"""Core library speed: energy evaluation, numeric synthesis, import time."""
from __future__ import annotations

import subprocess
import sys

import numpy as np
from timing import best_time, median_time


def run() -> list[tuple[str, float, str, str]]:
    import balancelab as bl

    rows = []
    arm = bl.singh.serial_2r_min_preload()
    q = np.random.default_rng(0).uniform(-np.pi, np.pi, (1_000_000, 2))
    arm.potential_energy(q[:1000])
    best = best_time(lambda: arm.potential_energy(q))
    rows.append(("2R potential_energy, 1e6 configurations", len(q) / best / 1e6, "M conf/s", ">= 10"))
    for name, fn in [
        ("lacoste_lever synthesis", lambda: bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)),
        ("min_preload_lever synthesis", lambda: bl.singh.min_preload_lever(10.0, 0.5, 0.5)),
        ("serial_2r_min_preload synthesis", bl.singh.serial_2r_min_preload),
        ("serial_2r_simplified synthesis", bl.singh.serial_2r_simplified),
        ("singh_fourbar synthesis", bl.singh.singh_fourbar),
        ("scissors_lift synthesis", bl.singh.scissors_lift),
        ("peaucellier_board synthesis", bl.singh.peaucellier_board),
        ("fourbar_two_springs synthesis", bl.lecture.fourbar_two_springs),
    ]:
        rows.append((name + " (median)", median_time(fn) * 1e3, "ms", "< 1"))
    out = subprocess.run([sys.executable, "-c", "import time; t = time.perf_counter(); import balancelab; "
                          "print(time.perf_counter() - t)"], capture_output=True, text=True, check=True)
    rows.append(("import balancelab (cold process)", float(out.stdout), "s", "< 0.5"))
    return rows

