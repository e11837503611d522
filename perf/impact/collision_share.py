#!/usr/bin/python3
"""How much of the projection scheme's wall readings on the Zhou wall is its wall collisions'.

Under the projection scheme an area sensor's (interpolated) reading is the pressure on its
face plus the traction of the scheme's wall collisions (docs/CASE_REFERENCE.md, `reading`);
the collisions are a discretisation error of its wall condition whose share falls with dx
(docs/IMPACT_LOADS.md). `reading = "collisions"` reads that traction alone, so
interpolated - collisions is the pressure's part.

  collision_share.py case OUT.toml
      writes zhou_2d.toml with, beside each area sensor and F_right_wall, a twin reading the
      collisions alone (name + "_coll"); run it with the projection variant only (WCSPH
      refuses the reading), e.g.
      perf/impact/run.sh --case OUT.toml --resolutions H/60 --c0 20 --jitters 0,0.002 \\
          --no-default --variant projection:numerics.scheme=projection --end-time 0.85 \\
          --no-snapshots --no-analyse --out DIR
  collision_share.py analyse RUN_DIR... [--out PREFIX]
      per sensor and run: the 1 ms filtered first-impact peak of the whole reading, of its
      pressure part and of the collisions alone; the collisions' share of the reading at that
      peak and of its impulse over 0.5 t* after contact; then the medians per resolution
      (text, and CSV with --out).

Definitions as analyse.py's (README.md, "Definitions"): contact at 0.05 rho g H, centred 1 ms
moving average, window 0.5 t* from contact; peaks in rho g H, the whole wall in rho g H^2/2.
"""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import loads_package  # noqa: E402, F401  (scripts/ on the path)
from run_folders import RunInfo, run_from_study  # noqa: E402
from sluice_loads.impact import (CONTACT_FRACTION, DEFAULT_FILTER_S,  # noqa: E402
                                 DEFAULT_WINDOW_STAR, Scales, first_impact_window)
from sluice_loads.runs import load_probe  # noqa: E402
from sluice_loads.signals import dry_as_zero, integral, moving_average  # noqa: E402
from sluice_loads.tables import format_cell, write_csv  # noqa: E402

CASE = HERE / "zhou_2d.toml"
AREA_SENSORS = ["y003mm_area", "y030mm_area", "y080mm_area", "P1_area"]
WALL = "F_right_wall"
SUFFIX = "_coll"


def probe_blocks(text: str) -> dict[str, str]:
    """Each [[probes]] block of a case's text (up to the next table or comment), by name."""
    blocks = {}
    for m in re.finditer(r"^\[\[probes\]\]\n(?:(?!\[|#).*\n?)*", text, re.M):
        name = re.search(r'^name\s*=\s*"([^"]+)"', m.group(0), re.M)
        if name:
            blocks[name.group(1)] = m.group(0).rstrip("\n") + "\n"
    return blocks


def collisions_case(text: str) -> str:
    """The case's text with a collisions twin beside each area sensor and the wall probe."""
    blocks = probe_blocks(text)
    twins = ["\n# Added by perf/impact/collision_share.py: the projection scheme's wall collisions "
             "alone\n# (reading = \"collisions\"; projection only).\n"]
    for name in AREA_SENSORS + [WALL]:
        block = re.sub(r'^name\s*=\s*"[^"]+"', f'name = "{name}{SUFFIX}"', blocks[name],
                       count=1, flags=re.M)
        block = re.sub(r"^reading\s*=.*\n", "", block, flags=re.M)
        twins.append(block.rstrip("\n") + '\nreading = "collisions"\n')
    return text.rstrip("\n") + "\n" + "\n".join(twins)


def share_row(run: RunInfo, sensor: str) -> dict | None:
    sc: Scales = run.scales
    probes = run.folder / "probes"
    whole, coll = probes / f"{sensor}.csv", probes / f"{sensor}{SUFFIX}.csv"
    if not whole.exists() or not coll.exists():
        return None
    # load_probe's value column is the first after the time: the pressure, or a force's Fx.
    t, p = load_probe(whole)
    tc_, c = load_probe(coll)
    if len(t) != len(tc_) or np.any(t != tc_):
        raise SystemExit(f"{run.folder}: {sensor} and its collisions twin have different samples")
    wall = sensor == WALL
    unit = sc.p * sc.H / 2 if wall else sc.p            # rho g H^2/2 per metre, or rho g H
    q, c = dry_as_zero(p), dry_as_zero(c)
    fq, fc = moving_average(t, q, DEFAULT_FILTER_S), moving_average(t, c, DEFAULT_FILTER_S)
    # Contact as analyse.py's: on the raw pressure of a sensor, on the filtered wall force.
    window = first_impact_window(t, fq if wall else q, CONTACT_FRACTION * unit,
                                 DEFAULT_WINDOW_STAR * sc.t)
    if window is None:
        return None
    t0, t1 = window
    w = (t >= t0) & (t <= t1)
    fp = fq - fc                                         # the pressure's part
    k = int(np.argmax(np.where(w, fq, -np.inf)))
    i_all, i_coll = integral(t, q, t0, t1), integral(t, c, t0, t1)
    return {"run": run.label, "dx": run.dx, "H_over_dx": sc.H / run.dx, "sensor": sensor,
            "peak": fq[k] / unit, "peak_pressure_part": float(np.max(np.where(w, fp, -np.inf))) / unit,
            "peak_collisions": float(np.max(np.where(w, fc, -np.inf))) / unit,
            "share_at_peak": fc[k] / fq[k] if fq[k] > 0 else float("nan"),
            "impulse_share": i_coll / i_all if i_all > 0 else float("nan"),
            "window_complete": bool(t[-1] >= t1)}


