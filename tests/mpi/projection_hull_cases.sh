#!/usr/bin/env bash
# Every shipped case (cases/*.toml) with numerics.scheme = "projection" and convex-hull
# neighbours for each operator ([neighbours.*]) runs to its (shortened) end on 1 and
# 3 ranks at coarse resolution, and the runs agree as the projection scheme's do with radius
# neighbours (tests/mpi/projection_rank_invariance.sh): per particle (matched by id) positions
# within 1e-9 m and pressure within 1e-6 of rho0 |g| H (H = the domain's height), the solver's
# tolerance. The three operators get three different policies (hull among the candidates
# within 2.5 dx for the gradient, hull corners and edge points within 3.1 dx for the
# Laplacian, hull corners for the surface test), so the gradient and the Laplacian are fitted
# separately, each over its own selection. WCSPH-only keys (the schema's
# applies = "wcsph", whole tables such as [[motions]] included: the walls stand still) and
# force and motion probes (sums of WCSPH pair forces, motions) are dropped from each file and
# reflective walls become dummy walls, as a user switching schemes must.
# Usage: projection_hull_cases.sh SLUICE_EXE SOURCE_DIR MPIEXEC
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_args.sh"

"$exe" schema >"$work/schema.json"
# The converted cases live in $work; the mesh files their [[walls.meshes]] name (relative to
# the case's folder) are found through a link.
ln -s "$src/cases/meshes" "$work/meshes"

# The case as a projection case: WCSPH-only keys dropped, the neighbour tables appended.
convert() { # in out
    /usr/bin/python3 - "$1" "$2" "$work/schema.json" <<'PY'
import json, re, sys
src, out, schema = sys.argv[1], sys.argv[2], json.load(open(sys.argv[3]))
wcsph = {(k["table"], k["key"]) for k in schema if k["applies"] == "wcsph"}
# Chunks from one table header to the next; force probes (WCSPH pair forces) go whole.
table, chunks, raw = "", [[]], [[]]
for line in open(src):
    m = re.match(r"\s*\[\[?\s*([A-Za-z0-9_.]+)\s*\]\]?", line)
    if m:
        table = m.group(1)
        chunks.append([])
        raw.append([])
    raw[-1].append(line)
    k = re.match(r"\s*([A-Za-z0-9_]+)\s*=", line)
    if k and (table, k.group(1)) in wcsph:
        continue
    # The projection scheme's wall condition lives on wall particles: dummy walls.
    if table == "walls" and k and k.group(1) == "model":
        line = 'model = "dummy"\n'
    chunks[-1].append(line)
# Tables of WCSPH only ([[motions]], [[damping_zones]]) go whole, and so do the probes that
# read a motion: the case's walls stand still under the projection scheme.
whole = {k["key"] for k in schema if k["table"] == "" and k["applies"] == "wcsph"}
def header(c):
    m = re.match(r"\s*\[\[?\s*([A-Za-z0-9_.]+)", c[0]) if c else None
    return m.group(1) if m else ""
# A free body (kind = "free_body") is no projection case's wall: its box or mesh goes whole (a
# fixed box may not lie in the water a floating one displaced).
def named(c, key):
    return {m.group(1) for l in c for m in [re.match(r'\s*' + key + r'\s*=\s*"([^"]+)"', l)] if m}
free = set()
for c in raw:
    if header(c) == "motions" and any(re.match(r'\s*kind\s*=\s*"free_body"', l) for l in c):
        free |= named(c, "name")
dropped = {i for i, c in enumerate(raw)
           if header(c) in ("walls.boxes", "walls.meshes") and named(c, "motion") & free}
lines = [l for i, c in enumerate(chunks)
         if header(c) not in whole and i not in dropped and
         not any(re.match(r'\s*type\s*=\s*"(force|motion)"', l) for l in c)
         for l in c]
lines.append("""
[neighbours.gradient]
selection = "convex-hull"
candidate_radius_over_dx = 2.5

[neighbours.laplacian]
selection = "convex-hull"
hull_points = "boundary"

[neighbours.free_surface]
selection = "convex-hull"
hull_points = "vertices"
""")
open(out, "w").writelines(lines)
PY
}

run() { # case out ranks args...
    local case=$1 out=$2 ranks=$3
    shift 3
    sluice_on "$ranks" run "$case" --out "$out" --threads 1 -q "$@"
}

compare() { # one three label scale (Pa, or a case file: its rho0 g H)
    /usr/bin/python3 "$src/tests/mpi/lib/compare_layouts.py" "$@" 2
}

# Coarse spacing per case (the Poiseuille channel keeps its own: its periodic axis needs three
# supports) and a short end time: a few steps.
for case in "$src"/cases/*.toml; do
    name=$(basename "$case" .toml)
    conv=$work/$name.toml
    convert "$case" "$conv"
    extra=(--set 'numerics.scheme="projection"' --set time.end_time=0.004
           --set time.output_interval=0.002)
    if [[ $name != poiseuille_2d ]]; then
        dx=0.04
        [[ $(grep -E '^dimension *= *3' "$case") ]] && dx=0.05
        extra+=(--set particles.dx=$dx)
    fi
    run "$conv" "$work/$name/1" 1 "${extra[@]}"
    run "$conv" "$work/$name/3" 3 "${extra[@]}"
    compare "$work/$name/1" "$work/$name/3" "$name" "$conv"
done
echo "ok projection with convex-hull neighbours: every shipped case on 1 and 3 ranks"
