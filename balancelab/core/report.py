"""The verdict of a design: its energy over many configurations, and whether it is balanced.

:func:`balance_report` is what :meth:`balancelab.Design.balance_report` computes; the
:class:`BalanceReport` it returns and the :class:`Energy` triple of
:meth:`balancelab.Design.potential_energy` live here too. Layer: core.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

__all__ = ["BALANCE_TOLERANCE", "Energy", "BalanceReport", "balance_report"]

#: Relative tolerance below which a design is reported balanced: the spread of its total
#: potential energy over the sampled configurations, divided by the energy scale.
BALANCE_TOLERANCE: float = 1e-9


class Energy(NamedTuple):
    """Potential energy (J): ``total = load + spring``, each of the shape of the configurations."""

    total: np.ndarray
    load: np.ndarray
    spring: np.ndarray


@dataclass(frozen=True)
class BalanceReport:
    """How well a design is balanced over a set of configurations.

    Attributes
    ----------
    variation : float
        ``(max V - min V) / scale`` over the configurations: 0 for a perfect balance.
    residual : float
        Largest generalized force ``|dV/dq|`` (J/rad) divided by ``scale`` (1/rad).
    scale : float
        Energy scale (J): the sum over every load and spring of the spread of its own
        energy over the configurations. It does not depend on where the origin is.
    energy : float
        Mean total potential energy (J).
    worst_q : numpy.ndarray
        Configuration with the largest residual generalized force.
    balanced : bool
        ``variation <= tolerance``.
    tolerance : float
        The tolerance used (default :data:`BALANCE_TOLERANCE`).
    n : int
        Number of configurations examined.
    """

    variation: float
    residual: float
    scale: float
    energy: float
    worst_q: np.ndarray
    balanced: bool
    tolerance: float
    n: int

    def __str__(self) -> str:
        verdict = "balanced" if self.balanced else "NOT balanced"
        q = ", ".join(f"{np.degrees(v):.1f}°" for v in np.atleast_1d(self.worst_q))
        return (f"{verdict}: energy varies by {self.variation:.2e} of its scale "
                f"({self.scale:.4g} J) over {self.n} configurations; "
                f"largest residual dV/dq = {self.residual:.2e} × scale per rad at q = ({q}); "
                f"mean energy {self.energy:.6g} J")


def balance_report(design, q=None, *, n: int = 1000, seed: int | None = 0,
                   tolerance: float = BALANCE_TOLERANCE) -> BalanceReport:
    """The :class:`BalanceReport` of ``design`` (see :meth:`balancelab.Design.balance_report`).

    Examples
    --------
    >>> import balancelab as bl
    >>> balance_report(bl.singh.lacoste_lever(10.0, 0.5, 0.2, 0.3)).balanced
    True
    """
    q = design.sample(n, seed) if q is None else design.check_q(q).reshape(-1, design.dof)
    vl, vs = design.element_energies(q)
    total = vl.sum(-1) + vs.sum(-1)
    scale = float(np.sum(np.ptp(vl, axis=0)) + np.sum(np.ptp(vs, axis=0))) if len(q) else 0.0
    if scale == 0.0:
        scale = float(np.max(np.abs(total))) if total.size else 0.0
    if scale == 0.0:
        raise ValueError(f"{design.name}: nothing in this design stores energy as it moves, "
                         "so there is nothing to balance")
    variation = float(np.ptp(total)) / scale
    gf = design.generalized_force(q)
    mag = np.max(np.abs(gf), axis=-1)
    worst = int(np.argmax(mag))
    return BalanceReport(variation=variation, residual=float(mag[worst]) / scale, scale=scale,
                         energy=float(np.mean(total)), worst_q=q[worst].copy(),
                         balanced=bool(variation <= tolerance), tolerance=tolerance, n=len(q))

