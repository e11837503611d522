#!/usr/bin/env bash
# A short real run writes the documented results folder: snapshots + XDMF series (with the
# fluid's spacing), probe CSVs with a header and time in the first column, and summary.json
# with the documented keys; and
# `sluice info` describes the case. Usage: run_outputs.sh <sluice executable> <source dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"

"$exe" info "$src/cases/dam_break_2d.toml" >"$work/info.txt" || fail "info exit code $?"
grep -q "3200 fluid" "$work/info.txt" || fail "info does not report the 3200 fluid particles"

"$exe" run "$src/cases/dam_break_2d.toml" --out "$work/out" --threads 2 --quiet \
    --set time.end_time=0.02 --set time.output_interval=0.01 \
    --set 'output.fields=["velocity","pressure","kind","spacing"]' || fail "run exit code $?"
out="$work/out"
[ -f "$out/summary.json" ] || fail "no summary.json"
[ -f "$out/snapshots.xmf" ] || fail "no snapshots.xmf"
n=$(ls "$out"/snapshots/snap_*.h5 2>/dev/null | wc -l)
[ "$n" -eq 3 ] || fail "expected 3 snapshots (t = 0, 0.01, 0.02), found $n"
# The fluid's spacing in every snapshot: at t = 0 the lattice, every fluid particle dx from its
# nearest fluid neighbour, less the hydrostatic start's compression (rho/rho0 - 1 up to
# g H / c0^2 = 0.0025 at the bottom: rows down to 0.9975 dx); walls NaN; in every snapshot the
# attributes count what the field shows, and summary.json reports the first and last ones.
/usr/bin/python3 - "$out" <<'PY' || fail "snapshot spacing"
import glob, math, sys
import h5py
import numpy as np
files = sorted(glob.glob(f"{sys.argv[1]}/snapshots/snap_*.h5"))
dx = 0.01
bad = []
for k, name in enumerate(files):
    with h5py.File(name) as f:
        s, kind, a = f["spacing"][:], f["kind"][:], f.attrs
        fluid = kind == 0
        if k == 0 and not (s[fluid].min() > 0.997 and s[fluid].max() <= 1 + 1e-12):
            bad.append(f"t = 0: fluid spacing {s[fluid].min()}..{s[fluid].max()} dx")
        if not np.all(np.isnan(s[~fluid])):
            bad.append(f"{name}: a wall particle has a spacing")
        counts = (int(a["fluid_particles"]), int(a["fluid_crowded"]), int(a["fluid_isolated"]))
        shown = (int(fluid.sum()), int((s[fluid] < 0.5).sum()), int(np.isnan(s[fluid]).sum()))
        if counts != shown:
            bad.append(f"{name}: attributes {counts}, field {shown}")
        if abs(a["crowded_below"] - dx / 2) > 1e-15:
            bad.append(f"{name}: crowded_below {a['crowded_below']}")
        if abs(a["closest_fluid_pair"] / dx - np.nanmin(s[fluid])) > 1e-9:
            bad.append(f"{name}: closest pair {a['closest_fluid_pair']} against the field")
# summary.json's census at the start and the end is the one the first and last snapshots
# took of the same states (the run takes it once there and reports it in both places).
import json
with open(f"{sys.argv[1]}/summary.json") as f:
    census = json.load(f)["extra"]["neighbours"]
for when, name in (("start", files[0]), ("end", files[-1])):
    with h5py.File(name) as f:
        a = f.attrs
        for key in ("fluid_particles", "fluid_crowded", "fluid_isolated"):
            if census[when][key] != int(a[key]):
                bad.append(f"summary {when} {key} {census[when][key]}, {name} {int(a[key])}")
        if census[when]["closest_fluid_pair"] != float(a["closest_fluid_pair"]):
            bad.append(f"summary {when} closest pair differs from {name}'s")
print("\n".join(bad))
sys.exit(1 if bad or len(files) != 3 else 0)
PY
for p in p2_right_wall front level_x0; do
    f="$out/probes/$p.csv"
    [ -f "$f" ] || { fail "missing $f"; continue; }
    head -1 "$f" | grep -q '^time_s,' || fail "$f header does not start with time_s"
    [ "$(wc -l <"$f")" -ge 3 ] || fail "$f has fewer than 2 samples"
done
for key in case dimension particles steps simulated_time wall_seconds \
    particle_steps_per_second threads ranks git_revision; do
    grep -q "\"$key\"" "$out/summary.json" || fail "summary.json lacks $key"
done
grep -q '"threads": 2' "$out/summary.json" || fail "summary.json does not record 2 threads"
grep -q '"mass_relative_change": 0.0' "$out/summary.json" || fail "mass not conserved exactly"

# A fixed time step above the stability limit is refused with both numbers, exit code 2.
"$exe" run "$src/cases/debris_box_3d.toml" --out "$work/bad" --set numerics.dt=0.001 \
    2>"$work/err.txt"
code=$?
[ $code -eq 2 ] || fail "unstable fixed dt: exit code $code, expected 2"
grep -q "numerics.dt" "$work/err.txt" || fail "unstable dt message does not name numerics.dt"
grep -q "stability limit" "$work/err.txt" || fail "unstable dt message does not give the limit"
[ ! -e "$work/bad" ] || fail "a refused case left a results folder"

# A run that goes wrong physically (no walls: the water falls out of the domain) stops with
# exit code 3 naming the particle and the step, keeps the last good snapshot, and leaves no
# summary.json (the folder does not look complete).
"$exe" run "$src/cases/hydrostatic_2d.toml" --out "$work/fall" --quiet --set walls.model=none \
    2>"$work/fall.txt"
code=$?
[ $code -eq 3 ] || fail "escaping particle: exit code $code, expected 3"
grep -q "particle .* outside the domain .*at step" "$work/fall.txt" || fail "no particle/step in: $(cat "$work/fall.txt")"
grep -q "last good state in" "$work/fall.txt" || fail "no last good snapshot named"
[ ! -e "$work/fall/summary.json" ] || fail "a failed run left summary.json"

if [ $failures -eq 0 ]; then echo "run_outputs: all checks passed"; fi
exit $failures
