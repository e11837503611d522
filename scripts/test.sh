#!/usr/bin/env bash
# The README's test command: set up a fresh Debian 12 machine, build in Release and run the
# whole test suite with ctest. Extra arguments go to ctest (e.g. -L unit).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/setup.sh" release
cd "$here"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ctest --preset release "$@"
