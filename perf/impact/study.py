#!/usr/bin/python3
"""Wall-impact pressure convergence study (perf/impact/README.md): the Zhou/Buchner dam break
(perf/impact/zhou_2d.toml) over resolutions x sound speeds x variants, then analyse.py.

    perf/impact/run.sh [--resolutions H/30,H/60,H/120] [--c0 10,20,40] [--end-time 1.0]
                       [--variant NAME:key=val,key=val ...] [--no-default] [--set KEY=VAL ...]
                       [--threads 1] [--jobs 1] [--nice 0] [--sluice build/release/sluice]
                       [--out perf/impact/results] [--quick] [--reuse] [--no-snapshots]
                       [--window 0.5] [--filter-ms 1.0] [--no-analyse] [--dry-run]

Every run is `sluice run zhou_2d.toml --set particles.dx=DX --set fluid.sound_speed=K sqrt(gH)
--set time.end_time=T --set probes.N.position=[x_wall - DX/2, y_N] ...` plus the variant's
overrides, in OUT/<variant>/H<H/dx>_c<K>/, with study_run.json beside summary.json (what
analyse.py needs: variant, dx, c0, scales, probe positions). A variant is a named set of
--set overrides: `--variant riemann:numerics.foo=bar,numerics.alpha=0.01` (values are TOML:
numbers, true/false, [a, b], words; commas inside [...] do not split). The variant "default"
(no overrides) is always run unless --no-default; `--variant default:key=val` gives it
overrides instead.
"""
from __future__ import annotations

import argparse
import json
import math
import re
import sys
import time
import tomllib
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
sys.path.insert(0, str(HERE))
import analyse  # noqa: E402
import run_folders  # noqa: E402
from sluice_loads import impact  # noqa: E402  (run_folders puts scripts/ on the path)
import sluice_run as sr  # noqa: E402

CASE = HERE / "zhou_2d.toml"
DEFAULT_RES = ["H/30", "H/60", "H/120"]
DEFAULT_C0 = [10.0, 20.0, 40.0]
QUICK_RES = ["H/30", "H/60"]
QUICK_C0 = [20.0, 40.0]
RATE_GUESS = 2.0e6  # particle-steps per second per thread (one thread, Release, 2-D; a guide)


def split_top(s: str, sep: str = ",") -> list[str]:
    """Splits at `sep` outside [...] and quotes."""
    out, depth, quote, cur = [], 0, None, ""
    for ch in s:
        if quote:
            quote = None if ch == quote else quote
        elif ch in "\"'":
            quote = ch
        elif ch == "[":
            depth += 1
        elif ch == "]":
            depth -= 1
        elif ch == sep and depth == 0:
            out.append(cur)
            cur = ""
            continue
        cur += ch
    if cur.strip():
        out.append(cur)
    return [x.strip() for x in out if x.strip()]


def toml_parse(v: str) -> object:
    """A --set value as TOML (number, bool, array, quoted string), else the bare word."""
    try:
        return tomllib.loads(f"v = {v}")["v"]
    except tomllib.TOMLDecodeError:
        return v


def parse_set(item: str) -> tuple[str, object]:
    k, eq, v = item.partition("=")
    if not eq or not k.strip():
        raise ValueError(f"'{item}': expected KEY=VALUE")
    key = re.sub(r"\[(\d+)\]", r".\1", k.strip())  # blocks[0].lo -> blocks.0.lo
    return key, toml_parse(v.strip())


def parse_variant(spec: str) -> tuple[str, dict]:
    name, _, rest = spec.partition(":")
    name = name.strip()
    if not name or not all(c.isalnum() or c in "_-." for c in name):
        raise ValueError(f"variant name '{name}': letters, digits, '_', '-', '.' only")
    return name, dict(parse_set(x) for x in split_top(rest))


def parse_resolution(s: str, H: float) -> float:
    s = s.strip()
    if s.upper().startswith("H/"):
        return H / float(s[2:])
    return float(s)


