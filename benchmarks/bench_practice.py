"""Practice library speed: the tolerance Monte Carlo of a 2R arm and spring selection."""
from __future__ import annotations

from timing import best_time, median_time


def run() -> list[tuple[str, float, str, str]]:
    import balancelab as bl
    from balancelab.methods.practice import selection, tolerance

    arm = bl.singh.serial_2r_min_preload()
    tol = tolerance.Tolerances(k=0.03, free_length=0.001, attachment=0.001, mass=0.02)
    t = best_time(lambda: tolerance.monte_carlo(arm, tol, 10_000, grid=15))
    rows = [("Monte Carlo: 1e4 built 2R arms x 225 configurations", t, "s", "< 1")]
    lever = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    rows.append(("select_springs, lecture link (median)",
                 median_time(lambda: selection.select_springs(lever, 0.15), repeat=5) * 1e3, "ms", "< 500"))
    return rows
