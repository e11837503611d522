#!/usr/bin/env python3
"""The fluid's x-momentum against the loads the walls read, for runs of perf/impact/zhou_2d.toml.

Between two snapshots the fluid's x-momentum changes by what the walls give it:

    Px(t_b) - Px(t_a) = -(I_right + I_left + I_floor,x),

I_* the impulses of the force probes F_right_wall (x+), F_left_wall (x-) and F_floor (y-),
which read the force on each wall (the fluid's is its opposite). Gravity and the fluid's
internal forces add nothing along x (they cancel in pairs under WCSPH; under the projection
scheme the WMLS gradient is not antisymmetric, so they need not). The residual says how well
a scheme's wall readings account for its flow's momentum: a reading that misses part of the
wall's action (e.g. a collision's tangential drag, which a pressure reading cannot see) or a
scheme that does not conserve momentum shows here. Printed per snapshot interval and in
total, in N s per metre of width and as a share of the reservoir wall's push |I_left|.

The impulse of a force sampled every step follows the scheme's time integration: under WCSPH
(leap-frog) the force sampled at t_k acts for (dt_{k-1} + dt_k)/2, under the projection
scheme the force sampled after step k acts for dt_k (tests/validation/
test_wall_loads_block_impact_2d.cpp). Needs snapshots (the default output of the case) and the
three force probes sampled every step.

    perf/impact/momentum_balance.py RUN_DIR [RUN_DIR ...] [--projection] [--from T] [--to T]
"""
import argparse
import glob
import sys
from pathlib import Path

import h5py
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import loads_package  # noqa: E402, F401  (scripts/ on the path)
from sluice_loads import signals  # noqa: E402  (cumulative_trapezoid)
from sluice_loads.runs import load_probe  # noqa: E402


def cumulative_impulse(t, f, projection):
    """Impulse from the start to each sample time, as the scheme applies the sampled force."""
    if not projection:
        # leap-frog: the force sampled at t_k acts half a step before and half after it
        return signals.cumulative_trapezoid(t, f)
    # the force sampled after step k acts over step k
    return np.concatenate([[0.0], np.cumsum(f[1:] * np.diff(t))])


def fluid_momentum(snapshot):
    with h5py.File(snapshot) as h:
        kind = h["kind"][()]
        fluid = kind == 0
        mass = h["mass"][()][fluid]
        vx = h["velocity"][()][fluid, 0]
        return float(h.attrs["time"]), float(np.sum(mass * vx))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--projection", action="store_true",
                    help="the runs used the projection scheme (its force integration rule)")
    ap.add_argument("--from", dest="t_from", type=float, default=0.45, help="first time [s]")
    ap.add_argument("--to", dest="t_to", type=float, default=np.inf, help="last time [s]")
    args = ap.parse_args()
    for run in args.runs:
        snaps = sorted(glob.glob(str(Path(run) / "snapshots" / "*.h5")))
        states = [fluid_momentum(s) for s in snaps]
        states = [s for s in states if args.t_from - 1e-9 <= s[0] <= args.t_to + 1e-9]
        if len(states) < 2:
            sys.exit(f"{run}: fewer than two snapshots in [{args.t_from}, {args.t_to}] s")
        impulses = {}
        for name in ("F_right_wall", "F_left_wall", "F_floor"):
            t, f = load_probe(Path(run) / "probes" / f"{name}.csv")
            impulses[name] = (t, cumulative_impulse(t, f, args.projection))

        def impulse(name, ta, tb):
            t, cum = impulses[name]
            return float(np.interp(tb, t, cum) - np.interp(ta, t, cum))

        print(f"{run}  ({'projection' if args.projection else 'WCSPH'} integration rule)")
        print(f"  {'t_a':>6} {'t_b':>6} {'dPx':>8} {'I_right':>8} {'I_left':>8} "
              f"{'I_floor':>8} {'residual':>9} {'of |I_left|':>11}")
        pairs = list(zip(states[:-1], states[1:])) + [(states[0], states[-1])]
        for k, ((ta, pa), (tb, pb)) in enumerate(pairs):
            ir, il = impulse("F_right_wall", ta, tb), impulse("F_left_wall", ta, tb)
            fl = impulse("F_floor", ta, tb)
            residual = (pb - pa) + ir + il + fl
            share = 100 * residual / abs(il) if il != 0 else float("nan")
            label = "  total" if k == len(pairs) - 1 else ""
            print(f"  {ta:6.3f} {tb:6.3f} {pb - pa:8.2f} {ir:8.2f} {il:8.2f} {fl:8.2f} "
                  f"{residual:9.2f} {share:10.1f} %{label}")


if __name__ == "__main__":
    main()
