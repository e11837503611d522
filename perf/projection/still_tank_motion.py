#!/usr/bin/env python3
"""What the still tank's pressure noise is made of (perf/projection/README.md, "What the noise
is"). Reads runs of cases/hydrostatic_2d.toml (WCSPH) and/or
cases/projection_hydrostatic_2d.toml with snapshots every 0.01 s, e.g.

    sluice run cases/projection_hydrostatic_2d.toml --out RUN --set time.output_interval=0.01
    perf/projection/still_tank_motion.py RUN [RUN ...]

and prints, over t >= --from (default 1 s): the bottom-centre probe's mean and noise as the code
wrote them, the same probe recomputed from the snapshots by Shepard interpolation (the code's)
and by a first-order moving-least-squares fit (exact for a hydrostatic field on any particle
arrangement: if it reads the same noise, the noise is in the particles' pressures, not in the
interpolation), the fluctuation of p + rho g y averaged over the whole bottom row and its
strongest frequencies, and the rms particle speed by height. The kernel of each run is taken
from its case name (the two shipped cases' settings)."""
import argparse, glob, json, os
import h5py
import numpy as np

RHO0, G, H_WATER, PROBE = 1000.0, 9.81, 0.4, np.array([0.2, 0.02])
DX = 0.01


def wendland_c2(q):  # 2-D shape; the normalisation cancels in every ratio below
    return np.where(q < 2, (1 - q / 2) ** 4 * (2 * q + 1), 0.0)


def quintic(q):
    c = lambda a: np.clip(a - q, 0, None) ** 5
    return np.where(q < 3, c(3) - 6 * c(2) + 15 * c(1), 0.0)


KERNELS = {"hydrostatic_2d": (wendland_c2, 1.5 * DX, 2.0),
           "projection_hydrostatic_2d": (quintic, 1.0333333333 * DX, 3.0)}


def analyse(run, t_from):
    case = json.load(open(os.path.join(run, "summary.json")))["case"]
    W, h, q_max = KERNELS[case]
    p_ref = RHO0 * G * (H_WATER - PROBE[1])
    t, shepard, linear, bottom, speed, layers = [], [], [], [], [], []
    edges = np.arange(0.0, 0.44, 0.04)
    for fn in sorted(glob.glob(os.path.join(run, "snapshots", "snap_*.h5"))):
        with h5py.File(fn) as f:
            if f.attrs["time"] < t_from:
                continue
            fluid = f["kind"][:] == 0
            x = f["position"][:, :2][fluid]
            p = f["pressure"][:][fluid]
            rho = f["density"][:][fluid]
            v = f["velocity"][:, :2][fluid]
            t.append(f.attrs["time"])
        d = x - PROBE
        r = np.hypot(d[:, 0], d[:, 1])
        s = r < q_max * h
        w = W(r[s] / h) * RHO0 * DX * DX / rho[s]
        shepard.append(np.sum(w * p[s]) / np.sum(w))
        B = np.column_stack([np.ones(s.sum()), d[s]])
        linear.append(np.linalg.solve((B * w[:, None]).T @ B, (B * w[:, None]).T @ p[s])[0])
        low = x[:, 1] < 0.03
        bottom.append(np.mean(p[low] + RHO0 * G * x[low, 1]))
        speed.append(np.sqrt(np.mean(np.sum(v * v, axis=1))))
        k = np.digitize(x[:, 1], edges) - 1
        layers.append([np.sqrt(np.mean(np.sum(v[k == b] ** 2, axis=1))) if np.any(k == b) else np.nan
                       for b in range(len(edges) - 1)])
    if len(t) < 8:
        raise SystemExit(f"{run}: fewer than 8 snapshots after t = {t_from} s")
    t, bottom = np.array(t), np.array(bottom)
    probe = np.loadtxt(os.path.join(run, "probes", "p1_bottom_centre.csv"), delimiter=",", skiprows=1)
    pc = probe[probe[:, 0] >= t_from, 1]
    fluct = bottom - bottom.mean()
    power = np.abs(np.fft.rfft(fluct)) ** 2
    freq = np.fft.rfftfreq(len(fluct), np.median(np.diff(t)))
    top = [f"{freq[i]:.2f}" for i in np.argsort(power)[::-1][:3]]
    layer = np.nanmean(np.array(layers), axis=0)
    print(f"{run} ({case}), {len(t)} snapshots from t = {t_from} s:")
    print(f"  probe as written: mean {pc.mean():.1f} Pa ({100 * (pc.mean() / p_ref - 1):+.2f} %), noise {pc.std():.1f} Pa")
    print(f"  recomputed: Shepard noise {np.std(shepard):.1f} Pa, linear MLS noise {np.std(linear):.1f} Pa "
          f"(mean {np.mean(linear):.1f} Pa)")
    print(f"  bottom row p + rho g y: noise {bottom.std():.1f} Pa, strongest frequencies {', '.join(top)} Hz")
    print(f"  rms particle speed {1e3 * np.mean(speed):.1f} mm/s; by height (m): " +
          ", ".join(f"{edges[b]:.2f}-{edges[b + 1]:.2f} {1e3 * layer[b]:.1f}" for b in range(len(layer))))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--from", dest="t_from", type=float, default=1.0)
    args = ap.parse_args()
    for run in args.runs:
        analyse(run, args.t_from)


if __name__ == "__main__":
    main()
