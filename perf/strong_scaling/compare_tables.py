#!/usr/bin/env python3
"""Side by side: a measured strong-scaling table (plot.py's scaling.csv) against reference
tables of the same case (an earlier machine's, a prediction), layout by layout: wall time and
parallel efficiency, and the measured efficiency's difference from each reference's.

    /usr/bin/python3 perf/strong_scaling/compare_tables.py MEASURED.csv REFERENCE.csv [MORE.csv ...]

Layouts missing from a reference print "-". The efficiencies are each table's own (against
its own 1x1 run), so tables from machines of different speeds compare."""

import csv
import os
import sys


def load(path):
    with open(path) as f:
        return {r["layout"]: r for r in csv.DictReader(f)}


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    measured = load(argv[1])
    refs = [(os.path.basename(p), load(p)) for p in argv[2:]]
    head = ["layout", "wall s", "eff"]
    for name, _ in refs:
        head += [f"eff {name}", "diff"]
    print(" | ".join(head))
    for layout, row in measured.items():
        eff = float(row["parallel_efficiency"])
        cells = [layout, f"{float(row['wall_seconds']):.3f}", f"{eff:.3f}"]
        for _, ref in refs:
            if layout in ref:
                e = float(ref[layout]["parallel_efficiency"])
                cells += [f"{e:.3f}", f"{eff - e:+.3f}"]
            else:
                cells += ["-", "-"]
        print(" | ".join(cells))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