FIGURES = ["peak", "peak_pressure_part", "peak_collisions", "share_at_peak", "impulse_share"]
COLUMNS = ["run", "dx", "H_over_dx", "sensor", *FIGURES, "window_complete"]
MEDIAN_COLUMNS = ["sensor", "H_over_dx", "runs", *FIGURES]


def analyse(runs: list[RunInfo], out: Path | None) -> None:
    rows = [r for run in runs for s in AREA_SENSORS + [WALL]
            if (r := share_row(run, s)) is not None]
    if not rows:
        raise SystemExit("no run with collisions twins (collision_share.py case ...)")
    lines = ["# perf/impact/collision_share.py analyse " + " ".join(str(r.folder) for r in runs),
             "# 1 ms filtered first-impact peak of the whole (interpolated) reading, of its "
             "pressure part (interpolated - collisions) and of the collisions alone, rho g H "
             "(whole wall: rho g H^2/2); the collisions' share of the reading at its peak and "
             "of its impulse over 0.5 t* from contact",
             f"{'run':18s} {'sensor':13s} {'H/dx':>5s} {'peak':>6s} {'press':>6s} {'coll':>6s} "
             f"{'share@pk':>8s} {'I share':>7s}"]
    for r in rows:
        lines.append(f"{r['run']:18s} {r['sensor']:13s} {r['H_over_dx']:5.0f} "
                     f"{format_cell(r['peak'], '6.3f')} {format_cell(r['peak_pressure_part'], '6.3f')} "
                     f"{format_cell(r['peak_collisions'], '6.3f')} "
                     f"{format_cell(r['share_at_peak'], '8.3f')} {format_cell(r['impulse_share'], '7.3f')}"
                     + ("" if r["window_complete"] else "  (window cut)"))
    lines += ["", "medians per resolution",
              f"{'sensor':13s} {'H/dx':>5s} {'runs':>4s} {'peak':>6s} {'press':>6s} {'coll':>6s} "
              f"{'share@pk':>8s} {'I share':>7s}"]
    medians = []
    for s in AREA_SENSORS + [WALL]:
        for n in sorted({round(r["H_over_dx"]) for r in rows}):
            g = [r for r in rows if r["sensor"] == s and round(r["H_over_dx"]) == n]
            if not g:
                continue
            m = {k: float(np.median([r[k] for r in g])) for k in FIGURES}
            medians.append({"sensor": s, "H_over_dx": n, "runs": len(g), **m})
            lines.append(f"{s:13s} {n:5d} {len(g):4d} {m['peak']:6.3f} {m['peak_pressure_part']:6.3f} "
                         f"{m['peak_collisions']:6.3f} {m['share_at_peak']:8.3f} {m['impulse_share']:7.3f}")
    text = "\n".join(lines) + "\n"
    print(text, end="")
    if out is not None:
        out.parent.mkdir(parents=True, exist_ok=True)
        Path(f"{out}.txt").write_text(text)
        write_csv(Path(f"{out}.csv"), rows, COLUMNS)
        write_csv(Path(f"{out}_medians.csv"), medians, MEDIAN_COLUMNS)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("case", help="write the case with the collisions twins")
    c.add_argument("out", type=Path)
    c.add_argument("--case", type=Path, default=CASE)
    a = sub.add_parser("analyse", help="the collisions' shares from run folders")
    a.add_argument("runs", type=Path, nargs="+")
    a.add_argument("--out", type=Path, help="PREFIX: PREFIX.txt, PREFIX.csv, PREFIX_medians.csv")
    args = ap.parse_args()
    if args.cmd == "case":
        args.out.write_text(collisions_case(args.case.read_text()))
        print(args.out)
    else:
        # Finished runs only (summary.json is written at the end; study_run.json by study.py).
        runs = [run_from_study(r) for r in args.runs
                if (r / "summary.json").exists() and (r / "study_run.json").exists()]
        analyse(sorted(runs, key=lambda r: (-r.dx, r.label)), args.out)


if __name__ == "__main__":
    main()
