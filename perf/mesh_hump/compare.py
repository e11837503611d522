#!/usr/bin/env python3
"""Water depths of a run of cases/dam_break_sill_2d.toml against the CADAM record (data/).

For each gauge (G10 at x = 25.5 m, G13 at the crest, 28.5 m, G20 at 35.5 m): the simulated depth
(the water_level probe less the bed there) at the record's times, and
  arrival  the first time the depth exceeds 0.02 m above its start (record: the same rule);
  peak     the largest depth up to t_end, and when;
  rms      the root-mean-square difference from the record over its points up to t_end;
  mean     the mean difference (simulated - record), i.e. the bias.
Usage: compare.py RUN_FOLDER [RUN_FOLDER ...]   (one row block per run; label = folder name)
"""
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
GAUGES = [("G10", 25.5, 0.0), ("G13", 28.5, 0.4), ("G20", 35.5, 0.0)]  # name, x, bed


def rows(path):
    """(t, value) pairs; a gauge with no water under it reads nan, taken as depth 0."""
    with open(path) as f:
        lines = [l for l in f if not l.startswith("#")]
    r = list(csv.reader(lines))
    return [(float(a), 0.0 if b == "nan" else float(b)) for a, b, *_ in r[1:] if a and b]


def interp(series, t):
    if t <= series[0][0]:
        return series[0][1]
    for (t0, y0), (t1, y1) in zip(series, series[1:]):
        if t0 <= t <= t1:
            return y0 + (y1 - y0) * (t - t0) / (t1 - t0) if t1 > t0 else y1
    return series[-1][1]


def arrival(series, rise=0.02):
    base = series[0][1]
    for t, y in series:
        if y > base + rise:
            return t
    return math.nan


def main():
    print(f"{'run':<14} {'gauge':<5} {'arrival s (exp)':>16} {'peak m (exp)':>14} "
          f"{'at s (exp)':>12} {'rms m':>7} {'mean m':>7} {'points':>6}")
    for run in sys.argv[1:]:
        for name, x, bed in GAUGES:
            sim_raw = rows(os.path.join(run, "probes", name + ".csv"))
            sim = [(t, max(level - bed, 0.0) if level > 0 else 0.0) for t, level in sim_raw]
            t_end = sim[-1][0]
            exp = sorted(rows(os.path.join(HERE, "data", f"cadam_sill_{name}.csv")))
            exp = [(t, y) for t, y in exp if t <= t_end]
            diffs = [interp(sim, t) - y for t, y in exp]
            rms = math.sqrt(sum(d * d for d in diffs) / len(diffs))
            mean = sum(diffs) / len(diffs)
            ps = max(sim, key=lambda p: p[1])
            pe = max(exp, key=lambda p: p[1])
            print(f"{os.path.basename(os.path.normpath(run)):<14} {name:<5} "
                  f"{arrival(sim):7.2f} ({arrival(exp):5.2f}) {ps[1]:6.3f} ({pe[1]:5.3f}) "
                  f"{ps[0]:5.2f} ({pe[0]:5.2f}) {rms:7.3f} {mean:+7.3f} {len(exp):6d}")


if __name__ == "__main__":
    main()
