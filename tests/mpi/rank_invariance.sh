#!/usr/bin/env bash
# Results do not depend on the number of ranks or threads: a 2-D and a 3-D case run on
# (ranks, threads) = (1,1), (1,2), (2,1), (3,1), (2,2) must write byte-identical snapshots
# (written in curve order, HDF5 without time stamps) and probe files. The balancer is forced
# to move the cut points every few steps, so the comparison covers states before and after
# rebalances and the migration they cause; the test checks that rebalances really happened,
# some of them between two rebuilds of the Verlet lists (by the positions of the last one).
# Usage: rank_invariance.sh SLUICE_EXE SOURCE_DIR MPIEXEC
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_args.sh"
source "$(dirname "${BASH_SOURCE[0]}")/lib/same_results.sh"

run() { # name ranks threads case args...
    local name=$1 ranks=$2 threads=$3 case=$4
    shift 4
    local out="$work/$name/${ranks}x${threads}"
    [[ $case == */* ]] && case="$src/$case" || case="$src/cases/$case" # tests/data/... or cases/
    sluice_on "$ranks" run "$case" --out "$out" --threads "$threads" -q "$@"
}

check_case() { # name case args...
    local name=$1 case=$2
    shift 2
    for layout in 1x1 1x2 2x1 3x1 2x2; do
        run "$name" "${layout%x*}" "${layout#*x}" "$case" "$@"
    done
    local ref="$work/$name/1x1"
    for layout in 1x2 2x1 3x1 2x2; do
        local dir="$work/$name/$layout"
        same_results "$ref" "$dir" "$name $layout against 1x1"
        if [[ $layout != 1x* ]]; then
            grep -q '"particles_moved"' "$dir/summary.json" ||
                { echo "FAIL $name: no rebalance happened on $layout"; exit 1; }
            grep -q '"at_rebuild": false' "$dir/summary.json" ||
                { echo "FAIL $name: no rebalance between rebuilds on $layout"; exit 1; }
        fi
        echo "ok $name $layout: $snaps snapshots and probes identical to 1x1"
    done
}

check_case dam_break_2d dam_break_2d.toml --set particles.dx=0.02 --set time.end_time=0.1 \
    --set time.output_interval=0.025 --set runtime.rebalance_every=25
# The acoustic damper reads its neighbours' velocities in the density stage (halo state).
check_case damper_2d dam_break_2d.toml --set particles.dx=0.02 --set time.end_time=0.1 \
    --set time.output_interval=0.025 --set runtime.rebalance_every=25 \
    --set numerics.acoustic_damper=0.3
# Every probe kind (point and area pressure, forces and moments on faces, a panel and an
# obstacle, a level, fronts along x and y), sampled every step where the particles are.
check_case probe_kinds_2d tests/data/probe_kinds_2d.toml --set runtime.rebalance_every=20
# Particles leaving the domain and removed (domain.particle_exit = "remove"): a block falls out
# of a wall-less domain row by row until 20 of its 200 particles are left; each removal forces
# a rebuild on every rank in the same step.
check_case free_fall_exit tests/data/free_fall_exit.toml --set 'domain.particle_exit="remove"' \
    --set time.end_time=0.345 --set runtime.rebalance_every=20
for layout in 1x1 2x1 3x1; do
    grep -q '"fluid_particles_removed": 180' "$work/free_fall_exit/$layout/summary.json" ||
        { echo "FAIL free_fall_exit: $layout did not remove 180 particles"; exit 1; }
done
# The default stops at the first exit (t = 0.2891 s) on every rank together; the message gives
# the last good state's spacing, reduced over the ranks: all 200 particles, a rigid lattice.
code=0
sluice_on 3 run "$src/tests/data/free_fall_exit.toml" --out "$work/free_fall_stop" -q \
    2>"$work/free_fall_stop.txt" || code=$?
[[ $code == 3 ]] || { echo "FAIL free_fall_stop: exit code $code on 3 ranks, expected 3"; exit 1; }
grep -q 'at the last good state 0 of 200 fluid particles (0 %) have a fluid neighbour closer than dx/2, the closest pair is 1 dx apart' \
    "$work/free_fall_stop.txt" ||
    { echo "FAIL free_fall_stop: no spacing over all ranks: $(cat "$work/free_fall_stop.txt")"; exit 1; }
# A bed given as a polyline mesh: its wall layers, the fluid block cut to it, a force probe on
# it; then the same bed as reflective segments (particles mirrored in the drift, the drift's
# turned velocities kept from the other groups' continuity rates).
check_case ramp_mesh_2d dam_break_ramp_2d.toml --set particles.dx=0.02 --set time.end_time=0.1 \
    --set time.output_interval=0.025 --set runtime.rebalance_every=25
check_case ramp_reflective_2d tests/data/mesh_loads/ramp_reflective_2d.toml \
    --set particles.dx=0.02 --set time.end_time=0.1 --set time.output_interval=0.025 \
    --set runtime.rebalance_every=25
# Moving walls: a rolling tank (every wall particle moves, changes cells and rank) read by
# gauges and a pressure probe in its frame, a force on its face and its motion; a piston
# paddle (a moving box) in a flume with a damping zone.
check_case sloshing_roll_2d sloshing_roll_2d.toml --set particles.dx=0.01 \
    --set time.end_time=0.2 --set time.output_interval=0.05 --set runtime.rebalance_every=25 \
    --set motions.0.ramp=0 --set motions.0.period=0.4
check_case wave_flume_2d wave_flume_piston_2d.toml --set particles.dx=0.04 \
    --set time.end_time=0.3 --set time.output_interval=0.075 --set runtime.rebalance_every=25 \
    --set motions.0.ramp=0 --set motions.0.wave_period=0.6 --set motions.0.wave_height=0.02
# A free body: a box falls onto the water; its load is summed over whichever ranks hold its
# particles (exact sums: the same bits for any layout) and every rank moves it alike.
check_case box_drop_2d box_drop_2d.toml --set particles.dx=0.02 --set time.end_time=0.3 \
    --set time.output_interval=0.075 --set runtime.rebalance_every=25
# Contact: boxes fall onto the floor and onto each other; every rank steps the same Bullet
# world.
check_case boxes_contact_2d tests/data/boxes_contact_2d.toml --set runtime.rebalance_every=25
check_case dam_break_3d dam_break_3d.toml --set time.end_time=0.02 \
    --set time.output_interval=0.005 --set runtime.rebalance_every=15 \
    --set 'runtime.initial_decomposition="key-range"'

# --trace writes one Chrome/Perfetto trace for all ranks: tasks of every stage on worker
# tracks and messages with peer and size on each rank's MPI track.
"$mpiexec" --oversubscribe -np 2 "$exe" run "$src/cases/dam_break_2d.toml" --out "$work/trace" \
    --threads 1 -q --set particles.dx=0.02 --set time.end_time=0.01 --trace "$work/trace.json"
/usr/bin/python3 - "$work/trace.json" <<'PY'
import json, sys
events = json.load(open(sys.argv[1]))["traceEvents"]
slices = [e for e in events if e.get("ph") == "X"]
ranks = {e["pid"] for e in slices}
names = {e["name"] for e in slices}
assert ranks == {0, 1}, ranks
for stage in ("density", "walls", "accel", "kick", "drift"):
    assert stage in names, stage
msgs = [e for e in slices if e["name"].startswith(("send ", "recv "))]
assert msgs and all("bytes" in e["args"] and "peer" in e["args"] for e in msgs)
assert all(e["dur"] >= 0 for e in slices)
print(f"ok trace: {len(slices)} slices, {len(msgs)} messages, ranks {sorted(ranks)}")
PY
