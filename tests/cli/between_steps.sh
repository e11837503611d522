#!/usr/bin/env bash
# perf/strong_scaling/between_steps.py on a hand-made 2-rank trace with known answers (ms):
# rank 0: graphs [0, 10), [20, 30), [32, 40); after the first, a reduction [10, 16) with the
#   bookkeeping [10, 11) inside it, a rebuild [16, 19) holding migrate [16, 17) and halo
#   counts [17, 18), nothing in [19, 20); after the second, a reduction [30, 32).
# rank 1 (its clock 100 ms off): graphs [100, 112), [120, 130), [133, 140); reductions
#   [112, 114) and [130, 133), nothing in [114, 120).
# Usage: between_steps.sh SLUICE_EXE SOURCE_DIR (the executable is not used)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
ev() { # pid tid name start_ms dur_ms step
    printf '{"name": "%s", "ph": "X", "pid": %d, "tid": %d, "ts": %d, "dur": %d, "args": {"step": %d}},\n' \
        "$3" "$1" "$2" $(($4 * 1000)) $(($5 * 1000)) "$6"
}
{
    echo '{"traceEvents": ['
    ev 0 0 density 0 10 1
    ev 0 10000 "send reduce to" 10 6 2
    ev 0 10000 bookkeeping 10 1 2
    ev 0 10000 rebuild 16 3 2
    ev 0 10000 "send migrate to" 16 1 2
    ev 0 10000 "send halo counts to" 17 1 2
    ev 0 0 density 20 10 2
    ev 0 10000 "send reduce to" 30 2 3
    ev 0 0 density 32 8 3
    ev 1 0 density 100 12 1
    ev 1 10000 "send reduce to" 112 2 2
    ev 1 0 density 120 10 2
    ev 1 10000 "send reduce to" 130 3 3
    ev 1 0 density 133 7 3
    echo '{"name": "process_name", "ph": "M", "pid": 0, "args": {"name": "rank 0"}}'
    echo ']}'
} >"$work/trace.json"
/usr/bin/python3 "$src/perf/strong_scaling/between_steps.py" "$work/trace.json" --skip 0 --json \
    >"$work/out.json"
/usr/bin/python3 - "$work/out.json" <<'PY'
import json, sys
o = json.load(open(sys.argv[1]))
def near(a, b):
    return abs(a - b) < 1e-12
r0, r1 = o["0"], o["1"]
# Rank 0: loop 32, graphs 20, gaps 10 + 2; reduce 6 + 2, migrate 1, halo counts 1, the rebuild's
# own 1 (19 - 16 minus the messages), bookkeeping 0 (inside the reduce; whole 1), other 1.
assert r0["steps"] == 2, r0
assert near(r0["loop_s"], 0.032) and near(r0["graphs_s"], 0.020), r0
assert near(r0["between_s"], 0.012), r0
k = r0["by_kind_s"]
assert near(k["reduce"], 0.008) and near(k["migrate"], 0.001), k
assert near(k["halo counts"], 0.001) and near(k["rebuild"], 0.001), k
assert near(k["bookkeeping"], 0.0) and near(r0["work_whole_s"]["bookkeeping"], 0.001), r0
assert near(r0["other_s"], 0.001), r0
# Reductions: first 6 ms on rank 0, 2 on rank 1 (least 2: rank 0 waited 4); second 2 and 3
# (least 2: rank 1 waited 1). Latency 2 + 2 on both.
assert near(r0["reduce_waiting_for_last_rank_s"], 0.004), r0
assert near(r1["reduce_waiting_for_last_rank_s"], 0.001), r1
assert near(r0["reduce_after_last_rank_s"], 0.004) and near(r1["reduce_after_last_rank_s"], 0.004)
# Rank 1: loop 33, graphs 12 + 10, gaps 8 + 3, reduce 5, other 6.
assert near(r1["loop_s"], 0.033) and near(r1["graphs_s"], 0.022), r1
assert near(r1["between_s"], 0.011) and near(r1["by_kind_s"]["reduce"], 0.005), r1
assert near(r1["other_s"], 0.006), r1
print("ok between_steps: rank 0 12 ms between (reduce 8, other 1), waits 4 and 1 ms")
PY
