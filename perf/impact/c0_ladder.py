#!/usr/bin/python3
"""First-impact peaks against the sound speed, one ladder per sensor, from analyse.py's CSVs.

    perf/impact/c0_ladder.py LABEL=impact_convergence.csv [LABEL=... ...] [--probes a,b,...]
                             [--variant default] [--png OUT.png]

Each CSV is one analyse.py output (`impact_convergence.csv`); its LABEL names the filter it was
made with, e.g. `1ms=.../impact_convergence.csv 10ms=.../impact_convergence.csv` for
`analyse.py STUDY --filter-ms 1` and `--filter-ms 10`; CSVs given the same label are merged.
An `impact_wall_force.csv` given the same way adds the whole downstream wall's force (over
rho g H^2 / 2) as the probe `wall_force`. A CSV from analyse.py since e8c7e1f also carries
the peak after its second, longer average (`peak_smooth_star`, analyse.py --smooth-ms, 10 ms by
default): it is printed and plotted as the line `10ms average` (`--smooth-label`: name the
width the CSV was made with; left out when a label of that name is given) from the first CSV
that has the probe, so one analyse.py run gives the 1 ms and the 10 ms ladders.
For every label, probe and resolution it prints the median (min-max) over the ensemble of the
filtered peak (`peak_filt_star`) and of the raw peak (`peak_raw_star`, from the first CSV that
has the probe) at each c0 / sqrt(gH), and the change of the median between successive c0,
(fine - coarse) / fine as analyse.py gives it. The question it answers: from which c0 on does a
peak stop moving, and at which averaging time? The PNG has one panel per probe: median and
range against c0 on log axes, one line per label (and the raw peak).
"""
from __future__ import annotations

import argparse
import csv
import statistics
import sys
from collections import defaultdict
from pathlib import Path

DEFAULT_PROBES = "y003mm_area,y030mm_area,y080mm_area,P1_area"
WALL = "wall_force"  # the probe name given to the rows of an impact_wall_force.csv


def load(path: Path, variant: str, out: dict | None = None) -> dict:
    """{(probe, H/dx): {c0_factor: [row, ...]}} of one analyse.py CSV, added to `out` if given
    (CSVs of one label are merged: e.g. studies of different c0 or dx read the same way)."""
    if out is None:
        out = defaultdict(lambda: defaultdict(list))
    with open(path) as f:
        for r in csv.DictReader(f):
            if r["variant"] != variant:
                continue
            if "probe" not in r:  # an impact_wall_force.csv: the whole downstream wall's force
                r = dict(r, probe=WALL, peak_filt_star=r["peak_filt"], peak_raw_star=r["peak_raw"],
                         peak_smooth_star=r.get("peak_smooth", ""))
            out[(r["probe"], round(float(r["H_over_dx"])))][float(r["c0_factor"])].append(r)
    return out


def ladder(rows_by_c0: dict, key: str) -> list[tuple[float, float, float, float, int]]:
    """(c0, median, min, max, n) of `key` at each c0, c0 ascending; NaN values skipped."""
    out = []
    for c0 in sorted(rows_by_c0):
        v = [float(r[key]) for r in rows_by_c0[c0] if r.get(key)]
        v = [x for x in v if x == x]
        if v:
            out.append((c0, statistics.median(v), min(v), max(v), len(v)))
    return out


def print_ladder(name: str, lad: list) -> None:
    cells = []
    for i, (c0, med, lo, hi, n) in enumerate(lad):
        step = ""
        if i:
            prev = lad[i - 1][1]
            step = f" [{100 * (med - prev) / med:+.0f} %]"
        cells.append(f"c0 {c0:g}: {med:.2f} ({lo:.2f}-{hi:.2f}, n={n}){step}")
    print(f"   {name:14s} " + "   ".join(cells))


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csvs", nargs="+", metavar="LABEL=CSV")
    ap.add_argument("--probes", default=DEFAULT_PROBES, help=f"default {DEFAULT_PROBES}")
    ap.add_argument("--variant", default="default")
    ap.add_argument("--png", type=Path)
    ap.add_argument("--smooth-label", default="10ms",
                    help="label of peak_smooth_star's line (analyse.py --smooth-ms; default 10ms)")
    a = ap.parse_args(argv)
    by_label: dict = {}
    for s in a.csvs:
        label, sep, path = s.partition("=")
        if not sep:
            ap.error(f"{s}: expected LABEL=CSV")
        by_label[label] = load(Path(path), a.variant, by_label.get(label))
    sets = list(by_label.items())
    probes = a.probes.split(",")
    print("first-impact peak [rho g H]: median (min-max) of the ensemble at each c0 / sqrt(gH);"
          " [change of the median from the previous c0, (fine - coarse) / fine]")
    panels = []
    for probe in probes:
        resolutions = sorted({h for _, d in sets for (p, h) in d if p == probe})
        for h in resolutions:
            print(f"{probe} at H/{h}")
            lines = []
            first = next((d[(probe, h)] for _, d in sets if (probe, h) in d), None)
            if first:
                lad = ladder(first, "peak_raw_star")
                print_ladder("raw", lad)
                lines.append(("raw", lad))
            for label, d in sets:
                if (probe, h) in d:
                    lad = ladder(d[(probe, h)], "peak_filt_star")
                    print_ladder(f"{label} average", lad)
                    lines.append((f"{label} average", lad))
            # Not when a label already gives that average (e.g. 10ms=... made with
            # --filter-ms 10): the line would be printed twice.
            smooth = (ladder(first, "peak_smooth_star")
                      if first and a.smooth_label not in by_label else [])
            if smooth:  # CSVs older than e8c7e1f have no such column
                print_ladder(f"{a.smooth_label} average", smooth)
                lines.append((f"{a.smooth_label} average", smooth))
            panels.append((f"{probe}, H/{h}", lines))
    if a.png and panels:
        import matplotlib  # noqa: PLC0415 (only when plotting)
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt  # noqa: PLC0415
        n = len(panels)
        cols = min(n, 3)
        rows = (n + cols - 1) // cols
        fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows), squeeze=False)
        for ax, (title, lines) in zip(axes.flat, panels):
            for name, lad in lines:
                c0 = [x[0] for x in lad]
                med = [x[1] for x in lad]
                ax.plot(c0, med, "o-" if name != "raw" else "s--", label=name)
                ax.fill_between(c0, [x[2] for x in lad], [x[3] for x in lad], alpha=0.15)
            ax.set_xscale("log", base=2)
            ax.set_yscale("log")
            ax.set_xticks(sorted({x[0] for _, lad in lines for x in lad}))
            ax.get_xaxis().set_major_formatter(matplotlib.ticker.ScalarFormatter())
            ax.set_title(title, fontsize=9)
            ax.set_xlabel("c0 / sqrt(gH)")
            ax.set_ylabel("first-impact peak force / (rho g H^2 / 2)" if title.startswith(WALL)
                          else "first-impact peak / (rho g H)")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7)
        for ax in list(axes.flat)[n:]:
            ax.axis("off")
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print(f"wrote {a.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
