#!/usr/bin/python3
"""How long a packed halo message waits to be posted, and what that wait costs the peer.

A halo exchange is packed by a task on a worker thread and posted (MPI_Isend) by that task
(with MPI_THREAD_MULTIPLE, the default since c8cbf90) or, with only MPI_THREAD_FUNNELED or
SLUICE_POST_FROM_MAIN set, by the rank's main thread at its next poll: the main thread sleeps
up to 1 ms between polls while tasks run (tasks/src/step_graph.cpp). Reads a
multi-rank `sluice run --trace` and reports, per exchange (`pressure`, `walls`, `velocity`;
the `state` exchange is packed and posted by the main thread itself), the delay from the end
of the pack to the post (median, 90th percentile), and the part of those delays during which
the peer rank had that message's receive pending and no task running: the exposed cost, in
µs per step summed over the ranks: what posting from the main thread costs, and what posting
from the pack task removes.

Usage: perf/strong_scaling/post_delay.py TRACE.json [--skip N]
"""
import argparse
import statistics
from collections import defaultdict

from trace_reader import MPI_TRACK, load_slices, step_slices, union


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("trace")
    ap.add_argument("--skip", type=int, default=2, help="leave out the first steps")
    args = ap.parse_args()
    pack, post, recv = {}, {}, {}
    tasks = defaultdict(list)
    steps = set()
    for step, a, b, e in step_slices(load_slices(args.trace)):
        if step <= args.skip:
            continue
        name, rank = e["name"], e["pid"]
        if e.get("tid") == MPI_TRACK:
            if name.startswith("send ") and name.endswith(" to"):
                post[(rank, step, name[5:-3])] = a
            elif name.startswith("recv ") and name.endswith(" from"):
                recv[(rank, step, name[5:-5])] = (a, b)
        else:
            tasks[rank].append((a, b))
            if name.startswith("pack "):
                pack[(rank, step, name[5:])] = b
        steps.add(step)
    busy = {r: union(iv) for r, iv in tasks.items()}

    def idle(rank, lo, hi):
        """Time in [lo, hi] during which no task of `rank` runs."""
        covered = sum(max(0.0, min(b, hi) - max(a, lo)) for a, b in busy.get(rank, []))
        return (hi - lo) - covered

    ranks = sorted(busy)
    delays, exposed = defaultdict(list), defaultdict(float)
    for (rank, step, name), packed in pack.items():
        if name == "state" or (rank, step, name) not in post:
            continue
        posted = post[(rank, step, name)]
        delays[name].append(posted - packed)
        for peer in ranks:
            if peer == rank or (peer, step, name) not in recv:
                continue
            a, b = recv[(peer, step, name)]
            lo, hi = max(a, packed), min(b, posted)
            if hi > lo:
                exposed[name] += idle(peer, lo, hi)
    n = max(1, len(steps))
    for name in sorted(delays):
        v = sorted(delays[name])
        print(f"{name:<10} pack to post: median {1e6 * statistics.median(v):6.0f} µs, "
              f"p90 {1e6 * v[int(0.9 * (len(v) - 1))]:6.0f} µs; peer idle meanwhile "
              f"{1e6 * exposed[name] / n:6.0f} µs per step")
    print(f"exposed in all: {1e6 * sum(exposed.values()) / n:.0f} µs per step (summed over the "
          f"ranks) in {n} steps")


if __name__ == "__main__":
    main()
