"""The bench guide's cut-pulley experiment: its synthetic data are marked so, and the analysis,
run on them, recovers the errors the generator put in."""
from __future__ import annotations

import importlib.util
import re
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parent.parent
BENCH = ROOT / "labs" / "bench"
DATA = BENCH / "measurements_cut_pulley_example.csv"


def _generator():
    spec = importlib.util.spec_from_file_location("synthetic_cut_pulley", BENCH / "synthetic_cut_pulley.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_the_example_is_marked_synthetic_and_is_what_the_generator_writes(tmp_path):
    text = DATA.read_text(encoding="utf-8")
    assert "SYNTHETIC" in text.splitlines()[1]
    rows = [line for line in text.splitlines() if line and not line.startswith("#")][1:]
    assert rows and all(line.endswith(",yes") for line in rows)
    out = tmp_path / "again.csv"
    _generator().main(out)
    assert out.read_text(encoding="utf-8") == text
    readme = (BENCH / "README.md").read_text(encoding="utf-8")
    assert "Experiment 2" in readme and "**synthetic**" in readme and "analysis_cut_pulley.ipynb" in readme


def test_the_analysis_runs_cleanly_and_recovers_the_generators_errors():
    nbclient = pytest.importorskip("nbclient")
    nb = nbformat.read(BENCH / "analysis_cut_pulley.ipynb", as_version=4)
    nbclient.NotebookClient(nb, timeout=600, kernel_name="python3",
                            resources={"metadata": {"path": str(BENCH)}}).execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error" or o.get("name") == "stderr"]
    text = "\n".join(o.get("text", "") for o in outputs)
    assert "SYNTHETIC" in text
    truth = _generator().TRUTH
    rate = float(re.search(r"rate: [\d.]+ N/m measured, [\d.]+ N/m nominal \(([-+\d.]+) %\)", text).group(1))
    assert abs(rate / 100 - (truth["rate_factor"] - 1)) < 0.01
    cable = float(re.search(r"cable clamped ([-+\d.]+) mm long", text).group(1))
    assert abs(cable / 1000 - truth["cable_long_m"]) < 0.0007
    friction = float(re.search(r"friction from the hysteresis: ([\d.]+) N m", text).group(1))
    assert abs(friction - truth["friction_Nm"]) < 0.05
    rms = float(re.search(r"RMS model - measurement ([\d.]+) N m", text).group(1))
    # the hand scale's noise (0.15 N at 0.5 m, halved by the difference) bounds what is left
    assert rms < 3 * truth["hand_noise_N"] * 0.5
