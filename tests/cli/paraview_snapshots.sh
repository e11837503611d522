#!/usr/bin/env bash
# ParaView (pvbatch, Debian's 5.11) reads the snapshots.xmf of real runs as sluice wrote them:
# a 2-D dam break, a coarse 3-D dam break, and a 2-D block falling out of a wall-less domain
# with domain.particle_exit = "remove" (the particle count drops from 200 to 160 to 60 between
# snapshots) writing every output field (acceleration, mass, spacing with its NaNs too).
# For each run and each of ParaView's XDMF readers (XDMFReader, which the README names, and
# Xdmf3ReaderS; tests/lib/paraview_read.py): as many time steps as the run wrote snapshot
# files, each at the file's `time`; as many points as the file has particles; the point
# arrays exactly the file's datasets; points and arrays equal to h5py's reading bit for bit
# (tests/lib/paraview_compare.py, in a separate process: h5py and ParaView link different
# HDF5 libraries). A pressure changed by one ulp in ParaView's reading must be caught.
# `scripts/plot paraview` then renders a 2-D and a 3-D step: PNG files of 1000 x 700 pixels,
# more than 16 colours, no colour covering 99 % of the image, and coloured fluid on them.
# Skipped (exit code 77) without pvbatch, or without h5py, matplotlib (scripts/plot), numpy or
# PIL for /usr/bin/python3; the rendering is skipped (77 after the reading checks) with neither
# a DISPLAY nor xvfb-run.
# Usage: paraview_snapshots.sh <sluice exe> <source dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
py=/usr/bin/python3
if ! command -v pvbatch >/dev/null; then
    echo "SKIP: no pvbatch (Debian's paraview and python3-paraview: SLUICE_WITH_PARAVIEW=1 bash scripts/setup.sh)"
    exit 77
fi
if ! "$py" -c "import h5py, matplotlib, numpy, PIL" 2>/dev/null; then
    echo "SKIP: $py lacks h5py, matplotlib, numpy or PIL (python3-h5py, python3-matplotlib)"
    exit 77
fi

run() { # name case-file --set...: a short run into $work/NAME
    local name=$1 case_file=$2
    shift 2
    "$exe" run "$case_file" --out "$work/$name" --threads 1 --quiet "$@" ||
        fail "$name: sluice run exit code $?"
}
run 2d "$src/cases/dam_break_2d.toml" --set particles.dx=0.02 --set time.end_time=0.05
run 3d "$src/cases/dam_break_3d.toml" --set particles.dx=0.04 --set time.end_time=0.04 \
    --set time.output_interval=0.02
run exit "$src/tests/data/free_fall_exit.toml" --set 'domain.particle_exit="remove"' \
    --set time.end_time=0.33 --set time.output_interval=0.03 \
    --set 'output.fields=["position","velocity","density","pressure","acceleration","mass","id","kind","spacing"]'

# What ParaView reads (one pvbatch for the three runs), then the comparison with the HDF5 files;
# the comparison prints a line per reader.
if ! pvbatch --force-offscreen-rendering "$src/tests/lib/paraview_read.py" \
    "$work/2d/snapshots.xmf" "$work/2d_pv" "$work/3d/snapshots.xmf" "$work/3d_pv" \
    "$work/exit/snapshots.xmf" "$work/exit_pv" >"$work/read.txt" 2>&1; then
    fail "pvbatch paraview_read.py: $(tail -5 "$work/read.txt")"
fi
for name in 2d 3d exit; do
    "$py" "$src/tests/lib/paraview_compare.py" "$work/$name" "$work/${name}_pv" \
        >"$work/${name}_compare.txt" 2>&1 || fail "$name: ParaView's reading differs from the files"
    sed "s/^/$name: /" "$work/${name}_compare.txt"
done
# The exit run's counts are what the comparison saw change: not the same count at every step.
grep -q 'XDMFReader: 12 steps, points \[200, .*, 160, 60\]' "$work/exit_compare.txt" ||
    fail "exit: not 12 steps ending 160, 60 particles: $(cat "$work/exit_compare.txt")"

# The comparison is exact: one ulp off in one pressure value is a difference.
if [ -d "$work/2d_pv" ]; then
    cp -r "$work/2d_pv" "$work/ulp_pv"
    "$py" - "$work/ulp_pv/XDMFReader_1.npz" <<'PY'
import sys
import numpy as np
arrays = dict(np.load(sys.argv[1]))
arrays["pressure"][7] = np.nextafter(arrays["pressure"][7], np.inf)
np.savez(sys.argv[1], **arrays)
PY
    if "$py" "$src/tests/lib/paraview_compare.py" "$work/2d" "$work/ulp_pv" >"$work/ulp.txt" 2>&1 ||
        ! grep -q 'XDMFReader step 1 .*pressure differs' "$work/ulp.txt"; then
        fail "a pressure one ulp off was not reported: $(cat "$work/ulp.txt")"
    fi
fi

if [ -z "${DISPLAY:-}" ] && ! command -v xvfb-run >/dev/null; then
    echo "SKIP: rendering not checked (no DISPLAY and no xvfb-run: Debian's xvfb)"
    [ $failures -eq 0 ] && exit 77
    exit 1
fi
render() { # name results field: scripts/plot paraview of the run's step 1
    if ! "$py" "$src/scripts/plot" paraview "$2" --step 1 --colour "$3" \
        --out "$work/$1.png" >"$work/$1_render.txt" 2>&1; then
        fail "plot paraview $1: $(tail -5 "$work/$1_render.txt")"
        return
    fi
    "$py" - "$work/$1.png" <<'PY' || fail "plot paraview $1: not a real picture"
import sys
from PIL import Image
img = Image.open(sys.argv[1]).convert("RGB")
w, h = img.size
colours = img.getcolors(maxcolors=w * h)
top = max(n for n, _ in colours)
vivid = sum(n for n, c in colours if max(c) - min(c) > 60)  # the colour map, not grey
ok = (w, h) == (1000, 700) and len(colours) > 16 and top < 0.99 * w * h and vivid > 0.001 * w * h
print(f"{sys.argv[1]}: {w} x {h}, {len(colours)} colours, largest {top / (w * h):.0%}, "
      f"coloured {vivid / (w * h):.1%}")
sys.exit(0 if ok else 1)
PY
}
render 2d "$work/2d" pressure
render 3d "$work/3d" velocity

[ $failures -eq 0 ] && echo "paraview snapshots: all checks passed"
exit $((failures > 0))
