#!/usr/bin/env bash
# scripts/plot on a short real run: `probes`, `history`, `snapshot` (also coloured by the
# fluid's spacing), `spacing` and `timeline` each write PNG files that are real pictures (at
# least 300 x 100 pixels, more than 16 colours, no colour covering 99 % of the image), not an
# empty canvas. `probes` also on the wall-load probes
# (force with a moment, area sensor, every-step sampling) in 2-D (a copy of dam_break_2d with
# them added: units per metre of width) and 3-D (cases/dam_break_3d.toml, which carries them):
# the line it prints for each panel must name the kind, the sensor size and the unit.
# Skipped (exit code 77) where Debian's python3 lacks matplotlib, h5py, numpy or PIL.
# Usage: plot_outputs.sh <sluice exe> <source dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
py=/usr/bin/python3
if ! "$py" -c "import matplotlib, h5py, numpy, PIL" 2>/dev/null; then
    echo "SKIP: $py lacks matplotlib, h5py, numpy or PIL (python3-matplotlib, python3-h5py)"
    exit 77
fi

out="$work/out"
"$exe" run "$src/cases/dam_break_2d.toml" --out "$out" --threads 2 --quiet \
    --set time.end_time=0.02 --set time.output_interval=0.01 --trace "$work/trace.json" \
    --set 'output.fields=["position","velocity","density","pressure","id","kind","spacing"]' ||
    fail "run exit code $?"

# Each subcommand prints the PNG files it wrote, one a line.
plot() { # name args...
    local name=$1
    shift
    if ! "$py" "$src/scripts/plot" "$@" >"$work/$name.txt" 2>&1; then
        fail "plot $name: exit code $?: $(tail -5 "$work/$name.txt")"
        return
    fi
    local pngs
    pngs=$(grep '\.png$' "$work/$name.txt")
    [ -n "$pngs" ] || fail "plot $name wrote no PNG: $(tail -5 "$work/$name.txt")"
    for f in $pngs; do
        "$py" - "$f" <<'PY' || fail "plot $name: $f is not a real picture"
import sys
from PIL import Image
img = Image.open(sys.argv[1]).convert("RGB")
w, h = img.size
colours = img.getcolors(maxcolors=w * h)
top = max(n for n, _ in colours)
ok = w >= 300 and h >= 100 and len(colours) > 16 and top < 0.99 * w * h
print(f"{sys.argv[1]}: {w} x {h}, {len(colours)} colours, largest {top / (w * h):.0%}")
sys.exit(0 if ok else 1)
PY
    done
}
plot probes probes "$out"
plot history history "$out"
plot snapshot snapshot "$out"
plot snapshot_spacing snapshot "$out" --field spacing
plot spacing spacing "$out"
# `spacing` prints its table: three snapshots of the 3200 fluid particles, none crowded yet.
[ "$(grep -Ec '^ +[0-9.e-]+ +3200 +0 +0 +0 ' "$work/spacing.txt")" = 3 ] ||
    fail "plot spacing: table is not three rows of 3200 fluid, 0 crowded: $(cat "$work/spacing.txt")"
plot timeline timeline "$work/trace.json"

# The wall-load probes. `probes` prints one line per panel: "probe NAME: what [unit]...".
expect() { # name regex: a line of plot NAME's output must match
    grep -Eq "$2" "$work/$1.txt" || fail "plot $1: no line matches '$2': $(cat "$work/$1.txt")"
}
cp "$src/cases/dam_break_2d.toml" "$work/loads_2d.toml"
cat >>"$work/loads_2d.toml" <<'TOML'

[[probes]]
name = "back_wall"
type = "force"
face = "x-"
moment_about = [0.0, 0.0]
interval = "every_step"

[[probes]]
name = "back_wall_p"
type = "pressure"
position = [0.0, 0.1]
diameter = 0.04
interval = "every_step"
TOML
"$exe" run "$work/loads_2d.toml" --out "$work/loads_2d" --threads 1 --quiet \
    --set particles.dx=0.02 --set time.end_time=0.02 2>/dev/null || fail "2-D wall-load run: exit code $?"
plot loads_2d probes "$work/loads_2d"
expect loads_2d '^probe back_wall: force on tank face x- \[N/m\]: Fx Fy; [0-9]+ samples, every step$'
expect loads_2d '^probe back_wall: moment about \(0, 0\) m \[N m/m\]: Mz$'
expect loads_2d '^probe back_wall_p: area sensor \(40 mm segment, wall force\) on the wall at \(0, 0.1\) m \[Pa\]'
expect loads_2d '^probe p2_right_wall: area sensor \(20 mm segment, wall force\) on face x\+ at \(1.6, 0.02\) m \[Pa\]; [0-9]+ samples, every 0.0002 s$'
expect loads_2d '^probe right_wall_force: force on tank face x\+ \[N/m\]: Fx Fy; [0-9]+ samples, every 0.0002 s$'

"$exe" run "$src/cases/dam_break_3d.toml" --out "$work/loads_3d" --threads 1 --quiet \
    --set time.end_time=0.02 2>/dev/null || fail "3-D run: exit code $?"
plot loads_3d probes "$work/loads_3d"
expect loads_3d '^probe far_wall_force: force on tank face x\+ \[N\]: Fx Fy Fz;'
expect loads_3d '^probe far_wall_force: moment about \(0.6, 0.1, 0\) m \[N m\]: Mx My Mz$'
expect loads_3d '^probe far_wall_p_area: area sensor \(⌀ 40 mm, wall force\) on face x\+ at \(0.6, 0.1, 0.03\) m \[Pa\]'
expect loads_3d '^probe far_wall_p_point: point probe at \(0.59, 0.1, 0.03\) m \[Pa\]'
expect loads_3d '^probe level_x040_y005: point gauge at x = 0.4 m, y = 0.05 m \[m\]'
expect loads_3d '^probe front_bulk: front along \+x, columns ≥ 60 mm deep \[m\]'

[ $failures -eq 0 ] && echo "plot outputs: all checks passed"
exit $((failures > 0))
