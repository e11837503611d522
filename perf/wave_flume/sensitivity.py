#!/usr/bin/env python3
"""What the wave's loss of height along a flume depends on: one short 2-D piston flume
(kh = 1, h = 0.2 m, H = 3 cm, dx = 2 cm, 3 wavelengths with a damping zone over the last one,
the flume of tests/validation/test_wave_makers_2d.cpp with more gauges) run as it is and with
one setting changed at a time (--set), the height at 0.1, 0.25, 0.5, 0.75, 1 and 1.5
wavelengths from the paddle over the requested height (first harmonic, last three periods).

Usage: perf/wave_flume/sensitivity.py [--threads N]; prints one line per variant.
"""
import argparse
import math
import shutil
import subprocess
from pathlib import Path

import numpy as np

from flume import EXE, G, group_velocity, harmonics, wave_number_period

HERE = Path(__file__).resolve().parent
KH, DEPTH, HEIGHT = 1.0, 0.2, 0.03
GAUGES = (0.1, 0.25, 0.5, 0.75, 1.0, 1.5)
VARIANTS = {
    "as is (alpha 0.02, delta 0.1, c0 14, dx 0.02)": [],
    "alpha 0.005": ["numerics.artificial_viscosity=0.005"],
    "delta 0.02": ["numerics.delta_sph=0.02"],
    "c0 28": ["fluid.sound_speed=28"],
    "dx 0.0125": ["particles.dx=0.0125", "walls.boxes.0.lo=[-0.05, 0]"],
}


def case_text():
    k, T = wave_number_period(KH, DEPTH)
    L = 2 * math.pi / k
    length = 3 * L
    end = 2 * T + L / group_velocity(k, DEPTH, T) + 3.5 * T
    probes = "".join(f'[[probes]]\nname = "g{i}"\ntype = "water_level"\nx = {f * L:.6f}\n'
                     f'interval = {T / 50:.6f}\n' for i, f in enumerate(GAUGES))
    return f"""[case]
name = "sensitivity"
dimension = 2
[domain]
lo = [-0.2, 0]
hi = [{length:.6f}, 0.35]
[fluid]
rho0 = 1000
viscosity = 1e-6
sound_speed = 14
gravity = [0, -9.81]
[particles]
dx = 0.02
[[blocks]]
lo = [0, 0]
hi = [{length:.6f}, {DEPTH}]
[numerics]
kernel = "wendland_c2"
h_over_dx = 1.5
artificial_viscosity = 0.02
[walls]
model = "dummy"
tank_lo = [-0.2, 0]
tank_hi = [{length:.6f}, 0.35]
tank_faces = ["x+", "y-"]
[[walls.boxes]]
lo = [-0.06, 0]
hi = [0, 0.35]
motion = "paddle"
[[motions]]
name = "paddle"
kind = "piston"
wave_height = {HEIGHT}
wave_period = {T:.8f}
depth = {DEPTH}
ramp = {2 * T:.6f}
[[damping_zones]]
start = [{2 * L:.6f}, 0]
end = [{length:.6f}, 0]
strength = {10 / T:.4f}
[time]
end_time = {end:.6f}
{probes}""", T, end


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--threads", type=int, default=2)
    args = ap.parse_args()
    text, T, end = case_text()
    work = HERE / "results" / "sensitivity"
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    case = work / "sensitivity.toml"
    case.write_text(text)
    print("H / H_target at " + ", ".join(f"{g} L" for g in GAUGES))
    for name, sets in VARIANTS.items():
        out = work / "run"
        shutil.rmtree(out, ignore_errors=True)
        cmd = [str(EXE), "run", str(case), "--out", str(out), "--threads", str(args.threads), "-q"]
        for s in sets:
            cmd += ["--set", s]
        subprocess.run(cmd, check=True)
        heights = []
        for i in range(len(GAUGES)):
            d = np.loadtxt(out / "probes" / f"g{i}.csv", delimiter=",", skiprows=1)
            m = d[:, 0] >= end - 3 * T
            a1, _ = harmonics(d[m, 0], d[m, 1] - d[m, 1].mean(), T)
            heights.append(f"{2 * abs(a1) / HEIGHT:.3f}")
        print(f"{name:48s} {' '.join(heights)}", flush=True)
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
