"""Reading a sluice --trace (Chrome trace JSON) for serial_share.py and between_steps.py: the
complete ("X") slices, each slice's step and interval in seconds, and interval unions."""
from __future__ import annotations

import json

MPI_TRACK = 10000  # the trace's track for the main thread (tasks/src/trace_*.cpp)


def load_slices(path):
    """The trace's complete slices (events with ph == "X")."""
    with open(path) as f:
        return [e for e in json.load(f)["traceEvents"] if e.get("ph") == "X"]


def step_slices(events):
    """(step, start s, end s, event) for every slice that belongs to a step."""
    for e in events:
        step = e.get("args", {}).get("step")
        if step is None:
            continue
        a = e["ts"] * 1e-6
        yield step, a, a + e["dur"] * 1e-6, e


def union(intervals):
    """The union of [a, b) intervals as sorted, disjoint [a, b] lists (empty ones dropped)."""
    out = []
    for a, b in sorted(intervals):
        if b <= a:
            continue
        if out and a <= out[-1][1]:
            out[-1][1] = max(out[-1][1], b)
        else:
            out.append([a, b])
    return out


def union_length(intervals):
    """Length of the union of [a, b) intervals."""
    return sum(b - a for a, b in union(intervals))
