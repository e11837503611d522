#!/usr/bin/python3
"""How much of a multi-rank run's loss is the cores' speed, not the code.

A rank's busy time in a step (the summed durations of its tasks) is its share of the step's
work divided by the speed of the core it ran on. Within one rank, threads that run at unequal
speeds even out by work stealing; between ranks, the work is split once per rebalance, so in
each step the faster rank waits for the slower one. On a machine whose cores change speed on
their own (a VM whose host shares caches, memory bandwidth or hyper-thread siblings with other
guests), that wait is the host's, and no change in the code between rebalances removes it.

This script measures it from traces (`sluice run --trace FILE`):

* **One multi-rank trace** (`core_speed.py TRACE.json`): each rank's busy time per step. In a
  step, a static split of equal work takes max_r b_r (the slowest rank), while the same work
  shared by the same cores as it becomes free (work stealing) would take R / sum_r (1 / b_r).
  The ratio of their sums over the steps is the **speed bound**: the parallel efficiency a
  static split could reach on these cores if communication and scheduling cost nothing. Each
  rank's busy times are first divided by its median over the run (times the mean of the
  medians), so that a difference of work that holds for the whole run (the balancer's business,
  reported as "work imbalance") does not count as speed.
* **Two independent runs at once** (`core_speed.py --independent A.json B.json`): the same
  case run twice, one process pinned to each core, at the same time (host_cores.sh does it).
  Both do the same work, so the ratio of their step times at each moment is the ratio of the
  cores' speeds. The runs' steps are aligned by time (each run's step time is sampled on a
  common grid of `--grid` seconds from the later start to the earlier end), and the same bound
  is taken over the grid. This needs no MPI: it is the host alone.

Both print the per-step (per-sample) speed ratio slowest/fastest (median, 90th percentile, the
share above 1.1) and the bound. For a multi-rank trace it also replays the busy times with the
work re-split every 1 and every 10 steps in proportion to the speeds of those steps, at no
cost: what the best balancer could win back, before paying for the rebuilds. Steps are counted after `--skip` (default 2: start-up).

Usage: perf/strong_scaling/core_speed.py TRACE.json [--skip N] [--json]
       perf/strong_scaling/core_speed.py --independent A.json B.json [--grid S] [--json]
"""
import argparse
import json
import statistics
import sys
from collections import defaultdict

from trace_reader import MPI_TRACK, load_slices, step_slices


def busy_per_step(events):
    """{pid: {step: (start s, end s, busy s)}} from the worker tracks (tasks only)."""
    out = defaultdict(dict)
    for step, a, b, e in step_slices(events):
        if e.get("tid") == MPI_TRACK:
            continue
        s0, s1, busy = out[e["pid"]].get(step, (a, b, 0.0))
        out[e["pid"]][step] = (min(s0, a), max(s1, b), busy + (b - a))
    return out


def ratio_figures(rows):
    """rows: per sample, the list of the ranks' (or runs') times. Ratio slowest/fastest."""
    ratios = sorted(max(r) / min(r) for r in rows if min(r) > 0)
    if not ratios:
        return {}
    return {
        "samples": len(ratios),
        "ratio_median": statistics.median(ratios),
        "ratio_p90": ratios[min(len(ratios) - 1, int(0.9 * len(ratios)))],
        "share_above_1.1": sum(r > 1.1 for r in ratios) / len(ratios),
    }


def speed_bound(rows):
    """sum of the work-stealing times over the sum of the static-split times."""
    ideal = sum(len(r) / sum(1.0 / t for t in r) for r in rows)
    static = sum(max(r) for r in rows)
    return ideal / static if static > 0 else float("nan")


def chased_bound(rows, every):
    """The bound if the work were re-split every `every` steps, at no cost, in proportion to
    the ranks' speeds over the last `every` steps (which is all a balancer can know)."""
    R = len(rows[0])
    share = [1.0 / R] * R
    ideal = sum(R / sum(1.0 / t for t in r) for r in rows)
    chased = 0.0
    for i, r in enumerate(rows):
        # b_r is the time of an equal share (1/R): share s takes s * R * b_r.
        chased += max(s * R * t for s, t in zip(share, r))
        if (i + 1) % every == 0:
            speed = [1.0 / sum(rows[k][q] for k in range(i + 1 - every, i + 1)) for q in range(R)]
            share = [v / sum(speed) for v in speed]
    return ideal / chased if chased > 0 else float("nan")


