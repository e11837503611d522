#!/usr/bin/env bash
# The README's main job: set up a fresh Debian 12 machine, build in Release and run the default
# case end to end. Results land in results/dam_break_2d/.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/setup.sh" release
cd "$here"
./build/release/sluice run cases/dam_break_2d.toml --out results/dam_break_2d "$@"
