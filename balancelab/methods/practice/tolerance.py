"""Tolerances: how far off is a built balancer? A vectorized Monte Carlo and its sensitivities.

Every built spring, anchor and mass differs a little from the drawing. Given tolerances,
:func:`monte_carlo` draws ``n`` built designs at once (normal errors with the given
standard deviations, or uniform within the given half-widths), evaluates the residual
generalized force ``dV/dq`` of all of them on a set of configurations in one vectorized
pass (:func:`balancelab.methods.practice.forces.batch_generalized_force`) and returns,
for each built design, the worst residual over the range. :func:`sensitivities` runs it
once per group of parameters to say which tolerance matters most.

Closed-form check (the tests use it): for the lecture's link with a ZFL spring whose
rate is off by a fraction ``e``, ``dV/dtheta = -e m g r cos(theta)``, so the worst
residual over ``[-90 deg, 90 deg]`` is ``|e| m g r``. The same holds for a real spring whose
cable wraps a non-circular pulley (its tension is ``1 + e`` times the one that balances);
there ``attachment`` moves the eyelet (the tangent point follows) and the cable's clamp
(the cable then ends that much farther along the profile), see
:func:`balancelab.methods.practice.forces.batch_generalized_force`. Layer: methods.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ...core.design import Design
from ...core.validation import finite_real, positive_int
from .forces import batch_generalized_force, configurations

__all__ = ["Tolerances", "MonteCarloResult", "monte_carlo", "sensitivities"]


class _TolerancesFields(NamedTuple):
    k: float = 0.0
    free_length: float = 0.0
    attachment: float = 0.0
    mass: float = 0.0


class Tolerances(_TolerancesFields):
    """Tolerances of a built design (standard deviations, or half-widths for ``uniform``).

    ``k``: relative error of every spring rate (0.05 = 5 %); ``free_length``: absolute
    error of every free length (m); ``attachment``: absolute error of each coordinate of
    every spring end (m; for a cable on a non-circular pulley, its eyelet and its clamp); ``mass``: relative error of every load (a mass error). Each
    must be finite and >= 0 (checked on construction).

    Examples
    --------
    >>> Tolerances(k=0.03).k
    0.03
    """

    __slots__ = ()

    def __new__(cls, k: float = 0.0, free_length: float = 0.0, attachment: float = 0.0, mass: float = 0.0):
        values = {name: finite_real(f"tolerance {name} (>= 0)", v, nonnegative=True)
                  for name, v in zip(_TolerancesFields._fields, (k, free_length, attachment, mass))}
        return super().__new__(cls, **values)


class MonteCarloResult(NamedTuple):
    """Result of :func:`monte_carlo`.

    ``worst`` (n,): largest ``|dV/dq_i|`` over configurations and coordinates of each built
    design (N m per rad); ``worst_per_coordinate`` (n, dof); ``q`` (m, dof) the configurations
    used; ``samples``: the drawn parameter arrays (``k``, ``free_length``, ``a_points``,
    ``b_points``, ``load_scale``).
    """

    worst: np.ndarray
    worst_per_coordinate: np.ndarray
    q: np.ndarray
    samples: dict

    def quantile(self, p: float) -> float:
        """The ``p``-quantile (0..1) of the worst residual: 95 % of built designs stay below ``quantile(0.95)``."""
        p = finite_real("p (quantile)", p)
        if not 0 <= p <= 1:
            raise ValueError(f"p (quantile) must be in [0, 1], got {p}")
        return float(np.quantile(self.worst, p))


def _tolerances(tolerances) -> Tolerances:
    if isinstance(tolerances, dict):
        unknown = set(tolerances) - set(Tolerances._fields)
        if unknown:
            raise ValueError(f"unknown tolerances {sorted(unknown)}; valid: {Tolerances._fields}")
        tolerances = Tolerances(**tolerances)
    if not isinstance(tolerances, Tolerances):
        raise TypeError(f"tolerances must be a Tolerances or a dict, got {type(tolerances).__name__}")
    for name, v in tolerances._asdict().items():
        finite_real(f"tolerance {name}", v, nonnegative=True)
    return tolerances


def _draw(design: Design, tol: Tolerances, n: int, rng, distribution: str) -> dict:
    def noise(shape, scale):
        if scale == 0:
            return np.zeros(shape)
        if distribution == "normal":
            return rng.normal(0.0, scale, shape)
        return rng.uniform(-scale, scale, shape)

    ns, nl = len(design.springs), len(design.loads)
    k = np.array([s.k for s in design.springs])
    l0 = np.array([s.free_length for s in design.springs])
    a = np.array([s.a.point for s in design.springs]).reshape(-1, 2)
    b = np.array([s.b.point for s in design.springs]).reshape(-1, 2)
    return {"k": k * (1 + noise((n, ns), tol.k)), "free_length": l0 + noise((n, ns), tol.free_length),
            "a_points": a + noise((n, ns, 2), tol.attachment), "b_points": b + noise((n, ns, 2), tol.attachment),
            "load_scale": 1 + noise((n, nl), tol.mass)}


def monte_carlo(design: Design, tolerances, n: int = 10_000, *, q=None, grid: int = 25, seed: int | None = 0,
                distribution: str = "normal", chunk: int = 2500) -> MonteCarloResult:
    """Worst residual generalized force of ``n`` built copies of ``design``.

    Parameters
    ----------
    design : Design
        The nominal (usually balanced) design.
    tolerances : Tolerances or dict
        See :class:`Tolerances`; all >= 0.
    n : int
        Number of built designs, >= 1.
    q : array_like, shape (m, dof), optional
        Configurations (rad); by default ``grid`` points per coordinate over the range.
    grid : int
        Points per coordinate when ``q`` is not given, >= 2.
    seed : int or None
        Seed of the random generator.
    distribution : {"normal", "uniform"}
        Tolerances are standard deviations, or half-widths of uniform errors.
    chunk : int
        Built designs evaluated at once (memory).

    Returns
    -------
    MonteCarloResult

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> r = monte_carlo(d, Tolerances(k=0.05), n=2000, grid=31)
    >>> bool(abs(r.quantile(0.5) / (0.05 * 2.0 * 9.81 * 0.5) - 0.674) < 0.05)   # median of |N(0, 1)|
    True
    """
    tol = _tolerances(tolerances)
    n = positive_int("n (built designs)", n)
    chunk = positive_int("chunk", chunk)
    if distribution not in ("normal", "uniform"):
        raise ValueError(f"distribution must be 'normal' or 'uniform', got {distribution!r}")
    q = configurations(design, q, grid)
    samples = _draw(design, tol, n, np.random.default_rng(seed), distribution)
    per = np.empty((n, design.dof))
    for start in range(0, n, chunk):
        part = {key: v[start:start + chunk] for key, v in samples.items()}
        Q = batch_generalized_force(design, q, **part)
        per[start:start + chunk] = np.maximum(Q.max(axis=1), -Q.min(axis=1))
    return MonteCarloResult(per.max(axis=1), per, q, samples)


def sensitivities(design: Design, tolerances, n: int = 4000, p: float = 0.95, **kwargs) -> dict:
    """Which tolerance matters most: the ``p``-quantile of the worst residual with one group at a time.

    Parameters
    ----------
    design : Design
    tolerances : Tolerances or dict
    n : int
        Built designs per group.
    p : float
        Quantile (0..1).
    **kwargs
        Passed to :func:`monte_carlo` (``q``, ``grid``, ``seed``, ``distribution``).

    Returns
    -------
    dict
        ``"all"`` (every tolerance at once) first, then each group name -> ``p``-quantile
        of the worst residual (N m per rad) with only that group's tolerance, from the
        largest to the smallest.

    Examples
    --------
    >>> import balancelab as bl
    >>> d = bl.lecture.single_link_spring(2.0, 0.5, 0.3, 0.2)
    >>> s = sensitivities(d, Tolerances(k=0.05, mass=0.01), n=500)
    >>> list(s)[:2]
    ['all', 'k']
    """
    tol = _tolerances(tolerances)
    groups = {}
    for name, value in tol._asdict().items():
        if value > 0:
            groups[name] = monte_carlo(design, Tolerances(**{name: value}), n, **kwargs).quantile(p)
    return {"all": monte_carlo(design, tol, n, **kwargs).quantile(p),
            **dict(sorted(groups.items(), key=lambda kv: -kv[1]))}
