# Sourced by tests/mpi/*.sh that compare whole runs: same_results REF DIR LABEL fails (exit 1,
# naming LABEL and the file) unless DIR's snapshots and probe files are byte-identical to REF's,
# and needs at least 3 snapshots in REF; it sets $snaps to their count.
same_results() {
    local ref=$1 dir=$2 label=$3
    snaps=$(ls "$ref/snapshots"/*.h5 | wc -l)
    [[ $snaps -ge 3 ]] || { echo "FAIL $label: only $snaps snapshots"; exit 1; }
    for f in "$ref"/snapshots/*.h5; do
        cmp "$f" "$dir/snapshots/$(basename "$f")" ||
            { echo "FAIL $label: differs in $(basename "$f")"; exit 1; }
    done
    diff -r "$ref/probes" "$dir/probes" || { echo "FAIL $label: probes differ"; exit 1; }
}
