"""Non-circular pulley: synthesis of a profile and its 2,000 points, the cable model's energy, and an export
checked against the balance bound (the cable wound on the written points)."""
from __future__ import annotations

import math
import tempfile
from pathlib import Path

from timing import median_time


def run() -> list[tuple[str, float, str, str]]:
    import numpy as np

    import balancelab as bl
    from balancelab.methods.practice.springs import ExtensionSpring

    lever = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    real = ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0)

    def profile():
        d = bl.realize.noncircular_pulley(lever, spring_model=real, angle_range=(-math.pi / 3, math.pi / 3),
                                          min_tension=45.0)
        return bl.realize.profile_part(d, n=2000)

    d = bl.realize.noncircular_pulley(lever, spring_model=real, angle_range=(-math.pi / 3, math.pi / 3),
                                      min_tension=45.0)
    q = np.linspace(-1.0, 1.0, 1000)
    out = Path(tempfile.mkdtemp(prefix="balancelab-bench-")) / "pulley.csv"

    def export():
        return bl.realize.export_profile(d, out)      # default: as many points as the bound 1e-9 needs

    return [("profile of 2,000 points: synthesis + part (median)", median_time(profile, repeat=10) * 1e3, "ms",
             "< 200"),
            ("cable-model energy at 1,000 angles (median)",
             median_time(lambda: d.potential_energy(q), repeat=20) * 1e3, "ms", "< 50"),
            ("export checked to the balance bound 1e-9 (about 27,000 points; median)",
             median_time(export, repeat=3) * 1e3, "ms", "< 5000")]
