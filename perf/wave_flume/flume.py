#!/usr/bin/env python3
"""Piston wave-maker against linear wave-maker theory, over kh from shallow to deep water.

For each configuration a 2-D flume is written (a piston paddle at x = 0, a damping zone one
wavelength long at the far end, gauges every half wavelength), run with build/release/sluice,
and its gauges analysed over the last three wave periods of the run (after the ramp and after
the wave front has passed two wavelengths):

  H_2L   the wave height at two wavelengths from the paddle (2 x the first-harmonic amplitude
         of a least-squares fit of the first two harmonics), against the requested height the
         Biesel transfer function turned into the stroke;
  T      the mean zero up-crossing period there, against the paddle's;
  a2     the second-harmonic amplitude at each gauge from 1 to 2.5 wavelengths: a free second
         harmonic (first-order generation) beats with the bound one, so a2 varies along the
         flume; with the second-order stroke (Madsen 1971) it stays at the Stokes bound value
         a2 = k a^2 cosh(kh) (2 + cosh 2kh) / (4 sinh^3 kh). Printed as the spread
         (max - min) / Stokes bound over the gauges;
  Kr     the reflection coefficient of the far end (damping zone), from the two-gauge method
         of Goda & Suzuki (1976) on the gauges at 1.5 and 1.75 wavelengths.

Usage: perf/wave_flume/flume.py [--only NAME ...] [--threads N] [--keep]
Prints a table; writes perf/wave_flume/results/<name>/ (removed unless --keep) and
perf/wave_flume/results/table.txt.
"""
import argparse
import math
import shutil
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
EXE = ROOT / "build" / "release" / "sluice"
G = 9.81

# name: (kh, depth h [m], wave height H [m], dx [m], second_order, artificial viscosity alpha)
CONFIGS = {
    "kh0.3": (0.3, 0.10, 0.006, 0.01, False, 0.02),
    "kh0.7": (0.7, 0.20, 0.02, 0.01, False, 0.02),
    "kh0.7_2nd": (0.7, 0.20, 0.02, 0.01, True, 0.02),
    "kh1.3": (1.3, 0.40, 0.04, 0.02, False, 0.02),
    "kh3.0": (3.0, 0.60, 0.04, 0.02, False, 0.02),
}


def wave_number_period(kh, h):
    k = kh / h
    omega = math.sqrt(G * k * math.tanh(kh))
    return k, 2 * math.pi / omega


def group_velocity(k, h, T):
    c = 2 * math.pi / T / k
    return c / 2 * (1 + 2 * k * h / math.sinh(2 * k * h))


GAUGES = (0.5, 1.0, 1.5, 1.75, 2.0, 2.25, 2.5)  # [wavelengths from the paddle]


def case_text(name, kh, h, H, dx, second, alpha, gauges=GAUGES):
    """The flume's case file: gauges at the given fractions of a wavelength, a zone one
    wavelength long beyond the last gauge (+0.25 L), a run long enough for the wave to pass
    two wavelengths and five more periods."""
    k, T = wave_number_period(kh, h)
    L = 2 * math.pi / k
    length = (max(gauges) + 0.25) * L + L
    top = h + max(0.3 * h, 6 * H) + 3 * dx
    c0 = 10 * math.sqrt(G * h)
    ramp = 2 * T
    end = ramp + 2 * L / group_velocity(k, h, T) + 5 * T
    paddle = 3 * dx
    gauges = [f * L for f in gauges]
    probes = "".join(
        f'[[probes]]\nname = "g{i}"\ntype = "water_level"\nx = {x:.6f}\ninterval = {T / 50:.6f}\n\n'
        for i, x in enumerate(gauges))
    text = f"""[case]
name = "{name}"
dimension = 2
[domain]
lo = [{-4 * dx - 0.05:.6f}, 0.0]
hi = [{length:.6f}, {top:.6f}]
[fluid]
rho0 = 1000.0
viscosity = 1.0e-6
sound_speed = {c0:.4f}
gravity = [0.0, -9.81]
[particles]
dx = {dx}
[[blocks]]
lo = [0.0, 0.0]
hi = [{length:.6f}, {h:.6f}]
[numerics]
kernel = "wendland_c2"
h_over_dx = 1.5
artificial_viscosity = {alpha}
[walls]
model = "dummy"
tank_lo = [{-4 * dx - 0.05:.6f}, 0.0]
tank_hi = [{length:.6f}, {top:.6f}]
tank_faces = ["x+", "y-"]
[[walls.boxes]]
lo = [{-paddle:.6f}, 0.0]
hi = [0.0, {top:.6f}]
motion = "paddle"
[[motions]]
name = "paddle"
kind = "piston"
wave_height = {H}
wave_period = {T:.8f}
depth = {h}
ramp = {ramp:.6f}
second_order = {"true" if second else "false"}
[[damping_zones]]
start = [{length - L:.6f}, 0.0]
end = [{length:.6f}, 0.0]
strength = {10 / T:.4f}
[time]
end_time = {end:.6f}
{probes}"""
    return text, k, T, L, gauges, end


