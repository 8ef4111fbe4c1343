#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Work against precision on the whole knot72 path to the paper's four points:
# the flat branch, BP1-BP4, modes 1-4 to the UZ labels at the points (a)-(d),
# with runs/knot72's constants files and NTST, NCOL replaced on both.  Prints a
# markdown table (time = median of REPEAT runs of the whole path; errors in F
# at (a)-(d) against a reference) for scripts/bench.sh.
# Usage: scripts/bench_scene.sh BUILD_DIR [REPEAT]
set -euo pipefail
build=${1:?usage: bench_scene.sh BUILD_DIR [REPEAT]}
repeat=${2:-3}
cd "$(dirname "$0")/.."
cable="$PWD/$build/cable"
work="$PWD/$build/bench_scene"
mkdir -p "$work"

# the grid: the settings the per-point benchmark found near 1e-8, and the two
# references (different NTST and NCOL: their agreement is the reference's uncertainty)
grid=${BENCH_SCENE_GRID:-"25:7 30:7 35:7 40:7 50:4 50:5 50:6 75:5 100:4 100:5"}
refs=${BENCH_SCENE_REFS:-"200:5 50:7"}
ref=${refs%% *}
ref2=${refs#* }

# one run of the path at NTST=$1 NCOL=$2: prints "seconds steps F_a F_b F_c F_d"
run_path() {
  local ntst=$1 ncol=$2 d="$work/v${1}_${2}"
  rm -rf "$d"
  mkdir -p "$d"
  for c in knot72 knot72sym; do
    sed "s/^NTST = [0-9]*, NCOL = [0-9]*/NTST = $ntst, NCOL = $ncol/" "runs/knot72/c.$c" > "$d/c.$c"
    grep -q "^NTST = $ntst, NCOL = $ncol" "$d/c.$c" || { echo "bench_scene: no NTST line in runs/knot72/c.$c" >&2; exit 1; }
  done
  cat > "$d/path.auto" <<'EOF'
flat = run(e='braid_knot', c='knot72', sv='flat')
m1 = run(flat('BP1'), e='braid_knot_sym', c='knot72sym', UZSTOP={'T': -2.10752}, sv='mode1')
m2 = run(flat('BP2'), e='braid_knot_sym', c='knot72sym', UZSTOP={'T': -9.89105}, sv='mode2')
m3 = run(flat('BP3'), e='braid_knot_sym', c='knot72sym', UZSTOP={'T': -10.97932}, sv='mode3')
m4 = run(flat('BP4'), e='braid_knot_sym', c='knot72sym', UZSTOP={'T': -15.51471}, sv='mode4')
print('FVAL %.13e %.13e %.13e %.13e' % (m1('UZ1')['F'], m2('UZ1')['F'], m3('UZ1')['F'], m4('UZ1')['F']))
EOF
  local t0 t1
  t0=$(date +%s.%N)
  (cd "$d" && "$cable" replay path.auto > log.txt 2>&1) || { echo "bench_scene: NTST=$ntst NCOL=$ncol failed (see $d/log.txt)" >&2; return 1; }
  t1=$(date +%s.%N)
  # accepted points of the five branches: the b-files' data rows (branch number != 0)
  local steps
  steps=$(cd "$d" && awk '$1 != 0' b.flat b.mode1 b.mode2 b.mode3 b.mode4 | wc -l)
  echo "$(awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.3f", b - a}') $steps $(sed -n 's/^FVAL //p' "$d/log.txt")"
}

median() { sort -g | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

declare -A F T S
for g in $refs $grid; do
  times=""
  for ((k = 0; k < repeat; k++)); do
    case " $refs " in *" $g "*) [ "$k" -gt 0 ] && continue ;; esac   # references: one run
    out=$(run_path "${g%:*}" "${g#*:}")
    times+="${out%% *}"$'\n'
    out="${out#* }"
    S[$g]="${out%% *}"
    F[$g]="${out#* }"
  done
  T[$g]=$(printf "%s" "$times" | median)
done

read -r ra rb rc rd <<< "${F[$ref]}"
read -r sa sb sc sd <<< "${F[$ref2]}"
echo "Reference: NTST = ${ref%:*}, NCOL = ${ref#*:}: F(a)..F(d) = $ra, $rb, $rc, $rd."
echo "Its uncertainty, the largest relative distance to NTST = ${ref2%:*}, NCOL = ${ref2#*:} over the four points:"
awk -v a="$ra" -v b="$rb" -v c="$rc" -v d="$rd" -v A="$sa" -v B="$sb" -v C="$sc" -v D="$sd" 'function r(x, y) {return (x > y ? x - y : y - x) / y}
  BEGIN {u = r(A, a); if (r(B, b) > u) u = r(B, b); if (r(C, c) > u) u = r(C, c); if (r(D, d) > u) u = r(D, d); printf "%.1e.\n", u}'
echo
echo "| NTST | NCOL | path (s) | steps | per step (s) | rel. error F(a) | F(b) | F(c) | F(d) | max | <= 1e-8 |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
best=""
for g in $grid; do
  read -r fa fb fc fd <<< "${F[$g]}"
  line=$(awk -v a="$ra" -v b="$rb" -v c="$rc" -v d="$rd" -v A="$fa" -v B="$fb" -v C="$fc" -v D="$fd" \
             -v n="${g%:*}" -v k="${g#*:}" -v t="${T[$g]}" -v st="${S[$g]}" 'function r(x, y) {return (x > y ? x - y : y - x) / y}
    BEGIN {m = r(A, a); if (r(B, b) > m) m = r(B, b); if (r(C, c) > m) m = r(C, c); if (r(D, d) > m) m = r(D, d);
           printf "| %d | %d | %.2f | %d | %.4f | %.1e | %.1e | %.1e | %.1e | %.1e | %s |", n, k, t, st, t / st, r(A, a), r(B, b), r(C, c), r(D, d), m, m <= 1e-8 ? "yes" : "no"}')
  echo "$line"
  case "$line" in *"| yes |") best+="${T[$g]} $g"$'\n' ;; esac
done
echo
if [ -n "$best" ]; then
  pick=$(printf "%s" "$best" | sort -g | head -1)
  g="${pick#* }"
  echo "Fastest setting with every relative error <= 1e-8: NTST = ${g%:*}, NCOL = ${g#*:} (${pick%% *} s, ${S[$g]} steps)."
else
  echo "No setting of the grid reaches 1e-8 at all four points."
fi
