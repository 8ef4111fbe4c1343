#!/usr/bin/env bash
# make scenes: replay every scene in runs/ (each runs/NAME/NAME.auto), with the
# time of each and of all of them together.
set -uo pipefail
cd "$(dirname "$0")/.."
status=0
all_start=$(date +%s)
for script in runs/*/*.auto; do
  name=$(basename "$(dirname "$script")")
  [ "$script" = "runs/$name/$name.auto" ] || continue
  echo "=== $name"
  start=$(date +%s)
  if ./cable replay "$script"; then
    echo "=== $name: done in $(( $(date +%s) - start )) s"
  else
    echo "=== $name: FAILED"; status=1
  fi
done
echo "=== scenes: total $(( $(date +%s) - all_start )) s"
exit $status
