"""Print every worked example of the catalog with its balance report (``python -m balancelab.course.gallery``)."""
from __future__ import annotations

from .catalog import catalog

__all__ = ["main"]


def main() -> int:
    """Build every catalog entry, print its report; return 1 if any verdict is unexpected.

    Returns
    -------
    int
        Process exit status.
    """
    status = 0
    entries = catalog()
    for i, (name, entry) in enumerate(entries.items(), 1):
        design = entry()
        report = design.balance_report()
        ok = report.balanced == entry.expected_balanced
        status |= not ok
        flag = "ok " if ok else "BAD"
        print(f"[{i:2d}/{len(entries)}] {flag} {name:32s} {report}")
    return status


if __name__ == "__main__":
    raise SystemExit(main())
