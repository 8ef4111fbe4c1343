#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# make scenes: replay every scene in runs/ (each runs/NAME/NAME.auto), with the
# time of each (wall clock, and the CPU time of the replay: on a shared machine
# the wall time depends on the load) and of all of them together.
set -uo pipefail
cd "$(dirname "$0")/.."
status=0
TIMEFORMAT='%U %S'
all_start=$(date +%s)
for script in runs/*/*.auto; do
  name=$(basename "$(dirname "$script")")
  [ "$script" = "runs/$name/$name.auto" ] || continue
  echo "=== $name"
  start=$(date +%s)
  cpu=$(mktemp)
  # bash's time keyword (user and system CPU of the replay) into $cpu; the
  # replay's own stderr goes to the script's
  if { time ./cable replay "$script" 2>&3; } 3>&2 2>"$cpu"; then
    echo "=== $name: done in $(( $(date +%s) - start )) s ($(awk '{printf "%.1f s of CPU", $1 + $2}' "$cpu"))"
  else
    echo "=== $name: FAILED"; status=1
  fi
  rm -f "$cpu"
done
echo "=== scenes: total $(( $(date +%s) - all_start )) s"
exit $status
