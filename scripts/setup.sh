#!/usr/bin/env bash
# Installs the Debian 12 packages sluice needs (as root, no prompts) and configures + builds
# the given CMake preset (default: release): every target, or only the targets named after
# it. Idempotent: packages already present are skipped and an existing build directory is
# reused. Usage: setup.sh [PRESET [TARGET...]]
# SLUICE_WITH_PARAVIEW=1 also installs ParaView 5.11, its Python and xvfb (about 85 MB to
# download, 770 MB installed): what tests/cli/paraview_snapshots.sh and `scripts/plot paraview`
# need; CI's release stage sets it, the normal set-up leaves it out.
set -euo pipefail
preset="${1:-release}"
shift || true
targets=("$@")
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

packages=(build-essential cmake ninja-build pkg-config git
          libopenmpi-dev openmpi-bin libtbb-dev libeigen3-dev
          libhdf5-openmpi-dev hdf5-tools doctest-dev libtomlplusplus-dev libcli11-dev
          libspdlog-dev libfmt-dev nlohmann-json3-dev libqhull-dev libssl-dev libcgal-dev libbullet-dev procps python3 python3-numpy python3-matplotlib python3-h5py python3-pil
          python3-scipy bsdutils)
# The fuzzer needs clang and its runtime (libFuzzer); other presets build with GCC.
[ "$preset" != fuzz ] || packages+=(clang-14 libclang-rt-14-dev)
[ "${SLUICE_WITH_PARAVIEW:-0}" != 1 ] || packages+=(paraview python3-paraview xvfb xauth)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
    echo "setup: installing ${missing[*]}"
    sudo_cmd=()
    [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
    export DEBIAN_FRONTEND=noninteractive
    "${sudo_cmd[@]}" apt-get update -qq
    "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cd "$here"
cmake --preset "$preset" >/dev/null
if ((${#targets[@]})); then
    cmake --build --preset "$preset" -j "$(nproc)" --target "${targets[@]}"
else
    cmake --build --preset "$preset" -j "$(nproc)"
fi
