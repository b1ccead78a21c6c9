"""The non-circular pulley as a part to cut: SVG, DXF and CSV at true scale.

The part is drawn in the link's frame (origin at the pivot, x along the link), in
millimetres. Three outlines and a hole:

* ``pitch``: the cable's centre line, the curve :func:`noncircular_pulley` synthesized
  (an open curve, for reference and for checking the part);
* ``groove``: the bottom of the cable's groove, the pitch curve moved inwards by the
  cable's radius and closed round the axle's boss: the outline of the core plate;
* ``flange``: the pitch curve moved outwards by the flange height and closed the same way:
  the outline of the two plates that keep the cable in the groove;
* ``axle``: the axle hole, a circle at the pivot.

Stack a flange, the core plate and a flange (or print the three as one part) and fix them
to the link with the x mark along the link. An export first checks that the cable wound on
the polyline it writes still balances the design (:mod:`.profile_check`). The DXF is written with ``ezdxf`` (the ``cad``
extra: ``pip install balancelab[cad]``).
"""
from __future__ import annotations

import csv
import math
import os
from pathlib import Path
from typing import NamedTuple

import numpy as np

from ...core.design import Design
from ...core.validation import finite_real, instance_of, positive_int
from ...core.report import BALANCE_TOLERANCE
from .profile import NoncircularProfile
from .profile_check import polyline_variation

__all__ = ["ProfilePart", "profile_part", "export_profile"]

#: decimals of a millimetre the SVG and CSV files give their points (DXF stores doubles): rounding
#: to 0.1 um would move the cable's path enough to spoil the balance bound (the check uses these)
DIGITS = 9

#: the most points an export writes while raising ``n`` to keep the balance bound
MAX_POINTS = 200_000

_LAYERS = {"groove": 1, "flange": 5, "pitch": 3, "axle": 1, "mark": 7}   # DXF colour numbers


class ProfilePart(NamedTuple):
    """The outlines of a non-circular pulley in the link's frame (m).

    ``pitch`` (n, 2) open; ``groove`` and ``flange`` (m, 2) closed (last point not repeated),
    counter-clockwise; ``axle_diameter`` (m); ``link_angle`` (n,) the link angle (rad) at which
    each pitch point is where the cable leaves the profile.
    """

    pitch: np.ndarray
    groove: np.ndarray
    flange: np.ndarray
    axle_diameter: float
    link_angle: np.ndarray


def _profile_of(design: Design, spring: int) -> NoncircularProfile:
    instance_of("design", design, Design, "a balancelab Design")
    if not design.springs:
        raise ValueError(f"{design.name} has no spring, so it has no non-circular pulley to export")
    spring = positive_int("spring", spring, 0, len(design.springs) - 1)
    prof = design.springs[spring].cable
    if not isinstance(prof, NoncircularProfile):
        raise ValueError(f"{design.name}: spring {spring} is not wound on a non-circular pulley "
                         "(build one with realize.noncircular_pulley)")
    return prof


def _size(name: str, value) -> float:
    """A part dimension (m): positive and below half a metre."""
    value = finite_real(f"{name} (m)", value, positive=True)
    if value > 0.5:
        raise ValueError(f"{name} must be below 0.5 m (a pulley's part), got {value} m")
    return value


def _hull(points: np.ndarray) -> np.ndarray:
    from scipy.spatial import ConvexHull

    return points[ConvexHull(points).vertices]


def _closed(arc: np.ndarray, hub: float) -> np.ndarray:
    t = np.linspace(0, 2 * math.pi, 181)[:-1]
    return _hull(np.concatenate([arc, hub * np.stack([np.cos(t), np.sin(t)], -1)]))


def _even_in_arc_length(prof: NoncircularProfile, n: int) -> np.ndarray:
    """Profile parameters of ``n`` points evenly spaced along the curve (in the order of growing psi)."""
    dense = np.linspace(-1.0, 1.0, 4 * n + 1)
    s = prof.arc_length(dense)
    if s[-1] < s[0]:
        dense, s = dense[::-1], s[::-1]
    return np.interp(np.linspace(s[0], s[-1], n), s, dense)


