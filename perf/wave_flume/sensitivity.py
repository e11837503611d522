#!/usr/bin/env python3
"""What the wave's loss of height along a flume depends on: the flume of flume.py at kh = 1
(h = 0.2 m, H = 3 cm, dx = 2 cm, gauges from 0.1 to 2 wavelengths) run as it is and with
one setting changed at a time, the height at each gauge over the requested height (first
harmonic, last three periods).

Usage: perf/wave_flume/sensitivity.py [--threads N]; prints one line per variant.
"""
import argparse
import shutil
import subprocess
from pathlib import Path

import numpy as np

from flume import EXE, harmonics, case_text

HERE = Path(__file__).resolve().parent
KH, DEPTH, HEIGHT = 1.0, 0.2, 0.03
GAUGES = (0.1, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0)
# name: (dx, alpha, extra `sluice run --set` overrides)
VARIANTS = {
    "as is (alpha 0.02, delta 0.1, c0 14, dx 0.02)": (0.02, 0.02, []),
    "alpha 0.005": (0.02, 0.005, []),
    "delta 0.02": (0.02, 0.02, ["numerics.delta_sph=0.02"]),
    "c0 28": (0.02, 0.02, ["fluid.sound_speed=28"]),
    "dx 0.0125": (0.0125, 0.02, []),
}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--threads", type=int, default=2)
    args = ap.parse_args()
    work = HERE / "results" / "sensitivity"
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    print("H / H_target at " + ", ".join(f"{g} L" for g in GAUGES))
    for name, (dx, alpha, sets) in VARIANTS.items():
        text, k, T, L, gauges, end = case_text("sensitivity", KH, DEPTH, HEIGHT, dx, False,
                                               alpha, GAUGES)
        case = work / "sensitivity.toml"
        case.write_text(text)
        out = work / "run"
        shutil.rmtree(out, ignore_errors=True)
        cmd = [str(EXE), "run", str(case), "--out", str(out), "--threads", str(args.threads), "-q"]
        for s in sets:
            cmd += ["--set", s]
        subprocess.run(cmd, check=True)
        heights = []
        for i in range(len(gauges)):
            d = np.loadtxt(out / "probes" / f"g{i}.csv", delimiter=",", skiprows=1)
            m = d[:, 0] >= end - 3 * T
            a1, _ = harmonics(d[m, 0], d[m, 1] - d[m, 1].mean(), T)
            heights.append(f"{2 * abs(a1) / HEIGHT:.3f}")
        print(f"{name:48s} {' '.join(heights)}", flush=True)
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
