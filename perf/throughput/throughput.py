#!/usr/bin/python3
"""Throughput of sluice on the fixed configurations of perf/README.md, and time per step against N.

    perf/throughput/run.sh [--threads 2] [--configs 1,2,3-200k,3-1m] [--short] [--scaling]
                           [--scaling-only] [--full] [--accuracy] [--out DIR] [--nice N]

For every configuration (a case file under perf/cases/) it runs `sluice run` once with I/O
off and prints: wall time of the time loop, particle-steps per second (whole steps; counting
wall particles and fluid only), the same per core, the busy time of each stage with the
neighbour interactions it achieved per busy second, the time spent between steps (rebin,
re-decomposition), and the peak resident memory per particle. --scaling runs the 2-D peer
case at 10^4 ... 10^6 fluid particles for a fixed number of steps and fits time per step
(and peak memory) against N. --accuracy also runs the validation dam break and hydrostatic
tank with configuration 1's numerics and prints their errors beside the speed. Results: OUT/throughput.csv, OUT/scaling.csv, OUT/report.md,
and each run's folder (summary.json).
"""
from __future__ import annotations

import argparse
import csv
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lib"))
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "speed_vs_error"))
import evaluate  # noqa: E402
import sluice_run as sr  # noqa: E402

CASES = sr.ROOT / "perf" / "cases"

# name -> (case file, end time the benchmark runs by default or None for the file's own, label)
# Configuration 3 would need 20,000 (200k) and 44,000 (1M) steps for the full 0.2 s; by
# default it runs a window of the same case (--full runs the file's 0.2 s).
CONFIGS = {
    "1": (CASES / "dam_break_2d_peer.toml", None, "2-D dam break, peer configuration, dp 0.01"),
    "2": (CASES / "dam_break_3d_obstacle.toml", None, "3-D dam break with obstacle, dp 0.0085"),
    "3-200k": (CASES / "dam_break_2d_peer_200k.toml", 0.002, "2-D peer case, 200k fluid"),
    "3-1m": (CASES / "dam_break_2d_peer_1m.toml", 0.0005, "2-D peer case, 1M fluid"),
}

# Pairs a stage's neighbour loop visits per step, from the census in summary.json
# (extra.neighbours): density, accel and drift (continuity rate) loop over fluid particles
# and all their neighbours; walls over wall particles and all theirs. The density stage also
# builds the step's neighbour list for every particle of its group (it is the first stage),
# so its time includes the neighbour search.
STAGE_PAIRS = {
    "density": ("fluid_fluid", "fluid_wall"),
    "walls": ("wall_fluid", "wall_wall"),
    "accel": ("fluid_fluid", "fluid_wall"),
    "drift": ("fluid_fluid", "fluid_wall"),
}


# Accuracy at the benchmark settings: the validation cases (cases/dam_break_2d.toml, the
# Martin & Moyce n^2 = 2 column, and cases/hydrostatic_2d.toml) run with configuration 1's
# numerics (kernel, h, CFL, alpha, delta and its Fourtakas form, EOS, no laminar viscosity;
# c0 = 20 sqrt(g H) for their own water depth H), errors as in tests/validation/ (perf/speed_vs_error/evaluate.py),
# compared with the validation thresholds.
PEER_NUMERICS = {"numerics.kernel": "wendland_c2", "numerics.h_over_dx": math.sqrt(2.0),
                 "numerics.cfl": 0.2, "numerics.artificial_viscosity": 0.02,
                 "numerics.delta_sph": 0.1, "numerics.density": "continuity",
                 "numerics.density_diffusion": "fourtakas",
                 "fluid.eos": "tait", "fluid.viscosity": 0.0, "output.snapshots": False}
ACCURACY = [
    ("dam_break", "cases/dam_break_2d.toml",
     {"fluid.sound_speed": 20 * math.sqrt(9.81 * 0.8), "time.end_time": 0.45,
      "probes.1.interval": 0.005},
     "front RMS deviation from Martin & Moyce", 0.15,
     "test_dam_break_2d guard 15 % (target 10 %)"),
    ("hydrostatic", "cases/hydrostatic_2d.toml", {"fluid.sound_speed": 20 * math.sqrt(9.81 * 0.4)},
     "worst bottom-pressure error after 1 s", 0.02, "test_hydrostatic_2d threshold 2 %"),
]


