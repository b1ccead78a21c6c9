"""Explorer latency and animation size for every catalog entry.

Latency is measured from a slider change (``Explorer.set``) to the updated picture (the
PNG handed to the widget), for every catalog entry explored through its stiffness (or
counterweight) slider and its configuration sliders: half the changes move the
configuration, half change the design (rebuilding it, its balance report and its
energy curve). Target: median < 50 ms and 95th percentile < 100 ms per entry.

Also reported: the size of the default ``animate(design).to_jshtml()`` of every entry
(target < 2 MB) and its frame rate (target >= 20 frames/s).

Run: ``.venv/bin/python benchmarks/run.py explore`` (or this file's ``run()``).
"""
from __future__ import annotations

import os
import time

os.environ.setdefault("MPLBACKEND", "Agg")

import numpy as np  # noqa: E402


def _latencies(explorer, design, changes: int = 20, seed: int = 0) -> np.ndarray:
    rng = np.random.default_rng(seed)
    qs = design.sample(changes, seed=seed)
    out = []
    for i in range(changes):
        if i % 2 == 0 or not explorer.params:
            kw = dict(zip(design.q_names, qs[i]))
        else:
            (p,) = explorer.params
            kw = {p: float(rng.uniform(0.6, 1.4))}
        t0 = time.perf_counter()
        explorer.set(**kw)
        out.append(time.perf_counter() - t0)
    return np.array(out) * 1e3


def run(changes: int = 20) -> list[tuple[str, float, str, str]]:
    """Rows ``(name, value, unit, target)``: latency per catalog entry, animation size."""
    import balancelab as bl
    from balancelab.viz.animation import animate
    from balancelab.viz.explorer import Explorer

    rows = []
    worst_median, worst_p95 = 0.0, 0.0
    for name, factory in bl.catalog().items():
        design = factory()
        ex = Explorer(design)
        ex.set(**dict(zip(design.q_names, design.sample(1, seed=3)[0])))  # warm up
        ms = _latencies(ex, design, changes)
        med, p95 = float(np.median(ms)), float(np.percentile(ms, 95))
        worst_median, worst_p95 = max(worst_median, med), max(worst_p95, p95)
        rows.append((f"explore {name}: median", med, "ms", "< 50 ms"))
        rows.append((f"explore {name}: p95", p95, "ms", "< 100 ms"))
    rows.append(("explore: worst median over the catalog", worst_median, "ms", "< 50 ms"))
    rows.append(("explore: worst p95 over the catalog", worst_p95, "ms", "< 100 ms"))
    cat = bl.catalog()
    for name, factory in cat.items():          # every entry: the size target moved here from the tests
        anim = animate(factory())
        t0 = time.perf_counter()
        size = len(anim.to_jshtml())
        rows.append((f"animate {name}: to_jshtml size", size / 1e6, "MB", "< 2 MB"))
        rows.append((f"animate {name}: to_jshtml time", time.perf_counter() - t0, "s", "(info)"))
        rows.append((f"animate {name}: frame rate", anim.fps, "frames/s", ">= 20"))
    return rows


if __name__ == "__main__":
    for row in run():
        print(f"{row[0]:55s} {row[1]:10.3g} {row[2]:9s} {row[3]}")
