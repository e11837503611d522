#!/usr/bin/env bash
# Fails (exit 1) when the product's own text speaks of how it was developed instead of what it
# does: work sessions, stops, tracker issues, the people and processes behind a change, a source
# paper named by its file number instead of its authors. Prints file:line:text for each hit.
#
# Checked: README.md, CMakeLists.txt files, cmake/, docs/, perf/ (its documents, perf/**/*.md,
# and its scripts, benchmark sources and case files), cases/, include/, src/, tasks/, scripts/,
# tests/ and .ci/ (tracked text files). Not checked: data (csv, h5, stl, obj, ply, off, png, svg,
# json, vtu, log, other txt, patch), tests/data/ (generated corpora that only hold data),
# perf/**/results/ (the measurement records: tables, logs and the runs' own files), this script
# itself.
#
# Usage: scripts/check_product_text.sh [file...]   (default: every checked file of the repository)
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# The patterns (Perl regular expressions, matched by grep -P), each with what it catches.
patterns=(
    '\b[Ss]essions?\b'                  # "session 45", "(session 35)", "this session's binary"
    '\b[Ss]tops? [0-9]+'                # "stop 33's run"
    '\b[Ii]ssues? #?[0-9]+'             # "issue 18", "issue #22", "issues 5 and 22"
    "\\b[Tt]he (foundation )?issue('s)?\\b|\\bissue's\\b|\\bissue-[0-9]" # "the issue's criterion", "issue-5 runs"
    '\b[Tt]he lead\b(?! (time|edge|term|order|coefficient))' # "the lead re-measures" (not "the lead time")
    '\(lead[,)]'                        # "(lead, ...)"
    '\bagents?\b'                       # "other agents", "agent sessions"
    '\bheld[- ]back (data|set|cases?|results?|runs?|measurements?)\b' # "held-back data"
    '\b[Ss]eeds? ?0{1,2}[0-9]\b'        # "seed 004", "seed 000's box": cite the paper instead
    '\b[Ss]eed[- ]0{1,2}[0-9]\b'        # "seed-000 run"
    '\b[Tt]he seed\b|\bseed (eqs?\.|§|section)|(?<!\$)\bseed$' # "the seed's text", "seed eq. 12", "seed" + newline + "004"
    '\bthis branch\b'                   # "this branch's binary": name the commit
    '\bworktree\b'                      # "built in this worktree"
    '\bother engineers\b'               # the machine's other users
)
# "helper" has legitimate uses in code ("small vector helpers", a helper function); in the
# documentation it only ever meant a person, so it is checked there alone, and a helper that is
# code (followed by a backquoted name or "function") is allowed.
doc_only_patterns=(
    '\b[Hh]elpers?\b(?! (function|template|class|`|\(`))'
)

join() { local IFS='|'; echo "$*"; }
code_re="$(join "${patterns[@]}")"
doc_re="$(join "${patterns[@]}" "${doc_only_patterns[@]}")"

if (($#)); then
    files=("$@")
else
    mapfile -t files < <(git ls-files -- README.md CMakeLists.txt cmake docs perf cases include src \
        tasks scripts tests .ci |
        grep -v -E '\.(csv|h5|stl|obj|ply|off|png|svg|json|vtu|vtk|log|patch|bin)$' |
        awk '!/\.txt$/ || /(^|\/)CMakeLists\.txt$/' |
        grep -v -E '^tests/data/|^perf/(.*/)?results/' | grep -v -x 'scripts/check_product_text.sh' |
        sort -u)
fi

hits=0
for f in "${files[@]}"; do
    [[ -f "$f" ]] || continue
    grep -Iq . "$f" || continue # binary or empty
    if [[ "$f" == *.md ]]; then re="$doc_re"; else re="$code_re"; fi
    if out=$(grep -n -P -- "$re" "$f"); then
        while IFS= read -r line; do
            echo "$f:$line"
            hits=$((hits + 1))
        done <<<"$out"
    fi
done

if ((hits)); then
    echo "check_product_text: $hits line(s) speak of the development process, not the software" >&2
    exit 1
fi
echo "check_product_text: ${#files[@]} files clean"
