#!/usr/bin/python3
"""Time to solution of the projection scheme against WCSPH on Park et al.'s (2014) 2-D
dam break (the targets of docs/PROJECTION.md §4: <= 1.5x WCSPH's wall time, front RMS <=
WCSPH's, <= 20 pressure-solver iterations per step on average).

Runs cases/dam_break_2d.toml (WCSPH) and cases/projection_dam_break_2d.toml (projection, in
the variants below) one after the other, round after round (interleaved, so that the load of
a shared machine drifts over all of them alike), and prints per run: process wall time and
CPU time, steps, ms per step, the front's RMS relative deviation from Martin & Moyce
(T <= 3, as perf/projection/dam_break_compare.py and tests/validation/test_dam_break_2d.cpp),
the pressure solver's mean and largest iterations per step (rank log), and the CPU-time ratio
to the WCSPH run of the same round. CPU time is the figure to compare on a loaded machine (one
worker thread: wall time also counts the time the process waited for a core).

Variants (projection): "adaptive" (the case as shipped: adaptive dt, the default Jacobi
preconditioner), "ilu0" (adaptive dt, projection.preconditioner = "block_ilu0"), "fixed"
(numerics.dt = 2e-4, the case's old fixed step), "jacobi" (adaptive dt, the Jacobi
preconditioner named), "fixed-jacobi" (both old settings: the scheme as it was before
aedddea); "ilu0-tol6", "ilu0-tol5", "jacobi-tol6", "jacobi-tol5" (a looser
projection.tolerance, 1e-6 or 1e-5 instead of the case's 1e-8); "shift0.05", "shift0.2", "shift0.5"
(particle shifting, projection.shifting = 0.05, 0.2 or 0.5); "two-level", "two-level-tol6"
(projection.preconditioner = "two_level", at the case's 1e-8 or at 1e-6); "minimum"
(correction_reference = "minimum", deviation_weight = "pnu_mps": the scheme before 76e7738);
"gamma0" (projection.gamma = 0).

Usage: perf/projection/time_to_solution.py [--dx 0.01] [--end 1.0] [--rounds 1]
           [--variants adaptive,fixed,jacobi,fixed-jacobi] [--threads 1] [--sluice PATH]
           [--wcsph-sluice PATH] [--out DIR] [--nice 10]

--nice 0 runs at normal priority: on a machine loaded by others' normal-priority jobs, a run
at nice 10 got 3 % of a core (42 s of CPU in 25 min), which CPU time does not count but the
wall clock does.
"""
from __future__ import annotations

import argparse
import math
import re
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "perf" / "lib"))
import sluice_run as sr  # noqa: E402

sys.path.insert(0, str(ROOT / "perf" / "projection"))
import dam_break_compare as dbc  # noqa: E402

A, G = dbc.A, dbc.G

VARIANTS = {
    "adaptive": [],
    "ilu0": ['projection.preconditioner="block_ilu0"'],
    "fixed": ["numerics.dt=2.0e-4"],
    "jacobi": ['projection.preconditioner="jacobi"'],
    "fixed-jacobi": ["numerics.dt=2.0e-4", 'projection.preconditioner="jacobi"'],
    # The solver tolerance's share (the shipped case solves to 1e-8).
    "ilu0-tol6": ['projection.preconditioner="block_ilu0"', "projection.tolerance=1e-6"],
    "ilu0-tol5": ['projection.preconditioner="block_ilu0"', "projection.tolerance=1e-5"],
    "jacobi-tol6": ['projection.preconditioner="jacobi"', "projection.tolerance=1e-6"],
    "jacobi-tol5": ['projection.preconditioner="jacobi"', "projection.tolerance=1e-5"],
    # The two-level preconditioner (coarse correction on aggregates of 2^D cells, then the
    # block ILU(0); docs/PROJECTION.md, "Preconditioner").
    "two-level": ['projection.preconditioner="two_level"'],
    "two-level-tol6": ['projection.preconditioner="two_level"', "projection.tolerance=1e-6"],
    # Particle shifting (projection.shifting = A; docs/PROJECTION.md, "Particle shifting").
    "shift0.05": ["projection.shifting=0.05"],
    "shift0.2": ["projection.shifting=0.2"],
    "shift0.5": ["projection.shifting=0.5"],
    # P7's reference and P3's weight as before 76e7738 (docs/PROJECTION.md, P3 and P7), and
    # the defaults without the density-deviation term.
    "minimum": ['projection.correction_reference="minimum"', 'projection.deviation_weight="pnu_mps"'],
    "gamma0": ["projection.gamma=0"],
}


