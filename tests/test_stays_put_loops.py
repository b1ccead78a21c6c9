"""Issue 19, item 3: joint loads on a closed loop say plainly that they are for open chains today."""
from __future__ import annotations

import pytest

import balancelab as bl
from balancelab.methods.general.examples import fourbar_issue11
from balancelab.methods.practice import forces, friction


@pytest.mark.parametrize("call", [lambda d: friction.stays_put(d, 0.5, n=9), lambda d: forces.joint_loads(d, n=9)])
def test_a_fourbar_gets_a_plain_message_not_a_wrong_one(call):
    with pytest.raises(ValueError) as err:
        call(fourbar_issue11())
    message = str(err.value)
    assert "open chains only" in message and "statically determinate" in message
    assert "indeterminate" not in message  # a revolute four-bar is statically determinate


def test_a_tree_still_gets_its_joint_loads():
    q, ok = friction.stays_put(bl.realize.approximate_lever(), 0.5, n=9)
    assert ok.all()
