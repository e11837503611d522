#!/usr/bin/env bash
# Packs the Release binaries with every shared library they need except glibc, and a copy of
# Debian's Open MPI, into one folder that runs on another x86-64 Linux machine without this
# project's Debian packages (glibc 2.36 or newer there). Used for the 16-core strong-scaling
# runs in perf/strong_scaling/README.md ("16 cores"), on an Ubuntu 24.04 machine.
#
# Usage: scripts/portable_bundle.sh OUT_DIR      (after cmake --build --preset release;
#                                                 the float binary is added when it is built)
# On the other machine, from the repository root (which must hold perf/ and cases/):
#   source OUT_DIR/env.sh        # PATH, LD_LIBRARY_PATH, OPAL_PREFIX, MPIRUN=orterun
#   perf/strong_scaling/run.sh ...
# env.sh copies the binaries to build/release/sluice (and build/release-float/sluice), where
# the perf scripts look for them.
set -euo pipefail
out=${1:?usage: scripts/portable_bundle.sh OUT_DIR}
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
multiarch=/usr/lib/x86_64-linux-gnu
[[ -x "$root/build/release/sluice" ]] || { echo "build/release/sluice missing: build first" >&2; exit 2; }
rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/ompi/usr/lib/x86_64-linux-gnu" "$out/ompi/usr/share" "$out/ompi/usr/bin"
cp "$root/build/release/sluice" "$out/bin/sluice"
[[ -x "$root/build/release-float/sluice" ]] && cp "$root/build/release-float/sluice" "$out/bin/sluice-float"
# Open MPI keeps its components and help files under its prefix; OPAL_PREFIX relocates them.
# orted is needed even by a single process (the singleton start forks it).
cp -a "$multiarch/openmpi" "$out/ompi/usr/lib/x86_64-linux-gnu/"
rm -rf "$out/ompi/usr/lib/x86_64-linux-gnu/openmpi/include"
cp -a /usr/share/openmpi "$out/ompi/usr/share/"
cp /usr/bin/orterun /usr/bin/orted "$out/ompi/usr/bin/"
objects=("$out"/bin/* /usr/bin/orterun /usr/bin/orted)
while IFS= read -r f; do objects+=("$f"); done < <(find "$multiarch/openmpi" -name '*.so*' -type f)
for o in "${objects[@]}"; do ldd "$o" 2>/dev/null | awk '$3 ~ /^\// {print $3}'; done | sort -u |
    while read -r lib; do
        case "$(basename "$lib")" in
        # glibc stays the other machine's own: its loader and libc must match each other.
        libc.so* | libm.so* | libpthread.so* | libdl.so* | librt.so* | ld-linux* | libresolv.so* | \
            libutil.so* | libmvec.so*) continue ;;
        esac
        case "$lib" in "$multiarch/openmpi/"*) continue ;; esac
        cp -L "$lib" "$out/lib/$(basename "$lib")"
    done
cat > "$out/env.sh" <<'ENV'
# Source from the repository root on the target machine.
_b="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export LD_LIBRARY_PATH="$_b/lib:$_b/ompi/usr/lib/x86_64-linux-gnu/openmpi/lib"
export OPAL_PREFIX="$_b/ompi/usr" PATH="$_b/ompi/usr/bin:$PATH" MPIRUN=orterun
mkdir -p build/release && cp "$_b/bin/sluice" build/release/sluice
if [[ -x "$_b/bin/sluice-float" ]]; then
    mkdir -p build/release-float && cp "$_b/bin/sluice-float" build/release-float/sluice
fi
unset _b
ENV
echo "bundle in $out: $(du -sh "$out" | cut -f1), $(ls "$out/lib" | wc -l) libraries"
