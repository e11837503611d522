#!/usr/bin/env python3
"""Cost of free bodies: a 2-D tank 2 m x 1.2 m with 1 m of water holding 100 boxes
(0.06 m x 0.06 m, a 10 x 10 grid 0.15 m apart), run once with every box a free body of
density 1000 (neutrally buoyant: they stay about where they are) and once with the same boxes
fixed. Prints wall seconds and particle-steps per second of each, and their ratio (free over
fixed, per particle-step), on 1 rank and on 2 ranks.

Usage: perf/floating_bodies/cost.py [--sluice build/release/sluice] [--threads 2]
       [--end 0.05] [--ranks 1 2]
The two runs of a layout are side by side in one window; run it twice to see the machine's
drift."""
import argparse
import json
import os
import subprocess
import tempfile


def case_text(free, end):
    """The tank with its 100 boxes; `free`: each box a free body (the block around them is
    cut to them). Without `free` the caller replaces the block (fixed boxes may not lie in
    one)."""
    lines = [
        "[case]", 'name = "bodies_cost"', "dimension = 2",
        "[domain]", "lo = [-0.05, -0.05]", "hi = [2.05, 1.25]",
        "[fluid]", "rho0 = 1000.0", "viscosity = 1.0e-6", "sound_speed = 30.0",
        "gravity = [0.0, -9.81]",
        "[particles]", "dx = 0.01",
        "[[blocks]]", "lo = [0.0, 0.0]", "hi = [2.0, 1.0]",
        "[numerics]", 'kernel = "wendland_c2"', "h_over_dx = 1.5",
        "artificial_viscosity = 0.02",
        "[walls]", 'model = "dummy"', "tank_lo = [0.0, 0.0]", "tank_hi = [2.0, 1.2]",
    ]
    motions = []
    for i in range(10):
        for j in range(10):
            x0, y0 = 0.2 + 0.15 * i, 0.12 + 0.08 * j
            lines += ["[[walls.boxes]]", f"lo = [{x0:.2f}, {y0:.2f}]",
                      f"hi = [{x0 + 0.06:.2f}, {y0 + 0.06:.2f}]"]
            if free:
                lines.append(f'motion = "b{i}_{j}"')
                motions += ["[[motions]]", f'name = "b{i}_{j}"', 'kind = "free_body"',
                            "density = 1000.0"]
    lines += motions
    lines += ["[time]", f"end_time = {end}", f"output_interval = {end}",
              "[output]", "snapshots = false"]
    return "\n".join(lines) + "\n"


def fixed_case_text(end):
    """The same particles with fixed boxes: the water as blocks around the boxes' columns."""
    text = case_text(True, end)
    out = []
    skip = False
    for line in text.splitlines():
        if line.startswith('motion = "b'):
            continue
        if line == "[[motions]]":
            skip = True
            continue
        if skip and (line.startswith("name = ") or line.startswith("kind = ")
                     or line.startswith("density = ")):
            continue
        skip = False
        out.append(line)
    text = "\n".join(out) + "\n"
    # Blocks: columns between the boxes, and the rows between them within each column.
    blocks = []
    xs = [0.2 + 0.15 * i for i in range(10)]
    edges = [0.0]
    for x in xs:
        edges += [x, x + 0.06]
    edges.append(2.0)
    for k in range(0, len(edges), 2):
        blocks.append((edges[k], 0.0, edges[k + 1], 1.0))  # water columns between boxes
    for x in xs:
        ys = [0.12 + 0.08 * j for j in range(10)]
        bottom = 0.0
        for y in ys:
            blocks.append((x, bottom, x + 0.06, y))
            bottom = y + 0.06
        blocks.append((x, bottom, x + 0.06, 1.0))
    block_text = "".join(
        f"[[blocks]]\nlo = [{a:.2f}, {b:.2f}]\nhi = [{c:.2f}, {d:.2f}]\n"
        for a, b, c, d in blocks if c - a > 1e-9 and d - b > 1e-9)
    return text.replace("[[blocks]]\nlo = [0.0, 0.0]\nhi = [2.0, 1.0]\n", block_text)


def run(sluice, text, ranks, threads, folder, name):
    path = os.path.join(folder, name + ".toml")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(folder, name)
    cmd = [sluice, "run", path, "--out", out, "--threads", str(threads), "-q"]
    if ranks > 1:
        cmd = ["mpirun", "--oversubscribe", "-np", str(ranks)] + cmd
    subprocess.run(cmd, check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sluice", default="build/release/sluice")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--end", type=float, default=0.05)
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    a = ap.parse_args()
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    os.environ.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    with tempfile.TemporaryDirectory() as folder:
        for ranks in a.ranks:
            threads = max(1, a.threads // ranks)
            fixed = run(a.sluice, fixed_case_text(a.end), ranks, threads, folder, f"fixed{ranks}")
            free = run(a.sluice, case_text(True, a.end), ranks, threads, folder, f"free{ranks}")
            ratio = fixed["particle_steps_per_second"] / free["particle_steps_per_second"]
            print(f"{ranks} rank(s) x {threads} thread(s): fixed boxes "
                  f"{fixed['particles']} particles, {fixed['steps']} steps, "
                  f"{fixed['particle_steps_per_second']:.4g} particle-steps/s; 100 free bodies "
                  f"{free['particles']} particles, {free['steps']} steps, "
                  f"{free['particle_steps_per_second']:.4g} particle-steps/s; cost per "
                  f"particle-step free/fixed = {ratio:.3f}")


if __name__ == "__main__":
    main()
