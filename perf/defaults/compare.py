#!/usr/bin/python3
"""The numerics a case gets when it leaves them out, against the recommended practice.

    perf/defaults/compare.py [--cases dam_break,hydrostatic,taylor_green,poiseuille]
                             [--threads 1] [--nice N] [--sluice PATH] [--out DIR]

Runs each validation case of perf/speed_vs_error (same files, resolutions of its quick sweep,
same error definitions: perf/speed_vs_error/evaluate.py) with two sets of numerics, every other
key as the case file has it:

  quintic    numerics.kernel = "quintic", h_over_dx = 1.0, artificial_viscosity = 0
  wendland   numerics.kernel = "wendland_c2", h_over_dx = 1.5, artificial_viscosity = 0.02
             (docs/RECOMMENDED_PRACTICE.md, "Kernel and h/dx" and "Artificial viscosity")
  wendland0  the same kernel with artificial_viscosity = 0 (which of the two changes counts)

Both keep the support at 3 dx. Prints, per case and resolution, the error, the share of the
fluid that ends closer than dx/2 to a neighbour (summary.json's spacing census), the time loop's
wall time per particle-step (summary.json's wall_seconds x threads: start-up left out) and the
ratios against quintic; writes OUT/defaults.csv. The settings run back to back at each
resolution, so their cost ratios are measured in one window.
"""
from __future__ import annotations

import argparse
import csv
import math
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
sys.path.insert(0, str(HERE.parent / "speed_vs_error"))
import evaluate  # noqa: E402
import sluice_run as sr  # noqa: E402
from sweep import CASES, resolution_overrides  # noqa: E402

SETTINGS = {
    "quintic": {"numerics.kernel": "quintic", "numerics.h_over_dx": 1.0,
                "numerics.artificial_viscosity": 0.0},
    "wendland": {"numerics.kernel": "wendland_c2", "numerics.h_over_dx": 1.5,
                 "numerics.artificial_viscosity": 0.02},
    # the kernel's share of the difference: the recommended kernel without viscosity
    "wendland0": {"numerics.kernel": "wendland_c2", "numerics.h_over_dx": 1.5,
                  "numerics.artificial_viscosity": 0.0},
}
COLUMNS = ["case", "dx", "setting", "error", "crowded_end", "core_s", "particle_steps",
           "ns_per_particle_step", "steps", "status", "git"]


def crowded_share(summary: dict) -> float:
    end = summary.get("extra", {}).get("neighbours", {}).get("end", {})
    n = end.get("fluid_particles", 0)
    return end.get("fluid_crowded", 0) / n if n else float("nan")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cases", default="dam_break,hydrostatic,taylor_green,poiseuille")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--nice", type=int, default=0)
    ap.add_argument("--sluice", type=Path, default=sr.DEFAULT_SLUICE)
    ap.add_argument("--out", type=Path, default=HERE / "results")
    ap.add_argument("--runs", type=Path, default=sr.ROOT / "results" / "defaults")
    args = ap.parse_args()
    sluice = sr.ensure_binary(args.sluice)
    git = sr.git_revision()
    print(f"== numerics left out vs recommended, git {git}, {args.threads} thread(s) per run")
    print(f"   machine: {sr.machine_description()}")
    rows = []
    for name in (c.strip() for c in args.cases.split(",") if c.strip()):
        if name not in CASES:
            sr.die(f"defaults: unknown case '{name}' (known: {', '.join(CASES)})")
        spec = CASES[name]
        case_file = sr.ROOT / spec["file"]
        base = sr.read_case(case_file)
        evaluator, measure = evaluate.EVALUATORS[name]
        print(f"\n-- {name} ({spec['file']}): {measure}")
        for dx in spec["dx"]["quick"]:
            per = {}
            for label, setting in SETTINGS.items():
                overrides = dict(spec["fixed"])
                overrides["time.end_time"] = spec["end"]["quick"]
                overrides.update(resolution_overrides(name, base, dx))
                overrides.update(setting)
                run = sr.run_sluice(sluice, case_file, args.runs / f"{name}_{label}_dx{dx:g}",
                                    args.threads, overrides, nice=args.nice, echo=False)
                row = {"case": name, "dx": dx, "setting": label, "git": git}
                if run.ok:
                    s = run.summary
                    ps = s["particles"] * s["steps"]
                    core_s = args.threads * s["wall_seconds"]
                    row.update(steps=s["steps"], particle_steps=ps, core_s=core_s,
                               ns_per_particle_step=1e9 * core_s / ps,
                               crowded_end=crowded_share(s),
                               error=evaluator(run.out_dir, sr.read_case(case_file, overrides)),
                               status="ok")
                else:
                    row.update(error=float("nan"), status=f"run failed (exit {run.returncode})")
                per[label] = row
                rows.append(row)
            q = per["quintic"]
            for r in per.values():
                print(f"   dx {dx:<8g} {r['setting']:<9} "
                      + (f"error {100 * r['error']:7.3f} %  crowded {100 * r['crowded_end']:5.1f} %"
                         f"  {r['ns_per_particle_step']:7.1f} ns/particle-step"
                         if r["status"] == "ok" else r["status"]))
            for label, w in per.items():
                if label != "quintic" and q["status"] == w["status"] == "ok":
                    print(f"   dx {dx:<8g} {label}/quintic: error x{w['error'] / q['error']:.2f}, "
                          f"cost x{w['ns_per_particle_step'] / q['ns_per_particle_step']:.2f}")
    args.out.mkdir(parents=True, exist_ok=True)
    path = args.out / "defaults.csv"
    with open(path, "w", newline="") as f:
        f.write(f"# sluice numerics left out vs recommended, git {git}; "
                f"machine: {sr.machine_description()}\n")
        w = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) and math.isfinite(v) else v)
                        for k, v in r.items()})
    print(f"\n   table: {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
