#!/usr/bin/env bash
# A migration tells every rank within two peer steps the halo it will receive
# (src/solver/rank_migration.cpp), including ranks that are not the sender's peers: a migrant
# that lands in a cell facing a third rank. On 9 ranks cut into key ranges and rebalanced every
# 10 steps, the 2-D dam break has such migrants: a binary that left out the counts for
# non-peers aborted with a truncated halo message (MPI_ERR_TRUNCATE) in each of 3 runs, while
# 3 ranks, as the other MPI tests run, never reach that path. The cuts follow measured times,
# so the layouts differ from run to run; the snapshots must be byte-identical to one rank's.
# Usage: migration_two_steps.sh SLUICE_EXE SOURCE_DIR MPIEXEC
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_args.sh"

args=(--threads 1 -q --set time.end_time=0.06 --set runtime.rebalance_every=10
    --set 'runtime.initial_decomposition="key-range"')
sluice_on 1 run "$src/cases/dam_break_2d.toml" --out "$work/1" "${args[@]}"
sluice_on 9 run "$src/cases/dam_break_2d.toml" --out "$work/9" "${args[@]}"
n=0
for f in "$work/1/snapshots"/*.h5; do
    cmp "$f" "$work/9/snapshots/$(basename "$f")" ||
        { echo "FAIL: 9 ranks differ from 1 in $(basename "$f")"; exit 1; }
    n=$((n + 1))
done
[[ $n -ge 3 ]] || { echo "FAIL: only $n snapshots"; exit 1; }
grep -q '"list_rebuilds": [1-9]' "$work/9/summary.json" || { echo "FAIL: no rebuild"; exit 1; }
echo "ok: $n snapshots of 9 ranks identical to 1 rank"
