#!/usr/bin/python3
"""Stability suite on hard cases (perf/stability/README.md): runs the cases of cases/hard/
with the sluice executable, measures each case's stability figures from its snapshots and probes, and prints
a PASS/FAIL line per rule. Exit status 0 when every rule passes, 1 otherwise, 2 on a usage
error. Called by perf/stability/run.sh; the rules are documented in perf/stability/README.md.

Each case is a list of runs (the case file plus --set overrides) and an evaluation of their
outputs. --coarse picks small, short versions (the ctest entries); the default resolutions
are the ones quoted in the README.
"""
import argparse
import glob
import json
import math
import os
import sys
import time
from pathlib import Path

import h5py
import numpy as np
from scipy.spatial import cKDTree

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "perf", "lib"))
import sluice_run as sr  # noqa: E402

G = 9.81


# ------------------------------------------------------------------------------------------
# Reading a run


class Run:
    """One finished sluice run: its folder, summary and snapshots (fluid particles only)."""

    def __init__(self, label, out, dx, summary, cpu_seconds):
        self.label, self.out, self.dx, self.summary = label, out, dx, summary
        self.cpu_seconds = cpu_seconds

    def snapshots(self):
        for path in sorted(glob.glob(os.path.join(self.out, "snapshots", "snap_*.h5"))):
            with h5py.File(path, "r") as f:
                fluid = f["kind"][:] == 0
                snap = {"t": float(f.attrs["time"])}
                for key in ("position", "velocity", "density", "pressure", "mass"):
                    if key in f:
                        snap[key] = f[key][:][fluid]
                dim = int(f.attrs["dimension"])
                snap["position"] = snap["position"][:, :dim]
                if "velocity" in snap:
                    snap["velocity"] = snap["velocity"][:, :dim]
                yield snap

    def probe(self, name):
        data = np.genfromtxt(os.path.join(self.out, "probes", name + ".csv"), delimiter=",",
                             names=True)
        return data[data.dtype.names[0]], data[data.dtype.names[1]]

    def cost(self):
        s = self.summary
        # CPU seconds (user + system) of the sluice process: on a shared, loaded machine a
        # steadier cost measure than wall time.
        return (f"{s['steps']} steps, {s['particles']} particles, wall {s['wall_seconds']:.1f} s, "
                f"{s['particle_steps_per_second'] / 1e6:.2f} M particle-steps/s, "
                f"CPU {self.cpu_seconds:.1f} s")


def run_case(args, case_file, label, dx, overrides):
    """Runs sluice on one case; returns a Run, or None (with the reason printed) if it failed."""
    out = os.path.join(args.out, label)
    sets = [f"particles.dx={dx}"] + overrides + args.set
    cmd = [args.sluice, "run", os.path.join(ROOT, case_file), "--threads", str(args.threads),
           "--out", out, "-q"]  # as sluice_run.run_sluice starts it
    for o in sets:
        cmd += ["--set", o]
    print("$ " + " ".join(cmd[:1] + [os.path.relpath(c, ROOT) if c.startswith(ROOT) else c
                                     for c in cmd[1:]]), flush=True)
    if args.reuse and os.path.exists(os.path.join(out, "summary.json")):
        with open(os.path.join(out, "summary.json")) as f:
            run = Run(label, out, dx, json.load(f), float("nan"))
        print(f"  reusing the finished run in {out}: {run.cost()}")
        return run
    t0 = time.monotonic()
    proc = sr.run_sluice(Path(args.sluice), Path(ROOT) / case_file, Path(out), args.threads,
                         echo=False, sets=sets)
    cpu = proc.cpu_s
    if proc.returncode != 0:
        print(f"  run failed after {time.monotonic() - t0:.1f} s (exit {proc.returncode}): "
              f"{proc.stderr_tail.strip()[-400:]}")
        return None
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    run = Run(label, out, dx, summary, cpu)
    print(f"  {run.cost()}", flush=True)
    return run


