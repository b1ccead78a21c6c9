"""Labelled diagrams read their positions from the design, and refuse names they do not know."""
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import balancelab as bl  # noqa: E402
from balancelab.viz import diagram, point_positions  # noqa: E402


@pytest.fixture
def lever():
    return bl.singh.lacoste_lever(weight=10.0, length=0.5, a_x=0.2, b_y=0.3)


@pytest.mark.parametrize("theta", [-1.0, 0.0, 0.6, 2.5])
def test_positions_follow_the_link_rotation(lever, theta):
    pos = point_positions(lever, [theta], {"A": (1, (0.2, 0.0)), "B": (0, (0.0, 0.3))})
    assert np.allclose(pos["A"], [0.2 * math.cos(theta), 0.2 * math.sin(theta)], atol=1e-12)
    assert np.allclose(pos["B"], [0.0, 0.3], atol=1e-12)


def test_diagram_labels_every_point_at_its_position(lever):
    pts = {"O": (0, (0.0, 0.0)), "B": (0, (0.0, 0.3)), "A": (1, (0.2, 0.0))}
    ax = diagram(lever, [0.6], points=pts, lengths=[("O", "B", "$b$")], angles=[("O", "+x", "A", "$t$")])
    texts = {t.get_text(): t for t in ax.texts}
    for name in pts:
        assert np.allclose(texts[name].xy, ax.positions[name])
    assert "$b$" in texts and "$t$" in texts
    # the angle arc spans exactly the link angle: its end points lie on the x-axis and on OA
    arc = [ln for ln in ax.lines if len(ln.get_xdata()) == 40][0]
    x, y = arc.get_xdata(), arc.get_ydata()
    assert math.isclose(math.atan2(y[0], x[0]), 0.0, abs_tol=1e-12)
    assert math.isclose(math.atan2(y[-1], x[-1]), 0.6, abs_tol=1e-12)
    plt.close("all")


def test_crowded_labels_are_pushed_apart(lever):
    pts = {"P": (0, (0.0, 0.0)), "Q": (0, (0.001, 0.0)), "R": (1, (0.5, 0.0))}
    ax = diagram(lever, [0.0], points=pts)
    off = {t.get_text(): np.array(t.xyann) for t in ax.texts if t.get_text() in pts}
    assert np.dot(off["P"], off["Q"]) < 0          # the two near points are labelled on opposite sides
    plt.close("all")


@pytest.mark.parametrize("kwargs, word", [
    (dict(points={"A": (5, (0.0, 0.0))}), "body"),
    (dict(points={"A": (1, (0.0,))}), "point"),
    (dict(points=[("A", 1)]), "points"),
    (dict(points={"A": (1, (0.0, 0.0))}, lengths=[("A", "Z", "x")]), "'Z'"),
    (dict(points={"A": (1, (0.0, 0.0))}, angles=[("A", "up", "A", "x")]), "reference"),
])
def test_bad_input_names_the_parameter(lever, kwargs, word):
    with pytest.raises((ValueError, TypeError), match=word):
        diagram(lever, [0.0], **kwargs)
    plt.close("all")
