#!/usr/bin/env bash
# Checkpoint/restart and failures across ranks:
#  - a run on 2 ranks stopped by the stop file continues on 1 rank; a run on 1 rank stopped by
#    SIGTERM continues on 2 ranks; a run on 2 ranks whose rank 1 alone gets SIGTERM stops on
#    both ranks at the same step and continues on 3 ranks. Every continued run's snapshots,
#    .xmf and probe CSVs are byte-identical to an uninterrupted one-rank run's.
#  - on 3 ranks, a task of rank 1 that throws in step 4 (--debug-fail-*) brings every rank down
#    with exit code 1 and the message naming rank and step, and a speed above limits.max_speed
#    on any rank stops all with exit code 3 naming the particle; neither hangs (timeout).
# Usage: checkpoint_restart.sh SLUICE_EXE SOURCE_DIR MPIEXEC
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_args.sh"

case_file="$src/cases/dam_break_2d.toml"
sets=(--set particles.dx=0.02 --set time.end_time=0.1 --set time.output_interval=0.025
      --set runtime.rebalance_every=25 --threads 1 --quiet)

run() { # ranks args...
    local ranks=$1
    shift
    SLUICE_TIMEOUT=120 sluice_on "$ranks" run "$case_file" "$@" "${sets[@]}"
}

wait_checkpoint() {
    for _ in $(seq 600); do [ -f "$1/checkpoint.h5" ] && return 0; sleep 0.1; done
    fail "no checkpoint appeared in $1"
}

same_results() { # dir label
    local dir=$1 label=$2 n=0 before=$failures
    for f in "$work/ref"/snapshots/*.h5; do
        cmp -s "$f" "$dir/snapshots/$(basename "$f")" || fail "$label: $(basename "$f") differs"
        n=$((n + 1))
    done
    [ "$(ls "$dir"/snapshots/*.h5 | wc -l)" -eq "$n" ] || fail "$label: snapshot count differs"
    cmp -s "$work/ref/snapshots.xmf" "$dir/snapshots.xmf" || fail "$label: snapshots.xmf differs"
    diff -r "$work/ref/probes" "$dir/probes" >/dev/null || fail "$label: probe CSVs differ"
    [ $failures -eq "$before" ] &&
        echo "ok $label: $n snapshots, xmf and probes identical to the uninterrupted 1-rank run"
}

run 1 --out "$work/ref" || fail "reference run: exit $?"

# 2 ranks, stop file -> 1 rank.
run 2 --out "$work/a" --set checkpoint.every_steps=20 2>"$work/a.txt" &
pid=$!
wait_checkpoint "$work/a"
# Rank 0 looks for the stop file at most every 200 ms, and the run may end soon after its
# first checkpoint: freeze the ranks (not mpiexec, which does not pass SIGSTOP on) while the
# file appears, for longer than that interval, as tests/cli/checkpoint_restart.sh does.
ranks=($(pgrep -f "^$exe run .*--out $work/a "))
[ ${#ranks[@]} -eq 2 ] || fail "expected 2 rank processes, found ${#ranks[@]}"
kill -STOP "${ranks[@]}"
touch "$work/a/stop"
sleep 0.3
kill -CONT "${ranks[@]}"
wait $pid
code=$?
[ $code -eq 4 ] || fail "2 ranks, stop file: exit code $code, expected 4 $(cat "$work/a.txt")"
grep -q "stopped by the stop file" "$work/a.txt" || fail "2 ranks: stop message missing"
run 1 --restart "$work/a" || fail "restart of a 2-rank checkpoint on 1 rank: exit $?"
same_results "$work/a" "2 ranks stopped, continued on 1"

# 1 rank, SIGTERM -> 2 ranks.
"$exe" run "$case_file" --out "$work/b" "${sets[@]}" --set checkpoint.every_steps=20 \
    2>/dev/null &
pid=$!
wait_checkpoint "$work/b"
kill -TERM $pid
wait $pid
code=$?
[ $code -eq 4 ] || fail "1 rank, SIGTERM: exit code $code, expected 4"
run 2 --restart "$work/b" || fail "restart of a 1-rank checkpoint on 2 ranks: exit $?"
same_results "$work/b" "1 rank stopped, continued on 2"

# 2 ranks, SIGTERM to rank 1's process only (as a batch system may deliver it) -> 3 ranks.
"$mpiexec" --oversubscribe -np 2 "$exe" run "$case_file" --out "$work/c" "${sets[@]}" \
    --set checkpoint.every_steps=20 2>"$work/c.txt" &
pid=$!
wait_checkpoint "$work/c"
ranks=($(pgrep -P $pid -f "$exe"))
[ ${#ranks[@]} -eq 2 ] || fail "expected 2 rank processes under mpiexec, found ${#ranks[@]}"
kill -TERM "${ranks[1]}"
wait $pid
code=$?
[ $code -eq 4 ] || fail "SIGTERM to one of 2 ranks: exit code $code, expected 4"
grep -q "stopped by a signal to another rank\|stopped by SIGTERM" "$work/c.txt" ||
    fail "one-rank SIGTERM: message missing: $(cat "$work/c.txt")"
run 3 --restart "$work/c" || fail "restart of a 2-rank checkpoint on 3 ranks: exit $?"
same_results "$work/c" "2 ranks (one signalled) stopped, continued on 3"

# A failing task on rank 1 of 3: every rank stops, exit code 1, the message, no hang.
run 3 --out "$work/fail" --debug-fail-rank 1 --debug-fail-step 4 2>"$work/fail.txt"
code=$?
[ $code -eq 1 ] || fail "debug failure on rank 1: exit code $code, expected 1 $(cat "$work/fail.txt")"
grep -q "step 4: deliberate failure of rank 1 in step 4 (--debug-fail-rank/--debug-fail-step) (on rank 1)" \
    "$work/fail.txt" || fail "debug failure message: $(cat "$work/fail.txt")"
grep -q "state before the failing step in" "$work/fail.txt" || fail "debug failure: no snapshot"
echo "ok failing task on rank 1 of 3: exit code $code"

# A blow-up on 3 ranks: exit code 3 with the particle, on whichever rank it is.
run 3 --out "$work/fast" --set limits.max_speed=0.3 2>"$work/fast.txt"
code=$?
[ $code -eq 3 ] || fail "speed limit on 3 ranks: exit code $code, expected 3"
grep -Eq "particle [0-9]+ reached a speed of .* at step [0-9]+, t = .*x = \[.*\(on rank [0-2]\)" \
    "$work/fast.txt" || fail "3-rank blow-up message: $(cat "$work/fast.txt")"
echo "ok blow-up on 3 ranks: exit code $code"

if [ $failures -eq 0 ]; then echo "checkpoint_restart (MPI): all checks passed"; fi
exit $failures
