#!/usr/bin/env bash
# The projection scheme continues a checkpoint bitwise: the state a step reads is x, v and the
# last pressure (the solver's starting iterate), all in the checkpoint. A run of 20 steps and a
# run of 10 steps continued with --restart for 10 more write byte-identical snapshots and probe
# files.
# Usage: projection_restart.sh <sluice executable> <source dir>
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
case_file="$src/cases/projection_hydrostatic_2d.toml"
common=(--threads 1 -q --set time.output_interval=0.01 --set checkpoint.every_steps=10)
"$exe" run "$case_file" --out "$work/a" "${common[@]}" --set time.end_time=0.02
"$exe" run "$case_file" --out "$work/b" "${common[@]}" --set time.end_time=0.01
"$exe" run "$case_file" --restart "$work/b" "${common[@]}" --set time.end_time=0.02
n=0
for f in "$work"/a/snapshots/*.h5; do
    cmp "$f" "$work/b/snapshots/$(basename "$f")"
    n=$((n + 1))
done
[[ $n -ge 3 ]] || { echo "FAIL: only $n snapshots"; exit 1; }
diff -r "$work/a/probes" "$work/b/probes"
echo "ok projection restart: $n snapshots and probes identical"
