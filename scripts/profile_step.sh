#!/bin/bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Where a continuation step's CPU time goes: perf profile of the flat (7,2)
# branch at issue 17's settings, printed as the inclusive share of each phase.
#
# Usage: scripts/profile_step.sh CABLE ISP [WORKDIR]
#   CABLE    the cable program (e.g. build/release/cable)
#   ISP      0 (no branch-point tests, NSV=0) or 2 (ISP=2 NSV=2)
#   WORKDIR  scratch directory (default: a new one under /tmp)
# Needs perf (linux-perf).  One thread, JAC=1, NTST 150, NCOL 4, IAD 3,
# EPSL = EPSU = 1e-7, EPSS = 1e-5, DS = -5, DSMAX = 5, NMX 60, from the first
# point of the flat branch (the start file of scripts/bench_compare.py).  The
# shares are of all samples of the run (start-up and the first point
# included); a phase's share counts everything it calls, so nested phases
# overlap.  Sampling: 500 Hz, call graphs by DWARF unwinding.
set -eu
cable=$(readlink -f "$1")
isp=$2
work=${3:-$(mktemp -d /tmp/cable-profile.XXXXXX)}
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$work"
cd "$work"
cp "$here/runs/knot72/c.knot72" .
nsv=0
[ "$isp" = 2 ] && nsv=2
set="NTST=150 NCOL=4 IAD=3 EPSL=1e-7 EPSU=1e-7 EPSS=1e-5 DS=-5.0 DSMAX=5.0 DSMIN=1e-6"
[ -f s.start150 ] || "$cable" run c=knot72 e=braid_knot NTST=150 NCOL=4 NMX=1 ISP=0 NSV=0 sv=start150 >/dev/null 2>&1
# shellcheck disable=SC2086
perf record -q -o perf.data --call-graph dwarf,16384 -F 500 "$cable" run c=knot72 e=braid_knot s=start150 IRS=1 \
  NMX=60 ISP="$isp" NSV="$nsv" JAC=1 NTHREADS=1 sv=prof $set >/dev/null 2>perf.err
perf report -i perf.data --stdio --children --sort symbol 2>/dev/null | grep -E '^ +[0-9]' >report.txt
share() { grep -E "\] $1( |$)" report.txt | head -1 | awk '{print $1}'; }
printf '%-58s %s\n' "phase (function)" "share"
while IFS='|' read -r name fn; do
  v=$(share "$fn")
  printf '%-58s %s\n' "$name ($fn)" "${v:--}"
done <<'EOF'
continuation steps after the first point|cable_cont_step
corrector solves|cont_correct_from
Jacobian assembly, all callers|colloc_system_jacobian
KINSOL's matrix zeroing|SUNMatZero
factorisations, all callers|abd_solver_factor
  local condensation|factor_interval
  band LU, LAPACK (before 2026-11-25)|dgbtf2_
  band LU, abd_band.c|abd_band_factor
solves J x = b, one vector (before 2026-11-25: all callers)|abd_solver_solve
solves J x = b, blocks of vectors (all callers)|abd_solver_solve_many
solves J^T y = c, one vector at a time (before)|abd_solver_solve_transpose
solves J^T y = c, blocks of vectors|abd_solver_solve_transpose_many
tangent and test functions after a corrector|tangent_from
extra factorisations for tangents (mesh, location)|cont_tangent
two smallest singular values|abd_solver_smallest_svd
pencil test|cont_pencil_crossings
double-BP location: Brent minimisations of sigma_1|dip_minimise
mesh adaptation|cont_adapt_mesh
EOF
echo "(perf data and the full report in $work)"
