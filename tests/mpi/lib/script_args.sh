# Sourced by every tests/mpi/*.sh script after its own `set` options: the common arguments
# and scratch folder of tests/lib/script_args.sh, then the third argument every MPI script
# takes (MPIEXEC) as $mpiexec, Open MPI allowed to run as root (CI runs as root), and
# sluice_on (below). It lives in lib/ because CMake registers every tests/mpi/*.sh as a test.
source "$(dirname "${BASH_SOURCE[0]}")/../../lib/script_args.sh"
mpiexec=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# sluice_on RANKS ARGS...: `sluice ARGS` on RANKS ranks, without a launcher on one (as a user
# runs it), under `timeout $SLUICE_TIMEOUT` when that is set.
sluice_on() {
    local ranks=$1
    shift
    local limit=()
    [[ -n ${SLUICE_TIMEOUT:-} ]] && limit=(timeout "$SLUICE_TIMEOUT")
    if [[ $ranks == 1 ]]; then
        "${limit[@]}" "$exe" "$@"
    else
        "${limit[@]}" "$mpiexec" --oversubscribe -np "$ranks" "$exe" "$@"
    fi
}
