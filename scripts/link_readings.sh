#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The readings study of the link captions (doc/links.md, "Readings of the
# captions"): the branches of Figs. 12.7-12.9 labelled at the captions' T and
# at the T of the readings, F(Delta) at the captions' T from the thin limit to
# contact of the tubes, and the readings that change a parameter (C, L2).
# Usage: scripts/link_readings.sh [SCRATCH_DIR] [fig127|fig128|fig129|tables ...]
# Runs niced, writes only into SCRATCH_DIR (default /tmp/cable-link-readings),
# prints the tables at the end (scripts/link_readings_table.py).  CPU time on
# the shared 2-core machine (2026-11-25): about 10 min per figure, fig129 30 min.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:-/tmp/cable-link-readings}
shift || true
stages=${*:-fig127 fig128 fig129 tables}
cable="$here/cable"
[ -x "$cable" ] || { echo "link_readings.sh: $cable not built (make)" >&2; exit 1; }
mkdir -p "$dir"
run_fig() { # NAME SCENE: constants of runs/SCENE, the two scripts of NAME
  local d="$dir/$1"
  mkdir -p "$d"
  cp "$here"/runs/"$2"/c.* "$d"/
  cp "$here"/scripts/link_readings/"$1"_*.auto "$d"/
  local stages="branch delta"
  if [ "$1" = fig127 ]; then # the reading t20 = +t10 needs the plug-in beside the run
    cp "$here"/build/release/plugins/link_t2plus.so "$d"/ ||
      { echo "link_readings.sh: build the plug-in first (make tests-build)" >&2; exit 1; }
    stages="branch delta t2plus"
  fi
  for s in $stages; do
    echo "== $1 $s (log: $d/$s.log)"
    (cd "$d" && nice -n 10 "$cable" replay "$1_$s.auto" >"$s.log" 2>&1) ||
      { echo "link_readings.sh: $1_$s.auto failed, see $d/$s.log" >&2; tail -n 5 "$d/$s.log" >&2; exit 1; }
  done
}
for st in $stages; do
  case $st in
    fig127) run_fig fig127 link62 ;;
    fig128) run_fig fig128 link43 ;;
    fig129) run_fig fig129 link102 ;;
    tables) /usr/bin/python3 "$here/scripts/link_readings_table.py" "$dir" ;;
    *) echo "link_readings.sh: unknown stage '$st' (fig127 fig128 fig129 tables)" >&2; exit 2 ;;
  esac
done
