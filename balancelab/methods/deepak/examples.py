"""The worked examples of Deepak & Ananthasuresh (2012), declared in the registry.

:func:`example_fourbar` is the crank-rocker every four-bar example uses, loaded by a
ZFL spring ``k_l = 100 N/m`` from ``K = (0.1, -0.2)`` m (an assumed geometry: the
paper's figures carry no dimensions). The examples are registered here, in course
order: the loaded four-bar, the building blocks, techniques 1-3, Herder's, the Watt
prototype, the gravity four-bar and the three balanced cognates. Layer: methods.
"""
from __future__ import annotations

from ...core.design import Design
from ...mechanisms.fourbar import PIVOTS, FourBar
from ..registry import register
from .blocks import balanced_parallelogram, balanced_plagiograph, basic_balancer, composed_springs_lever
from .cognate_balance import balance_cognates
from .gravity import gravity_technique2
from .technique1 import technique1
from .techniques import herder, spring_loaded_fourbar, technique2, technique3
from .watt import watt_prototype

__all__ = ["example_fourbar"]


def example_fourbar() -> FourBar:
    """A crank-rocker used by the worked examples (Grashof, crank turns fully).

    Returns
    -------
    FourBar
        ``A = (0, 0)``, ``B = (0.4, 0)``, crank 0.1 m, coupler 0.35 m, rocker 0.3 m,
        ``E = (0.2, 0.12)`` in the coupler frame (an assumed geometry: the paper's
        figures carry no dimensions).

    Examples
    --------
    >>> example_fourbar().crank
    0.1
    """
    return FourBar((0.0, 0.0), (0.4, 0.0), 0.1, 0.35, 0.3, (0.2, 0.12))


def _on_example_fourbar(method, *args) -> Design:
    """``method`` applied to :func:`example_fourbar` with the load spring ``k_l = 100 N/m`` from
    ``K = (0.1, -0.2)`` m (an assumed geometry)."""
    return method(example_fourbar(), (0.1, -0.2), 100.0, *args)


def _gravity_example() -> Design:
    return gravity_technique2(example_fourbar(), 2.0, 400.0, "A")


def _cognate_example(i: int) -> Design:
    """Cognate ``i`` of the example four-bar with the load spring ``k_l = 100 N/m`` from
    ``K = (0.1, -0.2)``, balanced by technique 2 based at its first pivot (``lambda = 0.1``)."""
    return balance_cognates(example_fourbar(), (0.1, -0.2), 100.0, 2, "A", "A", 0.1)[i]


def _reg(name: str, title: str, factory, *args, **kw) -> None:
    """Register a chapter-5 example; every call sorts by the order of registration."""
    register(name, title, factory, chapter=5, args=args, **kw)


def _register_examples() -> None:
    T = "(Deepak & Ananthasuresh 2012)"
    _reg("deepak_spring_loaded_fourbar", f"A spring-loaded four-bar before balancing {T}",
         _on_example_fourbar, spring_loaded_fourbar, expected_balanced=False)
    _reg("deepak_basic_balancer", "Basic spring force balancer (Deepak & Ananthasuresh, Fig. 4)",
         basic_balancer, 50.0, 0.3, 0.2)
    _reg("deepak_balanced_parallelogram", "Balanced parallelogram (Deepak & Ananthasuresh, Figs 6-7)",
         balanced_parallelogram, 40.0, 0.2, 0.3, kwargs={"dof": 2})
    _reg("deepak_composed_springs", "Two ZFL springs composed into one (Deepak & Ananthasuresh, Sec. 2.1.1)",
         composed_springs_lever, 30.0, (0.05, 0.2), 10.0, 0.25)
    _reg("deepak_plagiograph", "Balanced plagiograph (Deepak & Ananthasuresh, Sec. 2.1.2, eq. 1)",
         balanced_plagiograph, 0.2, 0.3, 1.5, 0.4, (0.1, -0.3), 80.0, 0.1)
    _reg("deepak_technique1", f"Technique 1 on the example four-bar {T}", _on_example_fourbar, technique1,
         0.3, 0.3)
    for base in PIVOTS:
        _reg(f"deepak_technique2_{base}", f"Technique 2 based at {base} on the example four-bar {T}",
             _on_example_fourbar, technique2, base, 0.1)
    for U in PIVOTS:
        for W in PIVOTS:
            _reg(f"deepak_technique3_{U}{W}", f"Technique 3 ({U}, {W}) on the example four-bar {T}",
                 _on_example_fourbar, technique3, U, W, 0.1)
    for base in PIVOTS:
        _reg(f"deepak_herder_{base}", f"Herder's design based at {base} on the example four-bar {T}",
             _on_example_fourbar, herder, base, 0.1)
    _reg("deepak_watt_prototype", f"The Watt 1:1:2 prototype {T}", watt_prototype)
    _reg("deepak_gravity_fourbar", "Gravity load as the limit of a spring load (Deepak & Ananthasuresh, "
         "Sec. 4)", _gravity_example)
    for i in range(3):
        _reg(f"deepak_cognate_{i + 1}", f"Cognate {i + 1} of the example four-bar, balanced by technique 2 "
             "(Deepak Sec. 3)", _cognate_example, i)


_register_examples()
