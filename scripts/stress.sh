#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Stress grid on the braid knot and link problems (issue 8): thin and thick
# rods, |T| up to 50, NTST from 10 to 2000, perturbed starts, long branches.
# Usage: scripts/stress.sh [BUILD_DIR]      (make stress; default build/release)
# Runs BUILD_DIR/tests/test_stress --full, prints every PASS/FAIL line and the
# table of outcomes (the rows of doc/stress.md), writes it to
# BUILD_DIR/stress.md, and exits non-zero when a case failed.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
bin="$build/tests/test_stress"
[ -x "$bin" ] || { echo "stress: $bin missing (make tests-build)" >&2; exit 1; }
log="$build/stress.log"
start=$(date +%s)
"$bin" --full | tee "$log"
rc=${PIPESTATUS[0]}
{
  echo "| case | problem | p | Delta | Ltot / L | NTST | end | points | LP/BP | last PAR(ICP(1)) | max abs(eta) | max drift | outside domain | all drift <= 1e-9 | perturbed vs clean: rel. diff of abs(F) (start drift) | s |"
  echo "|---|---|---:|---:|---:|---:|---|---:|---|---:|---:|---:|---:|---|---|---:|"
  sed -n 's/^TABLE //p' "$log"
} > "$build/stress.md"
echo
cat "$build/stress.md"
echo "stress: $(( $(date +%s) - start )) s, table in $build/stress.md; exit $rc"
exit "$rc"
