#!/usr/bin/python3
"""Serial share of a step from a --trace, and the Amdahl projection it implies.

Reads the Chrome/Perfetto trace `sluice run --trace FILE` writes (any number of ranks; a
2-rank run on a small machine is the intended input) and reports, per rank:

* the step windows: step s runs from the first event of step s on that rank (a task, a pack or
  a message, all tagged with their step) to the first event of step s+1 (the last step: to its
  last event's end), so the time between the graphs (reduction, migration, rebin) belongs to
  the step before;
* the *serial time*: the part of the windows in which no task of the rank runs on any thread
  (compute nodes, halo packs and unpacks; waiting for a message is not a task), i.e. what
  more cores cannot shorten;
* of the serial time, the part spent *waiting for a message* (a receive posted and not yet
  complete while no task runs: exposed communication, which overlap or a faster network
  shortens) and the rest (the main thread's work between the graphs and the scheduling gaps);
* the serial share f = serial time / window time and the mean concurrency (task-seconds per
  second of window).

Amdahl's law with the largest f over the ranks gives the speed-up S(N) = 1 / (f + (1 - f)/N)
and efficiency S(N)/N at N cores, printed for 16 and 128 (and --cores). It is an upper bound:
it assumes the parallel part scales perfectly (no more halo traffic, no imbalance), so it shows
what the serial part alone costs, which is the part a 2-core machine can measure.

Usage: perf/strong_scaling/serial_share.py TRACE.json [--skip STEPS] [--cores N ...] [--json]
  --skip: leave out the first STEPS steps of each rank (start-up, first list build); default 2.
"""
import argparse
import json
import sys
from collections import defaultdict

from trace_reader import MPI_TRACK, load_slices, step_slices, union_length



def rank_figures(events, skip):
    """events: the rank's X slices. Returns a dict of figures (seconds)."""
    first = {}           # step -> first event start
    last_end = {}        # step -> last event end
    tasks = defaultdict(list)  # step -> task intervals
    recvs = defaultdict(list)  # step -> receive intervals (posted .. complete)
    for step, a, b, e in step_slices(events):
        first[step] = min(first.get(step, a), a)
        last_end[step] = max(last_end.get(step, b), b)
        if e.get("tid") != MPI_TRACK:
            tasks[step].append((a, b))
        elif e["name"].startswith("recv "):
            recvs[step].append((a, b))
    steps = sorted(first)[skip:]
    if not steps:
        return None
    window = serial = busy = waiting = 0.0
    for s in steps:
        begin = first[s]
        end = first.get(s + 1, last_end[s])
        # Tasks of step s clipped to its window (a pack may straddle the boundary).
        def clip(iv):
            return [(max(a, begin), min(b, end)) for a, b in iv if min(b, end) > max(a, begin)]
        clipped = clip(tasks[s])
        covered = union_length(clipped)
        waiting += union_length(clipped + clip(recvs[s])) - covered
        window += end - begin
        serial += (end - begin) - covered
        busy += sum(b - a for a, b in clipped)
    return {"steps": len(steps), "window_s": window, "serial_s": serial,
            "waiting_s": waiting,
            "serial_share": serial / window if window > 0 else 0.0,
            "mean_concurrency": busy / window if window > 0 else 0.0}


def amdahl(f, n):
    s = 1.0 / (f + (1.0 - f) / n)
    return s, s / n


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("trace")
    ap.add_argument("--skip", type=int, default=2)
    ap.add_argument("--cores", type=int, nargs="*", default=[16, 128])
    ap.add_argument("--json", action="store_true", help="print the figures as JSON")
    args = ap.parse_args()
    events = load_slices(args.trace)
    by_rank = defaultdict(list)
    for e in events:
        by_rank[e["pid"]].append(e)
    ranks = {r: rank_figures(ev, args.skip) for r, ev in sorted(by_rank.items())}
    ranks = {r: v for r, v in ranks.items() if v}
    if not ranks:
        sys.exit(f"serial_share: no steps in {args.trace}")
    f = max(v["serial_share"] for v in ranks.values())
    projection = {n: amdahl(f, n) for n in args.cores}
    if args.json:
        print(json.dumps({"ranks": ranks, "serial_share_max": f,
                          "amdahl": {str(n): {"speedup": s, "efficiency": e}
                                     for n, (s, e) in projection.items()}}, indent=1))
        return
    print(f"{'rank':>4} {'steps':>6} {'window':>9} {'serial':>9} {'waiting':>9} {'share':>7} "
          f"{'concurrency':>11}")
    for r, v in ranks.items():
        print(f"{r:>4} {v['steps']:>6} {v['window_s']:>8.3f}s {v['serial_s']:>8.3f}s "
              f"{v['waiting_s']:>8.3f}s {100 * v['serial_share']:>6.2f}% "
              f"{v['mean_concurrency']:>11.2f}")
    print(f"serial share (largest over ranks): {100 * f:.2f}%")
    for n, (s, e) in projection.items():
        print(f"Amdahl at {n} cores: speed-up {s:.1f}, efficiency {e:.2f} "
              "(upper bound: perfect scaling of the rest)")


if __name__ == "__main__":
    main()