class Report:
    """Collects the rules of one case and prints them."""

    def __init__(self, case):
        self.case, self.ok = case, True

    def info(self, text):
        print(f"  {text}")

    def rule(self, name, passed, text):
        self.ok = self.ok and bool(passed)
        print(f"  [{'PASS' if passed else 'FAIL'}] {name}: {text}")

    def target(self, name, met, text):
        """A target that the model is known to miss in some setting: printed as MET or
        MISSED, not counted in the exit status (a guard rule beside it catches regressions)."""
        print(f"  [{'MET' if met else 'MISSED'}] target {name}: {text}")


# ------------------------------------------------------------------------------------------
# Measures


def min_pair_distance(x):
    """Smallest distance between two fluid particles, and the 1st percentile of the
    nearest-neighbour distances."""
    d, _ = cKDTree(x).query(x, k=2)
    return d[:, 1].min(), np.percentile(d[:, 1], 1)


def angular_momentum(s):
    m, x, v = s["mass"], s["position"], s["velocity"]
    c = (m[:, None] * x).sum(0) / m.sum()
    r = x - c
    return float((m * (r[:, 0] * v[:, 1] - r[:, 1] * v[:, 0])).sum())


def finite(s):
    return all(np.isfinite(s[k]).all() for k in ("position", "velocity", "density") if k in s)


