"""Stiffness-matrix method (Lustig et al. 2015): numeric synthesis and cached symbolic solve."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from timing import median_time

ROOT = Path(__file__).resolve().parent.parent

_COLD = r"""
import time
t0 = time.perf_counter()
from balancelab.methods import lustig as sm
{body}
t1 = time.perf_counter()
{body}
t2 = time.perf_counter()
print(t1 - t0, t2 - t1)
"""

# paper's example: three links (fixed world + two moving), the six unknowns of Table 3e
_PAPER = ("sm.solve(2, sm.LUSTIG_TOPOLOGY, sm.lustig_values(1, solved=False), sm.LUSTIG_UNKNOWNS)")
# three moving links, a spring between every pair, the twelve distal attachments unknown
_THREE = ("d = sm.balance_all_pairs((0.4, 0.3, 0.25), (3.0, 2.0, 1.0), ((0.2, 0.0), (0.15, 0.02), "
          "(0.1, 0.0)))\n"
          "sm.solve(3, ((0, 1), (0, 2), (1, 2), (0, 3), (1, 3), (2, 3)), d.parameters, "
          "tuple(f'b{c}{j}' for j in range(1, 7) for c in 'xy'))")

_FOUR = ("d = sm.balance_all_pairs((0.4, 0.3, 0.25, 0.2), (3.0, 2.0, 1.0, 0.5), ((0.2, 0.0), "
         "(0.15, 0.02), (0.1, 0.0), (0.1, 0.01)))\n"
         "sm.solve(4, tuple((i, j) for j in range(1, 5) for i in range(j)), d.parameters, "
         "tuple(f'b{c}{j}' for j in range(1, 11) for c in 'xy'))")



def _cold(body: str) -> tuple[float, float]:
    code = _COLD.format(body=body)
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                         check=True)
    cold, warm = (float(x) for x in out.stdout.split())
    return cold, warm


def run() -> list[tuple[str, float, str, str]]:
    from balancelab.methods import lustig as sm

    rows = []
    lengths, masses, coms = (0.4, 0.3, 0.25), (3.0, 2.0, 1.0), ((0.2, 0.0), (0.15, 0.02), (0.1, 0.0))
    t = median_time(lambda: sm.balance_all_pairs(lengths, masses, coms))
    rows.append(("numeric synthesis, 3 moving links, all-pairs springs -> Design", t * 1e3, "ms", "< 1"))
    chain = sm.SerialChain.from_values(2, sm.LUSTIG_TOPOLOGY, sm.lustig_values(1))
    t = median_time(lambda: sm.stiffness_matrix(chain), repeat=500)
    rows.append(("numeric K_t, paper example", t * 1e3, "ms", "< 1"))
    inputs = sm.lustig_values(1, solved=False)
    sm.solve(2, sm.LUSTIG_TOPOLOGY, inputs, sm.LUSTIG_UNKNOWNS)
    t = median_time(lambda: sm.solve(2, sm.LUSTIG_TOPOLOGY, inputs, sm.LUSTIG_UNKNOWNS))
    rows.append(("solve(), paper example, cached symbolic solution", t * 1e3, "ms", "< 1"))
    t = median_time(lambda: sm.synthesize(2, sm.LUSTIG_TOPOLOGY, inputs, sm.LUSTIG_UNKNOWNS,
                                           symbolic=False))
    rows.append(("synthesize() -> Design, paper example, cached", t * 1e3, "ms", "< 1"))
    cold, warm = _cold(_PAPER)
    rows.append(("symbolic derive + solve, 3-link chain (paper), cold incl. sympy import", cold, "s",
                 "< 2"))
    rows.append(("same, second call (lru_cache)", warm * 1e3, "ms", "< 1"))
    cold, warm = _cold(_THREE)
    rows.append(("symbolic derive + solve, 3 moving links, 12 unknowns, cold", cold, "s", "< 2"))
    rows.append(("same, second call (lru_cache)", warm * 1e3, "ms", "< 2"))
    cold, warm = _cold(_FOUR)
    rows.append(("symbolic derive + solve, 4 moving links, 20 unknowns, cold", cold, "s", "< 5"))
    return rows


if __name__ == "__main__":
    for row in run():
        print(row)
