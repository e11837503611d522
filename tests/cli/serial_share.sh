#!/usr/bin/env bash
# perf/strong_scaling/serial_share.py on a hand-made trace with known answers: two steps of
# 10 ms on one rank, tasks on two threads covering 6 ms of each (overlapping), a receive that
# is the only thing in flight for 1 ms of the gap of step 1.
# Usage: serial_share.sh SLUICE_EXE SOURCE_DIR (the executable is not used)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
cat >"$work/trace.json" <<'JSON'
{"traceEvents": [
 {"name": "density", "ph": "X", "pid": 0, "tid": 0, "ts": 0, "dur": 4000, "args": {"group": 0, "step": 1}},
 {"name": "accel", "ph": "X", "pid": 0, "tid": 1, "ts": 2000, "dur": 4000, "args": {"group": 1, "step": 1}},
 {"name": "recv state from", "ph": "X", "pid": 0, "tid": 10000, "ts": 5000, "dur": 2000, "args": {"peer": 1, "bytes": 8, "step": 1}},
 {"name": "send reduce to", "ph": "X", "pid": 0, "tid": 10000, "ts": 8000, "dur": 500, "args": {"peer": -1, "bytes": 8, "step": 1}},
 {"name": "density", "ph": "X", "pid": 0, "tid": 0, "ts": 10000, "dur": 6000, "args": {"group": 0, "step": 2}},
 {"name": "drift", "ph": "X", "pid": 0, "tid": 1, "ts": 10000, "dur": 6000, "args": {"group": 1, "step": 2}},
 {"name": "send reduce to", "ph": "X", "pid": 0, "tid": 10000, "ts": 19000, "dur": 1000, "args": {"peer": -1, "bytes": 8, "step": 2}}
]}
JSON
/usr/bin/python3 "$src/perf/strong_scaling/serial_share.py" "$work/trace.json" --skip 0 --json \
    --cores 16 >"$work/out.json"
/usr/bin/python3 - "$work/out.json" <<'PY'
import json, sys
o = json.load(open(sys.argv[1]))
r = o["ranks"]["0"]
# Windows: step 1 [0, 10) ms, step 2 [10, 20) ms (its last event's end). Tasks cover 6 ms of
# each, so 4 + 4 ms serial, 8/20 = 0.4; waiting: the receive alone during [6, 7) ms = 1 ms.
# Concurrency: (4 + 4 + 6 + 6) ms of tasks over 20 ms = 1.0.
assert abs(r["window_s"] - 0.020) < 1e-12, r
assert abs(r["serial_s"] - 0.008) < 1e-12, r
assert abs(r["waiting_s"] - 0.001) < 1e-12, r
assert abs(r["mean_concurrency"] - 1.0) < 1e-9, r
s = o["amdahl"]["16"]["speedup"]
assert abs(s - 1 / (0.4 + 0.6 / 16)) < 1e-9, s
print("ok serial_share: serial 8 ms of 20, waiting 1 ms, Amdahl S(16) = %.3f" % s)
PY
