#!/usr/bin/env bash
# perf/strong_scaling/core_speed.py on hand-made traces with known answers.
# Usage: core_speed.sh SLUICE_EXE SOURCE_DIR (the executable is not used)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
# Two ranks, three steps; task time per step rank 0: 10, 10, 20 ms; rank 1: 10, 20, 10 ms
# (rank 1's step 2 in two tasks; the main thread's slices do not count).
cat >"$work/two_ranks.json" <<'JSON'
{"traceEvents": [
 {"name": "density", "ph": "X", "pid": 0, "tid": 1, "ts": 0, "dur": 10000, "args": {"group": 0, "step": 1}},
 {"name": "density", "ph": "X", "pid": 1, "tid": 1, "ts": 0, "dur": 10000, "args": {"group": 0, "step": 1}},
 {"name": "density", "ph": "X", "pid": 0, "tid": 1, "ts": 20000, "dur": 10000, "args": {"group": 0, "step": 2}},
 {"name": "density", "ph": "X", "pid": 1, "tid": 1, "ts": 20000, "dur": 12000, "args": {"group": 0, "step": 2}},
 {"name": "accel", "ph": "X", "pid": 1, "tid": 1, "ts": 32000, "dur": 8000, "args": {"group": 0, "step": 2}},
 {"name": "send reduce to", "ph": "X", "pid": 0, "tid": 10000, "ts": 30000, "dur": 10000, "args": {"peer": -1, "bytes": 8, "step": 2}},
 {"name": "density", "ph": "X", "pid": 0, "tid": 1, "ts": 40000, "dur": 20000, "args": {"group": 0, "step": 3}},
 {"name": "density", "ph": "X", "pid": 1, "tid": 1, "ts": 40000, "dur": 10000, "args": {"group": 0, "step": 3}}
]}
JSON
# Two independent one-rank runs: A steps of 10 ms (0-30 ms), B steps of 20 ms (0-40 ms).
cat >"$work/a.json" <<'JSON'
{"traceEvents": [
 {"name": "density", "ph": "X", "pid": 0, "tid": 0, "ts": 0, "dur": 10000, "args": {"group": 0, "step": 1}},
 {"name": "density", "ph": "X", "pid": 0, "tid": 0, "ts": 10000, "dur": 10000, "args": {"group": 0, "step": 2}},
 {"name": "density", "ph": "X", "pid": 0, "tid": 0, "ts": 20000, "dur": 10000, "args": {"group": 0, "step": 3}}
]}
JSON
cat >"$work/b.json" <<'JSON'
{"traceEvents": [
 {"name": "density", "ph": "X", "pid": 0, "tid": 0, "ts": 5000, "dur": 20000, "args": {"group": 0, "step": 1}},
 {"name": "density", "ph": "X", "pid": 0, "tid": 0, "ts": 25000, "dur": 20000, "args": {"group": 0, "step": 2}}
]}
JSON
tool="$src/perf/strong_scaling/core_speed.py"
/usr/bin/python3 "$tool" "$work/two_ranks.json" --skip 0 --json >"$work/two.json"
/usr/bin/python3 "$tool" --independent "$work/a.json" "$work/b.json" --skip 0 --json >"$work/ind.json"
/usr/bin/python3 - "$work/two.json" "$work/ind.json" <<'PY'
import json, sys
two = json.load(open(sys.argv[1]))
ind = json.load(open(sys.argv[2]))
near = lambda a, b: abs(a - b) < 1e-9
# Medians 10 and 10 ms: no work imbalance. Per step, work stealing takes 2 / (1/b0 + 1/b1):
# 10, 13.33, 13.33 ms (sum 36.67); the static split max(b0, b1): 10, 20, 20 (sum 50).
assert near(two["work_imbalance"], 1.0), two
assert near(two["speed_bound"], (10 + 2 * 40 / 3) / 50), two
assert near(two["ratio_median"], 2.0) and near(two["share_above_1.1"], 2 / 3), two
# Re-split every step by the last step's speeds: step 1 equal (10), step 2 still equal (20),
# step 3 two thirds to rank 0 which has slowed to 20: (2/3) * 2 * 20 = 26.67 ms.
assert near(two["chased_bound"]["1"], (10 + 2 * 40 / 3) / (10 + 20 + 80 / 3)), two
# Independent runs aligned on their first steps; 10-ms samples at 0, 10, 20 ms (B ends at
# 40 ms after its start, A at 30): every sample 10 against 20 ms, bound 13.33 / 20.
assert ind["samples"] == 4 and near(ind["ratio_median"], 2.0), ind
assert near(ind["speed_bound"], 2 / 3), ind
print("ok core_speed: bound %.4f, chased %.4f, independent %.4f"
      % (two["speed_bound"], two["chased_bound"]["1"], ind["speed_bound"]))
PY
