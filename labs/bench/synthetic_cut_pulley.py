"""Write ``measurements_cut_pulley_example.csv``: SYNTHETIC bench data for the cut-pulley experiment.

Generated from the model, not measured: chapter 9's link and stock spring on the non-circular pulley
the library designs for them, with a spring 3 % softer than nominal, a cable clamped 2 mm long, an
eyelet-and-pivot friction of 0.12 N m, hand-scale noise 0.15 N, ruler noise 0.5 mm and calibration
noise 0.3 mm (numpy seed 11). Run it from this folder: ``python synthetic_cut_pulley.py``.
"""
from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np

import balancelab as bl
from balancelab.methods.practice import forces
from balancelab.methods.practice.springs import ExtensionSpring

SETUP = dict(mass_kg=2.0, length_m=0.5, eyelet_m=0.3, hand_m=0.5, min_tension_N=45.0, wire_d_m=3e-3,
             coil_D_m=24e-3, active_coils=60, initial_tension_N=40.0)
TRUTH = dict(rate_factor=0.97, cable_long_m=0.002, friction_Nm=0.12, hand_noise_N=0.15, ruler_noise_m=0.0005,
             calibration_noise_m=0.0003, seed=11)


def designed(setup=SETUP):
    """The pulley design the bench is cut from (the library's, for the set-up's numbers)."""
    spring = ExtensionSpring(setup["wire_d_m"], setup["coil_D_m"], setup["active_coils"],
                             initial_tension=setup["initial_tension_N"])
    link = bl.lecture.single_link_spring(setup["mass_kg"], setup["length_m"], setup["eyelet_m"], 0.2)
    return spring, bl.realize.noncircular_pulley(link, spring_model=spring, angle_range=(-math.pi / 3, math.pi / 3),
                                                 min_tension=setup["min_tension_N"], eyelet=(0.0, setup["eyelet_m"]))


def main(path: Path = Path(__file__).with_name("measurements_cut_pulley_example.csv")) -> None:
    rng = np.random.default_rng(TRUTH["seed"])
    spring, design = designed()
    s = design.springs[0]
    k_true = TRUTH["rate_factor"] * s.k
    built = design.replace(springs=[dataclasses.replace(s, k=k_true, free_length=s.free_length + TRUTH["cable_long_m"])])
    deg = np.arange(-60, 61, 15)
    q = np.radians(deg)[:, None]
    _, Q = forces.generalized_force(built, q)
    hand, tau = SETUP["hand_m"], TRUTH["friction_Nm"]
    up = (Q[:, 0] + tau) / hand + rng.normal(0, TRUTH["hand_noise_N"], len(deg))
    down = (-Q[:, 0] + tau) / hand + rng.normal(0, TRUTH["hand_noise_N"], len(deg))
    cab = s.cable.cable(q[:, 0])
    length = cab.path - s.cable.cable_length - TRUTH["cable_long_m"] + rng.normal(0, TRUTH["ruler_noise_m"], len(deg))
    masses = np.array([6.0, 8.0, 10.0, 12.0, 14.0])
    ext = (masses * bl.G - spring.initial_tension) / k_true + rng.normal(0, TRUTH["calibration_noise_m"], 5)
    lines = ["# balancelab bench experiment: a link balanced by a spring over a cut non-circular pulley",
             "# SYNTHETIC EXAMPLE DATA: generated from the model by synthetic_cut_pulley.py (spring 3 % softer than",
             "# nominal, cable clamped 2 mm long, friction 0.12 N m, hand-scale noise 0.15 N, ruler noise 0.5 mm,",
             "# calibration noise 0.3 mm, numpy seed 11); NOT a measurement. Replace the rows and the set-up.",
             *[f"# setup: {key} = {value:g}" for key, value in SETUP.items()],
             "# kind = 'angle': angle_deg = link angle from the horizontal, up_N / down_N = force at the hand to just",
             "#   start lifting / lowering the link (negative: it sinks or rises by itself and the hand holds it",
             "#   back), spring_length_m = the spring's length between the load points of its two hooks (ruler);",
             "# kind = 'calibration': mass_kg hung on the spring alone and the extension_m beyond its closed length.",
             "kind,angle_deg,up_N,down_N,spring_length_m,mass_kg,extension_m,synthetic"]
    lines += [f"angle,{d},{u:.3f},{w:.3f},{L:.4f},,,yes" for d, u, w, L in zip(deg, up, down, length)]
    lines += [f"calibration,,,,,{m:.1f},{x:.4f},yes" for m, x in zip(masses, ext)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main()
