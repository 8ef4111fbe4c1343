#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Run every test program in BUILD/tests, from the repository root, and print one
# summary line "N passed, M failed" (preceded by "K skipped" when checks were
# not performed: SKIP lines, e.g. malloc counting under a sanitizer).  A test
# program that crashes or exits non-zero without printing a FAIL line counts
# as one failure; one that performs no check at all (no PASS, no FAIL) too.
# Environment: CABLE_TEST_WRAPPER (e.g. valgrind ...), CABLE_TEST_QUICK=1,
# CABLE_TEST_JOBS (programs run at once; default 1).
set -u
build=${1:?usage: run-tests.sh BUILD_DIR}
cd "$(dirname "$0")/.."
# The test programs are applications of libcable, which leaves the BLAS thread
# count alone; small blocks run fastest on one thread (as `cable` sets it).
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1}
mkdir -p tests/tmp
passed=0; failed=0; skipped=0
programs=()
for t in "$build"/tests/test_*; do
  case "$t" in *.o|*.d) continue;; esac
  [ -x "$t" ] || continue
  name=$(basename "$t")
  # a program left in an old build directory after its source was deleted
  [ -f "tests/$name.c" ] || [ -f "tests/api/${name#test_}.c" ] || continue
  rm -f "tests/tmp/$name.rc"
  programs+=("$t")
done
# Run the programs (CABLE_TEST_JOBS at a time: under valgrind the programs are
# independent and each uses one core), then report them in a fixed order.
run_one() {
  local name; name=$(basename "$1")
  ${CABLE_TEST_WRAPPER:-} "$1" >"tests/tmp/$name.log" 2>&1
  echo $? >"tests/tmp/$name.rc"
}
export -f run_one
export CABLE_TEST_WRAPPER
jobs=${CABLE_TEST_JOBS:-1}
if [ "${#programs[@]}" -gt 0 ]; then
  if [ "$jobs" -gt 1 ]; then
    printf '%s\0' "${programs[@]}" | xargs -0 -n 1 -P "$jobs" bash -c 'run_one "$0"'
  else
    for t in "${programs[@]}"; do run_one "$t"; done
  fi
fi
for t in "${programs[@]}"; do
  name=$(basename "$t")
  log="tests/tmp/$name.log"
  rc=$(cat "tests/tmp/$name.rc" 2>/dev/null || echo 127)
  p=$(grep -c '^PASS' "$log"); f=$(grep -c '^FAIL' "$log"); k=$(grep -c '^SKIP' "$log")
  grep '^SKIP' "$log" | sed "s/^/$name: /"
  grep '^FAIL' "$log" | sed "s/^/$name: /"
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
    echo "$name: exited with status $rc (see $log):"; tail -n 20 "$log" | sed 's/^/    /'
    f=1
  fi
  if [ "$p" -eq 0 ] && [ "$f" -eq 0 ] && [ "$k" -eq 0 ]; then
    echo "$name: ran no check"; f=1
  fi
  if [ "$k" -gt 0 ]; then
    printf '%-32s %4d passed, %d failed, %d skipped\n' "$name" "$p" "$f" "$k"
  else
    printf '%-32s %4d passed, %d failed\n' "$name" "$p" "$f"
  fi
  passed=$((passed + p)); failed=$((failed + f)); skipped=$((skipped + k))
done
# The Python package's tests (tests/python, pytest): each test function counts
# once.  Not under a wrapper (valgrind) or a sanitizer build: CPython would
# load the instrumented extension without its runtime.
pyc=$(ls "$build"/python/cable/_cable*.so 2>/dev/null | head -n 1)
if [ -z "${CABLE_TEST_WRAPPER:-}" ] && [ "$build" = build/release ] && [ -n "$pyc" ]; then
  log=tests/tmp/pytest.log
  PYTHONPATH="$build/python" PYTHONDONTWRITEBYTECODE=1 CABLE_BUILD="$build" \
    ${PYTHON:-/usr/bin/python3} -m pytest -q -p no:cacheprovider tests/python >"$log" 2>&1
  rc=$?
  summary=$(tail -n 1 "$log")
  p=$(echo "$summary" | grep -o '[0-9]* passed' | grep -o '[0-9]*'); p=${p:-0}
  f=$(echo "$summary" | grep -o '[0-9]* \(failed\|error\)' | awk '{s += $1} END {print s + 0}')
  grep -E '^(FAILED|ERROR) ' "$log" | sed 's/^/pytest: /'
  if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
    echo "pytest: exited with status $rc (see $log):"; tail -n 20 "$log" | sed 's/^/    /'; f=1
  fi
  k=$(echo "$summary" | grep -o '[0-9]* skipped' | grep -o '[0-9]*'); k=${k:-0}
  if [ "$k" -gt 0 ]; then
    printf '%-32s %4d passed, %d failed, %d skipped\n' "pytest tests/python" "$p" "$f" "$k"
  else
    printf '%-32s %4d passed, %d failed\n' "pytest tests/python" "$p" "$f"
  fi
  passed=$((passed + p)); failed=$((failed + f)); skipped=$((skipped + k))
else
  echo "pytest tests/python: skipped (wrapper, sanitizer build or no extension in $build)"
fi
[ "$skipped" -gt 0 ] && echo "$skipped skipped (not performed; see the SKIP lines above)"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