def one_trace(path, skip):
    per_rank = busy_per_step(load_slices(path))
    ranks = sorted(per_rank)
    if len(ranks) < 2:
        sys.exit(f"{path}: one rank only; use --independent with two runs")
    steps = sorted(set.intersection(*(set(per_rank[r]) for r in ranks)))[skip:]
    raw = [[per_rank[r][s][2] for r in ranks] for s in steps]
    medians = [statistics.median(row[i] for row in raw) for i in range(len(ranks))]
    mean_median = sum(medians) / len(medians)
    norm = [[row[i] / medians[i] * mean_median for i in range(len(ranks))] for row in raw]
    fig = {
        "trace": path,
        "ranks": len(ranks),
        "steps": len(steps),
        "busy_median_ms": [1e3 * m for m in medians],
        "work_imbalance": max(medians) / mean_median,
        "bound_raw": speed_bound(raw),
        "speed_bound": speed_bound(norm),
        "chased_bound": {n: chased_bound(raw, n) for n in (1, 10)},
    }
    fig.update(ratio_figures(norm))
    return fig


def step_time_at(steps, t):
    """The busy time of the step that runs at time t (steps sorted by start), or None."""
    lo, hi = 0, len(steps) - 1
    if t < steps[0][0] or t > steps[-1][1]:
        return None
    while lo < hi:  # last step starting at or before t
        mid = (lo + hi + 1) // 2
        if steps[mid][0] <= t:
            lo = mid
        else:
            hi = mid - 1
    return steps[lo][2]


def independent(paths, grid, skip):
    runs = []
    for p in paths:
        per = busy_per_step(load_slices(p))
        if len(per) != 1:
            sys.exit(f"{p}: expected a one-rank trace")
        (steps,) = per.values()
        runs.append(sorted(steps[s] for s in sorted(steps)[skip:]))
    # The two processes' clocks are the same steady clock only if the host's is; sluice's trace
    # times are from the process's own start. Align on the first step of each run instead:
    # both were started together, and both took the same start-up work.
    for i, r in enumerate(runs):
        t0 = r[0][0]
        runs[i] = [(a - t0, b - t0, busy) for a, b, busy in r]
    end = min(r[-1][1] for r in runs)
    rows = []
    t = 0.0
    while t <= end:
        row = [step_time_at(r, t) for r in runs]
        if all(x is not None and x > 0 for x in row):
            rows.append(row)
        t += grid
    fig = {
        "traces": paths,
        "grid_s": grid,
        "seconds": end,
        "busy_median_ms": [1e3 * statistics.median(b for _, _, b in r) for r in runs],
        "speed_bound": speed_bound(rows),
    }
    fig.update(ratio_figures(rows))
    return fig


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("trace", nargs="?")
    ap.add_argument("--independent", nargs=2, metavar="TRACE")
    ap.add_argument("--grid", type=float, default=0.01, help="seconds between samples")
    ap.add_argument("--skip", type=int, default=2)
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    if bool(args.trace) == bool(args.independent):
        ap.error("give one multi-rank trace or --independent A.json B.json")
    fig = (independent(args.independent, args.grid, args.skip) if args.independent
           else one_trace(args.trace, args.skip))
    if args.json:
        print(json.dumps(fig, indent=1))
        return
    print(", ".join(f"{m:.1f}" for m in fig["busy_median_ms"]), "ms busy per step (median)",
          end="")
    if "work_imbalance" in fig:
        print(f"; work imbalance (max/mean of the medians) {fig['work_imbalance']:.3f}")
    else:
        print(f"; {fig['seconds']:.1f} s sampled every {fig['grid_s']} s")
    print(f"speed ratio slowest/fastest per {'step' if 'steps' in fig else 'sample'}: median "
          f"{fig['ratio_median']:.3f}, p90 {fig['ratio_p90']:.3f}, "
          f"{100 * fig['share_above_1.1']:.0f} % above 1.1")
    print(f"speed bound (static split against work stealing on the same cores): "
          f"{fig['speed_bound']:.3f}")
    if "bound_raw" in fig:
        print(f"  with the work imbalance counted too: {fig['bound_raw']:.3f}")
        print("  re-split at no cost by the last steps' speeds, every 1 / 10 steps: "
              + " / ".join(f"{v:.3f}" for v in fig["chased_bound"].values()))


if __name__ == "__main__":
    main()
