#!/usr/bin/env bash
# perf/strong_scaling/post_delay.py on a hand-made trace with a known answer: rank 0 packs
# the velocity at 10 ms and its main thread posts it at 10.5 ms; rank 1 has that receive
# pending from 0 to 12 ms and runs tasks until 10.2 ms, so it idles 0.3 ms of the 0.5 ms delay.
# Usage: post_delay.sh SLUICE_EXE SOURCE_DIR (the executable is not used)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
cat >"$work/trace.json" <<'JSON'
{"traceEvents": [
 {"name": "accel", "ph": "X", "pid": 0, "tid": 1, "ts": 0, "dur": 9000, "args": {"group": 0, "step": 1}},
 {"name": "pack velocity", "ph": "X", "pid": 0, "tid": 1, "ts": 9000, "dur": 1000, "args": {"group": 1, "step": 1}},
 {"name": "send velocity to", "ph": "X", "pid": 0, "tid": 10000, "ts": 10500, "dur": 300, "args": {"peer": 1, "bytes": 8, "step": 1}},
 {"name": "accel", "ph": "X", "pid": 1, "tid": 1, "ts": 0, "dur": 10200, "args": {"group": 0, "step": 1}},
 {"name": "recv velocity from", "ph": "X", "pid": 1, "tid": 10000, "ts": 0, "dur": 12000, "args": {"peer": 0, "bytes": 8, "step": 1}}
]}
JSON
out="$(/usr/bin/python3 "$src/perf/strong_scaling/post_delay.py" "$work/trace.json" --skip 0)"
echo "$out"
grep -q "velocity   pack to post: median    500 µs, p90    500 µs; peer idle meanwhile    300 µs per step" <<<"$out"
grep -q "exposed in all: 300 µs per step (summed over the ranks) in 1 steps" <<<"$out"
echo "ok post_delay"
