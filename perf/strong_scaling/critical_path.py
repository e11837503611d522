#!/usr/bin/python3
"""The critical path of each step from a sluice --trace, and the floor it puts on a step.

Reads the Chrome/Perfetto trace `sluice run --trace FILE` writes (rank 0 writes every rank's
events into one file; several files are read as one trace). Each task slice carries its `id`
and `preds` (the tasks it waited for: the step graph's edges); each halo message carries
`src`, `dst`, `bytes`, `flow` (the same on sender and receiver) and its `producer` (the pack
task, on the sender) or `consumer` (the unpack task, on the receiver). For every step this
builds the graph of the step's tasks on all ranks, joined across ranks by message edges

    pack (sender) -> message (sender's post .. receiver's completion) -> unpack (receiver)

weights each task by its wall duration and each message by its observed latency (the
receiver's completion minus the sender's post; on one node the ranks share one clock), and
finds the longest weighted chain: the tasks and messages that set the step's length. Per step:

* the chain (task names, ranks, durations), its length, and the step's length (first to last
  event of the step's graphs on any rank: tasks and halo messages); the difference is time
  no chain accounts for (a task ready but not yet running, the gate of a step run ahead);
* message rounds: how many rank-to-rank hops the chain crosses, and the bytes they carry;
* the floor at latency L and bandwidth B: compute on the chain + rounds x L + bytes / B,
  with compute as the chain's task wall time and, beside it, the tasks' CPU time (which an
  oversubscribed machine does not inflate).

Beside the chain, the other bound a step's graph has: the busiest rank's task wall time over
its threads (the main thread's state packs count as a thread). Summaries over the steps:
median and p90. The invariants the edges must satisfy (every
dependency ended before its dependent started; a message completed after it was posted, was
posted after its pack ended, and completed before its unpack started) are counted and printed.

Usage: perf/strong_scaling/critical_path.py TRACE.json [...] [--skip STEPS]
           [--latency L --bandwidth B ...] [--chains N] [--json]
  --skip: leave out the first STEPS steps (start-up, first list build); default 2.
  --latency/--bandwidth: network figures (s, bytes/s), paired in order; default the pairs
      (2e-6, 10e9) and (20e-6, 1e9).
  --chains: print the chains of N steps (the median step's first); default 1.
"""
import argparse
import json
import statistics
import sys
from collections import defaultdict

MPI_TRACK = 10000  # the main thread's message track (tasks/src/trace.cpp)
TOL = 3e-9  # s: times are written rounded to 1 ns (ts and dur each)


def load(paths):
    events = []
    for p in paths:
        with open(p) as f:
            events += [e for e in json.load(f)["traceEvents"] if e.get("ph") == "X"]
    return events


def quantile(xs, q):
    xs = sorted(xs)
    if not xs:
        return float("nan")
    k = q * (len(xs) - 1)
    lo = int(k)
    hi = min(lo + 1, len(xs) - 1)
    return xs[lo] + (xs[hi] - xs[lo]) * (k - lo)


def by_step(events):
    """step -> (tasks {(rank, id): event}, messages {flow: {"send": ev, "recv": ev}})."""
    tasks = defaultdict(dict)
    msgs = defaultdict(lambda: defaultdict(dict))
    for e in events:
        a = e.get("args", {})
        step = a.get("step")
        if step is None:
            continue
        if "id" in a:
            tasks[step][(e["pid"], a["id"])] = e
        elif "flow" in a:
            msgs[step][a["flow"]]["send" if e["name"].startswith("send ") else "recv"] = e
    return tasks, msgs


def t0(e):
    return e["ts"] * 1e-6


def t1(e):
    return (e["ts"] + e["dur"]) * 1e-6