def harmonics(t, eta, T):
    """First- and second-harmonic amplitudes and phases of eta(t) (least squares)."""
    w = 2 * math.pi / T
    A = np.c_[np.cos(w * t), np.sin(w * t), np.cos(2 * w * t), np.sin(2 * w * t), np.ones_like(t)]
    c = np.linalg.lstsq(A, eta, rcond=None)[0]
    return complex(c[0], -c[1]), complex(c[2], -c[3])


def up_crossing_period(t, eta):
    e = eta - eta.mean()
    band = 0.1 * np.std(e)
    crossings, armed = [], False
    for i in range(1, len(e)):
        armed = armed or e[i - 1] < -band
        if armed and e[i - 1] < 0 <= e[i]:
            crossings.append(t[i - 1] + (t[i] - t[i - 1]) * (-e[i - 1]) / (e[i] - e[i - 1]))
            armed = False
    if len(crossings) < 2:
        return float("nan")
    return (crossings[-1] - crossings[0]) / (len(crossings) - 1)


def goda_suzuki(a1, a2, k, dl):
    """Incident and reflected amplitudes from two gauges dl apart (Goda & Suzuki 1976)."""
    # eta_j = a_I e^{-i k x_j} + a_R e^{+i k x_j} with x_1 = 0, x_2 = dl (complex amplitudes).
    M = np.array([[1, 1], [np.exp(-1j * k * dl), np.exp(1j * k * dl)]])
    aI, aR = np.linalg.solve(M, np.array([a1, a2]))
    return abs(aI), abs(aR)


def run(name, cfg, threads, keep):
    kh, h, H, dx, second, alpha = cfg
    text, k, T, L, gauges, end = case_text(name, kh, h, H, dx, second, alpha)
    out = HERE / "results" / name
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    case = out / f"{name}.toml"
    case.write_text(text)
    t0 = time.time()
    subprocess.run([str(EXE), "run", str(case), "--out", str(out / "run"), "--threads",
                    str(threads), "-q"], check=True)
    wall = time.time() - t0
    amps = []
    period = float("nan")
    for i, x in enumerate(gauges):
        d = np.loadtxt(out / "run" / "probes" / f"g{i}.csv", delimiter=",", skiprows=1)
        m = d[:, 0] >= end - 3 * T
        t, eta = d[m, 0], d[m, 1] - d[m, 1].mean()
        a1, a2 = harmonics(t, eta, T)
        amps.append((x, a1, a2))
        if abs(x - 2 * L) < 1e-9:
            period = up_crossing_period(t, eta)
    a_2L = next(abs(a1) for x, a1, a2 in amps if abs(x - 2 * L) < 1e-9)
    a = H / 2
    bound = k * a * a * math.cosh(kh) * (2 + math.cosh(2 * kh)) / (4 * math.sinh(kh) ** 3)
    far = [abs(a2) for x, a1, a2 in amps if x >= L - 1e-9]
    spread = (max(far) - min(far)) / bound
    g15 = next(a1 for x, a1, a2 in amps if abs(x - 1.5 * L) < 1e-9)
    g175 = next(a1 for x, a1, a2 in amps if abs(x - 1.75 * L) < 1e-9)
    aI, aR = goda_suzuki(g15, g175, k, 0.25 * L)
    if not keep:
        shutil.rmtree(out / "run")
    heights = " ".join(f"{2 * abs(a1) / H:.3f}" for x, a1, a2 in amps)
    return (f"{name:10s} kh {kh:4.2f} h {h:.2f} m T {T:.3f} s L {L:.3f} m H {H:.3f} m "
            f"dx {dx:.3f} m (H/dx {H / dx:.1f}) alpha {alpha}  H_2L/H {2 * a_2L / H:.3f} ({100 * (2 * a_2L / H - 1):+.1f} %)"
            f"  T_2L/T {period / T:.4f} ({100 * (period / T - 1):+.2f} %)  a2 spread/bound "
            f"{spread:.2f} (bound {1000 * bound:.2f} mm)  Kr {aR / aI:.3f}  H/H_target at "
            f"0.5..2.5 L: {heights}  wall {wall:.0f} s")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--only", nargs="*", default=list(CONFIGS))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--keep", action="store_true")
    args = ap.parse_args()
    if not EXE.exists():
        sys.exit(f"{EXE} is missing: cmake --preset release && cmake --build --preset release")
    lines = []
    for name in args.only:
        line = run(name, CONFIGS[name], args.threads, args.keep)
        print(line, flush=True)
        lines.append(line)
    (HERE / "results").mkdir(exist_ok=True)
    (HERE / "results" / "table.txt").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