def accuracy(args, sluice: Path, out: Path) -> list[dict]:
    print("\n== accuracy at the benchmark settings (configuration 1's numerics)")
    rows = []
    for name, rel, extra, what, limit, source in ACCURACY:
        case = sr.ROOT / rel
        overrides = {**PEER_NUMERICS, **extra}
        if args.short:
            overrides["time.end_time"] = 0.05
        run = sr.run_sluice(sluice, case, out / f"accuracy_{name}", args.threads, overrides,
                            nice=args.nice)
        if not run.ok:
            print(f"   {name}: FAILED (exit {run.returncode})\n{run.stderr_tail}")
            rows.append({"case": name, "error": float("nan"), "status": "failed"})
            continue
        if args.short:
            print(f"   {name}: ran (--short: too short for an error figure)")
            continue
        err = evaluate.EVALUATORS[name][0](run.out_dir, sr.read_case(case, overrides))
        verdict = "within" if err < limit else "OUTSIDE"
        print(f"   {name}: {what} = {100 * err:.2f} % ({verdict} {source}); "
              f"{run.summary['steps']} steps, wall {run.summary['wall_seconds']:.1f} s")
        rows.append({"case": name, "error": err, "limit": limit, "status": verdict,
                     "wall_s": run.summary["wall_seconds"], "steps": run.summary["steps"]})
    return rows


def mean_census(summary: dict) -> dict:
    nb = summary.get("extra", {}).get("neighbours")
    if not nb:
        return {}
    return {k: 0.5 * (nb["start"][k] + nb["end"][k]) for k in nb["start"]}


def describe(run: sr.Run, threads: int) -> dict:
    s = run.summary
    ex = s["extra"]
    steps, wall = s["steps"], s["wall_seconds"]
    n_all, n_fluid = s["particles"], s["fluid_particles"]
    census = mean_census(s)
    stages = {}
    for name, busy in ex["stage_busy_seconds"].items():
        pairs = sum(census.get(k, 0) for k in STAGE_PAIRS.get(name, ()))
        stages[name] = {
            "busy_s": busy,
            "pairs_per_step": pairs,
            "pairs_per_busy_s": pairs * steps / busy if busy > 0 and pairs else float("nan"),
        }
    halo = sum(r.get("halo_pack_seconds", 0.0) for r in ex["parallel"]["ranks"])
    return {
        "particles": n_all, "fluid": n_fluid, "walls": n_all - n_fluid, "steps": steps,
        "simulated_s": s["simulated_time"], "wall_s": wall, "process_wall_s": run.process_wall_s,
        "cpu_s": run.cpu_s, "threads": threads,
        "psteps_per_s": n_all * steps / wall, "fluid_psteps_per_s": n_fluid * steps / wall,
        "psteps_per_s_core": n_all * steps / wall / threads,
        "fluid_psteps_per_s_core": n_fluid * steps / wall / threads,
        "time_per_step_s": wall / steps,
        "stages": stages, "rebin_s": ex.get("rebin_seconds", float("nan")), "halo_pack_s": halo,
        "neighbours_per_fluid": (census.get("fluid_fluid", 0) + census.get("fluid_wall", 0))
        / max(1, n_fluid),
        "peak_rss_bytes": run.peak_rss_bytes,
        "rss_per_particle": run.peak_rss_bytes / n_all,
        "git": s.get("git_revision", "?"),
        "precision": s.get("precision", "double"),
    }


def print_config(name: str, label: str, d: dict) -> None:
    print(f"\n-- configuration {name}: {label}")
    print(f"   particles {d['fluid']:,} fluid + {d['walls']:,} wall = {d['particles']:,}; "
          f"{d['steps']} steps to t = {d['simulated_s']:.4g} s; {d['threads']} thread(s); "
          f"{d['precision']} precision")
    print(f"   wall time (time loop) {d['wall_s']:.2f} s  (process {d['process_wall_s']:.2f} s, "
          f"CPU {d['cpu_s']:.2f} s); {1e3 * d['time_per_step_s']:.2f} ms/step")
    print(f"   particle-steps/s   {d['psteps_per_s'] / 1e6:.3f} M with walls, "
          f"{d['fluid_psteps_per_s'] / 1e6:.3f} M fluid only")
    print(f"   per core           {d['psteps_per_s_core'] / 1e6:.3f} M with walls, "
          f"{d['fluid_psteps_per_s_core'] / 1e6:.3f} M fluid only")
    print(f"   neighbours per fluid particle (mean of start and end) {d['neighbours_per_fluid']:.1f}")
    busy_total = sum(v["busy_s"] for v in d["stages"].values())
    print(f"   {'stage':<22} {'busy [s]':>9} {'share':>7} {'pairs/step':>12} {'pairs per busy s':>17}")
    for name, v in d["stages"].items():
        label = name + (" (+neighbour search)" if name == "density" else "")
        rate = "" if math.isnan(v["pairs_per_busy_s"]) else f"{v['pairs_per_busy_s'] / 1e6:.1f} M"
        pairs = f"{v['pairs_per_step']:,.0f}" if v["pairs_per_step"] else ""
        print(f"   {label:<22} {v['busy_s']:>9.2f} {100 * v['busy_s'] / busy_total:>6.1f}% "
              f"{pairs:>12} {rate:>17}")
    print(f"   {'rebin (between steps)':<22} {d['rebin_s']:>9.2f}   (main thread, wall)")
    print(f"   {'halo pack':<22} {d['halo_pack_s']:>9.2f}")
    print(f"   peak RSS {d['peak_rss_bytes'] / 2**20:.1f} MiB = "
          f"{d['rss_per_particle']:.0f} B per particle (incl. the process's fixed memory)")