def plan_runs(a, case: dict) -> list[dict]:
    sc = run_folders.case_scales(case)
    sqrt_gH = math.sqrt(sc.g * sc.H)
    x_wall = float(case.get("walls", {}).get("tank_hi", case["domain"]["hi"])[0])
    keeps_force = sr.projection_keeps_force_probes(a.sluice)
    def pressure_probes(projection: bool) -> list[tuple[int, dict]]:
        # indices as the run's case has them (sr.projection_case: an older binary's projection
        # run has no force probes)
        kept = [p for p in case["probes"]
                if not (projection and not keeps_force and sr.is_force_probe(p))]
        return [(i, p) for i, p in enumerate(kept) if p["type"] == "pressure"]

    num = case["numerics"]
    b = case["blocks"][0]
    area = (b["hi"][0] - b["lo"][0]) * (b["hi"][1] - b["lo"][1])
    perimeter = case["domain"]["hi"][0] + 2 * case["domain"]["hi"][1]
    runs = []
    for vname, vset in a.variants:
        pressure = pressure_probes({**a.common, **vset}.get("numerics.scheme") == "projection")
        for dx in a.dx:
            for k, jitter in [(k, j) for k in a.c0 for j in a.jitters]:
                c0 = k * sqrt_gH
                ov: dict[str, object] = {"particles.dx": dx, "fluid.sound_speed": c0,
                                         "time.end_time": a.end_time}
                probes = {}
                for i, p in pressure:
                    if "diameter" in p:  # an area sensor lies on the wall's surface at any dx
                        probes[p["name"]] = {"index": i, "position": list(p["position"])}
                        continue
                    pos = [round(x_wall - 0.5 * dx, 10), float(p["position"][1])]
                    ov[f"probes.{i}.position"] = pos
                    probes[p["name"]] = {"index": i, "position": pos}
                if a.no_snapshots:
                    ov["output.snapshots"] = False
                if jitter is not None:
                    ov["particles.jitter"] = jitter
                ov.update(a.common)
                ov.update(vset)
                # record what the run really gets, should an override change dx, c0 or a probe
                dx_run = float(ov["particles.dx"])
                c0 = float(ov["fluid.sound_speed"])
                for name, rec in probes.items():
                    rec["position"] = list(ov.get(f"probes.{rec['index']}.position", rec["position"]))
                label = f"H{sc.H / dx:g}_c{k:g}" + ("" if jitter is None else f"_j{jitter:g}")
                n_part = area / dx**2 + 3 * perimeter / dx
                dt = float(num.get("cfl", 0.25)) * float(num.get("h_over_dx", 1.5)) * dx / c0
                runs.append({"variant": vname, "label": label, "dx": dx_run, "c0": c0,
                             "c0_factor": round(c0 / sqrt_gH, 6), "end_time": a.end_time, "overrides": ov,
                             "probes": probes, "scales": vars(sc),
                             "out_dir": a.out / vname / label,
                             "est_s": n_part * a.end_time / dt / (RATE_GUESS * a.threads)})
    return runs


def _canon(ov: dict) -> dict:
    return {k: sr.toml_value(v) for k, v in ov.items()}


def reusable(run: dict) -> bool:
    """A finished run with the same overrides (its end time may be longer)."""
    f = run["out_dir"] / "study_run.json"
    s = run["out_dir"] / "summary.json"
    if not (f.exists() and s.exists()):
        return False
    with open(f) as fh:
        old = json.load(fh)
    with open(s) as fh:
        summ = json.load(fh)
    want = _canon(run["overrides"])
    have = dict(old.get("overrides", {}))
    if old.get("returncode") != 0:
        return False
    if float(summ.get("simulated_time", 0)) < run["end_time"] * (1 - 1e-9):
        return False
    want.pop("time.end_time")
    have.pop("time.end_time", None)
    return want == have


