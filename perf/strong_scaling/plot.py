#!/usr/bin/env python3
"""Tabulate and plot a strong-scaling sweep made by perf/strong_scaling/run.sh.

Reads OUT/RxT/summary.json for each layout RxT (R MPI ranks x T threads), writes
OUT/scaling.csv and OUT/scaling.png and prints the table to stdout.

    /usr/bin/python3 perf/strong_scaling/plot.py OUT [--layouts "1x1 1x2 2x1"]

Without --layouts every OUT/<R>x<T>/summary.json is read.

Definitions (see perf/strong_scaling/README.md):
  cores                = R * T
  speed-up             = wall(1x1) / wall(layout); without a 1x1 run the baseline is the layout
                         with the fewest cores, assumed to scale ideally up to its own core count:
                         speed-up = cores_b * wall_b / wall(layout)
  parallel efficiency  = speed-up / cores
  overlap efficiency   = hidden / total communication time, summed over ranks (1 for one rank)
  load imbalance       = max / mean rank busy time (1 for one rank)
"""

import argparse
import csv
import json
import os
import re
import sys

COLUMNS = [
    "layout", "ranks", "threads", "cores", "particles", "steps", "wall_seconds",
    "particle_steps_per_second", "speedup", "parallel_efficiency", "overlap_efficiency",
    "load_imbalance",
]
LAYOUT_RE = re.compile(r"^([1-9][0-9]*)x([1-9][0-9]*)$")


def read_rows(out, layouts):
    if layouts is None:
        layouts = [d for d in os.listdir(out)
                   if LAYOUT_RE.match(d) and os.path.isfile(os.path.join(out, d, "summary.json"))]
    rows = []
    for layout in layouts:
        m = LAYOUT_RE.match(layout)
        if not m:
            sys.exit(f"plot.py: bad layout '{layout}' (want RxT, e.g. 2x4)")
        path = os.path.join(out, layout, "summary.json")
        if not os.path.isfile(path):
            print(f"plot.py: no {path}; layout {layout} skipped", file=sys.stderr)
            continue
        with open(path) as f:
            s = json.load(f)
        r, t = int(m.group(1)), int(m.group(2))
        for key, want in (("ranks", r), ("threads", t)):
            if key in s and int(s[key]) != want:
                print(f"plot.py: warning: {path} says {key} = {s[key]}, the folder name {want}",
                      file=sys.stderr)
        total = s.get("extra", {}).get("parallel", {}).get("total", {})
        rows.append({
            "layout": layout,
            "ranks": r,
            "threads": t,
            "cores": r * t,
            "particles": int(s["particles"]),
            "steps": int(s["steps"]),
            "wall_seconds": float(s["wall_seconds"]),
            "particle_steps_per_second": float(s["particle_steps_per_second"]),
            "overlap_efficiency": float(total.get("overlap_efficiency", float("nan"))),
            "load_imbalance": float(total.get("load_imbalance", float("nan"))),
        })
    rows.sort(key=lambda x: (x["cores"], x["ranks"], x["threads"]))
    return rows


def add_speedup(rows):
    base = next((x for x in rows if x["layout"] == "1x1"), None)
    if base is None:
        base = min(rows, key=lambda x: (x["cores"], x["ranks"]))
        print(f"plot.py: no 1x1 run; baseline is {base['layout']}, taken as ideal "
              f"(speed-up {base['cores']})", file=sys.stderr)
    ref = base["cores"] * base["wall_seconds"]
    steps = {x["steps"] for x in rows}
    if len(steps) > 1:
        print(f"plot.py: warning: the runs took different numbers of steps {sorted(steps)}; "
              "wall times are not strictly comparable", file=sys.stderr)
    for x in rows:
        x["speedup"] = ref / x["wall_seconds"]
        x["parallel_efficiency"] = x["speedup"] / x["cores"]
    return base


def fmt(key, v):
    if isinstance(v, str):
        return v
    if key in ("ranks", "threads", "cores", "particles", "steps"):
        return str(v)
    if key == "wall_seconds":
        return f"{v:.4g}"
    if key == "particle_steps_per_second":
        return f"{v:.4g}"
    return f"{v:.3f}"


