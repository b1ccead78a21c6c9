"""The catalog: every worked example builds, proves itself, and is sensitive to its springs."""
from __future__ import annotations

import pytest

import balancelab as bl
from conftest import assert_exactly_balanced

ENTRIES = list(bl.catalog().items())


def test_catalog_is_ordered_and_named():
    names = [n for n, _ in ENTRIES]
    assert names[0] == "single_link_counterweight"
    assert len(set(names)) == len(names)
    for name, entry in ENTRIES:
        assert entry.name == name and entry.title
        assert callable(entry.function)


@pytest.mark.parametrize("name, entry", ENTRIES, ids=[n for n, _ in ENTRIES])
def test_every_entry_proves_itself(name, entry):
    d = entry()
    assert isinstance(d, bl.Design)
    if entry.expected_balanced:
        assert_exactly_balanced(d)
    else:
        r = d.balance_report()
        assert not r.balanced and r.variation > 1e-6
    if d.joints:
        assert d.joint_error(d.sample(200)).max() < 1e-9


def test_gallery_runs(capsys):
    from balancelab.course.gallery import main

    assert main() == 0
    out = capsys.readouterr().out
    assert out.count("\n") == len(ENTRIES) and "BAD" not in out
