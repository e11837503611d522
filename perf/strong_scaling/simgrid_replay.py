#!/usr/bin/python3
"""Replays sluice traces in SimGrid (smpirun -replay) and compares the predicted step time with
the measured one.

1. Calibration: the 1 x 1 trace (--calibrate) is replayed on one host with 1e9 flops per CPU
   second of a task; the flops per CPU second that make its predicted step time equal the
   measured one (the run's time per step that no task's CPU time accounts for: the main
   thread's poll, scheduling) are used for every other trace.
2. Each trace (an R x 1 run) is converted by to_simgrid_ti.py and replayed on each platform
   (--platform, repeatable; the first R hosts of the file, in the order its cluster names them),
   and its predicted step time (simulated time / steps), uncalibrated (the tasks' CPU time as
   measured: a dedicated core per rank) and calibrated, is printed beside the measured one
   (the trace's time from the first counted step's first event to the last one's end, over
   all ranks, / steps).

Usage: perf/strong_scaling/simgrid_replay.py --calibrate T1x1.json TRACE.json [...]
           --platform perf/strong_scaling/platforms/node28.xml [--platform ...] [--skip STEPS]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import to_simgrid_ti as ti  # noqa: E402


def hosts_of(platform):
    """Host names of the platform's first cluster (prefix + radical + suffix) or its hosts."""
    root = ET.parse(platform).getroot()
    c = root.find(".//cluster")
    if c is None:
        return [h.get("id") for h in root.iter("host")]
    names = []
    for part in c.get("radical").split(","):
        lo, _, hi = part.partition("-")
        for i in range(int(lo), int(hi or lo) + 1):
            names.append(f"{c.get('prefix', '')}{i}{c.get('suffix', '')}")
    return names


def measured_step(events, skip):
    steps = sorted({e["args"]["step"] for e in events if "step" in e.get("args", {})})[skip:]
    keep = set(steps)
    ev = [e for e in events if e.get("args", {}).get("step") in keep]
    span = (max(e["ts"] + e["dur"] for e in ev) - min(e["ts"] for e in ev)) * 1e-6
    return span / len(steps), len(steps)


def replay(events, platform, flops, skip):
    """Predicted seconds per step of the trace on the platform."""
    per_rank, steps = ti.convert(events, flops, skip)
    hosts = hosts_of(platform)
    if len(per_rank) > len(hosts):
        sys.exit(f"simgrid_replay.py: {platform} has {len(hosts)} hosts, the trace "
                 f"{len(per_rank)} ranks")
    with tempfile.TemporaryDirectory() as d:
        files = []
        for rank, lines in per_rank.items():
            files.append(os.path.join(d, f"rank_{rank}.txt"))
            with open(files[-1], "w") as f:
                f.write("\n".join(lines) + "\n")
        with open(os.path.join(d, "index.txt"), "w") as f:
            f.write("\n".join(files) + "\n")
        with open(os.path.join(d, "hosts"), "w") as f:
            f.write("\n".join(hosts[: len(per_rank)]) + "\n")
        run = subprocess.run(
            ["smpirun", "-np", str(len(per_rank)), "-platform", os.path.abspath(platform),
             "-hostfile", os.path.join(d, "hosts"), "-replay", os.path.join(d, "index.txt"),
             "--log=root.thresh:warning", "--log=smpi_replay.thresh:info"],
            cwd=d, capture_output=True, text=True, timeout=600)
    found = re.findall(r"Simulation time ([0-9.eE+-]+)", run.stdout + run.stderr)
    if run.returncode != 0 or not found:
        sys.exit(f"simgrid_replay.py: smpirun failed on {platform}:\n{run.stderr[-2000:]}")
    return max(float(x) for x in found) / steps


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("traces", nargs="+")
    ap.add_argument("--calibrate", required=True, help="trace of the 1 x 1 run")
    ap.add_argument("--platform", action="append", required=True)
    ap.add_argument("--skip", type=int, default=2)
    args = ap.parse_args()
    one = ti.load(args.calibrate)
    m1, n1 = measured_step(one, args.skip)
    p1 = replay(one, args.platform[0], 1e9, args.skip)
    flops = 1e9 * m1 / p1
    print(f"calibration ({args.calibrate}, {n1} steps): measured {m1 * 1e3:.3f} ms/step, "
          f"CPU time of its tasks and work {p1 * 1e3:.3f} ms/step -> {flops / 1e9:.3f} "
          f"Gflop per CPU second")
    print("ms per step; per platform: the replay with the tasks' CPU time as measured (cpu), "
          "and calibrated (cal), with cal / measured")
    print(f"{'trace':24s} {'ranks':>5s} {'measured':>9s} " +
          " ".join(f"{os.path.basename(p)[:-4] + ' cpu':>14s} {'cal':>8s} {'ratio':>6s}"
                   for p in args.platform))
    for t in args.traces:
        ev = ti.load(t)
        m, _ = measured_step(ev, args.skip)
        ranks = len({e["pid"] for e in ev})
        row = f"{t[-24:]:24s} {ranks:5d} {m * 1e3:9.3f} "
        for p in args.platform:
            raw = replay(ev, p, 1e9, args.skip)
            pred = replay(ev, p, flops, args.skip)
            row += f"{raw * 1e3:14.3f} {pred * 1e3:8.3f} {pred / m:6.3f} "
        print(row)


if __name__ == "__main__":
    main()