def do_run(run: dict, a) -> dict:
    t0 = time.time()
    case_file = a.case
    if run["overrides"].get("numerics.scheme") == "projection":
        # the projection scheme refuses the WCSPH-only keys (delta_sph, artificial viscosity...)
        # (beside the run folder: run_sluice empties the run folder first)
        run["out_dir"].parent.mkdir(parents=True, exist_ok=True)
        case_file = sr.projection_case(a.sluice, a.case, run["out_dir"].parent)
    r = sr.run_sluice(a.sluice, case_file, run["out_dir"], a.threads, run["overrides"],
                      nice=a.nice, echo=True)
    rec = {k: run[k] for k in ("variant", "label", "dx", "c0", "c0_factor", "end_time",
                               "probes", "scales")}
    rec.update({"overrides": _canon(run["overrides"]), "case": str(case_file),
                "sluice": str(a.sluice), "threads": a.threads, "returncode": r.returncode,
                "process_wall_s": r.process_wall_s, "cpu_s": r.cpu_s,
                "peak_rss_bytes": r.peak_rss_bytes, "stderr_tail": r.stderr_tail,
                "started": time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(t0))})
    run["out_dir"].mkdir(parents=True, exist_ok=True)
    with open(run["out_dir"] / "study_run.json", "w") as f:
        json.dump(rec, f, indent=1)
    status = "ok" if r.ok else f"FAILED (exit {r.returncode}): {r.stderr_tail}"
    print(f"   {run['variant']}/{run['label']}: {status}, {r.summary.get('steps', 0)} steps, "
          f"{r.summary.get('wall_seconds', float('nan')):.1f} s wall", flush=True)
    return rec


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 2)[2])
    ap.add_argument("--resolutions", help="dx values or H/N, comma-separated "
                    "(default H/30,H/60,H/120; --quick: H/30,H/60)")
    ap.add_argument("--c0", help="c0 / sqrt(gH), comma-separated (default 10,20,40; --quick: 20,40)")
    ap.add_argument("--end-time", type=float, default=1.0,
                    help="simulated time [s] (default 1.0: the first impact; 2.0 for the second)")
    ap.add_argument("--variant", action="append", default=[], metavar="NAME:key=val,...")
    ap.add_argument("--no-default", action="store_true", help="do not run the variant 'default'")
    ap.add_argument("--set", dest="sets", action="append", default=[], metavar="KEY=VAL",
                    help="override applied to every run (before the variant's)")
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=1, help="runs at the same time (default 1)")
    ap.add_argument("--nice", type=int, default=0, help="nice level of the sluice processes")
    ap.add_argument("--sluice", type=Path, default=sr.DEFAULT_SLUICE)
    ap.add_argument("--case", type=Path, default=CASE)
    ap.add_argument("--out", type=Path, default=HERE / "results")
    ap.add_argument("--quick", action="store_true",
                    help="H/30 and H/60 x c0 = 20, 40 (one step of each convergence direction)")
    ap.add_argument("--reuse", action="store_true",
                    help="skip runs whose results exist with the same overrides")
    ap.add_argument("--no-snapshots", action="store_true", help="probes only")
    ap.add_argument("--jitters", help="an ensemble per point: particles.jitter values, "
                    "comma-separated (e.g. 0,0.002,0.005,0.01); convergence is then judged on "
                    "the medians (a first-impact peak varies up to 2x between such runs)")
    ap.add_argument("--window", type=float, default=impact.DEFAULT_WINDOW_STAR)
    ap.add_argument("--filter-ms", type=float, default=1e3 * impact.DEFAULT_FILTER_S)
    ap.add_argument("--no-analyse", action="store_true")
    ap.add_argument("--dry-run", action="store_true", help="print the plan and stop")
    a = ap.parse_args(argv)

    a.case = a.case.resolve()
    case = sr.read_case(a.case)
    H = run_folders.case_scales(case).H
    res = a.resolutions.split(",") if a.resolutions else (QUICK_RES if a.quick else DEFAULT_RES)
    a.dx = [parse_resolution(s, H) for s in res]
    a.c0 = [float(x) for x in a.c0.split(",")] if a.c0 else (QUICK_C0 if a.quick else DEFAULT_C0)
    a.jitters = [float(x) for x in a.jitters.split(",")] if a.jitters else [None]
    try:
        variants = [parse_variant(v) for v in a.variant]
        a.common = dict(parse_set(s) for s in a.sets)
    except ValueError as e:
        sr.die(f"study.py: {e}")
    names = [n for n, _ in variants]
    if len(set(names)) != len(names):
        sr.die("study.py: a variant name is given twice")
    if not a.no_default and "default" not in names:
        variants.insert(0, ("default", {}))
    if not variants:
        sr.die("study.py: no variant to run")
    a.variants = variants
    a.out = a.out.resolve()

    runs = plan_runs(a, case)
    print(f"== impact study: {len(runs)} runs ({len(variants)} variant(s) x {len(a.dx)} dx x "
          f"{len(a.c0)} c0), end time {a.end_time} s, {a.threads} thread(s), {a.jobs} job(s)")
    print(f"   case {a.case}\n   out  {a.out}")
    for v, ov in variants:
        print(f"   variant {v}: " + (", ".join(f"{k}={sr.toml_value(x)}" for k, x in ov.items())
                                     or "(no overrides)"))
    todo = []
    for r in runs:
        skip = a.reuse and reusable(r)
        print(f"   {r['variant']:>10s}/{r['label']:12s} dx={r['dx']:g} c0={r['c0']:.2f} m/s"
              f"  ~{r['est_s']:.0f} s" + ("  (reused)" if skip else ""))
        if not skip:
            todo.append(r)
    est = sum(r["est_s"] for r in todo)
    print(f"   {len(todo)} to run, roughly {est / 60:.1f} min of {a.threads}-thread runs "
          f"(guess at {RATE_GUESS:.0e} particle-steps/s per thread)"
          + (f", ~{est / 60 / max(1, a.jobs):.1f} min with {a.jobs} jobs" if a.jobs > 1 else ""))
    if a.dry_run:
        return 0
    if todo:
        sr.ensure_binary(a.sluice)
    a.out.mkdir(parents=True, exist_ok=True)
    with open(a.out / "study.json", "w") as f:
        json.dump({"command": " ".join(sys.argv), "case": str(a.case), "sluice": str(a.sluice),
                   "git_revision": sr.git_revision(), "machine": sr.machine_description(),
                   "end_time": a.end_time, "dx": a.dx, "c0_factors": a.c0, "threads": a.threads,
                   "variants": {n: _canon(ov) for n, ov in variants},
                   "date": time.strftime("%Y-%m-%d %H:%M:%S")}, f, indent=1)
    failed = 0
    if todo:
        # cheapest first with one job (results early); dearest first with several (makespan)
        todo.sort(key=lambda r: r["est_s"], reverse=a.jobs > 1)
        with ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
            for rec in pool.map(lambda r: do_run(r, a), todo):
                failed += rec["returncode"] != 0
    if failed:
        print(f"== {failed} run(s) failed; see their study_run.json (stderr_tail) and logs/")
    if not a.no_analyse:
        ok = [run_folders.run_from_study(r["out_dir"]) for r in runs
              if (r["out_dir"] / "summary.json").exists()]
        analyse.analyse(ok, a.out, a.window, 1e-3 * a.filter_ms)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
