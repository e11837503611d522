#!/usr/bin/python3
"""The peer's (DualSPHysics) gauges of perf/impact/peer/zhou_2d_Def.xml as a sluice run folder,
then the first-impact figures of perf/impact/analyse.py on it.

    perf/impact/peer/peer_metrics.py PEER_RUN [PEER_RUN ...] [--no-analyse]

PEER_RUN is a folder made by perf/impact/peer/run.sh (Case_Def.xml, out/Run.out, out/Gauges*).
Writes PEER_RUN/probes/ with the files sluice writes for perf/impact/zhou_2d.toml, so that
analyse.py, panels.py and compare.py read both codes alike:

* <probe>.csv (time_s,pressure_Pa): the mesh gauge's Shepard density of the fluid particles at
  the probe point (any particle within the support; kclimit 1e-6, a dry point reads density 0
  and is written NaN as sluice writes a dry probe), turned into pressure with the peer's own
  equation of state p = B ((rho/rho0)^gamma - 1), B, gamma and rho0 read from out/Run.out.
  (The peer's pressure of the interpolated density, not an interpolated pressure: with the
  Tait EOS the two differ at second order in the spread of the densities within the support.)
* F_right_wall.csv (time_s,Fx_N,Fy_N): the sum of the force gauges of every particle of the
  downstream wall (Wall_kNN, Wall_above600mm, Wall_corner: the x+ face and the corner it
  shares, like sluice's face = "x+" force probe), N per metre of width. The peer's force gauge
  sums the momentum equation's pressure term of the fluid-boundary pairs (no viscous term),
  times the boundary particle's mass.
* the four wall panels of the case (y010mm_panel 0-20 mm, y030mm_panel 20-40 mm, y080mm_panel
  70-90 mm, P1_panel 150-170 mm): the sum of the two particles' gauges in the strip.
* study_run.json and summary.json, so that analyse.py takes the folder as a study run
  (variant "peer", label = the folder's name, dx, c0, probe positions as in sluice's case).
"""
from __future__ import annotations

import json
import math
import re
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import analyse  # noqa: E402  (perf/impact/analyse.py)
import metrics  # noqa: E402
import run_folders  # noqa: E402

DP = 0.01              # m, the XML's dp
WALL_X = 3.225         # the downstream wall's boundary particles
PROBE_X = 3.215        # the mesh gauges' points (sluice's probes, half a dp inside the fluid)
PROBES = {"P1": 0.16, "P2": 0.584, "P1_y120mm": 0.12, "y003mm": 0.003, "y015mm": 0.015,
          "y030mm": 0.03, "y080mm": 0.08}
# panel name -> (lo, hi) in z [m], as in perf/impact/zhou_2d.toml
PANELS = {"y010mm_panel": (0.0, 0.02), "y030mm_panel": (0.02, 0.04),
          "y080mm_panel": (0.07, 0.09), "P1_panel": (0.15, 0.17)}
N_STRIP = 60           # Wall_k00 .. Wall_k59: the particle at z = 0.005 + 0.01 k


def run_constants(run_out: Path) -> dict:
    """rho0, gamma, B (CteB), c0 (Cs0), steps, runtime from the peer's Run.out."""
    text = run_out.read_text(errors="replace")

    def num(key: str) -> float:
        m = re.search(rf"^{key}=([-+0-9.eE]+)", text, re.M)
        if not m:
            raise SystemExit(f"{run_out}: no {key}= line")
        return float(m.group(1))

    def stat(label: str) -> float:
        m = re.search(rf"^{label}\.*: *([0-9.,]+)", text, re.M)
        return float(m.group(1).replace(",", "")) if m else math.nan

    return {"rho0": num("RhopZero") if re.search(r"^RhopZero=", text, re.M) else num("Rhop0"),
            "gamma": num("Gamma"), "B": num("CteB"), "c0": num("Cs0"),
            "steps": stat("Steps of simulation"), "runtime_s": stat("Simulation Runtime"),
            "particles": stat("Particles of simulation \\(initial\\)")}


