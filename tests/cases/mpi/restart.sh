# Restart across rank counts: Sod's tube written on 3 ranks at t = 0.025 (pieces and particles.pvtp)
# and restarted on 2 ranks and on 1 (serially) to t = 0.05 gives the uninterrupted serial run's state
# to 1e-12; and a state written serially restarts on 3 ranks alike.
. "$(dirname "$0")/common.sh"
whole=$(sodCase whole 0.05)
impactSph -case "$whole" > "$whole/log" 2>&1 || fail "uninterrupted run: $(tail -3 "$whole/log")"

first=$(copyCase "$whole" "$WORK/first")
mfDictionary "$first/system/controlDict" -entry endTime -set 0.025 > /dev/null
onRanks 3 impactSph -case "$first" > "$first/log" 2>&1 || fail "3 ranks to 0.025: $(tail -3 "$first/log")"
[ -f "$first/0.025/particles.pvtp" ] || fail "3 ranks: no 0.025/particles.pvtp"

for n in 2 1; do
    c="$WORK/on$n"
    cp -r "$first" "$c"
    mfDictionary "$c/system/controlDict" -entry endTime -set 0.05 > /dev/null
    mfDictionary "$c/system/controlDict" -entry startFrom -set latestTime > /dev/null
    if [ "$n" = 1 ]; then
        impactSph -case "$c" > "$c/log.restart" 2>&1 || fail "restart on 1: $(tail -3 "$c/log.restart")"
    else
        onRanks "$n" impactSph -case "$c" > "$c/log.restart" 2>&1 || fail "restart on $n: $(tail -3 "$c/log.restart")"
    fi
    grep -q "Restarting from time 0.025" "$c/log.restart" || fail "restart on $n: not from 0.025"
    sameState "written on 3 ranks, restarted on $n, against the uninterrupted run" "$(latest "$whole")" "$(latest "$c")"
done

serialFirst=$(copyCase "$whole" "$WORK/serialFirst")
mfDictionary "$serialFirst/system/controlDict" -entry endTime -set 0.025 > /dev/null
impactSph -case "$serialFirst" > "$serialFirst/log" 2>&1 || fail "serial to 0.025"
mfDictionary "$serialFirst/system/controlDict" -entry endTime -set 0.05 > /dev/null
mfDictionary "$serialFirst/system/controlDict" -entry startFrom -set latestTime > /dev/null
onRanks 3 impactSph -case "$serialFirst" > "$serialFirst/log.restart" 2>&1 || fail "serial state restarted on 3 ranks"
sameState "written serially, restarted on 3 ranks" "$(latest "$whole")" "$(latest "$serialFirst")"
pass "restarts across 3, 2 and 1 ranks give the uninterrupted run's state to 1e-12"
