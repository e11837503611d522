#!/usr/bin/env bash
# Strong scaling of sluice: one fixed case, run at several layouts RxT (R MPI ranks x T worker
# threads each), then perf/strong_scaling/plot.py tabulates and plots wall time, speed-up,
# parallel efficiency, overlap efficiency and load imbalance against cores = R*T.
#
# Usage: perf/strong_scaling/run.sh [--case CASE.toml] [--layouts "1x1 1x2 2x1 2x2 ..."]
#                                   [--set KEY=VALUE ...] [--out DIR] [--repeat N]
#   --case     case file (default perf/cases/dam_break_2d_200k.toml)
#   --layouts  space-separated RxT list (default "1x1 1x2 2x1"); 1x1 is the speed-up baseline
#   --set      case override passed on to `sluice run --set` (repeatable)
#   --out      results folder (default results/strong_scaling); layout RxT goes to OUT/RxT
#   --repeat   runs per layout (default 1); with N > 1 the run with the median wall time is kept
# Relative paths are taken from the directory the script is called from.
# Environment: MPIRUN (default mpirun), MPIRUN_FLAGS (default: "--map-by slot:PE=T --bind-to
# core", each rank pinned to T cores of its own, when R x T fits the cores; "--bind-to none"
# when it does not, since Open MPI would otherwise pin each rank to one core when np <= 2 and
# serialise its T threads).
set -euo pipefail

usage() { sed -n '2,17p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
caller_pwd="$PWD"
abspath() { case "$1" in /*) printf '%s\n' "$1" ;; *) printf '%s\n' "$caller_pwd/$1" ;; esac; }

case_file="$root/perf/cases/dam_break_2d_200k.toml"
layouts="1x1 1x2 2x1"
out="$root/results/strong_scaling"
repeat=1
sets=()

while [[ $# -gt 0 ]]; do
    case "$1" in
        --case) case_file="$(abspath "${2:?--case needs a file}")"; shift 2 ;;
        --layouts) layouts="${2:?--layouts needs a list}"; shift 2 ;;
        --set) sets+=(--set "${2:?--set needs KEY=VALUE}"); shift 2 ;;
        --out) out="$(abspath "${2:?--out needs a folder}")"; shift 2 ;;
        --repeat) repeat="${2:?--repeat needs a number}"; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) echo "run.sh: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
    esac
done

[[ -f "$case_file" ]] || { echo "run.sh: case file '$case_file' not found" >&2; exit 2; }
[[ "$repeat" =~ ^[1-9][0-9]*$ ]] || { echo "run.sh: --repeat must be a positive integer" >&2; exit 2; }
for l in $layouts; do
    [[ "$l" =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || { echo "run.sh: bad layout '$l' (want RxT, e.g. 2x4)" >&2; exit 2; }
done

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun_cmd="${MPIRUN:-mpirun}"

cd "$root"
sluice="$root/build/release/sluice"
if [[ ! -x "$sluice" ]]; then
    echo "== building the Release binary (cmake --preset release) =="
    cmake --preset release
    cmake --build --preset release -j2
fi

mkdir -p "$out"
echo "== strong scaling: $case_file"
echo "   layouts: $layouts; repeat: $repeat; out: $out; host cores: $(nproc)"
if [[ ${#sets[@]} -gt 0 ]]; then echo "   overrides: ${sets[*]}"; fi

# One run of layout R x T into folder $3.
run_one() {
    local r="$1" t="$2" dir="$3"
    local cmd=("$sluice" run "$case_file" --threads "$t" --out "$dir" -q)
    if [[ "$r" -gt 1 ]]; then
        local flags
        if [[ -n "${MPIRUN_FLAGS+set}" ]]; then
            flags="$MPIRUN_FLAGS"
        elif [[ $((r * t)) -le "$(nproc)" ]]; then
            # 16 ranks x 1 thread on 16 cores: 8.81 s unbound, 4.85 s pinned (perf/strong_scaling).
            flags="--map-by slot:PE=$t --bind-to core"
        else
            flags="--bind-to none"
        fi
        local -a mpirun_flags
        read -r -a mpirun_flags <<< "$flags"
        cmd=("$mpirun_cmd" --oversubscribe "${mpirun_flags[@]}" -np "$r" "${cmd[@]}")
    fi
    if [[ ${#sets[@]} -gt 0 ]]; then cmd+=("${sets[@]}"); fi
    echo "   \$ ${cmd[*]}"
    "${cmd[@]}"
}

wall_of() { /usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["wall_seconds"])' "$1"; }

failed=()
done_layouts=()
for l in $layouts; do
    r="${l%x*}"; t="${l#*x}"
    dir="$out/$l"
    rm -rf "$dir"
    echo "-- layout $l ($r rank(s) x $t thread(s) = $((r * t)) cores)"
    if [[ "$repeat" -eq 1 ]]; then
        if run_one "$r" "$t" "$dir" && [[ -f "$dir/summary.json" ]]; then
            echo "   wall $(wall_of "$dir/summary.json") s"
            done_layouts+=("$l")
        else
            echo "   layout $l FAILED" >&2; failed+=("$l")
        fi
        continue
    fi
    ok=1
    for k in $(seq 1 "$repeat"); do
        if run_one "$r" "$t" "$dir/repeat_$k" && [[ -f "$dir/repeat_$k/summary.json" ]]; then
            echo "   repeat $k: wall $(wall_of "$dir/repeat_$k/summary.json") s"
        else
            ok=0; break
        fi
    done
    if [[ "$ok" -eq 0 ]]; then
        echo "   layout $l FAILED" >&2; failed+=("$l"); continue
    fi
    # Keep the median run (the lower median for even N): its summary.json becomes OUT/RxT's,
    # with the wall times of all repeats added as "repeat_wall_seconds".
    /usr/bin/python3 - "$dir" "$repeat" <<'PY'
import json, sys
d, n = sys.argv[1], int(sys.argv[2])
runs = []
for k in range(1, n + 1):
    with open(f"{d}/repeat_{k}/summary.json") as f:
        runs.append((json.load(f)["wall_seconds"], k))
walls = [w for w, _ in runs]
w, k = sorted(runs)[(n - 1) // 2]
with open(f"{d}/repeat_{k}/summary.json") as f:
    s = json.load(f)
s["repeat_wall_seconds"] = walls
s["median_of_repeat"] = k
with open(f"{d}/summary.json", "w") as f:
    json.dump(s, f, indent=2)
print(f"   median wall {w:.4g} s (repeat {k}; all: {', '.join(f'{x:.4g}' for x in walls)})")
PY
    done_layouts+=("$l")
done

if [[ ${#done_layouts[@]} -gt 0 ]]; then
    /usr/bin/python3 "$here/plot.py" "$out" --layouts "${done_layouts[*]}"
fi
if [[ ${#failed[@]} -gt 0 ]]; then
    echo "run.sh: failed layouts: ${failed[*]}" >&2
    exit 1
fi
