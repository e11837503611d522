#!/usr/bin/env bash
# Builds the libFuzzer targets for the case reader and the shape readers (preset `fuzz`: clang
# 14, ASan + UBSan) and runs each for a bounded time: the case reader seeded with the shipped
# cases and the bad-case corpus, the shape readers (a third of the time) with the shipped
# meshes and vertex files, each behind its format byte (tests/fuzz/fuzz_mesh_reader.cpp).
# Usage: scripts/fuzz.sh [seconds (default 60)] [extra libFuzzer flags...]
# Exit code non-zero if libFuzzer finds a crash, a sanitizer report, a leak, a timeout (10 s
# on one input) or an input needing more than 2 GiB; the input is saved as
# build/fuzz/artifacts/crash-* (replay: build/fuzz/tests/fuzz/fuzz_case_reader FILE).
set -euo pipefail
seconds="${1:-60}"
shift || true
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
bash scripts/setup.sh fuzz fuzz_case_reader fuzz_mesh_reader

# Seeds: every valid and bad case file. New inputs libFuzzer finds go to a scratch corpus
# (kept between runs on one machine).
corpus=build/fuzz/corpus
seeds=build/fuzz/seeds
rm -rf "$seeds"
mkdir -p "$corpus" "$seeds" build/fuzz/artifacts
find cases tests/data -name '*.toml' -exec cp --backup=numbered -t "$seeds" {} +
echo "fuzz: running fuzz_case_reader for ${seconds} s on $(ls "$seeds" | wc -l) seeds"
# One worker process: CI machines have two cores, and the rest of CI shares them.
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    build/fuzz/tests/fuzz/fuzz_case_reader "$corpus" "$seeds" \
    -dict=tests/fuzz/case.dict -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix=build/fuzz/artifacts/ "$@"

mesh_corpus=build/fuzz/mesh_corpus
mesh_seeds=build/fuzz/mesh_seeds
rm -rf "$mesh_seeds"
mkdir -p "$mesh_corpus" "$mesh_seeds"
# Format byte: 0 STL, 1 OBJ, 2 PLY, 3 OFF, 4 vertex file (the target's kExt order).
i=0
for f in cases/meshes/*.stl cases/meshes/*.csv tests/data/mesh_loads/*.csv; do
    case "$f" in *.stl) b='\x00' ;; *) b='\x04' ;; esac
    { printf "$b"; head -c 200000 "$f"; } >"$mesh_seeds/seed_$((i++))"
done
echo "fuzz: running fuzz_mesh_reader for $((seconds / 3)) s on $(ls "$mesh_seeds" | wc -l) seeds"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    build/fuzz/tests/fuzz/fuzz_mesh_reader "$mesh_corpus" "$mesh_seeds" \
    -max_total_time="$((seconds / 3))" -timeout=10 -rss_limit_mb=2048 -max_len=262144 \
    -print_final_stats=1 -artifact_prefix=build/fuzz/artifacts/ "$@"
