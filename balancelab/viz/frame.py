"""What every figure shares: the style, the checks of its inputs, configuration grids, fast rendering.

* :data:`PALETTE` and :data:`STYLE`: the colour-blind-safe Okabe-Ito palette and the
  role each colour plays in every figure of the course.
* :func:`check_design`, :func:`as_config`, :func:`count`: the input checks of the
  figures (a ``TypeError`` or ``ValueError`` naming the parameter).
* :func:`default_q` and :func:`range_grid`: the configurations a figure shows.
* :func:`new_axes` and :func:`tex_label`: Axes and axis labels.
* :class:`Blitter`: off-screen rendering of a figure whose only changes are known
  artists (animations and explorers).

Layer: viz; imports ``balancelab.core`` and matplotlib (lazily).
"""
from __future__ import annotations

import math
import re
from typing import Callable

import numpy as np

from ..core.design import Design
from ..core.validation import positive_int
from ..core.report import q_units

__all__ = ["PALETTE", "STYLE", "Blitter", "angle_label", "as_config", "check_design", "count", "default_q",
           "new_axes", "range_grid", "tex_label"]

#: Okabe-Ito colour-blind-safe palette (Okabe & Ito 2008), by name.
PALETTE = {
    "black": "#000000",
    "orange": "#E69F00",
    "sky": "#56B4E9",
    "green": "#009E73",
    "yellow": "#F0E442",
    "blue": "#0072B2",
    "vermillion": "#D55E00",
    "purple": "#CC79A7",
    "grey": "#7F7F7F",
}

#: The role each colour plays in every figure of the course.
STYLE = {
    "link": PALETTE["blue"],
    "ground": PALETTE["grey"],
    "zfl": PALETTE["vermillion"],
    "spring": PALETTE["purple"],
    "string": PALETTE["black"],
    "load": PALETTE["green"],
    "counterweight": PALETTE["orange"],
    "total": PALETTE["black"],
    "label": PALETTE["black"],
}


def check_design(design) -> Design:
    """``design`` itself if it is a :class:`balancelab.Design`, else a ``TypeError``.

    Parameters
    ----------
    design : Design

    Returns
    -------
    Design

    Examples
    --------
    >>> check_design("lever")
    Traceback (most recent call last):
    ...
    TypeError: design must be a balancelab.Design, got str
    """
    if not isinstance(design, Design):
        raise TypeError(f"design must be a balancelab.Design, got {type(design).__name__}")
    return design


def default_q(design: Design) -> np.ndarray:
    """A representative reachable configuration of ``design`` (rad), shape ``(dof,)``.

    Three fifths of the way through each coordinate's range when that is reachable,
    otherwise the first sampled reachable configuration.

    Parameters
    ----------
    design : Design

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)
    >>> round(float(np.degrees(default_q(d)[0])), 1)
    36.0
    """
    check_design(design)
    lo, hi = design.q_range[:, 0], design.q_range[:, 1]
    q = lo + 0.6 * (hi - lo)
    if bool(design.reachable(q)):
        return q
    return design.sample(1, seed=0)[0]


def count(name: str, n, minimum: int = 2) -> int:
    """``n`` as an int >= ``minimum``, or a ``ValueError`` naming ``name``.

    Parameters
    ----------
    name : str
        The parameter's name, for the message.
    n : int
        The number to check (a bool or a float is refused).
    minimum : int
        Smallest valid value.

    Returns
    -------
    int

    Examples
    --------
    >>> count("n", 5)
    5
    >>> count("n", 2.5)
    Traceback (most recent call last):
    ...
    TypeError: n must be an integer >= 2, got 2.5
    """
    return positive_int(name, n, minimum)


def as_config(design: Design, q) -> np.ndarray:
    """``q`` as one configuration (rad) of ``design``, shape ``(dof,)``; :func:`default_q` for None.

    Parameters
    ----------
    design : Design
    q : array_like or None
        One angle per coordinate (rad).

    Returns
    -------
    numpy.ndarray

    Raises
    ------
    ValueError
        If ``q`` does not hold one angle per coordinate.

    Examples
    --------
    >>> import balancelab as bl
    >>> as_config(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3), 0.5)
    array([0.5])
    """
    if q is None:
        return default_q(design)
    q = np.asarray(q, dtype=float).reshape(-1)
    if q.shape != (design.dof,):
        raise ValueError(f"q must hold {design.dof} angle(s) (rad) for the coordinates "
                         f"{design.q_names}, got shape {q.shape}")
    return q


def range_grid(design: Design, n: int) -> np.ndarray:
    """Configurations (rad) spread over the range: a line for 1 dof, a grid for 2, samples beyond.

    Parameters
    ----------
    design : Design
    n : int
        Number of configurations (for 2 dof, about ``n``: a square grid).

    Returns
    -------
    numpy.ndarray, shape (m, dof)
        Not all of them need be reachable.

    Examples
    --------
    >>> import balancelab as bl
    >>> range_grid(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3), 3)[:, 0].round(4).tolist()
    [-3.1416, 0.0, 3.1416]
    """
    lo, hi = design.q_range[:, 0], design.q_range[:, 1]
    if design.dof == 1:
        return np.linspace(lo[0], hi[0], n)[:, None]
    if design.dof == 2:
        m = max(2, int(round(math.sqrt(n))))
        a, b = np.meshgrid(np.linspace(lo[0], hi[0], m), np.linspace(lo[1], hi[1], m))
        return np.stack([a.ravel(), b.ravel()], axis=-1)
    return design.sample(n, seed=0)


