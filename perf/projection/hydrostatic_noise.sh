#!/usr/bin/env bash
# Park et al.'s (2014) hydrostatic tank for the full 5 s with both schemes: cases/hydrostatic_2d.toml
# (WCSPH) and cases/projection_hydrostatic_2d.toml (projection). Prints, per scheme, the mean
# bottom-centre pressure after 1 s against rho g (H - y_probe), its temporal noise (standard
# deviation after 1 s), the worst sample, the wall time and ms per step, and for the
# projection run the pressure solver's iterations and residual (from its rank log). Probe
# samples every 0.01 s.
# Usage: perf/projection/hydrostatic_noise.sh [--threads N] [--end T] [--no-wcsph] [--nice N]
#            [--set KEY=VALUE]...   (--set: passed to the projection run only, e.g.
#                                    --set projection.tolerance=1e-5)
# --nice: the runs' niceness (default 0; a niced run on a loaded machine got ~3 % of a core).
# The figures (pressure statistics) do not depend on the machine's load; the times do.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
exe=$root/build/release/sluice
threads=1
end=5.0
wcsph=1
niceness=0
proj_sets=()
while [[ $# -gt 0 ]]; do
    case $1 in
    --threads) threads=$2; shift 2 ;;
    --end) end=$2; shift 2 ;;
    --no-wcsph) wcsph=0; shift ;;
    --nice) niceness=$2; shift 2 ;;
    --set) proj_sets+=(--set "$2"); shift 2 ;;
    *) echo "unknown argument $1"; exit 2 ;;
    esac
done
[[ -x $exe ]] || { echo "build the release binary first: cmake --build --preset release"; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cases=(projection_hydrostatic_2d)
[[ $wcsph == 1 ]] && cases=(hydrostatic_2d projection_hydrostatic_2d)
for c in "${cases[@]}"; do
    extra=()
    [[ $c == projection_hydrostatic_2d ]] && extra=("${proj_sets[@]}")
    /usr/bin/time -f "$c: CPU %U s user, %S s system" nice -n "$niceness" "$exe" run "$root/cases/$c.toml" \
        --out "$work/$c" --threads "$threads" -q --set time.end_time="$end" \
        --set time.output_interval=0.01 --set output.snapshots=false "${extra[@]}"
done
/usr/bin/python3 - "$work" <<'PY'
import json, os, re, sys
import numpy as np
work = sys.argv[1]
p_ref = 1000 * 9.81 * (0.4 - 0.02)
print(f"bottom-centre probe, reference rho g (H - y) = {p_ref:.1f} Pa; statistics after 1 s")
for case, label in (("hydrostatic_2d", "WCSPH"), ("projection_hydrostatic_2d", "projection")):
    if not os.path.exists(f"{work}/{case}/summary.json"):
        continue
    d = np.loadtxt(f"{work}/{case}/probes/p1_bottom_centre.csv", delimiter=",", skiprows=1)
    m = d[:, 0] >= 1.0
    p = d[m, 1]
    s = json.load(open(f"{work}/{case}/summary.json"))
    wall, steps = s.get("wall_seconds", float("nan")), s.get("steps", 0)
    line = (f"{label:10s} mean {p.mean():8.1f} Pa ({100 * (p.mean() / p_ref - 1):+.2f} %), "
            f"noise (std) {p.std():6.1f} Pa ({100 * p.std() / p_ref:.2f} %), worst "
            f"{100 * np.abs(p / p_ref - 1).max():.2f} %, lag-1 autocorrelation "
            f"{np.corrcoef(p[:-1], p[1:])[0, 1]:+.2f}, {steps} steps, {wall:.1f} s wall, "
            f"{1e3 * wall / max(steps, 1):.2f} ms/step")
    print(line)
    if case.startswith("projection"):
        log = open(f"{work}/{case}/logs/rank_0.log").read()
        m = re.search(r"pressure solves: .*", log)
        if m:
            print("           " + m.group(0))
PY