def front_rms(out: Path) -> float:
    front = np.loadtxt(out / "probes" / "front.csv", delimiter=",", skiprows=1, ndmin=2)
    return dbc.front_rms(front[:, 0] * math.sqrt(2 * G / A), front[:, 1] / A)[0]


def solver_line(out: Path) -> tuple[float, int]:
    log = (out / "logs" / "rank_0.log").read_text()
    m = re.search(r"pressure solves: \d+ steps, ([\d.]+) iterations per step on average, "
                  r"at most (\d+)", log)
    return (float(m.group(1)), int(m.group(2))) if m else (float("nan"), 0)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dx", type=float, default=0.01)
    ap.add_argument("--end", type=float, default=1.0, help="simulated time [s]")
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--variants", default="adaptive,ilu0,fixed-jacobi")
    ap.add_argument("--sluice", default=str(sr.DEFAULT_SLUICE), help="binary of the projection runs")
    ap.add_argument("--wcsph-sluice", help="binary of the WCSPH runs (default: --sluice)")
    ap.add_argument("--out", help="keep the runs' results here (default: a temporary folder)")
    ap.add_argument("--nice", type=int, default=10, help="niceness of the runs (0: unchanged)")
    args = ap.parse_args()
    proj_exe = Path(args.sluice)
    wcsph_exe = Path(args.wcsph_sluice or args.sluice)
    for exe in (proj_exe, wcsph_exe):
        if not exe.exists():
            raise SystemExit(f"{exe} missing: cmake --build --preset release --target sluice")
    variants = args.variants.split(",")
    for v in variants:
        if v not in VARIANTS:
            raise SystemExit(f"unknown variant {v!r}; known: {', '.join(VARIANTS)}")
    common = [f"particles.dx={args.dx}", f"time.end_time={args.end}", "output.snapshots=false",
              "probes.1.interval=0.005"]
    print(f"dam break, dx = {args.dx} m, to t = {args.end} s, {args.threads} thread(s); "
          f"projection: {proj_exe}; WCSPH: {wcsph_exe}")
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(args.out or tmp)
        for rnd in range(args.rounds):
            wcsph_cpu = None
            for name in ["wcsph"] + variants:
                wcsph = name == "wcsph"
                case = "dam_break_2d" if wcsph else "projection_dam_break_2d"
                out = work / f"r{rnd}_{name}"
                run = sr.run_sluice(wcsph_exe if wcsph else proj_exe,
                                    ROOT / "cases" / f"{case}.toml", out, args.threads, nice=args.nice,
                                    echo=False, sets=common + ([] if wcsph else VARIANTS[name]))
                if not run.ok:
                    print(f"round {rnd} {name:12s} FAILED (exit {run.returncode}): "
                          f"{run.stderr_tail}", flush=True)
                    continue
                steps = run.summary.get("steps", 0)
                line = (f"round {rnd} {name:12s} wall {run.process_wall_s:7.1f} s, CPU "
                        f"{run.cpu_s:7.1f} s, {steps:6d} steps, "
                        f"{1e3 * run.cpu_s / max(steps, 1):6.2f} ms CPU/step, front RMS "
                        f"{100 * front_rms(out):5.1f} %")
                if wcsph:
                    wcsph_cpu = run.cpu_s
                else:
                    mean, most = solver_line(out)
                    line += f", solver {mean:5.1f} iterations/step (at most {most})"
                    if wcsph_cpu:
                        line += f", CPU time {run.cpu_s / wcsph_cpu:.2f}x WCSPH's"
                print(line, flush=True)


if __name__ == "__main__":
    main()
