#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# make bench: `cable explore` on the paper's (7,2) knot (Fig. 12.2) next to the knot72
# scene's acceptance path (the flat branch, BP1-BP4, modes 1-4 in the S0-symmetric
# formulation), and F at the paper's points (a)-(d) on the explored branches against the
# scene's (scripts/bench_explore.py).  Prints a markdown section for scripts/bench.sh.
# Usage: scripts/bench_explore.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: bench_explore.sh BUILD_DIR}
cd "$(dirname "$0")/.."
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1}
work="$PWD/$build/bench_explore"
rm -rf "$work" && mkdir -p "$work/scene"
cable="$PWD/$build/cable"

# the scene's acceptance path (as scripts/bench.sh's path_time): the knot72 script up to l1
cp runs/knot72/c.knot72 runs/knot72/c.knot72sym "$work/scene/"
sed '/^l1 = run(/,$d' runs/knot72/knot72.auto > "$work/scene/path.auto"
/usr/bin/time -o "$work/scene/time" -f "%e %U %S %x" "$cable" replay "$work/scene/path.auto" \
  > "$work/scene/log" 2>&1 || true
# the command of issue 28
cmd="explore TORUS=7 HAND=1 Delta=0.0051364907419 Ltot=1.98889 modes=4 out=$work/e72"
/usr/bin/time -o "$work/explore.time" -f "%e %U %S %x" "$cable" $cmd > "$work/explore.log" 2>&1 || true
# the same on the right arm only: the scene's four branch points, for a like-for-like time
/usr/bin/time -o "$work/explore_right.time" -f "%e %U %S %x" "$cable" $cmd arms=right pictures=0 \
  out="$work/e72r" > "$work/explore_right.log" 2>&1 || true

echo "## \`cable explore\` on the (7,2) knot of Fig. 12.2"
echo
echo "\`cable $cmd\` (out= in a scratch directory) against the knot72 scene's acceptance path"
echo "(\`runs/knot72/knot72.auto\` up to \`l1 = run(...)\`); CPU = user + system (/usr/bin/time)."
echo "Load before: $(cut -d' ' -f1-3 /proc/loadavg)."
echo
echo "| run | wall time (s) | CPU time (s) | exit status |"
echo "|---|---:|---:|---:|"
awk '{printf "| knot72 acceptance path (flat, BP1-BP4, modes 1-4 in braid_knot_sym) | %.1f | %.1f | %d |\n", $1, $2 + $3, $4}' "$work/scene/time" | tail -1
awk '{printf "| cable explore ... modes=4 (both arms: 8 BPs, every branch of each, pictures, table) | %.1f | %.1f | %d |\n", $1, $2 + $3, $4}' "$work/explore.time" | tail -1
awk '{printf "| the same with arms=right pictures=0 (the scene'"'"'s 4 BPs) | %.1f | %.1f | %d |\n", $1, $2 + $3, $4}' "$work/explore_right.time" | tail -1
echo
echo "Branches of the explore run (\\`table.txt\\`): name, branch point, direction j of n, formulation, points, end:"
echo
grep '^#   [rl][0-9].* [0-9]/[0-9]' "$work/e72/table.txt" | sed 's/^#   /    /' || true
echo
PYTHONPATH="$PWD/$build/python" /usr/bin/python3 scripts/bench_explore.py "$work/e72" "$work/scene"