def ellipse_ode(t_end, a0, rate, steps=4000):
    """Semi-axes a(t), b(t) of Monaghan's (1994) elliptical drop (velocity (-A0 x, A0 y)):
    a' = A a, b' = -A b, A' = A^2 (b^2 - a^2)/(a^2 + b^2), A(0) = -A0, a(0) = b(0) = R.
    Classical fourth-order Runge-Kutta."""
    def f(y):
        a, b, A = y
        return np.array([A * a, -A * b, A * A * (b * b - a * a) / (a * a + b * b)])
    y = np.array([a0, a0, -rate])
    if t_end <= 0:
        return y
    h = t_end / steps
    for _ in range(steps):
        k1 = f(y)
        k2 = f(y + h / 2 * k1)
        k3 = f(y + h / 2 * k2)
        k4 = f(y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
    return y


# ------------------------------------------------------------------------------------------
# Cases


def rotating_square_patch(args, rep):
    """Rigid rotation of a square with its suction pressure field (tensile instability)."""
    dx = 0.04 if args.coarse else 0.02
    run = run_case(args, "cases/hard/rotating_square_patch.toml", "rotating_square_patch", dx, [])
    if run is None:
        rep.rule("completes", False, "the run stopped")
        return
    worst, worst_p1, worst_t, L0, L, ok_finite, t_end = 1e9, 1e9, 0, None, None, True, 0
    for s in run.snapshots():
        dmin, p1 = min_pair_distance(s["position"])
        if dmin < worst:
            worst, worst_t = dmin, s["t"]
        worst_p1 = min(worst_p1, p1)
        L = angular_momentum(s)
        L0 = L if L0 is None else L0
        ok_finite = ok_finite and finite(s)
        t_end = s["t"]
    omega = 1.0
    rep.rule("completes", ok_finite and t_end * omega >= 5 - 1e-9,
             f"reached t omega = {t_end * omega:.2f} (>= 5) with finite fields")
    rep.rule("no clumping", worst > 0.5 * dx,
             f"minimum fluid pair distance over all snapshots {worst / dx:.3f} dx at "
             f"t = {worst_t:.2f} s (rule > 0.5 dx); 1st percentile of nearest-neighbour "
             f"distances {worst_p1 / dx:.3f} dx")
    rep.info(f"angular momentum drift (L(t_end) - L0)/L0 = {(L - L0) / L0:+.3e} "
             f"(reported; L0 = {L0:.2f} kg m^2/s per m)")


def elliptical_drop(args, rep):
    """Monaghan's elliptical drop against the semi-axis ODE."""
    dx = 0.05 if args.coarse else 0.025
    run = run_case(args, "cases/hard/elliptical_drop.toml", "elliptical_drop", dx, [])
    if run is None:
        rep.rule("completes", False, "the run stopped")
        return
    R, rate = 1.0, 100.0
    worst_a = worst_b = 0
    rows = []
    moments0 = None
    for s in run.snapshots():  # the run finished, so there is at least the t = 0 snapshot
        x, m = s["position"], s["mass"]
        c = (m[:, None] * x).sum(0) / m.sum()
        # A uniformly filled ellipse has <xi^2> = a^2/4: semi-axes from second moments,
        # scaled by the lattice disc's own value at t = 0 (its moment is not exactly R^2/4).
        mom = np.sqrt((m[:, None] * (x - c) ** 2).sum(0) / m.sum())
        moments0 = mom if moments0 is None else moments0
        a, b = R * mom / moments0
        ea, eb, _ = ellipse_ode(s["t"], R, rate)
        worst_a = max(worst_a, abs(a - ea) / ea)
        worst_b = max(worst_b, abs(b - eb) / eb)
        rows.append((s["t"], a, ea, b, eb))
    shown = rows[:: max(1, len(rows) // 4)]
    for t, a, ea, b, eb in shown + ([rows[-1]] if rows[-1] is not shown[-1] else []):
        rep.info(f"t = {t * 1e3:.2f} ms: a = {a:.4f} (ODE {ea:.4f}), b = {b:.4f} (ODE {eb:.4f})")
    rep.rule("completes", rows[-1][0] >= 0.008 - 1e-9, f"reached t = {rows[-1][0]:.4f} s")
    rep.rule("semi-major axis", worst_b < 0.02,
             f"max |b - b_ODE|/b_ODE over time = {100 * worst_b:.2f} % (rule < 2 %)")
    rep.rule("semi-minor axis", worst_a < 0.02,
             f"max |a - a_ODE|/a_ODE over time = {100 * worst_a:.2f} % (rule < 2 %)")


def dam_break_mach(args, rep):
    """Mach sweep: c0 = 10, 20, 40 sqrt(g H)."""
    dx = 0.02 if args.coarse else 0.01
    end = 0.3 if args.coarse else 0.4  # the front reaches the far wall at ~0.43 s
    H, a = 0.8, 0.4
    fronts, fluct = {}, {}
    for k in (10, 20, 40):
        c0 = k * math.sqrt(G * H)
        run = run_case(args, "cases/hard/dam_break_mach.toml", f"dam_break_mach_c{k}", dx,
                       [f"fluid.sound_speed={c0:.4f}", f"time.end_time={end}"])
        if run is None:
            rep.rule(f"c0 = {k} sqrt(gH) completes", False, "the run stopped")
            return
        rms = mx = 0
        for s in run.snapshots():
            dev = (s["density"] - 1000.0) / 1000.0
            rms = max(rms, float(np.sqrt(np.mean(dev ** 2))))
            mx = max(mx, float(np.abs(dev).max()))
        fluct[k] = (rms, mx)
        fronts[k] = run.probe("front")
        rep.rule(f"density, c0 = {k} sqrt(gH) = {c0:.1f} m/s", rms < 0.01,
                 f"max over time of the rms of (rho - rho0)/rho0 = {100 * rms:.3f} % (rule < 1 %); "
                 f"largest single |rho - rho0|/rho0 = {100 * mx:.2f} % (reported)")
    t_ref, x_ref = fronts[40]
    T = t_ref * math.sqrt(2 * G / a)
    window = (T >= 0.5) & np.isfinite(x_ref)
    for k in (10, 20):
        t, x = fronts[k]
        rel = (np.interp(t_ref[window], t, x) - x_ref[window]) / x_ref[window]
        # RMS over the window, as the dam-break validation test measures the front: the tip of
        # an inviscid surge jitters by about dx as tip particles join and leave the bulk, which
        # dominates the maximum (printed as well).
        rms = float(np.sqrt(np.mean(rel ** 2)))
        text = (f"RMS of (x_front - x_front(40))/x_front(40) over T >= 0.5 = {100 * rms:.2f} % "
                f"(target: < 2 %); largest {100 * np.abs(rel).max():.2f} %; front at "
                f"t = {t_ref[window][-1]:.3f} s: {np.interp(t_ref[window][-1], t, x):.4f} m vs "
                f"{x_ref[window][-1]:.4f} m")
        if k == 20:
            rep.rule(f"front, c0 = {k} vs 40 sqrt(gH)", rms < 0.02, text)
        else:
            # The front runs at ~2 sqrt(gH), Mach 0.2 at c0 = 10 sqrt(gH): compressibility
            # moves it by a few per cent (README). Target printed, regression guard at 5 %.
            rep.target(f"front, c0 = {k} vs 40 sqrt(gH)", rms < 0.02, text)
            rep.rule(f"front, c0 = {k} vs 40 sqrt(gH) guard", rms < 0.05,
                     f"RMS {100 * rms:.2f} % < 5 %")


def still_water_long(args, rep):
    """Hydrostatic tank held for a long time."""
    dx = 0.02
    end = 5.0 if args.coarse else 20.0
    run = run_case(args, "cases/hard/still_water_long.toml", "still_water_long", dx,
                   [f"time.end_time={end}"])
    if run is None:
        rep.rule("completes", False, "the run stopped")
        return
    H = 0.4
    ts, ek = [], []
    for s in run.snapshots():
        m, v = s["mass"], s["velocity"]
        ts.append(s["t"])
        ek.append(0.5 * float((m * (v ** 2).sum(1)).sum()) / (float(m.sum()) * G * H))
    ts, ek = np.array(ts), np.array(ek)
    for q in range(4):
        sel = (ts > q * end / 4) & (ts <= (q + 1) * end / 4 + 1e-9)
        rep.info(f"kinetic energy / (M g H), t in ({q * end / 4:.2f}, {(q + 1) * end / 4:.2f}] s: "
                 f"mean {ek[sel].mean():.3e}, max {ek[sel].max():.3e}")
    second = ek[(ts > end / 4) & (ts <= end / 2)].mean()
    last = ek[ts > 3 * end / 4].mean()
    rep.rule("kinetic energy floor", ek.max() < 1e-4,
             f"max E_k/(M g H) = {ek.max():.3e} (rule < 1e-4); floor (mean of the last quarter) "
             f"{last:.3e}")
    rep.rule("kinetic energy decays", last < second,
             f"mean of the last quarter {last:.3e} < mean of the second quarter {second:.3e}")
    t, level = run.probe("level_centre")
    start = level[(t > 0) & (t <= 1.0)].mean()
    final = level[t > end - 1.0].mean()
    late = (t > end / 2) & np.isfinite(level)
    rate = np.polyfit(t[late], level[late], 1)[0]
    rep.info(f"water level trend over the second half (least squares): {1e3 * rate:+.4f} mm/s "
             f"= {rate / dx:+.5f} dx/s (reported)")
    rep.rule("no surface drift", abs(final - start) < 0.1 * dx,
             f"water level at x = 0.2 m, mean of the last second {final:.5f} m vs first second "
             f"{start:.5f} m: drift {1e3 * (final - start):+.3f} mm = {(final - start) / dx:+.3f} "
             f"dx (rule |drift| < 0.1 dx)")


def high_speed_impact(args, rep):
    """Block hitting a wall at 10 m/s: peak wall pressure at several resolutions."""
    dxs = [0.005, 0.0025] if args.coarse else [0.01, 0.005, 0.0025]
    rho0, c0, U = 1000.0, 100.0, 10.0
    peaks = []
    for dx in dxs:
        run = run_case(args, "cases/hard/high_speed_impact.toml", f"high_speed_impact_dx{dx}", dx,
                       ["output.snapshots=false"])
        if run is None:
            rep.rule(f"dx = {dx} completes", False, "the run stopped")
            return
        t, p = run.probe("p_wall")
        i = int(np.nanargmax(p))
        peaks.append(float(p[i]))
        rep.rule(f"dx = {dx} m: finite peak", math.isfinite(p[i]) and p[i] < 100 * rho0 * c0 * U,
                 f"peak wall pressure {p[i] / 1e6:.3f} MPa at t = {1e3 * t[i]:.2f} ms = "
                 f"{p[i] / (rho0 * c0 * U):.2f} rho0 c0 U")
    changes = [abs(peaks[k + 1] - peaks[k]) / peaks[k + 1] for k in range(len(peaks) - 1)]
    text = ", ".join(f"{100 * c:.1f} %" for c in changes)
    converging = changes[-1] < 0.15 and all(changes[k + 1] < changes[k]
                                            for k in range(len(changes) - 1))
    rep.rule("peak converges", converging,
             f"relative change of the peak between successive resolutions: {text} "
             f"(rule: shrinking, last < 15 %)")


def debris_box_3d(args, rep):
    """Tak's (2024) 3-D falling block at its own settings (c = 350 m/s)."""
    # c = 350 m/s makes dt ~7 us: ~60 CPU-s per 0.01 s simulated on the shared 2-core machine.
    end = 0.01 if args.coarse else 0.12
    run = run_case(args, "cases/debris_box_3d.toml", "debris_box_3d", 0.0131578947368421,
                   [f"time.end_time={end}", "time.output_interval=0.01",
                    'output.fields=["position","velocity","density","pressure","mass","id",'
                    '"kind"]'])
    if run is None:
        rep.rule("completes", False, "the run stopped")
        return
    rep.rule("completes, mass exact", run.summary["mass_relative_change"] == 0.0,
             f"t = {run.summary['simulated_time']:.4f} s, mass change "
             f"{run.summary['mass_relative_change']}")
    worst, inside, z0, fall_err = 0.0, True, None, 0.0
    for s in run.snapshots():
        x = s["position"]
        inside = inside and bool(((x >= 0) & (x <= 1)).all()) and finite(s)
        worst = max(worst, float(np.abs(s["density"] - 1000.0).max() / 1000.0))
        z = float((s["mass"] * x[:, 2]).sum() / s["mass"].sum())
        z0 = z if z0 is None else z0
        if 0.02 <= s["t"] <= 0.09:  # free fall before the block reaches the floor (~0.1 s)
            free = 0.5 * G * s["t"] ** 2
            fall_err = max(fall_err, abs((z0 - z) - free) / free)
    rep.rule("inside the tank, finite", inside, "every fluid particle in [0, 1]^3")
    rep.rule("density", worst < 0.01,
             f"largest |rho - rho0|/rho0 = {100 * worst:.3f} % (rule < 1 %)")
    if end > 0.09:
        rep.rule("free fall", fall_err < 0.01,
                 f"centre of mass against g t^2/2 for 0.02 <= t <= 0.09 s: max error "
                 f"{100 * fall_err:.2f} % (rule < 1 %)")


CASES = {
    "rotating": rotating_square_patch,
    "mach": dam_break_mach,
    "still_water": still_water_long,
    "elliptical_drop": elliptical_drop,
    "impact": high_speed_impact,
    "debris_box": debris_box_3d,
}


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="*", help=f"cases to run (default: all): {', '.join(CASES)}")
    ap.add_argument("--coarse", action="store_true", help="small, short versions (ctest)")
    ap.add_argument("--sluice", default=os.path.join(ROOT, "build", "release", "sluice"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "stability"))
    ap.add_argument("--reuse", action="store_true",
                    help="evaluate finished runs found in --out instead of running them again "
                         "(their settings are not checked)")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="extra override for every run (e.g. numerics.shifting=0)")
    args = ap.parse_args()
    unknown = [c for c in args.cases if c not in CASES]
    if unknown:
        ap.error(f"unknown case(s) {', '.join(unknown)}; choose from {', '.join(CASES)}")
    if not os.access(args.sluice, os.X_OK):
        ap.error(f"no sluice executable at {args.sluice} (build it or pass --sluice)")
    failed = []
    for name in args.cases or list(CASES):
        print(f"== {name}{' (coarse)' if args.coarse else ''}", flush=True)
        rep = Report(name)
        CASES[name](args, rep)
        print(f"== {name}: {'PASS' if rep.ok else 'FAIL'}", flush=True)
        if not rep.ok:
            failed.append(name)
    print(f"stability suite: {'all passed' if not failed else 'FAILED: ' + ', '.join(failed)}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
