#!/usr/bin/env bash
# Installs what the book and its browser test need beyond PyPI (called by scripts/course.sh setup):
#   * npm (Debian's nodejs/npm) when missing: the book build fetches MathJax 3, require.js and the
#     ipywidgets HTML manager from the npm registry with `npm pack`;
#   * Debian's chromium for the browser test (driven by Python playwright; never `playwright install`);
#   * bubblewrap (`bwrap`), the sandbox the lab grader runs each submission in (without it the grader
#     warns and falls back to resource limits only).
# Needs root and apt-get for the Debian packages; without them it says what is missing and goes on
# (the browser test then skips with the reason).
set -uo pipefail
PY=${1:-.venv/bin/python}
need=()
command -v npm >/dev/null 2>&1 || need+=(nodejs npm)
command -v chromium >/dev/null 2>&1 || need+=(chromium)
command -v bwrap >/dev/null 2>&1 || need+=(bubblewrap)
if [ ${#need[@]} -eq 0 ]; then
    exit 0
fi
if command -v apt-get >/dev/null 2>&1 && [ "$(id -u)" = 0 ]; then
    echo "==> installing Debian packages: ${need[*]}"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq || echo "apt-get update failed; trying the install anyway" >&2
    if ! apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null; then
        echo "warning: could not install ${need[*]} with apt-get" >&2
    fi
else
    echo "warning: ${need[*]} missing and apt-get (as root) not available; install them by hand" >&2
fi
exit 0
