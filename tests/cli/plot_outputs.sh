#!/usr/bin/env bash
# scripts/plot on a short real run: `probes`, `history`, `snapshot` and `timeline` each write
# PNG files that are real pictures (at least 300 x 100 pixels, more than 16 colours, no colour
# covering 99 % of the image), not an empty canvas. Skipped (exit code 77) where Debian's
# python3 lacks matplotlib, h5py, numpy or PIL. Usage: plot_outputs.sh <sluice exe> <source dir>
set -u
exe=$(realpath "$1")
src=$(realpath "$2")
py=/usr/bin/python3
if ! "$py" -c "import matplotlib, h5py, numpy, PIL" 2>/dev/null; then
    echo "SKIP: $py lacks matplotlib, h5py, numpy or PIL (python3-matplotlib, python3-h5py)"
    exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

out="$work/out"
"$exe" run "$src/cases/dam_break_2d.toml" --out "$out" --threads 2 --quiet \
    --set time.end_time=0.02 --set time.output_interval=0.01 --trace "$work/trace.json" ||
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
plot timeline timeline "$work/trace.json"

[ $failures -eq 0 ] && echo "plot outputs: all checks passed"
exit $((failures > 0))
