#!/usr/bin/env bash
# The balancer also acts on a flow at rest, whose Verlet lists are never rebuilt. A hydrostatic
# tank is cut into equal key ranges, so one of two ranks starts with about 2 % of the
# particles. The rebalance must come between rebuilds (by the positions of the last rebuild),
# leave the two ranks nearly equal shares, and change no result: the snapshots stay
# byte-identical to a one-rank run's.
# Usage: balancer_at_rest.sh SLUICE_EXE SOURCE_DIR MPIEXEC
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_args.sh"

args=(--threads 1 -q --set time.end_time=0.02 --set time.output_interval=0.01
    --set 'runtime.initial_decomposition="key-range"' --set 'runtime.balance_cost="particles"')
"$exe" run "$src/cases/hydrostatic_2d.toml" --out "$work/1" "${args[@]}"
"$mpiexec" --oversubscribe -np 2 "$exe" run "$src/cases/hydrostatic_2d.toml" --out "$work/2" \
    "${args[@]}"

/usr/bin/python3 - "$work/2/summary.json" <<'PY'
import json, sys
x = json.load(open(sys.argv[1]))["extra"]
first = x["imbalance_history"][0]["imbalance"]
assert first > 1.5, f"key-range cut should start unbalanced, measured {first:.3f}"
between = [r for r in x["rebalances"] if not r["at_rebuild"]]
assert between, f"no rebalance between rebuilds: {x['rebalances']}"
assert x["list_rebuilds"] <= 2, f"{x['list_rebuilds']} list rebuilds in a tank at rest"
owned = [r["particles_at_end"] for r in x["parallel"]["ranks"]]
share = min(owned) / max(owned)
assert share > 0.9, f"ranks own {owned} particles after the rebalance"
print(f"ok: imbalance {first:.2f} at step 10, rebalanced at step {between[0]['step']} "
      f"between rebuilds ({between[0]['particles_moved']} particles moved), ranks own {owned}")
PY
for f in "$work/1"/snapshots/*.h5; do
    cmp "$f" "$work/2/snapshots/$(basename "$f")" ||
        { echo "FAIL: 2 ranks differ from 1 in $(basename "$f")"; exit 1; }
done
echo "ok: $(ls "$work/1"/snapshots/*.h5 | wc -l) snapshots identical on 1 and 2 ranks"