def step_path(tasks, msgs):
    """The longest chain of one step and the checks of its edges."""
    checks = {"dependency_edges": 0, "dependency_violations": 0, "message_edges": 0,
              "message_violations": 0, "unmatched_messages": 0}
    # Nodes: ("t", rank, id) tasks, ("m", flow) messages. Predecessors and weights.
    preds = defaultdict(list)
    weight = {}
    for (rank, tid), e in tasks.items():
        weight[("t", rank, tid)] = e["dur"] * 1e-6
        for p in e["args"]["preds"]:
            pe = tasks.get((rank, p))
            if pe is None:
                continue
            preds[("t", rank, tid)].append(("t", rank, p))
            checks["dependency_edges"] += 1
            if t1(pe) > t0(e) + TOL:
                checks["dependency_violations"] += 1
    for flow, pair in msgs.items():
        s, r = pair.get("send"), pair.get("recv")
        if s is None or r is None:
            checks["unmatched_messages"] += 1
            continue
        node = ("m", flow)
        weight[node] = max(0.0, t1(r) - t0(s))
        checks["message_edges"] += 1
        prod = tasks.get((s["pid"], s["args"]["producer"]))
        cons = tasks.get((r["pid"], r["args"]["consumer"]))
        bad = t1(r) < t0(s) - TOL
        if prod is not None:
            preds[node].append(("t", s["pid"], s["args"]["producer"]))
            bad |= t1(prod) > t0(s) + TOL
        if cons is not None:
            preds[("t", r["pid"], r["args"]["consumer"])].append(node)
            bad |= t1(r) > t0(cons) + TOL
        checks["message_violations"] += int(bad)
    # Longest path, in a topological order (Kahn's; an edge always points back in time, so a
    # cycle would be a malformed trace).
    succ = defaultdict(list)
    indeg = {n: 0 for n in weight}
    for n, ps in preds.items():
        for p in ps:
            succ[p].append(n)
            indeg[n] += 1
    ready = [n for n, d in indeg.items() if d == 0]
    best, came = {}, {}
    while ready:
        n = ready.pop()
        b, c = 0.0, None
        for p in preds[n]:
            if best[p] > b:
                b, c = best[p], p
        best[n] = b + weight[n]
        came[n] = c
        for q in succ[n]:
            indeg[q] -= 1
            if indeg[q] == 0:
                ready.append(q)
    if not best:
        return None, checks
    end = max(best, key=best.get)
    chain = []
    while end is not None:
        chain.append(end)
        end = came[end]
    chain.reverse()
    return chain, checks


def describe(chain, tasks, msgs):
    out = []
    for n in chain:
        if n[0] == "t":
            e = tasks[(n[1], n[2])]
            a = e["args"]
            where = f"group {a['group']}" if "group" in a else f"peer {a.get('peer')}"
            out.append({"kind": "task", "name": e["name"], "rank": n[1], "where": where,
                        "wall_s": e["dur"] * 1e-6, "cpu_s": a.get("cpu_us", 0.0) * 1e-6})
        else:
            s, r = msgs[n[1]]["send"], msgs[n[1]]["recv"]
            out.append({"kind": "message", "name": s["args"].get("kind", s["name"]),
                        "src": s["args"]["src"], "dst": s["args"]["dst"],
                        "bytes": s["args"]["bytes"], "latency_s": max(0.0, t1(r) - t0(s))})
    return out


def analyse(events, skip, networks):
    tasks, msgs = by_step(events)
    steps = sorted(tasks)[skip:]
    ranks = sorted({e["pid"] for e in events})
    rows = []
    totals = defaultdict(int)
    for s in steps:
        chain, checks = step_path(tasks[s], msgs[s])
        for k, v in checks.items():
            totals[k] += v
        if chain is None:
            continue
        items = describe(chain, tasks[s], msgs[s])
        ev = list(tasks[s].values()) + [m for p in msgs[s].values() for m in p.values()]
        length = max(t1(e) for e in ev) - min(t0(e) for e in ev)
        compute = sum(i["wall_s"] for i in items if i["kind"] == "task")
        cpu = sum(i["cpu_s"] for i in items if i["kind"] == "task")
        latency = sum(i["latency_s"] for i in items if i["kind"] == "message")
        rounds = sum(1 for i in items if i["kind"] == "message")
        nbytes = sum(i["bytes"] for i in items if i["kind"] == "message")
        # The other bound on a step: the busiest rank's task time over its threads.
        work, threads = defaultdict(float), defaultdict(set)
        for e in tasks[s].values():
            work[e["pid"]] += e["dur"] * 1e-6
            threads[e["pid"]].add(e["tid"])
        per_thread = max(w / len(threads[r]) for r, w in work.items())
        rows.append({"step": s, "step_s": length, "chain_s": compute + latency,
                     "work_per_thread_s": per_thread,
                     "compute_s": compute, "cpu_s": cpu, "message_s": latency,
                     "rounds": rounds, "bytes": nbytes, "tasks": len(items) - rounds,
                     "floors": [{"latency": L, "bandwidth": B,
                                 "floor_s": compute + rounds * L + nbytes / B,
                                 "floor_cpu_s": cpu + rounds * L + nbytes / B}
                                for L, B in networks],
                     "chain": items})
    return {"ranks": ranks, "steps": len(rows), "checks": dict(totals), "rows": rows}


