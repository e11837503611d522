#!/usr/bin/env bash
# The edges of a real trace: a 2-rank and a 1-rank run of a small dam break with --trace, read
# by perf/strong_scaling/critical_path.py. Exact invariants of the recorded times: every
# dependency ended before its dependent started; every halo message completed on its receiver
# after its sender posted it, was posted after its pack ended and completed before its unpack
# started (one clock origin for all ranks); every message's flow has a start and a finish; the
# chain is no longer than the step; on 2 ranks chains cross ranks, on 1 rank none does. The
# other readers of the trace still read it. Usage: critical_path_run.sh SLUICE_EXE SOURCE_DIR MPIEXEC
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_args.sh"
tools="$src/perf/strong_scaling"
small=(--threads 1 -q --set particles.dx=0.02 --set time.end_time=0.01)
for r in 1 2; do
    sluice_on $r run "$src/cases/dam_break_2d.toml" --out "$work/r$r" "${small[@]}" \
        --trace "$work/r$r.json" || fail "$r rank(s): exit code $?"
    /usr/bin/python3 "$tools/critical_path.py" "$work/r$r.json" --skip 0 --json \
        >"$work/cp$r.json" || fail "critical_path.py on $r rank(s): exit code $?"
done
/usr/bin/python3 - "$work/cp1.json" "$work/cp2.json" "$work/r2.json" <<'PY' || fail "invariants"
import json, sys
one, two = (json.load(open(p)) for p in sys.argv[1:3])
for o, ranks in ((one, 1), (two, 2)):
    c = o["checks"]
    assert len(o["ranks"]) == ranks and o["steps"] > 10, (ranks, o["steps"])
    assert c["dependency_edges"] > 0 and c["dependency_violations"] == 0, c
    assert c["message_violations"] == 0 and c["unmatched_messages"] == 0, c
    for r in o["rows"]:
        assert r["chain_s"] <= r["step_s"] + 1e-8, r
        assert r["compute_s"] > 0 and r["tasks"] >= 4, r  # at least one task per stage
assert one["checks"]["message_edges"] == 0
assert all(r["rounds"] == 0 and r["bytes"] == 0 for r in one["rows"])
assert two["checks"]["message_edges"] > 0
# Every message of a 2-rank step joins the ranks; the longest chain crosses at least once
# (the state message comes first, and every stage of a boundary group waits for a message).
assert all(r["rounds"] >= 1 and r["bytes"] > 0 for r in two["rows"]), \
    [r["rounds"] for r in two["rows"]]
events = json.load(open(sys.argv[3]))["traceEvents"]
starts = [e["id"] for e in events if e.get("ph") == "s"]
ends = [e["id"] for e in events if e.get("ph") == "f"]
assert starts and sorted(starts) == sorted(ends) and len(set(starts)) == len(starts)
print(f"ok: {two['steps']} steps, {two['checks']['message_edges']} message edges, rounds "
      f"{min(r['rounds'] for r in two['rows'])}..{max(r['rounds'] for r in two['rows'])}")
PY
for tool in serial_share.py between_steps.py post_delay.py core_speed.py; do
    /usr/bin/python3 "$tools/$tool" "$work/r2.json" >"$work/$tool.txt" 2>&1 ||
        fail "$tool on the trace: $(tail -3 "$work/$tool.txt")"
done
if [ $failures -eq 0 ]; then echo "critical_path_run: all checks passed"; fi
exit $failures