def new_axes(ax=None, figsize=(5.0, 4.0)):
    """``ax``, or the Axes of a new figure of size ``figsize`` (inches).

    Parameters
    ----------
    ax : matplotlib.axes.Axes, optional
    figsize : (float, float)

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> new_axes(figsize=(3.0, 2.0)).figure.get_size_inches().tolist()
    [3.0, 2.0]
    """
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt

    _, ax = plt.subplots(figsize=figsize, layout="constrained")
    return ax


_GREEK = {"alpha", "beta", "gamma", "delta", "theta", "phi", "psi", "varphi", "chi", "eta", "mu", "nu",
          "rho", "sigma", "tau", "omega", "xi", "zeta", "lambda", "kappa", "epsilon"}


def tex_label(name: str) -> str:
    """A name as mathtext: ``a1`` -> ``$a_{1}$``, ``k_b`` -> ``$k_{b}$``, ``theta_2`` -> ``$\\theta_{2}$``.

    Names that are not a symbol with an optional subscript are returned unchanged.

    Parameters
    ----------
    name : str

    Returns
    -------
    str

    Examples
    --------
    >>> tex_label("theta_2"), tex_label("a1"), tex_label("spring 1")
    ('$\\\\theta_{2}$', '$a_{1}$', 'spring 1')
    """
    m = re.fullmatch(r"([A-Za-z]+?)_?(\d+|(?<=_)[A-Za-z]\w*)?", name)
    if not m:
        return name
    base, sub = m.group(1), m.group(2)
    if base in _GREEK:
        base = "\\" + base
    elif len(base) > 1:
        return name
    if sub:
        return f"${base}_{{{sub}}}$"
    return f"${base}$" if (base.startswith("\\") or base.islower()) else name


def angle_label(design: Design, i: int = 0) -> str:
    """Axis label of coordinate ``i``: its symbol, what it measures (when known) and the unit.

    Parameters
    ----------
    design : Design
    i : int
        Index of the coordinate.

    Returns
    -------
    str

    Examples
    --------
    >>> import balancelab as bl
    >>> print(angle_label(bl.catalog()["singh_fourbar"]()))
    $\\theta$, crank angle from the x-axis (deg)
    """
    unit = "deg" if q_units(design)[i] == "rad" else "m"
    words = design.kinematics.describe()[i]
    words = words[: -len(f" ({unit})")] if words.endswith(f" ({unit})") else words
    return f"{tex_label(design.q_names[i])}, {words} ({unit})" if words else f"{tex_label(design.q_names[i])} ({unit})"


class Blitter:
    """Render a figure whose only changes are a known set of artists, off screen (Agg).

    The figure without the changing artists is drawn once and kept; each frame restores
    that background and draws the changing artists over it. A full redraw happens on
    request (limits or colour scales changed) or when the set of artists changes.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        A figure with an Agg canvas.
    dynamic : callable
        ``dynamic()`` returns the list of artists that change.

    Attributes
    ----------
    full_draws : int
        Number of full redraws so far.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> from matplotlib.backends.backend_agg import FigureCanvasAgg
    >>> fig = Figure(figsize=(2, 1), dpi=50); _ = FigureCanvasAgg(fig)
    >>> line, = fig.subplots().plot([0, 1], [0, 1])
    >>> b = Blitter(fig, lambda: [line])
    >>> b.render().shape, b.render().shape, b.full_draws
    ((50, 100, 3), (50, 100, 3), 1)
    """

    def __init__(self, fig, dynamic: Callable[[], list]) -> None:
        self.fig = fig
        self.dynamic = dynamic
        self._bg = None
        self._ids: list = []
        self.full_draws = 0

    def invalidate(self) -> None:
        """Redraw the whole figure at the next :meth:`render`."""
        self._bg = None

    def render(self, full: bool = False) -> np.ndarray:
        """Return the figure's pixels, shape (h, w, 3) uint8 (a view of the canvas buffer)."""
        canvas = self.fig.canvas
        dyn = self.dynamic()
        ids = [id(a) for a in dyn]
        if full or self._bg is None or ids != self._ids:
            vis = [a.get_visible() for a in dyn]
            for a in dyn:
                a.set_visible(False)
            try:
                canvas.draw()
                self._bg = canvas.copy_from_bbox(self.fig.bbox)
            finally:
                for a, v in zip(dyn, vis):
                    a.set_visible(v)
            self._ids = ids
            self.full_draws += 1
        else:
            canvas.restore_region(self._bg)
        renderer = canvas.get_renderer()
        for a in sorted(dyn, key=lambda a: a.get_zorder()):
            if a.get_visible():
                a.draw(renderer)
        return np.asarray(canvas.buffer_rgba())[..., :3]
