#!/usr/bin/env bash
# SIGKILL at random moments never leaves a corrupt latest checkpoint: a run writing a
# checkpoint after every step is killed again and again (often in the middle of a write); after
# each kill the run is continued from whatever checkpoint.h5 is there, which must open (a
# refusal is exit code 2). The finished results must be byte-identical to an uninterrupted
# run's.
# Nothing here depends on the machine's speed: each round waits until the run has replaced the
# checkpoint twice (so the checkpoint's step has advanced since the last kill), times that
# last step-and-write cycle, and kills at a uniformly random moment of the next cycle, so on a
# fast or a loaded machine alike a kill lands in a step or in a write in proportion to the
# time each takes. Every round must leave a checkpoint of a later step than the round before.
# The random delays are printed with their seed (SLUICE_TEST_SEED reproduces them).
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
now_us() { echo $(($(date +%s%N) / 1000)); }
# Waits (at most 120 s) until the checkpoint differs from $1 or the run $2 has ended; the new
# identity is left in $seen.
wait_for_new_checkpoint() {
    local before=$1 pid=$2 deadline=$(($(date +%s) + 120))
    seen=$before
    while kill -0 "$pid" 2>/dev/null; do
        seen=$(checkpoint_id)
        [ "$seen" == "$before" ] || return 0
        [ "$(date +%s)" -lt $deadline ] || return 1
        sleep 0.002
    done
}

out="$work/kill"
kills=0 restarts=0 finished=0 mid_write=0 last_step=-1
for round in $(seq 1 12); do
    if [ -f "$out/checkpoint.h5" ]; then
        args=(--restart "$out")
        restarts=$((restarts + 1))
    else
        args=(--out "$out")
    fi
    "$exe" run "$case_file" "${args[@]}" "${sets[@]}" --set checkpoint.every_steps=1 \
        2>"$work/err.txt" &
    pid=$!
    wait_for_new_checkpoint "$(checkpoint_id)" $pid || fail "round $round: no checkpoint in 120 s"
    t1=$(now_us)
    wait_for_new_checkpoint "$seen" $pid || fail "round $round: no second checkpoint in 120 s"
    cycle=$(($(now_us) - t1 + 1)) # one step and one write (or a few, if the polling missed some)
    delay=$(((RANDOM * 32768 + RANDOM) % cycle))
    sleep "$(printf '%d.%06d' $((delay / 1000000)) $((delay % 1000000)))"
    kill -KILL $pid 2>/dev/null && kills=$((kills + 1))
    { wait $pid; } 2>/dev/null
    code=$?
    # A temporary file left behind: the kill landed while the next checkpoint was being written.
    tmp=""
    [ -e "$out/.checkpoint.h5.tmp" ] && tmp=", in a write" && mid_write=$((mid_write + 1))
    step=$(h5dump -a /step "$out/checkpoint.h5" 2>/dev/null | awk '/\(0\):/ {print $2}')
    echo "round $round: ${args[0]}, killed $delay us into a $cycle us cycle$tmp, exit $code," \
        "checkpoint at step ${step:-none}"
    [ $code -eq 2 ] && fail "round $round: the checkpoint was refused: $(cat "$work/err.txt")"
    [ -n "$step" ] || fail "round $round: no readable checkpoint step"
    [ -n "$step" ] && [ "$step" -gt "$last_step" ] ||
        fail "round $round: checkpoint at step ${step:-none}, not after the last round's $last_step"
    last_step=${step:-$last_step}
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
    echo "checkpoint_sigkill: $kills kills ($mid_write in a write), $restarts restarts," \
        "$n snapshots and probes identical"
fi
exit $failures
