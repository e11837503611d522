#!/usr/bin/env bash
# The CADAM dam break over a triangular bottom sill (cases/dam_break_sill_2d.toml, its bed a
# polyline mesh) at dx = 0.05 and 0.025 m, and its gauges against the measured depths
# (compare.py). Usage: perf/mesh_hump/run.sh [--sluice EXE] [--threads N] [--out DIR]
#   [--end T]  (defaults: build/release/sluice, all cores, /tmp/sluice_mesh_hump, the case's 20 s)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
exe="$root/build/release/sluice" threads=0 out=/tmp/sluice_mesh_hump end=""
while (($#)); do
    case "$1" in
    --sluice) exe=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --end) end=$2; shift 2 ;;
    *) echo "run.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
mkdir -p "$out"
runs=()
for dx in 0.05 0.025; do
    dir="$out/dx$dx"
    sets=(--set particles.dx=$dx --set output.snapshots=false)
    [[ -n $end ]] && sets+=(--set time.end_time=$end)
    start=$(date +%s)
    "$exe" run "$root/cases/dam_break_sill_2d.toml" --out "$dir" --threads "$threads" -q "${sets[@]}"
    echo "dx = $dx m: $(($(date +%s) - start)) s wall, $(nproc) cores, $threads threads (0 = all)"
    runs+=("$dir")
done
/usr/bin/python3 "$here/compare.py" "${runs[@]}"