def _lower_tension(design: Design, spring: int, prof: NoncircularProfile, x, h, need: float) -> float:
    """The largest ``min_tension`` (N) whose profile keeps every cable line ``need`` from the pivot.

    The torque ``T h`` is fixed by the load; lowering the smallest tension by ``dm`` (``T^2`` drops
    by the same ``m^2 - m'^2`` everywhere) scales ``h`` by ``T / T'``.
    """
    s, p = design.springs[spring], design.parameters
    theta = prof.mid + prof.half * x
    tension = s.k * (prof.cable(theta).path - prof.cable_length - s.free_length)
    m2 = float(np.min((tension * h / need) ** 2 - tension ** 2)) + p.get("min_tension", float(tension.min())) ** 2
    return math.sqrt(m2) if m2 > 0 else 0.0


def _check_room(design: Design, spring: int, prof: NoncircularProfile, x, h, need: float) -> None:
    """ValueError unless the axle's boss and half the cable fit inside every cable line."""
    i = int(np.argmin(h))
    at = math.degrees(prof.mid + prof.half * x[i])
    if h[i] <= 0:
        raise ValueError(f"the pivot lies outside the profile: at link angle {at:.2f}° the cable's line passes "
                         f"{1000 * -h[i]:.3g} mm beyond the pivot, so no axle at the pivot can sit inside this "
                         "part; re-synthesize with the other turn, another eyelet or min_tension")
    if h[i] - need > 0:
        return
    m = _lower_tension(design, spring, prof, x, h, need)
    f_i = design.parameters.get("initial_tension", 0.0)
    hint = (f"re-synthesize with min_tension at most {math.floor(100 * m) / 100:.2f} N (a lower tension moves the cable's line away "
            "from the pivot)" if m > f_i else "a lower min_tension cannot help (the spring's initial tension "
            f"{f_i:.4g} N is the floor): move the eyelet")
    raise ValueError(f"the axle's boss and half the cable ({1000 * need:.3g} mm from the pivot) reach "
                     f"{1000 * (need - h[i]):.3g} mm into the cable's groove at link angle {at:.2f}°: use a smaller "
                     f"axle_diameter, boss or cable_diameter, or {hint}")


def profile_part(design: Design, spring: int = 0, *, n: int = 2000, axle_diameter: float = 0.008,
                 cable_diameter: float = 0.0015, flange: float = 0.004, boss: float = 0.004) -> ProfilePart:
    """The outlines of the non-circular pulley of ``design``'s spring ``spring``, ready to cut.

    Parameters
    ----------
    design : Design
        From :func:`balancelab.realize.noncircular_pulley`.
    spring : int
        Index of the spring wound on the profile.
    n : int
        Points on the pitch curve, >= 10, evenly spaced along it.
    axle_diameter : float
        Diameter of the axle hole (m), > 0.
    cable_diameter : float
        The cable's diameter (m), > 0: the groove is its radius deep below the pitch curve.
    flange : float
        Height of the flanges above the pitch curve (m), > 0.
    boss : float
        Material kept round the axle hole (m), > 0.

    Returns
    -------
    ProfilePart

    Raises
    ------
    ValueError
        When the axle's boss would reach the groove (the cable would run on the boss): the
        message says by how much.

    Examples
    --------
    >>> import math, balancelab as bl
    >>> from balancelab.methods.practice.springs import ExtensionSpring
    >>> lever = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> d = bl.realize.noncircular_pulley(lever, spring_model=ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0),
    ...                                   angle_range=(-math.pi / 3, math.pi / 3), min_tension=45.0)
    >>> part = profile_part(d, n=500)
    >>> part.pitch.shape, part.groove.shape[1]
    ((500, 2), 2)
    """
    prof = _profile_of(design, spring)
    n = positive_int("n (points on the pitch curve, at least 10)", n, minimum=10)
    axle, cable, flange, boss = (_size(name, v) for name, v in (("axle_diameter", axle_diameter),
                                 ("cable_diameter", cable_diameter), ("flange", flange), ("boss", boss)))
    x = _even_in_arc_length(prof, n)
    pitch, normal = prof.local_points(x), prof.normals(x)
    h = np.sum(pitch * normal, -1)            # distance of each tangent line from the pivot
    hub = axle / 2 + boss
    _check_room(design, spring, prof, x, h, hub + cable / 2)
    groove = _closed(pitch - cable / 2 * normal, hub)
    # the flange covers the groove past both ends of the pitch curve by its height, and the core plate
    tangent = np.stack([-normal[:, 1], normal[:, 0]], -1)
    caps = np.concatenate([pitch[[0, -1]] + flange * (normal[[0, -1]] + sign * tangent[[0, -1]])
                           for sign in (-1.0, 1.0)] + [pitch[[0, -1]] - cable / 2 * normal[[0, -1]]
                                                       + sign * flange * tangent[[0, -1]] for sign in (-1.0, 1.0)])
    outer = _closed(np.concatenate([pitch + flange * normal, caps, groove]), hub)
    return ProfilePart(pitch, groove, outer, axle, prof.mid + prof.half * x)


