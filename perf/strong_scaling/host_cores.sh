#!/usr/bin/env bash
# Do this machine's cores run at the same speed? Runs one case twice at the same time, each
# process with one thread and pinned to a core of its own (no MPI: the two runs never talk),
# with --trace, then core_speed.py --independent on the two traces: the ratio of the two runs'
# step times at each moment is the ratio of the cores' speeds, and the "speed bound" is the
# parallel efficiency a static split of work between these two cores could reach if
# communication cost nothing (README.md, "The host's cores").
#
# Usage: perf/strong_scaling/host_cores.sh [--case CASE.toml] [--cores "A B"] [--set KEY=VALUE ...]
#                                          [--out DIR]
#   --case   default perf/cases/dam_break_2d_200k.toml with time.end_time=0.004 (161 steps)
#   --cores  the two CPUs (default: the first two this process may run on)
#   --set    case override (repeatable; replaces the default end time when given)
#   --out    folder for the two runs and traces (default: a temporary folder, removed)
# Environment: SLUICE (default build/release/sluice).
set -euo pipefail

usage() { sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
sluice="${SLUICE:-$root/build/release/sluice}"
case_file="$root/perf/cases/dam_break_2d_200k.toml"
cores=""
out=""
sets=()

while [[ $# -gt 0 ]]; do
    case "$1" in
        --case) case_file="${2:?--case needs a file}"; shift 2 ;;
        --cores) cores="${2:?--cores needs two CPU numbers}"; shift 2 ;;
        --set) sets+=(--set "${2:?--set needs KEY=VALUE}"); shift 2 ;;
        --out) out="${2:?--out needs a folder}"; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "host_cores.sh: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
    esac
done
[[ ${#sets[@]} -gt 0 ]] || sets=(--set time.end_time=0.004)
[[ -x "$sluice" ]] || { echo "host_cores.sh: no sluice binary at $sluice (set SLUICE)" >&2; exit 2; }
if [[ -z "$cores" ]]; then
    # The CPUs of this process's affinity list, in order ("0-1" or "0,2,5-7").
    list="$(taskset -pc $$ | sed 's/.*: //')"
    cpus=()
    IFS=, read -ra parts <<<"$list"
    for p in "${parts[@]}"; do
        if [[ "$p" == *-* ]]; then cpus+=($(seq "${p%-*}" "${p#*-}")); else cpus+=("$p"); fi
    done
    [[ ${#cpus[@]} -ge 2 ]] || { echo "host_cores.sh: needs two CPUs, has ${cpus[*]}" >&2; exit 2; }
    cores="${cpus[0]} ${cpus[1]}"
fi
read -r cpu_a cpu_b <<<"$cores"
if [[ -z "$out" ]]; then
    out="$(mktemp -d)"
    trap 'rm -rf "$out"' EXIT
fi
mkdir -p "$out"

echo "host_cores.sh: $(basename "$case_file") on CPUs $cpu_a and $cpu_b at once, $(date -u +%H:%M:%S) UTC, load $(cut -d' ' -f1 /proc/loadavg)"
taskset -c "$cpu_a" "$sluice" run "$case_file" --threads 1 -q "${sets[@]}" \
    --out "$out/a" --trace "$out/a.json" &
pid_a=$!
taskset -c "$cpu_b" "$sluice" run "$case_file" --threads 1 -q "${sets[@]}" \
    --out "$out/b" --trace "$out/b.json" &
pid_b=$!
wait "$pid_a"
wait "$pid_b"
"$here/core_speed.py" --independent "$out/a.json" "$out/b.json"
