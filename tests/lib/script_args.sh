# Sourced by the shell tests (tests/cli/*.sh, tests/mpi/*.sh) after their own `set` options:
# the arguments they all start with (SLUICE_EXE SOURCE_DIR) as absolute paths $exe and $src,
# a scratch folder $work removed on exit, and fail(), which reports and counts a failure in
# $failures (a script ends with `exit $failures`). It lives in tests/lib/ because CMake
# registers every tests/cli/*.sh and tests/mpi/*.sh as a test.
exe=$(realpath "$1")
src=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
