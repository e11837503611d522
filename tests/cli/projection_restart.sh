#!/usr/bin/env bash
# The projection scheme continues a checkpoint bitwise: the state a step reads is x, v and the
# last pressure (the solver's starting iterate), all in the checkpoint. A run of 20 steps and a
# run of 10 steps continued with --restart for 10 more write byte-identical snapshots and probe
# files.
# Usage: projection_restart.sh <sluice executable> <source dir>
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
# Both the tank (fixed dt = 1 ms, 20 steps) and the dam break on its adaptive step (dx = 0.02 m,
# to 0.1 s: the step, the previous step and the limits are in the checkpoint too), each with
# the default block-ILU(0) preconditioner.
check() { # name case end half extra...
    local name=$1 case_file=$2 end=$3 half=$4
    shift 4
    local common=(--threads 1 -q --set checkpoint.every_steps=10 "$@")
    "$exe" run "$case_file" --out "$work/$name/a" "${common[@]}" --set time.end_time="$end"
    "$exe" run "$case_file" --out "$work/$name/b" "${common[@]}" --set time.end_time="$half"
    "$exe" run "$case_file" --restart "$work/$name/b" "${common[@]}" --set time.end_time="$end"
    local n=0
    for f in "$work/$name"/a/snapshots/*.h5; do
        cmp "$f" "$work/$name/b/snapshots/$(basename "$f")"
        n=$((n + 1))
    done
    [[ $n -ge 3 ]] || { echo "FAIL $name: only $n snapshots"; exit 1; }
    diff -r "$work/$name/a/probes" "$work/$name/b/probes"
    echo "ok projection restart, $name: $n snapshots and probes identical"
}
check tank "$src/cases/projection_hydrostatic_2d.toml" 0.02 0.01 --set time.output_interval=0.01
check dam_break "$src/cases/projection_dam_break_2d.toml" 0.1 0.05 --set particles.dx=0.02 \
    --set time.output_interval=0.02
