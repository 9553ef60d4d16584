# orderEstimate on bad input: exit status 1, a message naming orderEstimateDict's file and line and
# what is valid; nothing written.
. "$(dirname "$0")/common.sh"

study="$WORK/study"
makeStudy "$study"
dictFile="$study/system/orderEstimateDict"

# expectError <name> <dictionary text> <line, or '' for a message without one> <text the message must hold...>
expectError() {
    local name="$1" text="$2" line="$3" status=0 log="$WORK/log.$1"
    shift 3
    writeDict "$study" "$text"
    rm -rf "$study/postProcessing"
    orderEstimate -case "$study" > "$log" 2>&1 || status=$?
    [ "$status" = 1 ] || fail "$name: exit status $status, expected 1: $(cat "$log")"
    if [ -n "$line" ]; then
        grep -qF "Error: $dictFile:$line:" "$log" || fail "$name: no orderEstimateDict:$line in: $(cat "$log")"
    fi
    for p in "$@"; do grep -qF -- "$p" "$log" || fail "$name: message lacks '$p': $(cat "$log")"; done
    ! grep -q "internal" "$log" || fail "$name: an internal error: $(cat "$log")"
    [ ! -e "$study/postProcessing" ] || fail "$name: postProcessing/ written"
    pass "$name: $(grep Error "$log" | head -n 1)"
}
replace() {  # <keyword> <new line>: goodDict with the line of <keyword> replaced
    printf '%s\n' "$goodDict" | awk -v k="$1" -v l="$2" '$1 == k { print l; next } { print }'
}

expectError twoRuns "$(replace runs 'runs (coarse fine);')" 1 "expected exactly 3 runs (coarse medium fine), found 2"
expectError missingField "$(replace fields 'fields (pressure densty);')" 2 \
    "no field 'densty' in $study/coarse/0/particles.vtp; fields:" "density" "pressure" "(did you mean 'density'?)"
expectError integerField "$(replace fields 'fields (region);')" 2 "holds integers" "real fields:"
expectError countsNotIncreasing "$(replace runs 'runs (medium coarse fine);')" 1 \
    "strictly increasing particle counts" "the medium run 'coarse' has 200 particles, the coarse run 'medium' 800"
expectError missingRun "$(replace runs 'runs (coarse medium finest);')" 1 "the fine run's directory $study/finest does not exist"
expectError unknownKeyword "$goodDict
nrom l2;" 9 "1 unknown entry in orderEstimateDict" "'nrom' (did you mean 'norm'?)"
expectError badNorm "$(replace norm 'norm l3;')" 3 "expected one of infinity | l2, found 'l3'"
expectError hNotThree "$(replace h 'h (0.15 0.075);')" 8 "expected 3 values"
expectError noGridPoint "$(replace interior 'interior 2;')" 5 "at none of the 2 times is a grid point"

# A run with no time directories, and runs with no time in common.
mkdir -p "$study/empty"
expectError noTimes "$(replace runs 'runs (coarse medium empty);')" 1 "has no time directory with a particles.vtp"
mv "$study/fine/0" "$study/fine/0.7"
mv "$study/fine/0.5" "$study/fine/0.9"
expectError noCommonTime "$goodDict" 1 "the runs have no time in common" "fine: 0.7 0.9"

# Command-line times: only the runs' common times can be chosen.
writeDict "$study" "$goodDict"
mv "$study/fine/0.7" "$study/fine/0"
status=0
orderEstimate -case "$study" -time 0.9 > "$WORK/log.time" 2>&1 || status=$?
[ "$status" = 1 ] && grep -qF -- "-time 0.9 matches no time of all three runs; there are: 0" "$WORK/log.time" ||
    fail "-time 0.9: status $status: $(cat "$WORK/log.time")"
pass "-time of a time not in all runs: $(grep Error "$WORK/log.time")"
