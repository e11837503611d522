#!/usr/bin/env bash
# Work inflation W(R)/W(1) on one machine: the same case on R = 1, 2, 4, 8, 16 ranks x 1
# thread (oversubscribed where R exceeds the cores), W = the tasks' total thread CPU time
# (summary.json, extra.parallel.total.task_cpu_seconds), which is the work the ranks do
# whatever the core count; beside it the same by stage and for the halo packing (CPU), and the
# time between steps (rebin, migration, balancing; wall time of the main threads, summed).
# Usage: perf/strong_scaling/work_inflation.sh [--sluice EXE] [--ranks "1 2 4 8 16"]
#          [--out DIR] [CASE [--set KEY=VALUE ...]]
#   default case: cases/dam_break_2d.toml at dx = 0.005 m for 0.05 s (25,600 fluid particles)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
exe="$root/build/release/sluice" ranks="1 2 4 8 16" out=/tmp/sluice_work_inflation
while (($#)); do
    case "$1" in
    --sluice) exe=$2; shift 2 ;;
    --ranks) ranks=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) break ;;
    esac
done
case_file="${1:-$root/cases/dam_break_2d.toml}"
(($#)) && shift
sets=("$@")
((${#sets[@]})) || sets=(--set particles.dx=0.005 --set time.end_time=0.05)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
for r in $ranks; do
    mpirun --oversubscribe -np "$r" "$exe" run "$case_file" --out "$out/r$r" --threads 1 -q \
        --set output.snapshots=false "${sets[@]}"
done
/usr/bin/python3 - "$out" $ranks <<'PY'
import json, sys
out, ranks = sys.argv[1], [int(r) for r in sys.argv[2:]]
rows = []
for r in ranks:
    p = json.load(open(f"{out}/r{r}/summary.json"))["extra"]["parallel"]
    w = p["total"]["task_cpu_seconds"]
    halo = sum(x["halo_pack_cpu_seconds"] for x in p["ranks"])
    between = sum(x["between_steps_wall_seconds"] for x in p["ranks"])
    stages = p["total"]["stage_task_cpu_seconds"]
    rows.append((r, w, halo, between, stages))
w1 = rows[0][1]
print(f"{'ranks':>5} {'W = task CPU s':>14} {'W(R)/W(1)':>9} {'halo pack s':>11} "
      f"{'between steps s':>15}  stage task CPU s")
for r, w, halo, between, stages in rows:
    st = " ".join(f"{k} {v:.2f}" for k, v in stages.items())
    print(f"{r:>5} {w:>14.2f} {w / w1:>9.3f} {halo:>11.3f} {between:>15.2f}  {st}")
PY