def read_mesh_gauge(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """time, density of a one-point mesh gauge CSV (three header lines, ';' separated)."""
    d = np.loadtxt(path, delimiter=";", skiprows=3, ndmin=2)
    return d[:, 0], d[:, 1]


def read_force_gauge(path: Path) -> np.ndarray:
    """rows of time, |F|, Fx, Fy, Fz of a force gauge CSV."""
    return np.loadtxt(path, delimiter=";", skiprows=1, ndmin=2)


def dedupe(t: np.ndarray, *cols: np.ndarray) -> tuple[np.ndarray, ...]:
    """Drops repeated times (the gauge writes t = 0 from its first call and the first step)."""
    keep = np.concatenate([[True], np.diff(t) > 0])
    return (t[keep],) + tuple(c[keep] for c in cols)


def convert(run: Path) -> dict:
    out = run / "out"
    k = run_constants(out / "Run.out")
    probes = run / "probes"
    probes.mkdir(exist_ok=True)
    # pressure probes
    for name in PROBES:
        t, rho = read_mesh_gauge(out / f"GaugesMesh_{name}_Rhop.csv")
        t, rho = dedupe(t, rho)
        with np.errstate(invalid="ignore"):
            p = np.where(rho > 0, k["B"] * ((rho / k["rho0"]) ** k["gamma"] - 1.0), np.nan)
        np.savetxt(probes / f"{name}.csv", np.column_stack([t, p]), delimiter=",",
                   header="time_s,pressure_Pa", comments="", fmt="%.9g")
    # wall forces: every particle of the x+ face
    parts = [read_force_gauge(out / f"GaugesForce_Wall_k{i:02d}.csv") for i in range(N_STRIP)]
    rest = [read_force_gauge(out / f"GaugesForce_Wall_{n}.csv") for n in ("above600mm", "corner")]
    n = min(len(a) for a in parts + rest)
    t = parts[0][:n, 0]
    for a in parts + rest:
        if not np.allclose(a[:n, 0], t):
            raise SystemExit(f"{run}: force gauges at different times")

    def write_force(name: str, arrays: list[np.ndarray]) -> None:
        fx = sum(a[:n, 2] for a in arrays)
        fz = sum(a[:n, 4] for a in arrays)
        tt, fx, fz = dedupe(t, fx, fz)
        np.savetxt(probes / f"{name}.csv", np.column_stack([tt, fx, fz]), delimiter=",",
                   header="time_s,Fx_N,Fy_N", comments="", fmt="%.9g")

    write_force("F_right_wall", parts + rest)
    for name, (lo, hi) in PANELS.items():
        ks = [i for i in range(N_STRIP) if lo < 0.005 + DP * i < hi]
        write_force(name, [parts[i] for i in ks])
    # the records analyse.py reads for a study run
    sc = metrics.zhou_scales()
    end = float(t[-1])
    with open(run / "study_run.json", "w") as f:
        json.dump({"variant": "peer", "label": run.name, "dx": DP, "c0": k["c0"],
                   "c0_factor": round(k["c0"] / math.sqrt(sc.g * sc.H), 2), "end_time": end,
                   "scales": {"H": sc.H, "g": sc.g, "rho0": sc.rho0},
                   "probes": {p: {"position": [PROBE_X, y]} for p, y in PROBES.items()},
                   "returncode": 0, "code": "DualSPHysics v5.4 CPU",
                   "eos": {"B": k["B"], "gamma": k["gamma"], "rho0": k["rho0"]}}, f, indent=1)
    with open(run / "summary.json", "w") as f:
        json.dump({"simulated_time": end, "steps": int(k["steps"]) if k["steps"] == k["steps"]
                   else 0, "wall_seconds": k["runtime_s"], "particles": k["particles"]}, f,
                  indent=1)
    return k


def main(argv: list[str]) -> int:
    runs = [Path(a) for a in argv if not a.startswith("--")]
    if not runs:
        print(__doc__)
        return 2
    infos = []
    for r in runs:
        k = convert(r)
        print(f"{r}: c0 {k['c0']:.2f} m/s, B {k['B']:.6g} Pa, gamma {k['gamma']:g}, "
              f"{k['steps']:.0f} steps, {k['runtime_s']:.0f} s -> {r / 'probes'}")
        infos.append(run_folders.run_from_study(r))
    if "--no-analyse" not in argv:
        analyse.analyse(infos, runs[0] / "analysis", plots=False)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
