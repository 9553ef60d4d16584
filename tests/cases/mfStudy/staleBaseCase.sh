# A change to the base case makes finished variants stale (issue 16 item 3): the done marker holds
# a fingerprint of every file the variants copy. After a first study, a changed endTime in the
# base case's controlDict (not in studyDict) reruns every level, and its steps follow the new
# endTime; a change to studyDict that leaves the variants' entries as they were (a comment)
# reruns none; a marker from before fingerprints (none in it) counts as stale.
. "$(dirname "$0")/common.sh"
c=$(newCase stale)
mfStudy -case "$c" > "$c/log.first" 2>&1 || fail "first study failed: $(tail "$c/log.first")"
grep -q '^baseInputs [0-9a-f]\{16\}$' "$c/study/h0.01/mfStudy.done" || fail "no fingerprint in the marker: $(cat "$c/study/h0.01/mfStudy.done")"
echo "// a comment: the variants' entries are unchanged" >> "$c/system/studyDict"
mfStudy -case "$c" > "$c/log.comment" 2>&1 || fail "second study failed: $(tail "$c/log.comment")"
[ "$(grep -c 'finished before, not rerun' "$c/log.comment")" = 3 ] || fail "a studyDict comment reran variants: $(cat "$c/log.comment")"
# endTime 0.2 -> 0.1 in the base case: half the steps (250 at h = 0.01, deltaT 4e-4).
sed -i 's#^endTime .*#endTime         0.1;#' "$c/system/controlDict"
grep -q '^endTime         0.1;' "$c/system/controlDict" || fail "the fixture's endTime line is not where the test expects it"
mfStudy -case "$c" > "$c/log.changed" 2>&1 || fail "changed study failed: $(tail "$c/log.changed")"
[ "$(grep -c "the base case's inputs (files the variants copy) changed since it ran: rerun" "$c/log.changed")" = 3 ] ||
    fail "a changed base case did not rerun the variants: $(cat "$c/log.changed")"
[ "$(field "$c/study/results.csv" h0.01 steps)" = 250 ] || fail "h0.01 after endTime 0.1: $(field "$c/study/results.csv" h0.01 steps) steps"
# A marker written before fingerprints: rerun (nothing says what case it was run from).
sed -i '/^baseInputs /d' "$c/study/h0.005/mfStudy.done"
mfStudy -case "$c" > "$c/log.old" 2>&1 || fail "study after an old marker failed: $(tail "$c/log.old")"
grep -q "h0.005: the base case's inputs" "$c/log.old" || fail "a marker without a fingerprint was trusted: $(cat "$c/log.old")"
[ "$(grep -c 'finished before, not rerun' "$c/log.old")" = 2 ] || fail "expected the two others kept: $(cat "$c/log.old")"
pass "a changed base case reruns its finished variants; a studyDict comment does not"
