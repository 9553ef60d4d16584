# A restart state whose solver entry is damaged (previousDeltaTExact, the leapfrog's half step) is an
# input error naming the state file and line, exit 1, and the case is left as it was. On a668953 it
# was read by strtod alone: "nan" or "0x1p-10garbage" resumed the run with a wrong half step.
. "$(dirname "$0")/common.sh"
c=$(newCase "$SOURCE/sodShockTube" damaged)
setEntry "$c/system/controlDict" endTime 0.01
setEntry "$c/system/controlDict" writeInterval 0.005
runCase "$c" > /dev/null
[ -f "$c/0.01/state" ] || fail "no state at 0.01"
setEntry "$c/system/controlDict" endTime 0.02
setEntry "$c/system/controlDict" startFrom latestTime
for bad in nan inf -0x1p-10 0x1p-10garbage '""'; do
    cp "$c/0.01/state" "$WORK/state.good"
    sed -i "s|^previousDeltaTExact .*|previousDeltaTExact \"$bad\";|" "$c/0.01/state"
    sed -i 's|""""|""|' "$c/0.01/state"
    (cd "$c" && find . -type f ! -name 'log.*' ! -name state -exec sha256sum {} + | sort -k2) > "$WORK/before"
    status=0; impactSph -case "$c" > "$c/log.restart" 2>&1 || status=$?
    [ "$status" -eq 1 ] || fail "previousDeltaTExact '$bad': exit status $status, expected 1: $(tail "$c/log.restart")"
    grep -q "0.01/state:[0-9]*.*previousDeltaTExact" "$c/log.restart" ||
        fail "previousDeltaTExact '$bad': the error does not name the state file's line: $(tail "$c/log.restart")"
    (cd "$c" && find . -type f ! -name 'log.*' ! -name state -exec sha256sum {} + | sort -k2) > "$WORK/after"
    cmp -s "$WORK/before" "$WORK/after" || fail "previousDeltaTExact '$bad': the case changed: $(diff "$WORK/before" "$WORK/after")"
    cp "$WORK/state.good" "$c/0.01/state"
    pass "previousDeltaTExact '$bad' refused"
done
impactSph -case "$c" > "$c/log.restart" 2>&1 || fail "the good state did not restart: $(tail "$c/log.restart")"
pass "damaged restart states refused, the good one restarts"