THROUGHPUT_COLUMNS = [
    "config", "case", "threads", "fluid", "walls", "particles", "steps", "simulated_s", "wall_s",
    "process_wall_s", "cpu_s", "psteps_per_s", "fluid_psteps_per_s", "psteps_per_s_core", "fluid_psteps_per_s_core",
    "time_per_step_s", "density_busy_s", "walls_busy_s", "accel_busy_s", "kick_busy_s",
    "drift_busy_s", "rebin_s", "density_pairs_per_busy_s", "walls_pairs_per_busy_s",
    "accel_pairs_per_busy_s", "drift_pairs_per_busy_s", "neighbours_per_fluid",
    "peak_rss_bytes", "rss_per_particle", "git", "precision"]


def throughput_row(name: str, case: Path, d: dict) -> dict:
    row = {"config": name, "case": case.name}
    for k in THROUGHPUT_COLUMNS:
        if k in d:
            row[k] = d[k]
    for st in ("density", "walls", "accel", "kick", "drift"):
        v = d["stages"].get(st)
        row[f"{st}_busy_s"] = v["busy_s"] if v else ""
        if st in STAGE_PAIRS:
            row[f"{st}_pairs_per_busy_s"] = v["pairs_per_busy_s"] if v else ""
    return row


def scaling(args, sluice: Path, out: Path) -> list[dict]:
    """Time per step of the 2-D peer case against N, a fixed number of steps each."""
    base = CONFIGS["1"][0]
    sizes = [1e4, 3e4, 1e5] if args.short else [1e4, 3e4, 1e5, 3e5, 1e6]
    steps = 5 if args.short else args.scaling_steps
    print(f"\n== scaling in N: {base.name}, {steps} steps per run, {args.threads} thread(s)")
    rows = []
    for n in sizes:
        dx = round(math.sqrt(2.0 / n), 7)  # the 1 m x 2 m column holds 2/dx^2 particles
        case = sr.read_case(base, {"particles.dx": dx})
        end = (steps + 0.5) * sr.acoustic_dt(case)
        run = sr.run_sluice(sluice, base, out / f"scaling_{int(n)}", args.threads,
                            {"particles.dx": dx, "time.end_time": end}, nice=args.nice)
        if not run.ok:
            print(f"   N = {n:.0e}: FAILED (exit {run.returncode})\n{run.stderr_tail}")
            continue
        d = describe(run, args.threads)
        rows.append({"dx": dx, "fluid": d["fluid"], "particles": d["particles"],
                     "steps": d["steps"], "wall_s": d["wall_s"],
                     "time_per_step_s": d["time_per_step_s"],
                     "ns_per_particle_step": 1e9 * d["time_per_step_s"] / d["particles"],
                     "peak_rss_bytes": d["peak_rss_bytes"],
                     "rss_per_particle": d["rss_per_particle"]})
        r = rows[-1]
        print(f"   N = {r['particles']:>9,} ({r['fluid']:,} fluid): {1e3 * r['time_per_step_s']:9.2f} "
              f"ms/step, {r['ns_per_particle_step']:7.1f} ns per particle-step, peak RSS "
              f"{r['peak_rss_bytes'] / 2**20:7.1f} MiB ({r['rss_per_particle']:.0f} B/particle)")
    if len(rows) >= 2:
        ns = [float(r["particles"]) for r in rows]
        exponent = sr.power_law_exponent(ns, [r["time_per_step_s"] for r in rows])
        a, b = sr.fit_line(ns, [r["time_per_step_s"] for r in rows])
        ma, mb = sr.fit_line(ns, [float(r["peak_rss_bytes"]) for r in rows])
        print(f"   time per step ~ N^{exponent:.3f} (log-log slope; 1 = linear); "
              f"linear fit {1e3 * a:.2f} ms + {1e9 * b:.1f} ns x N")
        print(f"   peak RSS ~ {ma / 2**20:.1f} MiB + {mb:.0f} B x N (marginal memory per particle)")
        for r in rows:
            r["loglog_exponent"] = exponent
            r["fit_ms_intercept"], r["fit_ns_per_particle"] = 1e3 * a, 1e9 * b
            r["rss_fit_mib_intercept"], r["rss_fit_bytes_per_particle"] = ma / 2**20, mb
    with open(out / "scaling.csv", "w", newline="") as f:
        if rows:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
    return rows


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--threads", type=int, default=2, help="worker threads (default 2)")
    ap.add_argument("--configs", default="1,2,3-200k,3-1m",
                    help=f"comma-separated subset of {', '.join(CONFIGS)} (default: all)")
    ap.add_argument("--short", action="store_true",
                    help="a few steps per configuration (checks the harness in minutes)")
    ap.add_argument("--full", action="store_true",
                    help="configuration 3 runs its file's full 0.2 s instead of a window")
    ap.add_argument("--accuracy", action="store_true",
                    help="also print the front and hydrostatic errors at the benchmark settings")
    ap.add_argument("--scaling", action="store_true", help="also run the scaling-in-N sweep")
    ap.add_argument("--scaling-only", action="store_true", help="only the scaling-in-N sweep")
    ap.add_argument("--scaling-steps", type=int, default=20,
                    help="steps per scaling run (default 20)")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="extra case override for every configuration (repeatable)")
    ap.add_argument("--out", type=Path, default=sr.ROOT / "results" / "throughput")
    ap.add_argument("--sluice", type=Path, default=sr.DEFAULT_SLUICE)
    ap.add_argument("--nice", type=int, default=0, help="run sluice under nice -n N")
    args = ap.parse_args()

    chosen = [] if args.scaling_only else [c.strip() for c in args.configs.split(",") if c.strip()]
    for c in chosen:
        if c not in CONFIGS:
            sr.die(f"throughput: unknown configuration '{c}' (known: {', '.join(CONFIGS)})")
    if args.threads < 1:
        sr.die("throughput: --threads must be >= 1")
    sluice = sr.ensure_binary(args.sluice)
    out = args.out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    extra = {}
    for kv in args.set:
        if "=" not in kv:
            sr.die(f"throughput: --set wants KEY=VALUE, got '{kv}'")
        k, v = kv.split("=", 1)
        extra[k] = _parse_value(v)

    print(f"== sluice throughput, git {sr.git_revision()}, {args.threads} thread(s)"
          f"{', SHORT mode (a few steps each)' if args.short else ''}")
    print(f"   machine: {sr.machine_description()}")
    rows, failed = [], []
    for name in chosen:
        case, window, label = CONFIGS[name]
        overrides = dict(extra)
        if args.short:
            overrides["time.end_time"] = 5.5 * sr.acoustic_dt(sr.read_case(case, overrides))
        elif window is not None and not args.full:
            overrides["time.end_time"] = window
        run = sr.run_sluice(sluice, case, out / f"config_{name}", args.threads, overrides,
                            nice=args.nice)
        if not run.ok:
            print(f"\n-- configuration {name}: FAILED (exit {run.returncode})\n{run.stderr_tail}")
            failed.append(name)
            continue
        d = describe(run, args.threads)
        print_config(name, label, d)
        rows.append(throughput_row(name, case, d))
    if rows:
        with open(out / "throughput.csv", "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=THROUGHPUT_COLUMNS, extrasaction="ignore")
            w.writeheader()
            w.writerows(rows)
        print(f"\n   table: {out / 'throughput.csv'}")
    if args.accuracy:
        acc = accuracy(args, sluice, out)
        if any(r["status"] == "failed" for r in acc):
            failed.append("accuracy")
    if args.scaling or args.scaling_only:
        scaling(args, sluice, out)
        print(f"   table: {out / 'scaling.csv'}")
    if failed:
        print(f"throughput: failed configurations: {', '.join(failed)}", file=sys.stderr)
        return 1
    return 0


def _parse_value(text: str) -> object:
    import tomllib
    try:
        return tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        return text


if __name__ == "__main__":
    sys.exit(main())