def summary(rows, key):
    xs = [r[key] for r in rows]
    return {"median": statistics.median(xs) if xs else float("nan"), "p90": quantile(xs, 0.9)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("traces", nargs="+")
    ap.add_argument("--skip", type=int, default=2)
    ap.add_argument("--latency", type=float, action="append")
    ap.add_argument("--bandwidth", type=float, action="append")
    ap.add_argument("--chains", type=int, default=1)
    ap.add_argument("--json", action="store_true")
    args = ap.parse_args()
    lat = args.latency or [2e-6, 20e-6]
    bw = args.bandwidth or [10e9, 1e9]
    if len(lat) != len(bw):
        sys.exit("critical_path.py: give as many --latency as --bandwidth values")
    networks = list(zip(lat, bw))
    events = load(args.traces)
    res = analyse(events, args.skip, networks)
    rows = res["rows"]
    if not any("preds" in e.get("args", {}) for e in events):
        sys.exit(f"critical_path.py: {args.traces[0]}: no task carries 'preds' "
                 "(a trace written before the edges were recorded)")
    if args.json:
        res["summary"] = {k: summary(rows, k) for k in
                          ("step_s", "chain_s", "compute_s", "cpu_s", "message_s", "rounds",
                           "bytes", "work_per_thread_s")}
        json.dump(res, sys.stdout, indent=1)
        print()
        return
    us = 1e6
    print(f"{len(res['ranks'])} rank(s), {len(rows)} steps (first {args.skip} skipped)")
    c = res["checks"]
    print(f"edges: {c.get('dependency_edges', 0)} dependency, {c.get('message_edges', 0)} message;"
          f" violations: {c.get('dependency_violations', 0)} dependency,"
          f" {c.get('message_violations', 0)} message; unmatched messages:"
          f" {c.get('unmatched_messages', 0)}")
    if not rows:
        return
    print(f"{'per step':28s} {'median':>12s} {'p90':>12s}")
    for key, label, scale in (("step_s", "step length [us]", us), ("chain_s", "chain length [us]", us),
                              ("compute_s", "  tasks on it, wall [us]", us),
                              ("cpu_s", "  tasks on it, CPU [us]", us),
                              ("message_s", "  messages on it [us]", us),
                              ("rounds", "message rounds", 1), ("bytes", "bytes on it", 1),
                              ("tasks", "tasks on it", 1),
                              ("work_per_thread_s", "busiest rank's work/thread", us)):
        s = summary(rows, key)
        print(f"{label:28s} {s['median'] * scale:12.1f} {s['p90'] * scale:12.1f}")
    ratio = summary([{"r": r["chain_s"] / r["step_s"]} for r in rows if r["step_s"] > 0], "r")
    print(f"{'chain / step':28s} {ratio['median']:12.3f} {ratio['p90']:12.3f}")
    for k, (L, B) in enumerate(networks):
        for key, label in (("floor_s", "wall"), ("floor_cpu_s", "CPU")):
            s = summary([{"f": r["floors"][k][key]} for r in rows], "f")
            print(f"floor, {label:4s} L={L * us:g}us B={B / 1e9:g}GB/s".ljust(28) +
                  f" {s['median'] * us:12.1f} {s['p90'] * us:12.1f}")
    med = statistics.median_low([r["chain_s"] for r in rows])
    shown = [r for r in rows if r["chain_s"] == med][:1]
    shown += [r for r in rows if r not in shown][: max(0, args.chains - 1)]
    for r in shown:
        print(f"\nstep {r['step']}: step {r['step_s'] * us:.1f} us, chain {r['chain_s'] * us:.1f} us,"
              f" {r['rounds']} message rounds")
        for i in r["chain"]:
            if i["kind"] == "task":
                print(f"  rank {i['rank']:3d}  {i['name']:24s} {i['where']:10s}"
                      f" {i['wall_s'] * us:10.1f} us (CPU {i['cpu_s'] * us:.1f})")
            else:
                print(f"  {i['src']:3d} -> {i['dst']:<3d}  message {i['name']:16s}"
                      f" {i['bytes']:>9d} B {i['latency_s'] * us:10.1f} us")


if __name__ == "__main__":
    main()
