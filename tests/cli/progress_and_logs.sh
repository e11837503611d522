#!/usr/bin/env bash
# What a user sees while a case runs: a progress line rewritten in place on a terminal, plain
# lines in a batch job, nothing with --quiet, every log line with --verbose; and the per-rank
# log file results/<case>/logs/rank_0.log in every mode.
# Usage: progress_and_logs.sh <sluice executable> <source dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
short=(--threads 1 --set time.end_time=0.01 --set time.output_interval=0.005)
case_file="$src/cases/dam_break_2d.toml"

# Batch job (stderr is a file): plain lines, no carriage return, the done line, a log file
# with the start, the progress and the end, and no debug lines.
"$exe" run "$case_file" --out "$work/batch" "${short[@]}" >"$work/batch.out" 2>"$work/batch.err" ||
    fail "batch run: exit code $?"
grep -q $'\r' "$work/batch.err" && fail "batch: carriage return in a non-terminal log"
grep -qE '^step 1  t [0-9.e-]+/0.01 s  [0-9.]+%  dt [0-9.e+-]+ s  [0-9.e+-]+ pstep/s  ETA ' \
    "$work/batch.err" || fail "batch: no first progress line: $(cat "$work/batch.err")"
grep -qE '^step [0-9]+  t 0.01[0-9]*/0.01 s  100.0%.*  wall [0-9]+s$' "$work/batch.err" ||
    fail "batch: no final progress line: $(cat "$work/batch.err")"
grep -q '^sluice: done: ' "$work/batch.err" || fail "batch: no done line"
[ ! -s "$work/batch.out" ] || fail "batch: progress went to stdout: $(cat "$work/batch.out")"
log="$work/batch/logs/rank_0.log"
[ -f "$log" ] || fail "batch: no $log"
grep -q '\[rank 0\] \[info\] case dam_break_2d .*rank 0 of 1' "$log" || fail "log: no start line"
grep -q '\[info\] step 1  t ' "$log" || fail "log: no progress line"
grep -q '\[info\] done: [0-9]* steps' "$log" || fail "log: no done line"
grep -q '\[debug\]' "$log" && fail "log: debug lines without --verbose"

# --quiet: nothing at all on the terminal; the log file is still complete.
"$exe" run "$case_file" --out "$work/quiet" "${short[@]}" --quiet >"$work/quiet.out" \
    2>"$work/quiet.err" || fail "quiet run: exit code $?"
[ ! -s "$work/quiet.err" ] || fail "--quiet printed: $(cat "$work/quiet.err")"
[ ! -s "$work/quiet.out" ] || fail "--quiet printed on stdout: $(cat "$work/quiet.out")"
grep -q '\[info\] done: ' "$work/quiet/logs/rank_0.log" || fail "--quiet: log file incomplete"

# --verbose: every log line (snapshots written) on the terminal, debug lines in the file.
"$exe" run "$case_file" --out "$work/verbose" "${short[@]}" --verbose 2>"$work/verbose.err" ||
    fail "verbose run: exit code $?"
[ "$(grep -c '^sluice: snapshot .*snap_00000[0-2].h5 at t = ' "$work/verbose.err")" -eq 3 ] ||
    fail "--verbose: expected 3 snapshot lines: $(cat "$work/verbose.err")"
grep -q '^sluice: done: ' "$work/verbose.err" || fail "--verbose: no done line"
grep -q '\[debug\] snapshot ' "$work/verbose/logs/rank_0.log" || fail "--verbose: no debug lines in the log"

# --quiet and --verbose contradict each other: a usage error.
"$exe" run "$case_file" --quiet --verbose >/dev/null 2>&1
rc=$?
[ $rc -eq 2 ] || fail "--quiet --verbose: exit code $rc, expected 2"

# On a terminal (a pseudo-terminal from script(1)): the line is rewritten with \r.
if command -v script >/dev/null; then
    script -qefc "$(printf '%q ' "$exe" run "$case_file" --out "$work/tty" "${short[@]}")" \
        /dev/null >"$work/tty.txt" 2>&1 || fail "terminal run: exit code $?"
    grep -q $'\rstep ' "$work/tty.txt" || fail "terminal: the progress line is not rewritten with \\r"
    # The final state ends the line: the done line starts on a fresh one.
    grep -q 'wall [0-9]*s.*' "$work/tty.txt" || fail "terminal: no final progress line"
else
    echo "note: script(1) not found; terminal mode not checked"
fi

if [ $failures -eq 0 ]; then echo "progress_and_logs: all checks passed"; fi
exit $failures
