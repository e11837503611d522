#!/usr/bin/env bash
# domain.particle_exit on a block falling freely out of a wall-less domain
# (tests/data/free_fall_exit.toml): no pressure acts in it, so row k (initial height
# y0 = 0.41 + 0.02 k m) leaves through y = 0 at t = sqrt(2 y0 / g), exactly:
#  - "stop" (the default) stops the run with exit code 3 when the lowest row leaves
#    (t = 0.2891 s), naming the key that would drop such particles, and gives the last good
#    state's spacing (a rigid lattice: nothing crowded, the closest pair 1 dx apart);
#  - "remove" drops the rows as they leave and counts them: by t = 0.3 s two rows (40 of 200
#    particles) have gone, the last snapshot holds the other 160 inside the domain, and
#    mass_final is 4/5 of mass_initial; the projection scheme, whose explicit gravity runs
#    ahead by O(g t dt), may lose the third row too (exact at t = 0.3029 s); the throughput
#    in summary.json counts each step with the particles it started with;
#  - a checkpoint written between the two removals continues to the same snapshot and the
#    same count;
#  - when every particle has left (t = 0.3468 s, the top row) the run stops with exit code 3.
# Usage: particle_exit.sh SLUICE_EXE SOURCE_DIR
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
case_file="$src/tests/data/free_fall_exit.toml"
remove=(--set 'domain.particle_exit="remove"')

# Default: the first particle to leave stops the run.
"$exe" run "$case_file" --out "$work/stop" -q 2>"$work/stop.txt"
code=$?
[ $code -eq 3 ] || fail "particle_exit = \"stop\": exit code $code, expected 3"
grep -q 'reached a position outside the domain .*domain.particle_exit = "remove"' \
    "$work/stop.txt" || fail "stop message: $(cat "$work/stop.txt")"
grep -q 'at step [0-9]*, t = 0.289' "$work/stop.txt" ||
    fail "the lowest row did not leave at t = sqrt(2 * 0.41 / g) = 0.2891 s: $(cat "$work/stop.txt")"
# The failure message gives the last good state's spacing: the block falls as a rigid lattice.
grep -q 'at the last good state 0 of 200 fluid particles (0 %) have a fluid neighbour closer than dx/2, the closest pair is 1 dx apart' \
    "$work/stop.txt" || fail "stop message without the rigid lattice's spacing: $(cat "$work/stop.txt")"

# The final state of a run: fluid count, lowest y, removed count, mass ratio.
final_state() { # results folder
    /usr/bin/python3 - "$1" <<'PY'
import glob, json, sys
import h5py
out = sys.argv[1]
s = json.load(open(f"{out}/summary.json"))
with h5py.File(sorted(glob.glob(f"{out}/snapshots/*.h5"))[-1]) as f:
    y = f["position"][:, 1]
print(len(y), f"{y.min():.6f}", s["fluid_particles_removed"], f"{s['mass_final'] / s['mass_initial']:.12f}")
PY
}

for scheme in wcsph projection; do
    sets=("${remove[@]}")
    [ $scheme = projection ] && sets+=(--set 'numerics.scheme="projection"')
    if ! "$exe" run "$case_file" --out "$work/$scheme" -q "${sets[@]}" 2>"$work/$scheme.txt"; then
        fail "$scheme, particle_exit = \"remove\": $(cat "$work/$scheme.txt")"
        continue
    fi
    read -r n ymin removed ratio <<<"$(final_state "$work/$scheme")"
    # WCSPH's leap-frog falls exactly (two rows); the projection step's explicit gravity runs
    # ahead by O(g t dt), which may take the third row (exact at t = 0.3029 s) out too.
    expected=$([ $scheme = wcsph ] && echo "40" || echo "40 60")
    [[ " $expected " == *" $removed "* ]] || fail "$scheme: $removed removed, expected $expected"
    [ $((n + removed)) = 200 ] || fail "$scheme: $n left + $removed removed is not 200"
    /usr/bin/python3 -c "import sys; sys.exit(abs(float(sys.argv[1]) - int(sys.argv[2]) / 200) > 1e-12)" \
        "$ratio" "$n" || fail "$scheme: mass ratio $ratio for $n of 200 particles left"
    /usr/bin/python3 -c "import sys; sys.exit(not 0 <= float(sys.argv[1]) < 0.02)" "$ymin" ||
        fail "$scheme: the lowest particle left is at y = $ymin (the next row: 0 <= y < 0.02)"
    grep -q "$removed fluid particles left the domain and were removed over the run" \
        "$work/$scheme/logs/rank_0.log" || fail "$scheme: the log does not count the removals"
    # The throughput counts each step's particles: 200 to step 516, 180 to step 530 and 160
    # after (WCSPH), not 200 for every step.
    [ $scheme = wcsph ] && { /usr/bin/python3 - "$work/$scheme/summary.json" <<'PY' ||
import json, sys
s = json.load(open(sys.argv[1]))
n = s["steps"]
done = s["particle_steps_per_second"] * s["wall_seconds"]
expected = 200 * 516 + 180 * (530 - 516) + 160 * (n - 530)
print(f"particle-steps {done:.6g}, expected {expected}")
sys.exit(abs(done / expected - 1) > 1e-9)
PY
        fail "$scheme: particle_steps_per_second does not count the removed particles out"; }
    echo "$scheme: $removed of 200 removed by t = 0.3 s, $n left, lowest at y = $ymin"
done

# A checkpoint between the two removals (step 520: the rows left at steps 516 and 530).
"$exe" run "$case_file" --out "$work/ckpt" -q "${remove[@]}" --set time.end_time=0.293 \
    --set checkpoint.every_steps=520 || fail "run to the checkpoint: exit code $?"
"$exe" run "$case_file" --restart "$work/ckpt" -q "${remove[@]}" ||
    fail "restart: exit code $?"
last=$(basename "$(ls "$work/wcsph/snapshots/"*.h5 | tail -1)")
cmp -s "$work/wcsph/snapshots/$last" "$work/ckpt/snapshots/$last" ||
    fail "the restarted run's last snapshot differs from the uninterrupted run's"
grep -q '"fluid_particles_removed": 40' "$work/ckpt/summary.json" ||
    fail "the restarted run does not count the removals before the checkpoint"

# Every particle gone: nothing left to simulate.
"$exe" run "$case_file" --out "$work/empty" -q "${remove[@]}" --set time.end_time=0.5 \
    2>"$work/empty.txt"
code=$?
[ $code -eq 3 ] || fail "all particles removed: exit code $code, expected 3"
grep -q "every fluid particle has left the domain by step [0-9]*, t = 0.34" "$work/empty.txt" ||
    fail "all particles removed: $(cat "$work/empty.txt")"
exit $failures
