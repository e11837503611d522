#!/usr/bin/env bash
# Yeh & Petroff bore on a square column (perf/impact/yeh_petroff_3d.toml): one sluice run and
# its force on the column against the experiment (yeh_petroff.py prints it, PNG beside the run).
# Usage: perf/impact/yeh_petroff.sh [--dx DX] [--dry] [--projection] [--end T] [--threads N]
#                                   [--out DIR] [--sluice PATH] [--set KEY=VALUE ...]
#   --dry   leave out the 1 cm wet bed (needed for dx > 0.01 m, which cannot hold it); the
#           surge then runs over a dry floor: say so when quoting the result.
#   --projection  the projection scheme (the case without its WCSPH-only keys; the column's
#           force probe integrates the interpolated pressure over the column's faces).
# Cost on the 2-core development machine: dx = 0.02 m dry, 0.9 s: ~6 min on 1 thread;
# dx = 0.01 m with the wet bed (224k particles), 0.75 s: 25 min on 2 threads (5d69565);
# --projection --dry: dx = 0.015 m, 0.9 s: 28 min on 1 thread; dx = 0.01 m, 0.8 s: 61 min on 2
# threads (274d72b).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
dx=0.01 dry=0 projection=0 end=0.75 threads=2 out="$root/results/yeh_petroff" sluice="$root/build/release/sluice"
sets=()
while (($#)); do
    case "$1" in
    --dx) dx=$2; shift 2 ;;
    --dry) dry=1; shift ;;
    --projection) projection=1; shift ;;
    --end) end=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --sluice) sluice=$2; shift 2 ;;
    --set) sets+=(--set "$2"); shift 2 ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "yeh_petroff.sh: unknown argument $1" >&2; exit 2 ;;
    esac
done
case_file="$here/yeh_petroff_3d.toml"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
if ((projection)); then
    # perf/lib/sluice_run.py: projection_case drops the keys the projection scheme refuses.
    case_file="$(/usr/bin/python3 - "$sluice" "$case_file" "$tmp" <<'PY'
import sys
from pathlib import Path
sys.path.insert(0, str(Path(sys.argv[2]).resolve().parents[1] / "lib"))
import sluice_run
print(sluice_run.projection_case(Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])))
PY
)"
    sets+=(--set 'numerics.scheme="projection"')
fi
if ((dry)); then
    # The case without its wet-bed blocks (blocks 1..4): only the reservoir stays.
    /usr/bin/python3 - "$case_file" "$tmp/yeh_petroff_dry.toml" <<'PY'
import sys
text = open(sys.argv[1]).read()
parts = text.split("[[blocks]]")
rest = parts[-1][parts[-1].index("[numerics]"):]
open(sys.argv[2], "w").write(parts[0] + "[[blocks]]" + parts[1] + rest)
PY
    case_file="$tmp/yeh_petroff_dry.toml"
fi
"$sluice" run "$case_file" --threads "$threads" -q --out "$out" \
    --set particles.dx="$dx" --set time.end_time="$end" "${sets[@]}"
/usr/bin/python3 "$here/yeh_petroff.py" "$out" --png "$out/yeh_petroff_force.png"
