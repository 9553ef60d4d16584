# Issue 14, run control and CSV output end to end: a restart of a finished run has nothing to do
# (exit 0, nothing written; it used to rewrite the last time and add CSV rows); a rerun from the
# same start time rewrites the function objects' CSVs with its own rows, the earlier file kept as
# <file>.old; endTime not after startTime and write times named alike are refused at the start.
. "$(dirname "$0")/common.sh"
snapshot() { (cd "$1" && find . -type f ! -name 'log*' | sort | xargs sha256sum); }

c=$(newCase finished)
particleFlight -case "$c" > "$WORK/log1" 2>&1 || fail "first run failed: $(tail "$WORK/log1")"
before=$(snapshot "$c")
status=0; particleFlight -case "$c" > "$WORK/log2" 2>&1 || status=$?
[ $status -eq 0 ] || fail "restart at endTime: exit status $status: $(tail "$WORK/log2")"
grep -q "Nothing to do: the run already reached endTime 1" "$WORK/log2" || fail "no 'Nothing to do': $(tail "$WORK/log2")"
[ "$(snapshot "$c")" = "$before" ] || fail "restart at endTime changed the case: $(diff <(echo "$before") <(snapshot "$c"))"
pass "a restart at endTime does nothing, exit 0"

csv="$c/postProcessing/conserved/0/conservedQuantities.csv"
cp "$csv" "$WORK/first.csv"
mfDictionary "$c/system/controlDict" -entry startFrom -set startTime > /dev/null
particleFlight -case "$c" > "$WORK/log3" 2>&1 || fail "rerun failed: $(tail "$WORK/log3")"
cmp "$csv" "$WORK/first.csv" || fail "the rerun's conservedQuantities.csv differs from the first run's"
cmp "$csv.old" "$WORK/first.csv" || fail "the first run's conservedQuantities.csv was not kept as .old"
[ "$(grep -c '^time,' "$csv")" -eq 1 ] || fail "header repeated in $csv"
pass "a rerun from the start time rewrites its CSVs, keeping the earlier ones as .old"

d=$(newCase refused)
before=$(snapshot "$d")
mfDictionary "$d/system/controlDict" -entry endTime -set 0 > /dev/null
status=0; particleFlight -case "$d" > "$WORK/log4" 2>&1 || status=$?
[ $status -eq 1 ] || fail "endTime 0: exit status $status"
grep -q "controlDict:[0-9]*:[0-9]*: keyword 'endTime': endTime 0 is not after startTime 0" "$WORK/log4" ||
    fail "endTime 0: $(tail -n 3 "$WORK/log4")"
mfDictionary "$d/system/controlDict" -entry endTime -set 2 > /dev/null
mfDictionary "$d/system/controlDict" -entry writeInterval -set 0.05 > /dev/null
mfDictionary "$d/system/controlDict" -entry writePrecision -set 2 > /dev/null
status=0; particleFlight -case "$d" > "$WORK/log5" 2>&1 || status=$?
[ $status -eq 1 ] || fail "writePrecision 2: exit status $status"
grep -q "controlDict:[0-9]*:[0-9]*: .*writePrecision 2 names the write times .* Set writePrecision 3" "$WORK/log5" ||
    fail "writePrecision 2: $(tail -n 3 "$WORK/log5")"
[ "$(snapshot "$d" | grep -v controlDict)" = "$(echo "$before" | grep -v controlDict)" ] || fail "a refused start changed the case"
pass "endTime 0 and writePrecision 2 refused at their controlDict line, nothing written"
