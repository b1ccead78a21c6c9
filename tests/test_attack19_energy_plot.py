"""Issue 19: energy_plot refuses an n whose plot would not fit (instead of allocating TiBs) and an ax
that is not a matplotlib Axes, naming the parameter."""
import matplotlib
import pytest

import balancelab as bl

matplotlib.use("Agg")


def _arm() -> bl.Design:
    lk = bl.Linkage("2R")
    lk.revolute("ground", (0.0, 0.0), "upper", (0.0, 0.0))
    lk.revolute("upper", (1.0, 0.0), "fore", (0.0, 0.0))
    lk.mass("upper", 1.0, com=(0.5, 0.0))
    lk.mass("fore", 1.0, com=(0.5, 0.0))
    return lk.build()


def _lever() -> bl.Design:
    lk = bl.Linkage("lever")
    lk.revolute("ground", (0.0, 0.0), "arm", (0.0, 0.0))
    lk.mass("arm", 1.0, com=(0.5, 0.0))
    return lk.build()


def test_huge_n_on_a_map_is_refused_naming_n_and_range():
    with pytest.raises(ValueError, match=r"^n must be an integer from 2 to 447 .* got 1000000"):
        bl.energy_plot(_arm(), n=10**6)


def test_huge_n_on_curves_is_refused_and_the_largest_allowed_map_draws():
    with pytest.raises(ValueError, match=r"^n must be an integer from 2 to 200000 .* got 1000000"):
        bl.energy_plot(_lever(), n=10**6)
    ax = bl.energy_plot(_arm(), n=447, residual=False)
    assert ax.energy.n == 447
    import matplotlib.pyplot as plt
    plt.close("all")


def test_ax_that_is_not_axes_is_a_type_error_naming_ax():
    with pytest.raises(TypeError, match=r"^ax must be a matplotlib Axes"):
        bl.energy_plot(_arm(), ax="x")
    with pytest.raises(TypeError, match=r"^ax must be a matplotlib Axes"):
        bl.energy_plot(_lever(), ax=3)
