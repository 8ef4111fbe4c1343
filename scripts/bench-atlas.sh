#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# make bench, the atlas part: cable.atlas on Dask, 1 against 2 local workers and
# the scheduler's overhead per task (scripts/bench_atlas.py).  Prints a Markdown
# section on standard output (scripts/bench.sh puts it in doc/benchmarks.md);
# run alone: bash scripts/bench-atlas.sh build/release [N_TINY_TASKS]
set -euo pipefail
build=${1:?usage: bench-atlas.sh BUILD_DIR [N_TINY_TASKS]}
cd "$(dirname "$0")/.."
echo "## The atlas on Dask (cable.atlas, doc/atlas.md)"
echo
PYTHONPATH="$build/python" PYTHONDONTWRITEBYTECODE=1 ${PYTHON:-/usr/bin/python3} scripts/bench_atlas.py "${2:-200}"
