#!/usr/bin/env bash
# One entry point for instructors, students and CI.
#   bash scripts/course.sh book    set up .venv and build the course site into _build/html
#   bash scripts/course.sh test    set up .venv and run every test (library, book, labs, browser)
#   bash scripts/course.sh bench   set up .venv and print the benchmark tables
# Needs only python3 (>= 3.10) with pip; everything else is installed from the package registries.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
VENV=$ROOT/.venv
PY=$VENV/bin/python

log() { printf '\n==> %s\n' "$*"; }

setup() {
    if [ ! -x "$PY" ]; then
        log "creating $VENV"
        python3 -m venv "$VENV"
    fi
    log "installing balancelab and its extras (pinned by constraints.txt)"
    "$PY" -m pip install --quiet --upgrade pip
    "$PY" -m pip install --quiet -c constraints.txt -e ".[test]"
    if [ -x scripts/setup_extras.sh ]; then
        bash scripts/setup_extras.sh "$PY"
    fi
}

cmd=${1:-help}
shift || true
case "$cmd" in
    book)
        setup
        if [ -f scripts/build_book.sh ]; then
            bash scripts/build_book.sh "$PY" "$@"
        else
            log "running the gallery of worked examples"
            "$PY" -m balancelab.course.gallery
        fi
        ;;
    test)
        setup
        # Lint and type checks first (configured in pyproject.toml; README, "Lint and types"): either
        # failing fails the command. BALANCELAB_SKIP_STATIC=1 skips both (a quick local re-run of tests).
        if [ "${BALANCELAB_SKIP_STATIC:-0}" != 1 ]; then
            log "ruff check (lint)"
            "$PY" -m ruff check
            log "mypy (types)"
            "$PY" -m mypy
        fi
        log "running the test suite on ${BALANCELAB_TEST_WORKERS:-2} workers"
        # One worker builds the site and runs the browser tests (the "site" group, see tests/conftest.py),
        # the other takes the library, labs and grading tests. BALANCELAB_TEST_WORKERS=0 runs in one process.
        # --durations: the slowest tests are printed, so that a CI log shows where its time goes.
        "$PY" -m pytest -n "${BALANCELAB_TEST_WORKERS:-2}" --dist loadgroup --durations=30 "$@"
        ;;
    bench)
        setup
        "$PY" benchmarks/run.py "$@"
        ;;
    *)
        echo "usage: bash scripts/course.sh {book|test|bench}" >&2
        exit 2
        ;;
esac
