"""Spring-loaded four-bars and cognates (Deepak & Ananthasuresh 2012): synthesis and kinematics speed.

Rows (name, value, unit, target):

* every balancing option (technique 2 at A and B, technique 3 with its four options,
  each with its parameters) on all three cognates of one four-bar, plus the six
  cognate families with their focal pivot and k_b ratio: < 5 ms (median);
* the same including building the four-bar (its crank range) from scratch: for
  information;
* loop closure of 10^6 four-bar configurations (closed-form positions and the
  link-length check of ``loop_closure_error``): < 0.5 s (best of 3);
* the same through ``Design.joint_error`` (general pose path): for information.
"""
from __future__ import annotations


import numpy as np
from timing import best_time, median_time

K = (0.1, -0.2)
KL = 100.0
OPTIONS = [(2, "A", "A"), (2, "A", "B"), (3, "A", "A"), (3, "A", "B"), (3, "B", "A"), (3, "B", "B")]


def _all_options(fb):
    from balancelab import deepak as cg
    from balancelab import deepak as sf

    out = []
    for c in cg.cognates(fb):
        for W in "AB":
            out.append(sf.technique2_parameters(c, K, KL, W, 0.1))
            for U in "AB":
                out.append(sf.technique3_parameters(c, K, KL, U, W, 0.1))
    for t, U, W in OPTIONS:
        out.append(cg.cognate_family(fb, K, KL, t, U, W))
    return out



def run() -> list[tuple[str, float, str, str]]:
    from balancelab import deepak as sf

    rows = []
    fb = sf.example_fourbar()
    rows.append(("all balancing options, 3 cognates (median)", median_time(lambda: _all_options(fb)) * 1e3,
                 "ms", "< 5"))
    rows.append(("same, four-bar built from scratch (median)",
                 median_time(lambda: _all_options(sf.example_fourbar()), 20) * 1e3, "ms", "info"))
    q = np.random.default_rng(0).uniform(-np.pi, np.pi, 1_000_000)
    err = sf.loop_closure_error(fb, q)
    assert float(err.max()) < 1e-12
    rows.append(("loop closure, 1e6 four-bar configurations (best of 3)",
                 best_time(lambda: sf.loop_closure_error(fb, q)), "s", "< 0.5"))
    d = sf.spring_loaded_fourbar(fb, K, KL)
    rows.append(("same via Design.joint_error (best of 3)", best_time(lambda: d.joint_error(q)), "s", "info"))
    return rows


if __name__ == "__main__":
    for row in run():
        print(row)
