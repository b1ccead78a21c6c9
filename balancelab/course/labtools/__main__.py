"""``python -m balancelab.course.labtools``: the same command as ``balancelab-labs``."""
import sys

from .cli import main

__all__: list[str] = []

if __name__ == "__main__":
    sys.exit(main())
