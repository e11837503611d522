# Sourced by every tests/mpi/*.sh script after its own `set` options: the common arguments
# and scratch folder of tests/lib/script_args.sh, then the third argument every MPI script
# takes (MPIEXEC) as $mpiexec, and Open MPI allowed to run as root (CI runs as root). It lives
# in lib/ because CMake registers every tests/mpi/*.sh as a test.
source "$(dirname "${BASH_SOURCE[0]}")/../../lib/script_args.sh"
mpiexec=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
