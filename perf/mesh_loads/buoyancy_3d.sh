#!/usr/bin/env bash
# Archimedes on a 3-D STL solid (tests/data/mesh_loads/buoyancy_3d.toml): the force probe on
# the submerged icosphere against rho0 g V, V its enclosed volume, mean and spread over
# 0.5-1.5 s, at the spacings given (default 0.02 and 0.0125 m: 5 and 8 dx across the radius).
# Usage: perf/mesh_loads/buoyancy_3d.sh [--sluice EXE] [--out DIR] [DX ...]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
exe="$root/build/release/sluice" out=/tmp/sluice_buoyancy_3d
while (($#)); do
    case "$1" in
    --sluice) exe=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) break ;;
    esac
done
spacings=("$@")
((${#spacings[@]})) || spacings=(0.02 0.0125)
for dx in "${spacings[@]}"; do
    dir="$out/dx$dx"
    start=$(date +%s)
    "$exe" run "$root/tests/data/mesh_loads/buoyancy_3d.toml" --out "$dir" -q \
        --set particles.dx=$dx
    /usr/bin/python3 - "$dir" "$dx" "$(($(date +%s) - start))" <<'PY'
import csv, json, math, sys
run, dx, wall = sys.argv[1], float(sys.argv[2]), sys.argv[3]
rows = [r for r in csv.DictReader(open(f"{run}/probes/body.csv")) if float(r["time_s"]) >= 0.5]
fz = [float(r["Fz_N"]) for r in rows]
fx = [float(r["Fx_N"]) for r in rows]
V = 0.00415274  # the icosphere's enclosed volume (sluice info)
B = 1000 * 9.81 * V
mean = sum(fz) / len(fz)
sd = math.sqrt(sum((f - mean) ** 2 for f in fz) / len(fz))
n = json.load(open(f"{run}/summary.json"))["fluid_particles"]
print(f"dx = {dx} m ({0.1 / dx:.1f} dx across the radius, {n} fluid particles, {wall} s wall): "
      f"Fz mean {mean:.2f} N against rho0 g V = {B:.2f} N ({100 * (mean / B - 1):+.2f} %), "
      f"spread {100 * sd / B:.1f} %, Fx mean {sum(fx) / len(fx):+.3f} N, {len(fz)} samples")
PY
done
