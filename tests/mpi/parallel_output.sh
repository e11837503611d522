#!/usr/bin/env bash
# Snapshots and checkpoints are written by every rank (its slice, through MPI-IO) and hold the
# same datasets for any rank layout:
#  - the 2-D dam break on 1, 2 and 3 ranks (the balancer moving the cuts every 25 steps) writes
#    byte-identical snapshots and .xmf (cmp), and checkpoints whose every dataset and every
#    attribute but `ranks` and `wall_seconds` (the writer's layout and wall clock) are
#    identical (h5diff, h5dump);
#  - the run's totals in summary.json (particle counts, fluid mass, the neighbour census at
#    the start and the end), which no rank gathers any more, are the same on 1, 2 and 3 ranks,
#    also on a periodic case (Poiseuille flow);
#  - the 3-rank run's last checkpoint, continued on 2 ranks (each rank reads an even share and
#    sends it to its owners), rewrites the snapshots after the checkpoint (every field,
#    acceleration, mass and the fluid's spacing included) byte-identical to the
#    uninterrupted runs'. The spacing field and attributes come from a census that the owner
#    of each cell takes and sends back to the particles' holders (spacing_census.hpp).
# Usage: parallel_output.sh SLUICE_EXE SOURCE_DIR MPIEXEC
set -u
source "$(dirname "${BASH_SOURCE[0]}")/lib/script_args.sh"

case_file="$src/cases/dam_break_2d.toml"
sets=(--set particles.dx=0.02 --set time.end_time=0.1 --set time.output_interval=0.025
      --set runtime.rebalance_every=25 --set checkpoint.every_steps=50
      --set 'output.fields=["position","velocity","acceleration","density","pressure","mass","id","kind","spacing"]'
      --threads 1 --quiet)

run() { # ranks args...
    local ranks=$1
    shift
    SLUICE_TIMEOUT=120 sluice_on "$ranks" run "$case_file" "$@" "${sets[@]}"
}

particle_sets=(id kind x x_ref v v_half a rho mass p probe_next probe_bytes snapshot_time
               snapshot_particles)
layout_free_attributes=(format format_version case_fingerprint dimension sluice_version time
                        step dt dt_prev u_max limit_acoustic limit_viscous limit_force out_next
                        last_output_time)

same_checkpoint() { # a.h5 b.h5 label
    local a=$1 b=$2 label=$3 before=$failures
    for s in "${particle_sets[@]}"; do
        h5diff -q "$a" "$b" "/$s" "/$s" >/dev/null 2>&1 || fail "$label: dataset $s differs"
    done
    for at in "${layout_free_attributes[@]}"; do
        [ "$(h5dump -a "/$at" "$a" | tail -n +2)" == "$(h5dump -a "/$at" "$b" | tail -n +2)" ] ||
            fail "$label: attribute $at differs"
    done
    [ $failures -eq "$before" ] && echo "ok $label"
}

totals() { # summary.json: the layout-independent totals, one line
    /usr/bin/python3 -c 'import json, sys
j = json.load(open(sys.argv[1]))
print([j[k] for k in ("particles", "fluid_particles", "mass_initial", "mass_final")],
      j["extra"]["neighbours"])' "$1"
}

same_totals() { # a.json b.json label
    local a b
    a=$(totals "$1") b=$(totals "$2")
    [[ -n $a && $a == "$b" ]] || fail "$3: summary totals differ: $a / $b"
    [[ $a == *fluid_fluid* ]] || fail "$3: no census in $a"
    [[ $a == *fluid_crowded* && $a == *closest_fluid_pair* ]] || fail "$3: no spacing in $a"
}

same_snapshots() { # dir label
    local dir=$1 label=$2 n=0 before=$failures
    for f in "$work/r1"/snapshots/*.h5; do
        cmp -s "$f" "$dir/snapshots/$(basename "$f")" || fail "$label: $(basename "$f") differs"
        n=$((n + 1))
    done
    [ "$n" -ge 4 ] || fail "$label: only $n snapshots"
    [ "$(ls "$dir"/snapshots/*.h5 | wc -l)" -eq "$n" ] || fail "$label: snapshot count differs"
    cmp -s "$work/r1/snapshots.xmf" "$dir/snapshots.xmf" || fail "$label: snapshots.xmf differs"
    diff -r "$work/r1/probes" "$dir/probes" >/dev/null || fail "$label: probe CSVs differ"
    [ $failures -eq "$before" ] && echo "ok $label: $n snapshots, xmf and probes identical to 1 rank"
}

for r in 1 2 3; do
    run $r --out "$work/r$r" || fail "run on $r ranks: exit $?"
done
[ -f "$work/r1/checkpoint.h5" ] || fail "the 1-rank run wrote no checkpoint"
for r in 2 3; do
    same_snapshots "$work/r$r" "$r ranks"
    same_checkpoint "$work/r1/checkpoint.h5" "$work/r$r/checkpoint.h5" \
        "$r ranks: checkpoint datasets and attributes identical to 1 rank's"
done
for r in 2 3; do
    same_totals "$work/r1/summary.json" "$work/r$r/summary.json" "$r ranks"
done
"$exe" run "$src/cases/poiseuille_2d.toml" --out "$work/p1" --set time.end_time=0.01 -q ||
    fail "Poiseuille on 1 rank: exit $?"
"$mpiexec" --oversubscribe -np 3 "$exe" run "$src/cases/poiseuille_2d.toml" --out "$work/p3" \
    --set time.end_time=0.01 -q || fail "Poiseuille on 3 ranks: exit $?"
same_totals "$work/p1/summary.json" "$work/p3/summary.json" "Poiseuille (periodic), 3 ranks"
[ $failures -eq 0 ] && echo "ok summary totals and neighbour census identical on 1, 2, 3 ranks"

# The writer's layout is recorded, and is the only other difference.
h5dump -a /ranks "$work/r3/checkpoint.h5" | grep -q "(0): 3" || fail "ranks attribute is not 3"

# The 3-rank checkpoint (at step 50 k, before the end) continued on 2 ranks.
step_of() { h5dump -a /step "$1" | sed -n 's/.*(0): \([0-9]*\).*/\1/p'; }
cp -r "$work/r3" "$work/c"
from=$(step_of "$work/c/checkpoint.h5")
run 2 --restart "$work/c" || fail "restart of the 3-rank checkpoint on 2 ranks: exit $?"
grep -q "\"restarted_from_step\": $from" "$work/c/summary.json" ||
    fail "the restart did not start at the checkpoint's step $from"
same_snapshots "$work/c" "3 ranks continued on 2 from step $from"

if [ $failures -eq 0 ]; then echo "parallel_output (MPI): all checks passed"; fi
exit $failures
