#!/usr/bin/python3
"""The projection dam break (cases/projection_dam_break_2d.toml) with radius neighbours and with
convex-hull neighbours per operator (perf/convex_hull/README.md, "Stability in a run"): does
the run finish, how far is the front from Martin & Moyce (RMS relative deviation for T <= 3,
as perf/projection/dam_break_compare.py), the pressure solver's iterations, the highest fluid particle (the run-up jet) and the fraction
of fluid particles on surface rows (p = 0) in the last snapshot.

Usage: perf/convex_hull/hull_dam_break.py [--dx 0.02] [--end 0.8] [--threads 1] [--out DIR]
"""
from __future__ import annotations

import argparse
import json
import math
import sys
import tempfile
from pathlib import Path

import h5py
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "perf" / "lib"))
sys.path.insert(0, str(ROOT / "perf" / "projection"))
import sluice_run as sr  # noqa: E402
from dam_break_compare import A, G, front_rms, read_probe  # noqa: E402

HULL = '"convex-hull"'
POLICIES = {
    "radius (Park et al. 2014)": [],
    "hull: gradient": [f"neighbours.gradient.selection={HULL}"],
    "hull: Laplacian": [f"neighbours.laplacian.selection={HULL}"],
    "hull: free surface": [f"neighbours.free_surface.selection={HULL}"],
    "hull: all three": [f"neighbours.{op}.selection={HULL}"
                        for op in ("gradient", "laplacian", "free_surface")],
}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dx", type=float, default=0.02)
    ap.add_argument("--end", type=float, default=0.8, help="simulated time [s]")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--out", help="keep the runs here (default: a temporary folder)")
    args = ap.parse_args()
    sluice = sr.ensure_binary(sr.DEFAULT_SLUICE)
    t_scale = math.sqrt(2 * G / A)
    print(f"projection dam break, dx = {args.dx} m, to t = {args.end} s; {sr.machine_description()}")
    print(f"{'neighbours':20s} {'result':>8s} {'steps':>6s} {'front RMS':>9s} {'iter/step':>9s} "
          f"{'top y [m]':>9s} {'surface %':>9s} {'wall s':>7s}")
    with tempfile.TemporaryDirectory() as tmp:
        for k, (label, sets) in enumerate(POLICIES.items()):
            out = Path(args.out or tmp) / f"policy_{k}"
            run = sr.run_sluice(sluice, ROOT / "cases" / "projection_dam_break_2d.toml", out,
                                args.threads, sets=[f"particles.dx={args.dx}",
                                                    f"time.end_time={args.end}",
                                                    f"time.output_interval={args.end / 4}",
                                                    "probes.1.interval=0.005"] + sets)
            summary = out / "summary.json"
            s = json.load(open(summary)) if summary.exists() else {}
            front = read_probe(out / "probes" / "front.csv")
            T, Z = front[:, 0] * t_scale, front[:, 1] / A
            rms = front_rms(T, Z)[0]
            log = (out / "logs" / "rank_0.log").read_text()
            line = next((ln for ln in log.splitlines() if "pressure solves:" in ln), "")
            iters = line.split("steps, ")[1].split(" iterations")[0] if "steps, " in line else "?"
            snaps = sorted((out / "snapshots").glob("*.h5"))
            top = surf = float("nan")
            if snaps:
                with h5py.File(snaps[-1], "r") as f:
                    fluid = f["kind"][:] == 0 if "kind" in f else slice(None)
                    top = float(f["position"][:][fluid][:, 1].max())
                    p = f["pressure"][:][fluid]
                    surf = 100 * float(np.mean(p == 0))
            result = "ok" if run.ok else f"exit {run.returncode}"
            print(f"{label:20s} {result:>8s} {s.get('steps', 0):6d} {100 * rms:8.1f}% {iters:>9s} "
                  f"{top:9.3f} {surf:9.1f} {s.get('wall_seconds', float('nan')):7.1f}")


if __name__ == "__main__":
    main()