def _svg(part: ProfilePart, path: Path) -> None:
    mm = 1000.0
    allp = np.concatenate([part.flange, part.pitch]) * mm
    lo, hi = allp.min(0) - 5, allp.max(0) + 5
    w, h = hi - lo

    def d(points, closed):
        body = " ".join(f"{x:.{DIGITS}f},{-y:.{DIGITS}f}" for x, y in points * mm)
        return f"M {body}" + (" Z" if closed else "")

    r = part.axle_diameter / 2 * mm
    lines = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:.4f}mm" height="{h:.4f}mm" '
             f'viewBox="{lo[0]:.4f} {-hi[1]:.4f} {w:.4f} {h:.4f}">',
             "<title>non-circular pulley (balancelab), mm, link frame: x along the link, y up</title>",
             f'<path id="flange" d="{d(part.flange, True)}" fill="none" stroke="blue" stroke-width="0.1"/>',
             f'<path id="groove" d="{d(part.groove, True)}" fill="none" stroke="red" stroke-width="0.1"/>',
             f'<path id="pitch" d="{d(part.pitch, False)}" fill="none" stroke="green" stroke-width="0.1" '
             'stroke-dasharray="1 1"/>',
             f'<circle id="axle" cx="0" cy="0" r="{r:.4f}" fill="none" stroke="red" stroke-width="0.1"/>',
             f'<path id="mark" d="M {r + 1:.4f},0 L {r + 4:.4f},0" stroke="black" stroke-width="0.2"/>',
             "</svg>"]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def _dxf(part: ProfilePart, path: Path) -> None:
    try:
        import ezdxf
    except ImportError:   # pragma: no cover - the cad extra is part of the test set-up
        raise ImportError("DXF export needs ezdxf: pip install 'balancelab[cad]'") from None
    doc = ezdxf.new("R2010", units=4)    # millimetres
    for name, colour in _LAYERS.items():
        doc.layers.add(name.upper(), color=colour)
    msp = doc.modelspace()
    mm = 1000.0
    msp.add_lwpolyline((part.flange * mm).tolist(), close=True, dxfattribs={"layer": "FLANGE"})
    msp.add_lwpolyline((part.groove * mm).tolist(), close=True, dxfattribs={"layer": "GROOVE"})
    msp.add_lwpolyline((part.pitch * mm).tolist(), close=False, dxfattribs={"layer": "PITCH"})
    r = part.axle_diameter / 2 * mm
    msp.add_circle((0.0, 0.0), r, dxfattribs={"layer": "AXLE"})
    msp.add_line((r + 1, 0.0), (r + 4, 0.0), dxfattribs={"layer": "MARK"})
    doc.saveas(path)


def _csv(part: ProfilePart, path: Path) -> None:
    with path.open("w", newline="", encoding="utf-8") as f:
        f.write("# balancelab non-circular pulley: the cable's centre line (pitch curve) in the link frame, "
                f"mm (x along the link, origin at the pivot); axle diameter {1000 * part.axle_diameter:.4f} mm\n")
        w = csv.writer(f)
        w.writerow(["link_angle_deg", "x_mm", "y_mm"])
        for a, (x, y) in zip(np.degrees(part.link_angle), part.pitch * 1000.0):
            w.writerow([f"{a:.6f}", f"{x:.{DIGITS}f}", f"{y:.{DIGITS}f}"])


