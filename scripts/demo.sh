#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# make demo: the main job, the paper's (7,2) knot scene (Fig. 12.2 and the
# cable knots (a)-(d)) on its defaults.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
./cable replay runs/knot72/knot72.auto
end=$(date +%s)
echo
echo "demo: knot72 scene done in $((end - start)) s"
echo "demo: output in runs/knot72/: b.*, s.*, d.* (AUTO-07p formats), the pictures"
echo "      (knot72*.png) and the comparison with the paper in runs/knot72/knot72_compare.txt"
