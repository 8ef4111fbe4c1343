#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Fuzz cable's input parsers (run scripts are Python: CPython parses them) with libFuzzer (clang-14), ASan and UBSan:
#   constants  cable_constants_parse_string (+ parse_override)   auto_iface/files/constants_parse.c
#   sfile      cable_sfile_read on a temporary file               auto_iface/files/aufile_read.c
# Usage: scripts/fuzz.sh [TARGET ...]       (default: both, one after the other)
# Env:   FUZZ_SECONDS  total fuzzing time, shared equally by the targets (default 600)
#        FUZZ_JOBS     1 (default): sequential; N > 1: N targets at once (same share each)
# Output: build/fuzz/<target> binaries, build/fuzz/corpus/<target>/ (grown corpus),
#         build/fuzz/crashes/<target>/ (crash inputs), build/fuzz/<target>.log,
#         and a summary line per target: seconds, executions, exec/s, corpus size, crashes.
# A crash input belongs in tests/data/fuzz_regressions/<target>/ (replayed by
# tests/test_fuzz_regressions.c) together with the fix.  Exit status: non-zero
# when any target crashed.
set -uo pipefail

cd "$(dirname "$0")/.."
out=build/fuzz
total=${FUZZ_SECONDS:-600}
jobs=${FUZZ_JOBS:-1}
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(constants sfile)

# ---- toolchain: clang-14 with the libFuzzer runtime (Debian: clang-14, libclang-rt-14-dev)
need=()
command -v clang-14 >/dev/null || need+=(clang-14)
ls /usr/lib/llvm-14/lib/clang/*/lib/linux/libclang_rt.fuzzer-*.a >/dev/null 2>&1 || need+=(libclang-rt-14-dev)
if [ ${#need[@]} -gt 0 ]; then
  echo "fuzz: installing ${need[*]}"
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "fuzz: not root and no sudo; install: ${need[*]}" >&2; exit 1; }
    sudo=sudo
  fi
  $sudo apt-get update -q && $sudo apt-get install -y -q "${need[@]}" || { echo "fuzz: apt-get failed" >&2; exit 1; }
fi

# ---- build: the library sources each target needs, compiled straight into one binary
CC=clang-14
FLAGS=(-std=c11 -D_POSIX_C_SOURCE=200809L -g -O1 -fno-omit-frame-pointer
       -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined
       -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wmissing-prototypes -Wvla
       -Iinclude -Icontinuation/base -Icontinuation -Iequations -Iauto_iface/files)
common=(continuation/base/cable_error.c continuation/base/cable_status.c)
srcs_constants=(auto_iface/files/constants_parse.c auto_iface/files/names.c continuation/cable_constants.c
                auto_iface/files/aufile_read.c continuation/cable_solution.c continuation/cable_problem.c)
srcs_sfile=(auto_iface/files/aufile_read.c auto_iface/files/names.c continuation/cable_constants.c
            continuation/cable_solution.c continuation/cable_problem.c)
# inputs longer than this are cut: real constants files are a few
# kB; s-files are larger, and a few solutions of a small NTST cover the reader
declare -A maxlen=([constants]=4096 [sfile]=16384)

mkdir -p "$out"
for t in "${targets[@]}"; do
  case $t in constants|sfile) ;; *) echo "fuzz: unknown target $t" >&2; exit 2 ;; esac
  declare -n srcs="srcs_$t"
  echo "fuzz: building $out/$t"
  $CC "${FLAGS[@]}" "tests/fuzz/fuzz_$t.c" "${srcs[@]}" "${common[@]}" -lm -o "$out/$t" || exit 1
  unset -n srcs
done

# ---- seed corpora: the committed seeds, the project's own inputs, the regressions
seed() {   # seed TARGET FILE [PREFIX]: copy FILE (<= maxlen) into the target's corpus
  local t=$1 f=$2 prefix=${3:-} dest
  [ -f "$f" ] || return 0
  [ "$(stat -c %s "$f")" -le "${maxlen[$t]}" ] || return 0
  dest="$out/corpus/$t/seed_${prefix}$(echo "$f" | tr '/' '_')"
  { printf '%s' "$prefix"; cat "$f"; } > "$dest"
}
for t in "${targets[@]}"; do
  mkdir -p "$out/corpus/$t" "$out/crashes/$t"
  for f in tests/fuzz/corpus/$t/* tests/data/fuzz_regressions/$t/*; do
    [ -f "$f" ] && cp "$f" "$out/corpus/$t/"
  done
  case $t in
    constants) for f in tests/data/c.* runs/*/c.*; do seed constants "$f"; done ;;
    sfile)     for f in tests/data/s.* runs/*/s.*; do seed sfile "$f"; done ;;
  esac
done

# ---- run
share=$(( total / ${#targets[@]} ))
[ "$share" -ge 1 ] || share=1
run_one() {
  local t=$1
  echo "fuzz: $t for ${share}s"
  ( cd "$out/crashes/$t" &&
    "../../$t" -max_total_time="$share" -max_len="${maxlen[$t]}" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix=./ "../../corpus/$t" ) > "$out/$t.log" 2>&1
  echo $? > "$out/$t.rc"
}
# crash files of earlier runs stay where they are; only new ones count below
stamp="$out/.run-start"
touch "$stamp"
pids=()
for t in "${targets[@]}"; do
  if [ "$jobs" -gt 1 ]; then
    run_one "$t" & pids+=($!)
    while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do sleep 1; done
  else
    run_one "$t"
  fi
done
[ ${#pids[@]} -gt 0 ] && wait "${pids[@]}"

# ---- summary
status=0
printf '%-10s %8s %12s %9s %8s %8s\n' target seconds executions exec/s corpus crashes
for t in "${targets[@]}"; do
  log="$out/$t.log"
  execs=$(sed -n -e 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  secs=$(grep -a -o 'Done [0-9]* runs in [0-9]* second' "$log" | awk '{print $5}' | tail -1)
  ncorp=$(ls "$out/corpus/$t" | wc -l)
  ncrash=$(find "$out/crashes/$t" -newer "$stamp" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  printf '%-10s %8s %12s %9s %8s %8s\n' "$t" "${secs:-?}" "${execs:-?}" "${rate:-?}" "$ncorp" "$ncrash"
  if [ "$(cat "$out/$t.rc")" != 0 ] || [ "$ncrash" -gt 0 ]; then
    status=1
    echo "fuzz: $t FAILED (exit $(cat "$out/$t.rc")); see $log and $out/crashes/$t/" >&2
    grep -a -m3 -E 'ERROR: |runtime error|SUMMARY' "$log" >&2
  fi
done
exit $status
