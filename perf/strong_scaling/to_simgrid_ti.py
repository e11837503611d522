#!/usr/bin/python3
"""A sluice --trace as SimGrid time-independent traces, one file per rank, for `smpirun -replay`.

Each rank's events become one sequence of SMPI replay actions, in the order they happened on
the rank (the trace of an R x 1 run: one worker thread and the main thread; with more threads
the tasks of a rank are replayed one after the other, so use R x 1 traces):

* a task (compute node, pack, unpack) -> `compute F` with F = its CPU seconds x --flops
  (the platform's hosts run at 1 Gflop/s, so --flops 1e9 replays the measured CPU time;
  simgrid_replay.py calibrates it against a measured run);
* the main thread's work between graphs (`bookkeeping`, `rebuild`) -> `compute` of its wall
  time less the messages inside it;
* a halo message -> `isend DST TAG BYTES` when the sender posted it and `wait` when it
  completed; `irecv SRC TAG BYTES` when the receiver posted it and `wait` just before the
  unpack that consumed it (a message outside the graphs: at its completion);
* the step's all-gather (`reduce`) -> `allgather B B` at its completion.

A message that the trace holds on one side only (the other rank's events were truncated) is
left out on both. Usage:
  perf/strong_scaling/to_simgrid_ti.py TRACE.json OUTDIR [--flops F] [--skip STEPS]
writes OUTDIR/rank_R.txt and OUTDIR/index.txt (the file list smpirun -replay takes) and
prints the ranks and the steps converted.
"""
import argparse
import bisect
import json
import os
import sys
from collections import defaultdict

MPI_TRACK = 10000
WORK = ("bookkeeping", "rebuild")  # the main thread's own work slices (tasks/src/trace.cpp)
# Tags of messages outside the graphs (the graphs' own are 1000 + exchange).
OTHER_TAGS = {}


def other_tag(kind):
    return OTHER_TAGS.setdefault(kind, 100 + len(OTHER_TAGS))


def load(path):
    with open(path) as f:
        return [e for e in json.load(f)["traceEvents"] if e.get("ph") == "X"]


def convert(events, flops, skip):
    """Returns ({rank: [action lines]}, steps converted)."""
    steps = sorted({e["args"]["step"] for e in events if "step" in e.get("args", {})})[skip:]
    keep = set(steps)
    ranks = sorted({e["pid"] for e in events})
    ev = [e for e in events if e.get("args", {}).get("step") in keep]
    # Messages by their two ends: graph messages by flow id, others by (step, kind, src, dst).
    ends = defaultdict(dict)
    for e in ev:
        a = e["args"]
        if e["tid"] != MPI_TRACK or not e["name"].startswith(("send ", "recv ")):
            continue
        if a.get("peer", -1) < 0:
            continue  # a collective (reduce, gathers): below
        kind = a.get("kind", e["name"].split(" ", 1)[1].rsplit(" ", 1)[0])
        src = a.get("src", e["pid"] if e["name"].startswith("send ") else a["peer"])
        dst = a.get("dst", a["peer"] if e["name"].startswith("send ") else e["pid"])
        key = a["flow"] if "flow" in a else (a["step"], kind, src, dst)
        ends[key]["send" if e["name"].startswith("send ") else "recv"] = (e, src, dst, kind)
    consumed = {}  # (rank, unpack id) -> the receive's wait
    timed = defaultdict(list)  # rank -> (time, order, line)
    for key, pair in ends.items():
        if "send" not in pair or "recv" not in pair:
            continue
        s, src, dst, kind = pair["send"]
        r = pair["recv"][0]
        tag = s["args"].get("tag", other_tag(kind))
        size = s["args"]["bytes"]
        t_post, t_done = s["ts"], s["ts"] + s["dur"]
        timed[src].append((t_post, 2, f"{src} isend {dst} {tag} {size}"))
        timed[src].append((t_done, 3, f"{src} wait {src} {dst} {tag}"))
        timed[dst].append((r["ts"], 0, f"{dst} irecv {src} {tag} {size}"))
        wait = f"{dst} wait {src} {dst} {tag}"
        if "consumer" in r["args"]:
            consumed[(dst, r["args"]["consumer"])] = wait
        else:
            timed[dst].append((r["ts"] + r["dur"], 1, wait))
    messages_of = defaultdict(list)  # rank -> sorted (post, done) of its messages, in µs
    for e in ev:
        if e["tid"] == MPI_TRACK and e["name"].startswith(("send ", "recv ")):
            messages_of[e["pid"]].append((e["ts"], e["ts"] + e["dur"]))
    for spans in messages_of.values():
        spans.sort()
    for e in ev:
        a = e["args"]
        rank = e["pid"]
        if "id" in a:
            wait = consumed.get((rank, a["id"]))
            if wait:
                timed[rank].append((e["ts"], 1, wait))
            timed[rank].append((e["ts"], 4, f"{rank} compute {a.get('cpu_us', 0) * 1e-6 * flops:.0f}"))
        elif e["tid"] == MPI_TRACK and e["name"] in WORK:
            # Its wall time less the messages inside it (those are replayed as messages).
            lo, hi = e["ts"], e["ts"] + e["dur"]
            spans = messages_of[rank]
            k = bisect.bisect_left(spans, (lo, -1.0))
            inner = 0.0
            while k < len(spans) and spans[k][0] <= hi:
                if spans[k][1] <= hi:
                    inner += spans[k][1] - spans[k][0]
                k += 1
            timed[rank].append((e["ts"], 4,
                                f"{rank} compute {max(0, e['dur'] - inner) * 1e-6 * flops:.0f}"))
        elif e["tid"] == MPI_TRACK and e["name"].startswith("send reduce"):
            n = a.get("bytes", 8)
            timed[rank].append((e["ts"] + e["dur"], 1, f"{rank} allgather {n} {n}"))
    out = {}
    for rank in ranks:
        lines = [f"{rank} init"]
        lines += [line for _, _, line in sorted(timed[rank])]
        lines.append(f"{rank} finalize")
        out[rank] = lines
    return out, len(steps)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("trace")
    ap.add_argument("outdir")
    ap.add_argument("--flops", type=float, default=1e9, help="flops per CPU second of a task")
    ap.add_argument("--skip", type=int, default=2)
    args = ap.parse_args()
    per_rank, steps = convert(load(args.trace), args.flops, args.skip)
    os.makedirs(args.outdir, exist_ok=True)
    files = []
    for rank, lines in per_rank.items():
        path = os.path.abspath(os.path.join(args.outdir, f"rank_{rank}.txt"))
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        files.append(path)
    with open(os.path.join(args.outdir, "index.txt"), "w") as f:
        f.write("\n".join(files) + "\n")
    print(f"{len(per_rank)} ranks, {steps} steps -> {args.outdir}/index.txt")


if __name__ == "__main__":
    sys.exit(main())
