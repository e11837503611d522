#!/usr/bin/env bash
# A rank's grid memory follows its occupied cells, not the domain (docs/ARCHITECTURE.md, "Cell
# storage"): perf/memory/sparse_domain_3d.toml puts 8,000 particles in a 20 m x 20 m x 5 m tank
# (about 9.5 million cells at dx = 0.02 m, some 600 occupied), and its peak resident memory on
# one rank must be within 16 MiB of the same block's in a 1 m x 1 m x 1 m tank (3,000 cells).
# Any array per grid cell breaks it: the ranges' begin and end alone were 8 bytes a cell, 73 MiB
# here (the peaks measured were 253 MiB against 72 before the change, 69 against 72 after it).
# Usage: sparse_grid_memory.sh SLUICE_EXE SOURCE_DIR
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
case_file="$src/perf/memory/sparse_domain_3d.toml"
small=(--set 'domain.hi=[1.0,1.0,1.0]' --set 'walls.tank_hi=[1.0,1.0,1.0]'
    --set 'blocks[0].lo=[0.3,0.3,0.0]' --set 'blocks[0].hi=[0.7,0.7,0.4]')

peak_kib() { # out_dir extra-args...
    local out=$1
    shift
    /usr/bin/time -f %M -o "$work/$(basename "$out").kib" "$exe" run "$case_file" --out "$out" \
        --threads 1 -q --set output.snapshots=false "$@" ||
        fail "the run into $out failed"
    tail -1 "$work/$(basename "$out").kib"
}
large=$(peak_kib "$work/large")
compact=$(peak_kib "$work/compact" "${small[@]}")
echo "peak resident: 20 m tank $((large / 1024)) MiB, 1 m tank $((compact / 1024)) MiB"
[ "$large" -le $((compact + 16 * 1024)) ] ||
    fail "the 20 m tank peaks at $((large / 1024)) MiB, more than 16 MiB above the 1 m tank's $((compact / 1024)) MiB"
exit $failures
