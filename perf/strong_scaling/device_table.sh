#!/usr/bin/env bash
# The 16-core strong-scaling table in one short run: the 2-D 232k-particle dam break
# (perf/cases/dam_break_2d_200k.toml) and the 3-D peer dam break with an obstacle
# (perf/cases/dam_break_3d_obstacle.toml), each at the layouts 1x1 1x16 2x8 4x4 16x1, 0.005 s
# of simulated time (201 and 58 steps), no snapshots. Writes OUT/2d/ and OUT/3d/ (run.sh's
# folders, scaling.csv, scaling.png) and prints each table beside the committed 16-core table
# (results/*_16core.csv) and, where present, a predicted table (results/*_prediction.csv).
#
# On the development machine, pack the Release build with its libraries (about 60 MiB) into
# build/bundle, which a machine without this project's packages can run:
#   perf/strong_scaling/device_table.sh --pack
# On the 16-core machine, from the repository root (build/bundle carried there):
#   perf/strong_scaling/device_table.sh --out DIR [--budget SECONDS] [--end-time T]
# A machine with the packages installed needs no bundle: build/release/sluice is used (built
# with -j$(nproc) if missing). --budget (default 420 s) skips the layouts that would start
# after it, so the script stays inside a lease; the 3-D sweep starts only if the 2-D one left
# more than a third of it.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
out="$root/results/device_table"
budget=420
end_time=0.005
layouts="1x1 1x16 2x8 4x4 16x1"
while [[ $# -gt 0 ]]; do
    case "$1" in
        --pack) bash "$root/scripts/portable_bundle.sh" "$root/build/bundle"
                du -sh "$root/build/bundle"; exit 0 ;;
        --out) out="${2:?--out needs a folder}"; shift 2 ;;
        --budget) budget="${2:?--budget needs seconds}"; shift 2 ;;
        --end-time) end_time="${2:?--end-time needs seconds}"; shift 2 ;;
        --layouts) layouts="${2:?--layouts needs a list}"; shift 2 ;;
        -h|--help) sed -n '2,18p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "device_table.sh: unknown argument '$1'" >&2; exit 2 ;;
    esac
done
[[ "$out" = /* ]] || out="$PWD/$out"
cd "$root"
if [[ -f build/bundle/env.sh ]] && ! ldd build/release/sluice >/dev/null 2>&1; then
    # shellcheck disable=SC1091
    source build/bundle/env.sh
elif [[ ! -x build/release/sluice ]]; then
    cmake --preset release && cmake --build --preset release --target sluice -j"$(nproc)"
fi
mkdir -p "$out"
{ echo "host: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
  echo "binary: $(build/release/sluice --version 2>&1 | head -1)"; date -u; } | tee "$out/host.txt"

start=$SECONDS
sweep() { # name case reference-csv
    local name="$1" case_file="$2" ref="$3" todo=()
    for l in $layouts; do
        if (( SECONDS - start < budget )); then todo+=("$l"); else echo "   $name $l skipped (budget)"; fi
    done
    [[ ${#todo[@]} -gt 0 ]] || return 0
    # One layout per run.sh call, so that the budget is checked between layouts.
    for l in "${todo[@]}"; do
        (( SECONDS - start < budget )) || { echo "   $name $l skipped (budget)"; continue; }
        local left=$(( budget - (SECONDS - start) + 60 ))
        timeout "$left" "$here/run.sh" --case "$case_file" --layouts "$l" --out "$out/$name" \
            --set time.end_time="$end_time" || echo "   $name $l failed or timed out"
    done
    /usr/bin/python3 "$here/plot.py" "$out/$name" >/dev/null || true
    local pred="${ref%_16core.csv}_prediction.csv"
    /usr/bin/python3 "$here/compare_tables.py" "$out/$name/scaling.csv" "$ref" \
        $([[ -f "$pred" ]] && echo "$pred") | tee "$out/$name/comparison.txt"
}
sweep 2d perf/cases/dam_break_2d_200k.toml "$here/results/dam_break_2d_200k_16core.csv"
if (( SECONDS - start < budget * 2 / 3 )); then
    sweep 3d perf/cases/dam_break_3d_obstacle.toml "$here/results/dam_break_3d_obstacle_16core.csv"
else
    echo "3-D sweep skipped: the 2-D sweep used $((SECONDS - start)) s of the ${budget} s budget"
fi
echo "device_table.sh: $((SECONDS - start)) s; results in $out"
