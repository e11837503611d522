#!/usr/bin/env bash
# Are two sluice binaries' results byte-identical? Runs the default case (cases/dam_break_2d.toml:
# 2 threads to 0.3 s, and 2 ranks to 0.2 s) and the 3-D peer case
# (perf/cases/dam_break_3d_obstacle.toml with snapshots, to 0.03 s) with each binary and compares
# every snapshot (.h5) and probe file (.csv) with cmp. This is the check a change that must not
# alter results (a refactor, a faster loop) is held to: byte-identical outputs before and
# after. Prints one line per run and exits 1 if any file differs or is missing.
# Usage: scripts/same_outputs.sh SLUICE_BEFORE SLUICE_AFTER [WORK_DIR]
set -uo pipefail
[[ $# -ge 2 ]] || { echo "usage: $0 SLUICE_BEFORE SLUICE_AFTER [WORK_DIR]" >&2; exit 2; }
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
before=$(realpath "$1")
after=$(realpath "$2")
work=${3:-$(mktemp -d)}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
status=0

runs=(
    "db_2threads|1|cases/dam_break_2d.toml --threads 2 --set time.end_time=0.3"
    "db_2ranks|2|cases/dam_break_2d.toml --threads 1 --set time.end_time=0.2"
    "obstacle_3d|1|perf/cases/dam_break_3d_obstacle.toml --threads 2 --set time.end_time=0.03 --set output.snapshots=true --set time.output_interval=0.01"
)
for entry in "${runs[@]}"; do
    IFS='|' read -r name ranks args <<<"$entry"
    for side in before after; do
        bin=$before
        [[ $side == after ]] && bin=$after
        launch=("$bin")
        ((ranks > 1)) && launch=(mpirun --oversubscribe -np "$ranks" "$bin")
        # shellcheck disable=SC2086 # $args is a list of words
        (cd "$here" && "${launch[@]}" run $args --out "$work/$name/$side" -q) ||
            { echo "$name: the $side binary failed"; status=1; continue 2; }
    done
    n=0
    bad=0
    while IFS= read -r f; do
        n=$((n + 1))
        cmp -s "$work/$name/before/$f" "$work/$name/after/$f" ||
            { bad=$((bad + 1)); echo "  differs: $name/$f"; }
    done < <(cd "$work/$name/before" && find . -type f \( -name '*.h5' -o -name '*.csv' \) | sort)
    ((n > 0)) || { echo "$name: no output files"; status=1; }
    ((bad == 0)) || status=1
    echo "$name: $n files compared, $bad differ"
done
exit $status
