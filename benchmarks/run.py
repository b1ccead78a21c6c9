"""Print every benchmark of balancelab as one table.

Usage (from the repository root; ``bash scripts/course.sh bench`` does the set-up first)::

    .venv/bin/python benchmarks/run.py            # every bench_*.py
    .venv/bin/python benchmarks/run.py core book  # only bench_core.py and bench_book.py
    .venv/bin/python benchmarks/run.py practice   # tolerance Monte Carlo (1e4 built 2R arms < 1 s)

Each ``benchmarks/bench_<topic>.py`` exposes ``run()`` returning rows
``(name, measured value, unit, target text)``. Targets live here, not in timed tests.
"""
from __future__ import annotations

import importlib.util
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent


def _load(path: Path):
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def main(argv: list[str]) -> int:
    sys.path[:0] = [str(HERE.parent), str(HERE)]
    files = sorted(HERE.glob("bench_*.py"))
    if argv:
        files = [f for f in files if f.stem.removeprefix("bench_") in argv]
    rows = []
    for f in files:
        t0 = time.perf_counter()
        print(f"running {f.name} ...", file=sys.stderr, flush=True)
        try:
            for name, value, unit, target in _load(f).run():
                rows.append((f.stem.removeprefix("bench_"), name, value, unit, target))
        except Exception as err:  # a broken benchmark is reported, the others still run
            rows.append((f.stem.removeprefix("bench_"), f"FAILED: {type(err).__name__}: {err}", float("nan"), "", ""))
        print(f"  {f.name}: {time.perf_counter() - t0:.1f} s", file=sys.stderr, flush=True)
    w = max([len(r[1]) for r in rows] + [9])
    print(f"{'topic':10s} {'benchmark':{w}s} {'measured':>14s} {'unit':10s} target")
    print("-" * (w + 50))
    for topic, name, value, unit, target in rows:
        print(f"{topic:10s} {name:{w}s} {value:14.4g} {unit:10s} {target}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
