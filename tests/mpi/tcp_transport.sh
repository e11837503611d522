#!/usr/bin/env bash
# Ranks that talk over TCP, as ranks on different nodes of a cluster do: Open MPI limited to its
# TCP transport over the loopback interface (`--mca pml ob1 --mca btl tcp,self`: no shared
# memory between ranks), 4 ranks placed as two "nodes" of 2 slots each, must write snapshots
# and probe files byte-identical to one rank, with the balancer moving the cut points so that
# migration and the changed halos travel over TCP too.
# Usage: tcp_transport.sh SLUICE_EXE SOURCE_DIR MPIEXEC
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_args.sh"
source "$(dirname "${BASH_SOURCE[0]}")/lib/same_results.sh"

args=(run "$src/cases/dam_break_2d.toml" --threads 1 -q --set particles.dx=0.02
      --set time.end_time=0.06 --set time.output_interval=0.015 --set runtime.rebalance_every=25)
"$exe" "${args[@]}" --out "$work/one"
"$mpiexec" --oversubscribe -np 4 --host localhost:2,127.0.0.1:2 \
    --mca pml ob1 --mca btl tcp,self --mca btl_tcp_if_include lo \
    "$exe" "${args[@]}" --out "$work/tcp"

same_results "$work/one" "$work/tcp" "4 ranks over TCP against 1 rank"
grep -q '"particles_moved"' "$work/tcp/summary.json" ||
    { echo "FAIL: no rebalance happened on 4 ranks"; exit 1; }
grep -q '"ranks": 4' "$work/tcp/summary.json" || { echo "FAIL: not 4 ranks"; exit 1; }
echo "ok: 4 ranks over TCP (two nodes of 2), $snaps snapshots and probes identical to 1 rank"
