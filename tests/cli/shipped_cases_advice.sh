#!/usr/bin/env bash
# The shipped cases follow docs/RECOMMENDED_PRACTICE.md: `sluice info` raises no warning on a
# file under cases/ unless the file says why, in a comment "sluice info warns (KEY)" naming the
# warning's key; and no such comment names a key that is not warned about (a stale excuse).
# The short example of docs/CASE_REFERENCE.md raises none at all.
# Usage: shipped_cases_advice.sh SLUICE_EXE SOURCE_DIR
set -euo pipefail
exe=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail=0
while IFS= read -r case_file; do
    "$exe" info "$case_file" >"$work/info.txt" 2>&1 || {
        echo "FAIL: sluice info refused $case_file"
        sed 's/^/    /' "$work/info.txt"
        fail=1
        continue
    }
    warned=$(sed -n "s/^sluice: warning: key '\([^']*\)'.*/\1/p" "$work/info.txt" | sort -u)
    explained=$(tr '\n' ' ' <"$case_file" | sed 's/ *# */ /g' |
        grep -o 'sluice info warns ([^)]*)' | sed 's/.*(\(.*\))/\1/' | sort -u || true)
    for key in $warned; do
        if ! grep -qxF "$key" <<<"$explained"; then
            echo "FAIL: $case_file: sluice info warns about '$key' and no comment says why:"
            grep "key '$key'" "$work/info.txt" | sed 's/^/    /'
            fail=1
        fi
    done
    for key in $explained; do
        if ! grep -qxF "$key" <<<"$warned"; then
            echo "FAIL: $case_file: a comment explains a warning about '$key' that sluice info no longer gives"
            fail=1
        fi
    done
done < <(find "$src/cases" -name '*.toml' | sort)

awk '/^## Short example/{f=1} /^## Overriding/{f=0} f' "$src/docs/CASE_REFERENCE.md" |
    awk '/^```toml/{f=1; next} /^```/{f=0} f' >"$work/short.toml"
"$exe" info "$work/short.toml" >"$work/info.txt" 2>&1 || {
    echo "FAIL: CASE_REFERENCE's short example is refused"
    cat "$work/info.txt"
    fail=1
}
if grep -q "warning" "$work/info.txt"; then
    echo "FAIL: CASE_REFERENCE's short example raises a warning:"
    grep "warning" "$work/info.txt"
    fail=1
fi
[[ $fail == 0 ]] && echo "shipped cases: every sluice info warning explained in its file"
exit $fail
