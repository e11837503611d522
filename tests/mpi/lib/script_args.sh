# Sourced by every tests/mpi/*.sh script after its own `set` options: the three arguments they
# all take (SLUICE_EXE SOURCE_DIR MPIEXEC) as exe, src and mpiexec, Open MPI allowed to run as
# root (CI runs as root), and a scratch folder $work removed on exit. It lives in lib/ because
# CMake registers every tests/mpi/*.sh as a test.
exe=$(realpath "$1")
src=$(realpath "$2")
mpiexec=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
