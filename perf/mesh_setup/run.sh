#!/usr/bin/env bash
# Set-up cost of a large mesh: a 1 m cube tank filled to 0.6 m at dx = 0.01 (564,120 fluid and
# 203,682 wall particles) with a UV sphere of 100,488 triangles (radius 0.2 m) as a solid
# obstacle, against the same case without it: wall time of `sluice check` and of a run of one
# step (set-up, the first step, the final output). Usage: perf/mesh_setup/run.sh [SLUICE_EXE]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
exe="${1:-$root/build/release/sluice}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$root/scripts/make_meshes.py" sphere --centre 0.5 0.5 0.3 --radius 0.2 --kind uv \
    --triangles 100000 --format stl-binary --out "$work/sphere_100k.stl" >/dev/null
write_case() { # file with_mesh
    cat >"$1" <<TOML
[case]
name = "mesh_setup"
dimension = 3
[domain]
lo = [0, 0, 0]
hi = [1, 1, 1]
[fluid]
rho0 = 1000
viscosity = 1e-3
sound_speed = 30
[particles]
dx = 0.01
[[blocks]]
lo = [0, 0, 0]
hi = [1, 1, 0.6]
[numerics]
kernel = "wendland_c2"
h_over_dx = 1.5
[walls]
model = "dummy"
tank_lo = [0, 0, 0]
tank_hi = [1, 1, 1]
[time]
end_time = 1e-5
[output]
snapshots = false
TOML
    if [[ $2 == yes ]]; then
        printf '[[walls.meshes]]\nfile = "%s"\nrole = "solid"\n' "$work/sphere_100k.stl" >>"$1"
    fi
}
write_case "$work/plain.toml" no
write_case "$work/mesh.toml" yes
for c in plain mesh; do
    s=$(date +%s.%N)
    "$exe" check "$work/$c.toml" >/dev/null
    m=$(date +%s.%N)
    "$exe" run "$work/$c.toml" --out "$work/out_$c" -q
    e=$(date +%s.%N)
    step=$(python3 -c "import json; print(json.load(open('$work/out_$c/summary.json'))['wall_seconds'])")
    python3 -c "print(f'$c: check {$m - $s:.2f} s, run {$e - $m:.2f} s (of which stepping {$step:.2f} s), $(nproc) cores')"
done