def _verified_part(design: Design, spring: int, n, tolerance: float, options: dict) -> tuple[ProfilePart, float]:
    """The part with enough points that the cable on its polyline keeps the balance bound, and its variation.

    ``n`` given: that many points or a ValueError naming ``n``; ``None``: from 2,000 points up, the
    variation falling as ``1/n^2`` (:mod:`.profile_check`), at most :data:`MAX_POINTS`.
    """
    count = 2000 if n is None else positive_int("n (points on the pitch curve, at least 10)", n, minimum=10)
    for _ in range(6):
        part = profile_part(design, spring, n=count, **options)
        variation = polyline_variation(design, spring, np.round(part.pitch * 1000.0, DIGITS) / 1000.0)
        if variation <= tolerance:
            return part, variation
        needed = int(math.ceil(count * math.sqrt(variation / tolerance) * 1.15 / 100.0)) * 100
        if n is not None or needed > MAX_POINTS:
            break
        count = max(needed, count + 100)
    advice = (f"about {needed} points would (n={needed}, or n=None to let the export choose)" if needed <= MAX_POINTS
              else f"about {needed} would, more than the {MAX_POINTS} an export writes")
    raise ValueError(f"n={count} points on the pitch curve: the cable wound on them varies the energy by "
                     f"{variation:.3g} of what the load exchanges, above the bound tolerance={tolerance:.3g}; "
                     f"{advice}; or pass a looser tolerance")


def export_profile(design: Design, path, spring: int = 0, *, n: int | None = None,
                   tolerance: float = BALANCE_TOLERANCE, **options) -> Path:
    """Write the non-circular pulley of ``design`` to ``path`` (.svg, .dxf or .csv) at true scale, in mm.

    Before writing, the part is checked as cut: the cable is wound on the *polyline* to be
    written, as rounded in the file (tangent vertex from the eyelet, chords to the clamp;
    :mod:`.profile_check`, not the profile's series), and the energy of the design with that cable must vary by at most
    ``tolerance`` of what the rest of the design exchanges over the profile's range.

    Parameters
    ----------
    design : Design
        From :func:`balancelab.realize.noncircular_pulley`.
    path : str or pathlib.Path
        The file to write; its suffix chooses the format: ``.svg`` (flange blue, groove and
        axle red, pitch curve green dashed), ``.dxf`` (layers FLANGE, GROOVE, PITCH, AXLE, MARK)
        or ``.csv`` (the pitch curve, one point a row, with the link angle it serves).
    spring : int
        Index of the spring wound on the profile.
    n : int, optional
        Points on the pitch curve, >= 10; too few for ``tolerance`` is a ValueError that names
        ``n`` and about how many would do. By default as many as the bound needs, from 2,000 up
        (the error falls as ``1/n^2``; at most 200,000).
    tolerance : float
        The bound, ``0 < tolerance < 1``: by default the balance bound of
        :meth:`balancelab.Design.balance_report` (1e-9), which takes some tens of thousands of
        points. A part cut to 0.01 mm cannot hold that (the cut shifts the cable's path by about
        as much); pass the variation you can accept, e.g. ``1e-6``, for fewer points.
    **options
        Passed to :func:`profile_part` (``axle_diameter``, ``cable_diameter``, ``flange``, ``boss``).

    Returns
    -------
    pathlib.Path

    Raises
    ------
    ValueError
        When the polyline does not keep the bound (naming ``n``), or as :func:`profile_part`.

    Examples
    --------
    >>> import math, tempfile, pathlib, balancelab as bl
    >>> from balancelab.methods.practice.springs import ExtensionSpring
    >>> lever = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> d = bl.realize.noncircular_pulley(lever, spring_model=ExtensionSpring(3e-3, 24e-3, 60, initial_tension=40.0),
    ...                                   angle_range=(-math.pi / 3, math.pi / 3), min_tension=45.0)
    >>> with tempfile.TemporaryDirectory() as tmp:
    ...     out = export_profile(d, pathlib.Path(tmp) / "pulley.csv", n=1000, tolerance=1e-6)
    ...     len(out.read_text().splitlines())
    1002
    """
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path must be a file name (str or pathlib.Path), got {type(path).__name__}")
    path = Path(path)
    writers = {".svg": _svg, ".dxf": _dxf, ".csv": _csv}
    if path.suffix.lower() not in writers:
        raise ValueError(f"path must end in .svg, .dxf or .csv, got {path.name!r}")
    tolerance = finite_real("tolerance (relative energy variation)", tolerance, positive=True)
    if tolerance >= 1:
        raise ValueError(f"tolerance (relative energy variation) must be in (0, 1), got {tolerance}")
    _profile_of(design, spring)
    part, _ = _verified_part(design, spring, n, tolerance, options)
    writers[path.suffix.lower()](part, path)
    return path
