#!/usr/bin/env bash
# perf/strong_scaling/critical_path.py on a hand-made 2-rank trace with a known answer (µs):
# rank 0: density g0 [0, 100), pack pressure [100, 110) posted at 115, kick g0 [150, 160);
# rank 1: density g0 [0, 50), density g1 [50, 90), the pressure from rank 0 done at 140,
#   unpack [145, 155), kick g0 [160, 180) after density g0, density g1 and the unpack.
# Longest chain: density (100) -> pack (10) -> message (140 - 115 = 25) -> unpack (10) ->
# kick (20) = 165 µs with 1 message round of 800 bytes; the step spans [0, 180) = 180 µs.
# Floor at L = 2 µs, B = 1e9 B/s: 140 + 2 + 0.8 = 142.8 µs. A second step on which rank 1's
# unpack starts before the message completes must count as one violated message edge.
# Usage: critical_path.sh SLUICE_EXE SOURCE_DIR (the executable is not used)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
task() { # pid tid name ts dur step id preds
    printf '{"name": "%s", "ph": "X", "pid": %d, "tid": %d, "ts": %d, "dur": %d, "args": {"group": 0, "step": %d, "cpu_us": %d, "id": %d, "preds": [%s]}},\n' \
        "$3" "$1" "$2" "$4" "$5" "$6" "$5" "$7" "$8"
}
msg() { # pid name ts dur step src dst role id flow
    printf '{"name": "%s", "ph": "X", "pid": %d, "tid": 10000, "ts": %d, "dur": %d, "args": {"peer": 0, "bytes": 800, "step": %d, "src": %d, "dst": %d, "kind": "pressure", "tag": 1001, "%s": %d, "flow": %d}},\n' \
        "$2" "$1" "$3" "$4" "$5" "$6" "$7" "$8" "$9" "${10}"
}
{
    echo '{"traceEvents": ['
    for step in 1 2; do
        o=$(((step - 1) * 1000)) # the second step 1 ms later; ids of the second run from 10
        b=$(((step - 1) * 10))
        late=$([ "$step" = 2 ] && echo 10 || echo 0) # step 2: the message completes late
        task 0 0 density $o 100 $step $b ""
        task 0 0 "pack pressure" $((o + 100)) 10 $step $((b + 1)) "$b"
        task 0 0 kick $((o + 150)) 10 $step $((b + 2)) "$b,$((b + 1))"
        msg 0 "send pressure to" $((o + 115)) 5 $step 0 1 producer $((b + 1)) $step
        task 1 0 density $o 50 $step $b ""
        task 1 0 density $((o + 50)) 40 $step $((b + 1)) ""
        msg 1 "recv pressure from" $o $((140 + late)) $step 0 1 consumer $((b + 2)) $step
        task 1 0 "unpack pressure" $((o + 145)) 10 $step $((b + 2)) "$b,$((b + 1))"
        task 1 0 kick $((o + 160)) 20 $step $((b + 3)) "$b,$((b + 1)),$((b + 2))"
    done
    echo '{"name": "process_name", "ph": "M", "pid": 0, "args": {"name": "rank 0"}}'
    echo ']}'
} >"$work/trace.json"
/usr/bin/python3 "$src/perf/strong_scaling/critical_path.py" "$work/trace.json" --skip 0 \
    --latency 2e-6 --bandwidth 1e9 --json >"$work/out.json"
/usr/bin/python3 - "$work/out.json" <<'PY'
import json, sys
o = json.load(open(sys.argv[1]))
near = lambda a, b: abs(a - b) < 1e-12
assert o["steps"] == 2, o["steps"]
c = o["checks"]
# Dependency edges per step: rank 0 has 1 + 2, rank 1 has 2 + 3.
assert c["dependency_edges"] == 16 and c["dependency_violations"] == 0, c
assert c["message_edges"] == 2 and c["message_violations"] == 1, c
r = o["rows"][0]
assert near(r["step_s"], 180e-6) and near(r["chain_s"], 165e-6), r
assert near(r["compute_s"], 140e-6) and near(r["message_s"], 25e-6), r
assert r["rounds"] == 1 and r["bytes"] == 800 and r["tasks"] == 4, r
names = [(i["kind"], i.get("rank", i.get("src")), i["name"]) for i in r["chain"]]
assert names == [("task", 0, "density"), ("task", 0, "pack pressure"),
                 ("message", 0, "pressure"), ("task", 1, "unpack pressure"),
                 ("task", 1, "kick")], names
assert near(r["floors"][0]["floor_s"], 142.8e-6), r["floors"]
PY
echo "ok critical_path"
