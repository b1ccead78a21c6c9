#!/usr/bin/env bash
# Build the course site into _build/html, offline-ready (called by `bash scripts/course.sh book`).
#   bash scripts/build_book.sh PYTHON [--force] [--all]
# Fetches MathJax 3, require.js and the ipywidgets HTML manager from the npm registry (once; kept
# in the git-ignored book/_vendor/), then builds with every chapter executed (cached between
# builds; --force re-executes all), warnings as errors (-W --keep-going, nitpicky).
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${1:-.venv/bin/python}
shift || true
if ! command -v npm >/dev/null 2>&1 && [ ! -f book/_vendor/vendor/VERSIONS.txt ]; then
    bash scripts/setup_extras.sh "$PY"
fi
exec "$PY" scripts/build_book.py "$@"
