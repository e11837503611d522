#!/usr/bin/env bash
# SIGKILL at random moments never leaves a corrupt latest checkpoint: a run writing a
# checkpoint after every step is killed again and again (often in the middle of a write); after
# each kill the run is continued from whatever checkpoint.h5 is there, which must open (a
# refusal is exit code 2). The finished results must be byte-identical to an uninterrupted
# run's. Each kill waits until the run has replaced the checkpoint at least once, then lands
# at a random moment of the following steps and writes, so every round makes progress however
# slow or loaded the machine is. The random delays are printed with their seed
# (SLUICE_TEST_SEED reproduces them).
# Needs h5dump (hdf5-tools) to print the checkpoint's step.
# Usage: checkpoint_sigkill.sh <sluice executable> <source dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"

case_file="$src/cases/dam_break_2d.toml"
sets=(--set particles.dx=0.02 --set time.end_time=0.2 --set time.output_interval=0.05
      --threads 1 --quiet)
seed=${SLUICE_TEST_SEED:-$$}
RANDOM=$seed
echo "seed $seed"

"$exe" run "$case_file" --out "$work/ref" "${sets[@]}" || fail "reference run: exit $?"

# The checkpoint file's identity: the write protocol renames a finished temporary file over it,
# so a new checkpoint changes its inode or its change time.
checkpoint_id() { stat -c '%i %z' "$out/checkpoint.h5" 2>/dev/null || echo none; }
# Waits (at most 120 s) until the checkpoint differs from $1 or the run $2 has ended.
wait_for_new_checkpoint() {
    local before=$1 pid=$2 waited=0
    while kill -0 "$pid" 2>/dev/null && [ "$(checkpoint_id)" == "$before" ]; do
        sleep 0.005
        waited=$((waited + 1))
        [ $waited -lt 24000 ] || return 1
    done
}

out="$work/kill"
kills=0 restarts=0 finished=0 advanced=0 last_step=""
for round in $(seq 1 12); do
    if [ -f "$out/checkpoint.h5" ]; then
        args=(--restart "$out")
        restarts=$((restarts + 1))
    else
        args=(--out "$out")
    fi
    before=$(checkpoint_id)
    "$exe" run "$case_file" "${args[@]}" "${sets[@]}" --set checkpoint.every_steps=1 \
        2>"$work/err.txt" &
    pid=$!
    wait_for_new_checkpoint "$before" $pid || fail "round $round: no new checkpoint in 120 s"
    ms=$((RANDOM % 40)) # a few steps' worth: often in the middle of the next write
    delay=$(printf '0.%03d' $ms)
    sleep "$delay"
    kill -KILL $pid 2>/dev/null && kills=$((kills + 1))
    { wait $pid; } 2>/dev/null
    code=$?
    step=$(h5dump -a /step "$out/checkpoint.h5" 2>/dev/null | awk '/\(0\):/ {print $2}')
    echo "round $round: ${args[0]}, killed ${delay} s after a new checkpoint, exit $code, checkpoint at step ${step:-none}"
    [ -n "$step" ] && [ "$step" != "$last_step" ] && advanced=$((advanced + 1)) && last_step=$step
    [ $code -eq 2 ] && fail "round $round: the checkpoint was refused: $(cat "$work/err.txt")"
    if [ $code -eq 0 ]; then
        finished=1
        break
    fi
    [ $code -eq 137 ] || fail "round $round: exit code $code, expected 137 (SIGKILL) or 0"
done
if [ $finished -eq 0 ]; then
    "$exe" run "$case_file" --restart "$out" "${sets[@]}" 2>"$work/err.txt" ||
        fail "final restart: exit $? $(cat "$work/err.txt")"
fi
[ $kills -ge 5 ] || fail "only $kills kills landed while the run was going"
[ $restarts -ge 3 ] || fail "only $restarts restarts from a checkpoint"
[ $advanced -ge 3 ] || fail "the checkpoint advanced only $advanced times between kills"

n=0
for f in "$work/ref"/snapshots/*.h5; do
    cmp -s "$f" "$out/snapshots/$(basename "$f")" || fail "$(basename "$f") differs"
    n=$((n + 1))
done
[ "$(ls "$out"/snapshots/*.h5 | wc -l)" -eq "$n" ] || fail "snapshot count differs"
cmp -s "$work/ref/snapshots.xmf" "$out/snapshots.xmf" || fail "snapshots.xmf differs"
diff -r "$work/ref/probes" "$out/probes" >/dev/null || fail "probe CSVs differ"
ls -a "$out" "$out/snapshots" | grep -q '\.tmp$' && fail "temporary files left behind"

if [ $failures -eq 0 ]; then
    echo "checkpoint_sigkill: $kills kills, $restarts restarts, $n snapshots and probes identical"
fi
exit $failures
