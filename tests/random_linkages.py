"""Random linkages of every kind the builder makes, for the property tests of issue 19 (a helper, no tests)."""
from __future__ import annotations

import numpy as np

import balancelab as bl


def chain(rng, n):
    lk = bl.Linkage(f"{n}R chain")
    prev, tip = "ground", (0.0, 0.0)
    for i in range(n):
        length = rng.uniform(0.2, 0.8)
        lk.revolute(prev, tip, f"link{i + 1}", (0.0, 0.0))
        lk.mass(f"link{i + 1}", rng.uniform(0.5, 3.0), com=(rng.uniform(0, length), rng.uniform(-0.1, 0.1)))
        prev, tip = f"link{i + 1}", (length, 0.0)
    return lk.build()


def fourbar(rng):
    while True:
        crank, coupler, rocker, ground = rng.uniform(0.2, 1.0, 4)
        try:
            bl.mechanisms.check_assembly(crank, coupler, rocker, ground)
            break
        except ValueError:
            continue
    lk = bl.Linkage("four-bar")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (crank, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (coupler, 0.0), "rocker", (rocker, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (ground, 0.0))
    for body, length in (("crank", crank), ("coupler", coupler), ("rocker", rocker)):
        lk.mass(body, rng.uniform(0.5, 3.0), com=(rng.uniform(0, length), rng.uniform(-0.1, 0.1)))
    return lk.build(guess={"crank": rng.uniform(-np.pi, np.pi), "rocker": rng.uniform(-np.pi, np.pi)})


def flat_parallelogram(rng):
    crank, ground = rng.uniform(0.2, 1.0, 2)
    lk = bl.Linkage("parallelogram drawn flat")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (crank, 0.0), "coupler", (0.0, 0.0))
    lk.revolute("coupler", (ground, 0.0), "rocker", (crank, 0.0))
    lk.revolute("rocker", (0.0, 0.0), "ground", (ground, 0.0))
    for body, length in (("crank", crank), ("coupler", ground), ("rocker", crank)):
        lk.mass(body, rng.uniform(0.5, 3.0), com=(rng.uniform(0, length), 0.0))
    return lk.build()


def fivebar(rng):
    a, b, c, d, e = rng.uniform(0.3, 0.7, 5)
    lk = bl.Linkage("five-bar")
    lk.revolute("ground", (0.0, 0.0), "left", (0.0, 0.0))
    lk.revolute("left", (a, 0.0), "upper left", (0.0, 0.0))
    lk.revolute("upper left", (b, 0.0), "upper right", (c, 0.0))
    lk.revolute("upper right", (0.0, 0.0), "right", (d, 0.0))
    lk.revolute("right", (0.0, 0.0), "ground", (e * 0.6, 0.0))
    for body in ("left", "upper left", "upper right", "right"):
        lk.mass(body, rng.uniform(0.5, 2.0), com=(0.15, 0.0))
    return lk.build(guess={"left": 1.6, "upper left": 0.3, "upper right": 2.8, "right": 1.5})


def watt(rng):
    from balancelab.methods.general.examples import watt_sixbar
    return watt_sixbar()


KINDS = {"2R": lambda r: chain(r, 2), "3R": lambda r: chain(r, 3), "four-bar": fourbar,
         "flat parallelogram": flat_parallelogram, "five-bar": fivebar, "Watt": watt}


def moving(design):
    return list(design.bodies[1:])


def ground_springs(design, rng, free="moving"):
    """One ZFL spring from the ground to each moving body; ``free``: which end the solver places."""
    out = []
    for b in moving(design):
        g = ("ground", (float(rng.uniform(-0.3, 0.3)), float(rng.uniform(0.1, 0.5))))
        m = (b, (float(rng.uniform(0.0, 0.4)), 0.0))
        if free == "moving":
            m = (b, None)
        elif free == "ground":
            g = ("ground", None)
        elif free == "both":
            g, m = ("ground", None), (b, None)
        out.append((g, m))
    return out


def slider_crank(rng):
    crank = rng.uniform(0.1, 0.3)
    rod = rng.uniform(0.4, 0.8)
    lk = bl.Linkage("slider-crank")
    lk.revolute("ground", (0.0, 0.0), "crank", (0.0, 0.0))
    lk.revolute("crank", (crank, 0.0), "rod", (0.0, 0.0))
    lk.revolute("rod", (rod, 0.0), "slider", (0.0, 0.0))
    angle = rng.uniform(-0.5, 0.5)
    lk.prismatic("ground", (0.0, 0.0), "slider", (0.0, 0.0), axis=(np.cos(angle), np.sin(angle)))
    for body, length in (("crank", crank), ("rod", rod)):
        lk.mass(body, rng.uniform(0.5, 3.0), com=(rng.uniform(0, length), rng.uniform(-0.05, 0.05)))
    lk.mass("slider", rng.uniform(0.5, 3.0))
    return lk.build(guess={"crank": 1.0})


KINDS["slider-crank"] = slider_crank