def write_csv(rows, path):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for x in rows:
            w.writerow([x[c] if isinstance(x[c], (str, int)) else f"{x[c]:.6g}" for c in COLUMNS])


def print_table(rows):
    cells = [COLUMNS] + [[fmt(c, x[c]) for c in COLUMNS] for x in rows]
    widths = [max(len(r[i]) for r in cells) for i in range(len(COLUMNS))]
    for n, r in enumerate(cells):
        print("  ".join(v.ljust(w) if i == 0 else v.rjust(w)
                        for i, (v, w) in enumerate(zip(r, widths))))
        if n == 0:
            print("  ".join("-" * w for w in widths))


def plot(rows, base, path, title):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.ticker
    except ImportError:
        print("plot.py: matplotlib is not installed for /usr/bin/python3, so no "
              f"{os.path.basename(path)} (install the Debian package python3-matplotlib); "
              "the CSV is written", file=sys.stderr)
        return False

    markers = ["o", "s", "^", "D", "v", "P", "X", "*", "<", ">", "h"]
    by_ranks = {}
    for x in rows:
        by_ranks.setdefault(x["ranks"], []).append(x)
    style = {r: (markers[i % len(markers)], f"C{i % 10}") for i, r in enumerate(sorted(by_ranks))}
    cores = sorted({x["cores"] for x in rows})
    cmin, cmax = min(cores), max(cores)
    # Layouts with the same core count (2x1, 1x2) get their labels stacked, not overprinted:
    # in each panel the highest point's label on top, each next one 11 points lower.
    def label(ax, x, key, color):
        same = sorted((y for y in rows if y["cores"] == x["cores"]), key=lambda y: -y[key])
        slot = [y["layout"] for y in same].index(x["layout"])
        ax.annotate(x["layout"], (x["cores"], x[key]), textcoords="offset points",
                    xytext=(6, 4 - 11 * slot), fontsize=8, color=color)

    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    (ax_wall, ax_sp), (ax_eff, ax_ov) = axes

    def series(ax, key, label_points=True, only=None):
        for r, xs in sorted(by_ranks.items()):
            if only is not None:
                xs = [x for x in xs if only(x)]
            if not xs:
                continue
            m, c = style[r]
            ax.plot([x["cores"] for x in xs], [x[key] for x in xs], marker=m, color=c,
                    linestyle="-", label=f"{r} rank{'s' if r > 1 else ''} x T threads")
            if label_points:
                for x in xs:
                    label(ax, x, key, c)

    series(ax_wall, "wall_seconds")
    ax_wall.set_ylabel("wall time [s]")
    ax_wall.set_title("Wall time")

    ax_sp.plot([cmin, cmax], [cmin, cmax], "k--", linewidth=1, label="ideal")
    series(ax_sp, "speedup")
    ax_sp.set_ylabel(f"speed-up (vs {base['layout']})")
    ax_sp.set_title("Speed-up")

    ax_eff.axhline(0.90, color="tab:green", linestyle="--", linewidth=1, label="90%")
    ax_eff.axhline(0.85, color="tab:orange", linestyle="--", linewidth=1, label="85%")
    series(ax_eff, "parallel_efficiency")
    ax_eff.set_ylabel("parallel efficiency = speed-up / cores")
    ax_eff.set_title("Parallel efficiency")
    lo = min(x["parallel_efficiency"] for x in rows)
    hi = max(x["parallel_efficiency"] for x in rows)
    ax_eff.set_ylim(min(0.0, lo - 0.05), max(1.05, hi + 0.05))

    # Panel 4: only multi-rank layouts (one rank has no messages and no imbalance). The colour
    # and marker are those of the rank count, as in the other panels, so (cores, colour) names
    # the layout: filled = overlap efficiency (left axis), open = load imbalance (right axis).
    from matplotlib.lines import Line2D
    ax_im = ax_ov.twinx()
    multi = {r: xs for r, xs in by_ranks.items() if r > 1}
    for r, xs in sorted(multi.items()):
        m, c = style[r]
        ax_ov.plot([x["cores"] for x in xs], [x["overlap_efficiency"] for x in xs], marker=m,
                   color=c, linestyle="-")
        ax_im.plot([x["cores"] for x in xs], [x["load_imbalance"] for x in xs], marker=m,
                   color=c, linestyle="--", markerfacecolor="none")
    if not multi:
        ax_ov.text(0.5, 0.5, "no multi-rank layout", transform=ax_ov.transAxes, ha="center",
                   va="center")
    ax_ov.set_ylim(0, 1.05)
    ax_ov.set_ylabel("overlap efficiency = hidden / total comm. (filled)")
    ax_im.axhline(1.0, color="grey", linestyle=":", linewidth=1)
    imax = max([x["load_imbalance"] for xs in multi.values() for x in xs] + [1.0])
    ax_im.set_ylim(0.95, max(1.25, imax + 0.05))
    ax_im.set_ylabel("load imbalance = max / mean rank busy (open)")
    ax_ov.set_title("Overlap efficiency and load imbalance (ranks > 1)", pad=38)
    handles = [Line2D([], [], color="k", marker="o", linestyle="-",
                      label="overlap efficiency (left)"),
               Line2D([], [], color="k", marker="o", linestyle="--", markerfacecolor="none",
                      label="load imbalance (right)")]
    handles += [Line2D([], [], color=style[r][1], marker=style[r][0], linestyle="none",
                       label=f"{r} ranks") for r in sorted(multi)]
    # Above the axes: inside, it would hide points wherever they fall.
    ax_ov.legend(handles=handles, fontsize=8, loc="lower center", bbox_to_anchor=(0.5, 1.0),
                 ncol=3, frameon=False)
    # Cores on a log2 axis (1, 2, 4, ... 16 evenly spaced); wall time and speed-up log-log.
    for ax in (ax_wall, ax_sp, ax_eff, ax_ov):
        ax.set_xscale("log", base=2)
        ax.set_xticks(cores)
        ax.set_xticklabels([str(c) for c in cores])
        ax.minorticks_off()
        ax.set_xlim(cmin / 1.4, cmax * 1.6)
        ax.set_xlabel("cores = ranks x threads")
        ax.grid(True, alpha=0.3)
    plain = matplotlib.ticker.FuncFormatter(lambda v, _: f"{v:g}")
    for ax in (ax_wall, ax_sp):
        ax.set_yscale("log")
        ax.yaxis.set_major_locator(matplotlib.ticker.LogLocator(base=10, subs=(1, 2, 5)))
        ax.yaxis.set_major_formatter(plain)
        ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    walls = [x["wall_seconds"] for x in rows]
    ax_wall.set_ylim(min(walls) / 1.5, max(walls) * 1.5)
    speedups = [x["speedup"] for x in rows]
    ax_sp.set_ylim(min(min(speedups), cmin) / 1.5, max(max(speedups), cmax) * 1.5)
    for ax in (ax_wall, ax_sp, ax_eff):
        ax.legend(fontsize=8, loc="best")

    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return True


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", help="results folder of run.sh (holds RxT/summary.json)")
    ap.add_argument("--layouts", help='space-separated layouts, e.g. "1x1 1x2 2x1" '
                    "(default: every RxT folder with a summary.json)")
    args = ap.parse_args()
    layouts = args.layouts.split() if args.layouts else None
    rows = read_rows(args.out, layouts)
    if not rows:
        sys.exit(f"plot.py: no RxT/summary.json under {args.out}")
    base = add_speedup(rows)

    csv_path = os.path.join(args.out, "scaling.csv")
    png_path = os.path.join(args.out, "scaling.png")
    write_csv(rows, csv_path)
    print_table(rows)
    title = (f"Strong scaling: {rows[0]['particles']} particles, {rows[0]['steps']} steps "
             f"(baseline {base['layout']})")
    made = plot(rows, base, png_path, title)
    print(f"wrote {csv_path}" + (f" and {png_path}" if made else ""))


if __name__ == "__main__":
    main()
