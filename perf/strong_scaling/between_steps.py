#!/usr/bin/python3
"""Where a rank's time between two step graphs goes, from a --trace.

Reads the Chrome/Perfetto trace `sluice run --trace FILE` writes (a run on several ranks) and,
per rank, splits the loop into the step graphs and the gaps between them. A step's graph runs
from its first task (compute node, halo pack or unpack) to its last; the gap after it ends at
the first task of the next step. In the gap, the main thread's slices (track "MPI, main
thread") name what it did: the step's reduction (`reduce`: the time-step all-gather, or the
wait for the non-blocking one), `migrate` (at a Verlet-list rebuild; since 6e72242 it carries
the halo counts too), `halo counts` (a round of its own: at a rebuild in older binaries, now
only at the start and after a rebalance),
`rebalance`, and the main thread's own work where the run records it: `rebuild` (the rest of
a Verlet-list rebuild: rebin sort, regrouping, halo plan) and `bookkeeping` (busy times,
profile, trace, while the step's reports travel). A message inside a work slice counts as the
message. What no slice covers is put down as `other` (the scheduling gap, posting the next
step's receives; in traces of older binaries also the unrecorded work).

For the reduction it also says how much of it was waiting for the slowest rank (per step, this
rank's time in it minus the least time any rank spent in it) and how much was left once the
last rank had entered (that least time: latency).

Usage: perf/strong_scaling/between_steps.py TRACE.json [--skip STEPS] [--json]
  --skip: leave out the first STEPS steps (start-up, first list build); default 2.
"""
import argparse
import json
import sys
from collections import defaultdict

from trace_reader import MPI_TRACK, load_slices, step_slices, union

# In order of precedence: a message slice inside a work slice counts as the message.
KINDS = ["reduce", "migrate", "halo counts", "rebalance", "rebuild", "bookkeeping"]


def covered(intervals, lo, hi):
    """Length of the union of intervals clipped to [lo, hi)."""
    return sum(max(0.0, min(b, hi) - max(a, lo)) for a, b in union(intervals))


def kind_of(name):
    for k in KINDS:
        if k in name:
            return k
    return None


def parse(events):
    """Per rank: step -> task intervals, and the main thread's named slices."""
    ranks = defaultdict(lambda: {"tasks": defaultdict(list), "main": []})
    for step, a, b, e in step_slices(events):
        r = ranks[e["pid"]]
        if e.get("tid") == MPI_TRACK:
            k = kind_of(e["name"])
            if k is not None:
                r["main"].append((k, a, b))
        else:
            r["tasks"][step].append((a, b))
    return ranks


def figures(rank, skip, reduce_entry):
    steps = sorted(rank["tasks"])[skip:]
    if len(steps) < 2:
        return None
    first = {s: min(a for a, _ in rank["tasks"][s]) for s in steps}
    last = {s: max(b for _, b in rank["tasks"][s]) for s in steps}
    loop = first[steps[-1]] - first[steps[0]]
    graphs = gaps = 0.0
    by_kind = defaultdict(float)
    other = 0.0
    raw = defaultdict(float)  # work slices whole, even where a message covers them
    n_gaps = 0
    for s, nxt in zip(steps, steps[1:]):
        graphs += last[s] - first[s]
        lo, hi = last[s], first[nxt]
        if hi <= lo:
            continue
        n_gaps += 1
        gaps += hi - lo
        named = []
        for k in KINDS:
            before = covered(named, lo, hi)
            named += [(a, b) for kk, a, b in rank["main"] if kk == k]
            by_kind[k] += covered(named, lo, hi) - before
        other += (hi - lo) - covered(named, lo, hi)
        for k in ("bookkeeping", "rebuild"):
            raw[k] += covered([(a, b) for kk, a, b in rank["main"] if kk == k], lo, hi)
    return {"steps": len(steps) - 1, "loop_s": loop, "graphs_s": graphs, "between_s": gaps,
            "between_share": gaps / loop if loop > 0 else 0.0,
            "by_kind_s": dict(by_kind), "other_s": other, "gaps": n_gaps,
            "work_whole_s": dict(raw)}


def reduce_skew(ranks):
    """Per rank: seconds of the reduction spent waiting for the last rank to enter it.

    The ranks' clocks share an origin set after a barrier at the start of the time loop, but
    only to within that barrier's skew, so entries are not compared directly: a
    reduction completes on every rank at about the same moment, so the rank that entered last
    spent the least time in it (the latency), and each rank's excess over that least time is
    its wait for the last rank."""
    entries = defaultdict(dict)  # k-th reduce -> rank -> duration
    for r, d in ranks.items():
        red = sorted((a, b) for k, a, b in d["main"] if k == "reduce")
        for i, (a, b) in enumerate(red):
            entries[i][r] = b - a
    wait = defaultdict(float)
    after = defaultdict(float)
    for per in entries.values():
        if len(per) != len(ranks):
            continue
        least = min(per.values())
        for r, dur in per.items():
            wait[r] += dur - least
            after[r] += least
    return wait, after


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("trace")
    ap.add_argument("--skip", type=int, default=2)
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    events = load_slices(args.trace)
    ranks = parse(events)
    wait, after = reduce_skew(ranks)
    out = {}
    for r in sorted(ranks):
        v = figures(ranks[r], args.skip, None)
        if v is None:
            continue
        v["reduce_waiting_for_last_rank_s"] = wait[r]
        v["reduce_after_last_rank_s"] = after[r]
        out[r] = v
    if not out:
        sys.exit(f"between_steps: no steps in {args.trace}")
    if args.json:
        print(json.dumps(out, indent=1))
        return
    for r, v in out.items():
        n = v["steps"]
        ms = lambda t: 1e3 * t / n
        pct = lambda t: 100 * t / v["loop_s"]
        print(f"rank {r}: {n} steps, loop {v['loop_s']:.3f} s, graphs {v['graphs_s']:.3f} s, "
              f"between {v['between_s']:.3f} s = {ms(v['between_s']):.2f} ms/step = "
              f"{pct(v['between_s']):.2f} % of the loop")
        for k in KINDS + ["other"]:
            t = v["other_s"] if k == "other" else v["by_kind_s"].get(k, 0.0)
            if t > 0:
                print(f"  {k:<12} {ms(t):8.3f} ms/step {pct(t):6.2f} %")
        for k, t in v["work_whole_s"].items():
            if t > v["by_kind_s"].get(k, 0.0) + 1e-9:
                print(f"  ({k} whole: {ms(t):.3f} ms/step, the rest of it while a message "
                      "was in flight)")
        print(f"  reduce: waiting for the last rank {ms(wait[r]):.3f} ms/step, after it "
              f"{ms(after[r]):.3f} ms/step")


if __name__ == "__main__":
    main()
