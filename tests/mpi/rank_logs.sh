#!/usr/bin/env bash
# On several ranks every rank writes its own log (results/<case>/logs/rank_N.log) while only
# rank 0 talks on the terminal. Usage: rank_logs.sh <sluice executable> <source dir> <mpiexec>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_args.sh"

"$mpiexec" --oversubscribe -np 2 "$exe" run "$src/cases/dam_break_2d.toml" --out "$work/out" \
    --threads 1 --set time.end_time=0.005 2>"$work/err.txt" || fail "exit code $?"
for r in 0 1; do
    log="$work/out/logs/rank_$r.log"
    [ -f "$log" ] || { fail "no $log"; continue; }
    grep -q "\[rank $r\] \[info\] case dam_break_2d .*rank $r of 2" "$log" || fail "rank $r: no start line"
    grep -q "\[rank $r\] \[info\] step 1  t " "$log" || fail "rank $r: no progress line"
    grep -q "\[rank $r\] \[info\] done: " "$log" || fail "rank $r: no done line"
done
[ ! -e "$work/out/logs/rank_2.log" ] || fail "a log for a rank that does not exist"
[ "$(grep -c '^sluice: done: ' "$work/err.txt")" -eq 1 ] || fail "the terminal got the done line more than once: $(cat "$work/err.txt")"
[ "$(grep -c '^step 1 ' "$work/err.txt")" -eq 1 ] || fail "progress from more than one rank: $(cat "$work/err.txt")"

if [ $failures -eq 0 ]; then echo "rank_logs: all checks passed"; fi
exit $failures
