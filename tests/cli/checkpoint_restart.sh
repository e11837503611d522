#!/usr/bin/env bash
# Checkpoint/restart and faults on one rank, through the real executable:
#  - a stop file or SIGTERM stops a run with exit code 4 after writing a checkpoint; the run
#    continued with --restart writes snapshots, .xmf and probe CSVs byte-identical to an
#    uninterrupted run's;
#  - checkpoints of another case, of another format version, truncated, or missing are refused
#    with exit code 2 and the reason;
#  - a blow-up (speed above limits.max_speed) stops with exit code 3 naming particle, step,
#    time, position and the quantity, and leaves a last snapshot even with snapshots off;
#  - a task that throws (--debug-fail-*) stops the run with exit code 1 and its message;
#  - a rolling tank (moving walls) continues after SIGTERM with identical results.
# Usage: checkpoint_restart.sh <sluice executable> <source dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"

case_file="$src/cases/dam_break_2d.toml"
sets=(--set particles.dx=0.02 --set time.end_time=0.1 --set time.output_interval=0.025 --quiet)

same_results() { # reference other label
    local ref=$1 dir=$2 label=$3 n=0 before=$failures
    for f in "$ref"/snapshots/*.h5; do
        cmp -s "$f" "$dir/snapshots/$(basename "$f")" || fail "$label: $(basename "$f") differs"
        n=$((n + 1))
    done
    [ "$(ls "$dir"/snapshots/*.h5 | wc -l)" -eq "$n" ] || fail "$label: snapshot count differs"
    cmp -s "$ref/snapshots.xmf" "$dir/snapshots.xmf" || fail "$label: snapshots.xmf differs"
    diff -r "$ref/probes" "$dir/probes" >/dev/null || fail "$label: probe CSVs differ"
    [ -f "$dir/summary.json" ] || fail "$label: no summary.json after the restart"
    [ $failures -eq "$before" ] &&
        echo "ok $label: $n snapshots, xmf and probes identical to the uninterrupted run"
}

# Waits (at most 60 s) for the first checkpoint of a run started in the background.
wait_checkpoint() {
    for _ in $(seq 600); do [ -f "$1/checkpoint.h5" ] && return 0; sleep 0.1; done
    fail "no checkpoint appeared in $1"
}

"$exe" run "$case_file" --out "$work/ref" "${sets[@]}" --threads 1 || fail "reference run: exit $?"
[ ! -e "$work/ref/checkpoint.h5" ] || fail "a run without [checkpoint] settings wrote one"

# Stop file: exit 4, a message naming the checkpoint and the command that continues.
"$exe" run "$case_file" --out "$work/stop" "${sets[@]}" --set checkpoint.every_steps=20 \
    2>"$work/stop.txt" &
pid=$!
wait_checkpoint "$work/stop"
# The run looks for the stop file at most every 200 ms and, on a quiet machine, finishes about
# 0.3 s after its first checkpoint: freeze it while the file appears, for longer than that
# interval, so that its next step looks (without this it failed in 2 of 5 runs here).
kill -STOP $pid
touch "$work/stop/stop"
sleep 0.3
kill -CONT $pid
wait $pid
code=$?
[ $code -eq 4 ] || fail "stop file: exit code $code, expected 4"
grep -q "stopped by the stop file after step" "$work/stop.txt" || fail "stop message: $(cat "$work/stop.txt")"
grep -q -- "--restart $work/stop" "$work/stop.txt" || fail "stop message lacks the restart command"
[ ! -e "$work/stop/stop" ] || fail "the stop file was left behind"
[ ! -e "$work/stop/summary.json" ] || fail "a stopped run wrote summary.json"
"$exe" run "$case_file" --restart "$work/stop" "${sets[@]}" || fail "restart after stop: exit $?"
grep -q '"restarted_from_step"' "$work/stop/summary.json" || fail "summary lacks restarted_from_step"
# Wall time over all segments: equal to wall_seconds for a run that never stopped, and larger
# by the first segment's (saved in the checkpoint) after a restart.
wall_segments() { # summary.json -> "wall_seconds wall_seconds_all_segments"
    /usr/bin/python3 -c "import json, sys; d = json.load(open(sys.argv[1])); \
print(d['wall_seconds'], d['extra']['wall_seconds_all_segments'])" "$1"
}
read -r w all <<<"$(wall_segments "$work/ref/summary.json")"
[ "$w" = "$all" ] || fail "uninterrupted run: wall_seconds_all_segments $all != wall_seconds $w"
read -r w all <<<"$(wall_segments "$work/stop/summary.json")"
/usr/bin/python3 -c "import sys; sys.exit(not float(sys.argv[2]) > float(sys.argv[1]) > 0)" "$w" "$all" ||
    fail "restarted run: wall_seconds_all_segments $all not above this segment's $w"
same_results "$work/ref" "$work/stop" "stop file + restart"

# SIGTERM, then a restart with other threads and checkpoint settings (they do not change results).
"$exe" run "$case_file" --out "$work/term" "${sets[@]}" --set checkpoint.every_steps=25 \
    2>"$work/term.txt" &
pid=$!
wait_checkpoint "$work/term"
kill -TERM $pid
wait $pid
code=$?
[ $code -eq 4 ] || fail "SIGTERM: exit code $code, expected 4"
grep -q "stopped by SIGTERM" "$work/term.txt" || fail "SIGTERM message: $(cat "$work/term.txt")"
"$exe" run "$case_file" --restart "$work/term" "${sets[@]}" --threads 2 \
    --set checkpoint.every_steps=7 || fail "restart after SIGTERM: exit $?"
same_results "$work/ref" "$work/term" "SIGTERM + restart"

# A reference run of a case, the same run stopped by SIGTERM after its first checkpoint (every
# EVERY steps) and continued on 2 threads: the same results.
sigterm_restart() { # label case every set...
    local label=$1 case=$2 every=$3 dir="$work/${1// /_}"
    shift 3
    "$exe" run "$case" --out "$dir.ref" "$@" --threads 1 || fail "$label reference: exit $?"
    "$exe" run "$case" --out "$dir" "$@" --threads 1 --set checkpoint.every_steps="$every" \
        2>/dev/null &
    local pid=$!
    wait_checkpoint "$dir"
    kill -TERM $pid
    wait $pid
    local code=$?
    [ $code -eq 4 ] || fail "$label SIGTERM: exit code $code, expected 4"
    "$exe" run "$case" --restart "$dir" "$@" --threads 2 || fail "$label restart: exit $?"
    same_results "$dir.ref" "$dir" "$label SIGTERM + restart"
}

# 3-D: the same through Checkpoint<3>.
sigterm_restart "3-D" "$src/cases/dam_break_3d.toml" 5 \
    --set time.end_time=0.02 --set time.output_interval=0.005 --quiet
# Moving walls: a rolling tank continues on its motion (the walls' poses are functions of time,
# their particles part of the state) with the same results.
sigterm_restart "rolling tank" "$src/cases/sloshing_roll_2d.toml" 50 \
    --set particles.dx=0.01 --set time.end_time=0.15 --set time.output_interval=0.05 \
    --set motions.0.ramp=0 --set motions.0.period=0.4 --quiet
# A free body: its state and last load travel in the checkpoint (its particles with the rest).
sigterm_restart "free body" "$src/cases/box_drop_2d.toml" 60 \
    --set particles.dx=0.02 --set time.end_time=0.25 --set time.output_interval=0.05 --quiet
# Contact: boxes resting on the floor and on each other when the run stops; Bullet's world is
# built afresh every step, so nothing but the bodies' state needs to travel.
sigterm_restart "contact" "$src/tests/data/boxes_contact_2d.toml" 300 --quiet

# Wall-clock cadence: every 0.001 minutes a checkpoint replaces the last; a run that finished
# leaves its last one, from which the end is reached again with the same results.
"$exe" run "$case_file" --out "$work/wall" "${sets[@]}" --threads 1 \
    --set checkpoint.every_minutes=0.001 || fail "every_minutes run: exit $?"
[ -f "$work/wall/checkpoint.h5" ] || fail "every_minutes wrote no checkpoint"
"$exe" run "$case_file" --restart "$work/wall" "${sets[@]}" || fail "restart (wall): exit $?"
same_results "$work/ref" "$work/wall" "every_minutes checkpoint + restart"

# Refusals: exit code 2 and the reason; the folder is not touched.
refused() { # label expected-text dir args...
    local label=$1 text=$2 dir=$3
    shift 3
    "$exe" run "$case_file" --restart "$dir" "${sets[@]}" "$@" 2>"$work/err.txt"
    local c=$?
    [ $c -eq 2 ] || fail "$label: exit code $c, expected 2"
    grep -q "$text" "$work/err.txt" || fail "$label: message lacks '$text': $(cat "$work/err.txt")"
}
cp -r "$work/term" "$work/base"
refused "another case" "written by another case" "$work/base" --set fluid.sound_speed=30
refused "no checkpoint" "no such file" "$work/nothing"
cp -r "$work/base" "$work/cut"
truncate -s 3000 "$work/cut/checkpoint.h5"
refused "truncated" "not a readable HDF5 file" "$work/cut"
cp -r "$work/base" "$work/v2"
/usr/bin/python3 -c "import h5py, sys; h5py.File(sys.argv[1], 'r+').attrs.modify('format_version', 99)" \
    "$work/v2/checkpoint.h5" || fail "could not edit the version"
refused "other version" "format version 99" "$work/v2"
cmp -s "$work/base/snapshots.xmf" "$work/v2/snapshots.xmf" || fail "a refused restart touched the folder"

# Blow-up: a speed limit far below the collapse's speeds stops the run with exit code 3.
"$exe" run "$case_file" --out "$work/fast" "${sets[@]}" --set limits.max_speed=0.3 \
    --set output.snapshots=false 2>"$work/fast.txt"
code=$?
[ $code -eq 3 ] || fail "speed limit: exit code $code, expected 3"
grep -Eq "particle [0-9]+ reached a speed of [0-9.e+-]+ m/s \(limits.max_speed = 0.3 m/s\) at step [0-9]+, t = [0-9.e+-]+ s: x = \[" \
    "$work/fast.txt" || fail "blow-up message: $(cat "$work/fast.txt")"
ls "$work/fast/snapshots/"snap_000000.h5 >/dev/null 2>&1 || fail "no last snapshot with snapshots off"
grep -q "last good state in" "$work/fast.txt" || fail "blow-up message names no snapshot"

# A task that throws: exit code 1 with its message, no hang.
timeout 60 "$exe" run "$case_file" --out "$work/throw" "${sets[@]}" --debug-fail-rank 0 \
    --debug-fail-step 3 2>"$work/throw.txt"
code=$?
[ $code -eq 1 ] || fail "debug failure: exit code $code, expected 1"
grep -q "step 3: deliberate failure of rank 0 in step 3" "$work/throw.txt" ||
    fail "debug failure message: $(cat "$work/throw.txt")"

if [ $failures -eq 0 ]; then echo "checkpoint_restart: all checks passed"; fi
exit $failures
