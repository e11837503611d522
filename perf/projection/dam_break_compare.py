#!/usr/bin/python3
"""Park et al.'s (2014) 2-D dam break with both schemes: cases/dam_break_2d.toml (WCSPH) and
cases/projection_dam_break_2d.toml (projection). Plots, in one PNG, the surge front Z = x/a
against T = t sqrt(2 g / a) with Martin & Moyce's (1952) points, and the pressure history of
probe P2 (right wall, 0.02 m above the floor). Prints per scheme the front's RMS relative
deviation from Martin & Moyce for T <= 3 (as tests/validation/test_dam_break_2d.cpp), the
peak wall pressure and its time, steps, wall time and ms per step.

Usage: perf/projection/dam_break_compare.py [--end 1.0] [--threads 1] [--png FILE] [--out DIR]
"""
from __future__ import annotations

import argparse
import csv
import json
import math
import sys
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "perf" / "lib"))
import sluice_run as sr  # noqa: E402

SLUICE = sr.DEFAULT_SLUICE
A, G = 0.4, 9.81  # column width [m], gravity


def read_probe(path: Path) -> np.ndarray:
    return np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


def martin_moyce() -> list[tuple[float, float]]:
    rows = []
    with open(ROOT / "tests" / "data" / "martin_moyce_1952_n2_2.csv") as f:
        for r in csv.reader(line for line in f if not line.startswith("#")):
            if r[0] == "case":
                continue
            rows.append((float(r[1]), float(r[2])))
    return rows


def front_rms(T: np.ndarray, Z: np.ndarray) -> tuple[float, int]:
    """RMS relative deviation of a front Z(T) (T = t sqrt(2g/A), Z = x/A) from Martin & Moyce
    over T <= 3 (and the run's end), and the number of experimental points it used."""
    rel = [(np.interp(t, T, Z) - z) / z for t, z in martin_moyce() if t <= 3.0 and t <= T[-1]]
    return (math.sqrt(sum(r * r for r in rel) / len(rel)) if rel else float("nan")), len(rel)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--end", type=float, default=1.0, help="simulated time [s]")
    ap.add_argument("--out", help="keep the two runs' results here (default: a temporary folder)")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--png", default=str(ROOT / "perf" / "projection" / "dam_break_compare.png"))
    args = ap.parse_args()
    if not SLUICE.exists():
        raise SystemExit("build the release binary first: cmake --build --preset release")
    exp = martin_moyce()
    T_scale = math.sqrt(2 * G / A)
    fig, (ax_front, ax_p) = plt.subplots(1, 2, figsize=(12, 4.5))
    ax_front.plot([t for t, _ in exp], [z for _, z in exp], "ko", label="Martin & Moyce 1952")
    with tempfile.TemporaryDirectory() as tmp:
        work = args.out or tmp
        for case, label in (("dam_break_2d", "WCSPH"), ("projection_dam_break_2d", "projection")):
            out = Path(work) / case
            run = sr.run_sluice(SLUICE, ROOT / "cases" / f"{case}.toml", out, args.threads,
                                nice=10, sets=[f"time.end_time={args.end}",
                                               "output.snapshots=false",
                                               "probes.0.interval=0.001",
                                               "probes.1.interval=0.005"])
            if not run.ok:
                raise SystemExit(f"{case}: sluice failed (exit {run.returncode}): "
                                 f"{run.stderr_tail}")
            front = read_probe(out / "probes" / "front.csv")
            press = read_probe(out / "probes" / "p2_right_wall.csv")
            T, Z = front[:, 0] * T_scale, front[:, 1] / A
            rms, points = front_rms(T, Z)
            s = json.load(open(out / "summary.json"))
            wall, steps = s.get("wall_seconds", float("nan")), s.get("steps", 0)
            p = np.nan_to_num(press[:, 1])
            k = int(np.argmax(p))
            print(f"{label:10s} front RMS deviation from Martin & Moyce (T <= 3, {points} "
                  f"points) {100 * rms:.1f} %; P2 peak {p[k]:.0f} Pa at t = {press[k, 0]:.3f} s; "
                  f"{steps} steps, {wall:.1f} s wall, {1e3 * wall / max(steps, 1):.2f} ms/step")
            if case.startswith("projection"):
                log = (out / "logs" / "rank_0.log").read_text()
                line = next((ln for ln in log.splitlines() if "pressure solves:" in ln), "")
                print("           " + line[line.find("pressure solves:"):])
            ax_front.plot(T, Z, label=f"{label} (RMS {100 * rms:.1f} %)")
            ax_p.plot(press[:, 0], p / (1000 * G * A), label=label, lw=0.8)
    ax_front.set(xlabel="T = t sqrt(2g/a)", ylabel="Z = x_front / a", xlim=(0, 3.5), ylim=(1, 4.2),
                 title="surge front")
    ax_front.legend()
    ax_p.set(xlabel="t [s]", ylabel="p / (rho g a)", title="P2: right wall, 0.02 m above floor")
    ax_p.legend()
    fig.tight_layout()
    fig.savefig(args.png, dpi=120)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
