# The start directory is input: a run never writes into it, whether nothing is left to run
# (endTime <= the start time, which used to rewrite 0/particles.vtp and add 0/state) or a later
# time would get the start directory's name at a small writePrecision.
. "$(dirname "$0")/common.sh"
snapshot() { (cd "$1" && find . -type f | sort | xargs sha256sum); }

c=$(newCase input)
before=$(snapshot "$c")
mfDictionary "$c/system/controlDict" -entry endTime -set 0 > /dev/null
status=0; particleFlight -case "$c" > "$WORK/log1" 2>&1 || status=$?
[ $status -le 1 ] || fail "endTime 0: exit status $status: $(tail "$WORK/log1")"
[ ! -e "$c/0/state" ] || fail "endTime 0 added 0/state"
mfDictionary "$c/system/controlDict" -entry endTime -set 1.0 > /dev/null
[ "$(snapshot "$c")" = "$before" ] || fail "endTime 0 changed the case: $(diff <(echo "$before") <(snapshot "$c"))"
pass "endTime 0 leaves 0/ alone"

mfDictionary "$c/system/controlDict" -entry endTime -set 0.5 > /dev/null
particleFlight -case "$c" > "$WORK/log2" 2>&1 || fail "run to 0.5 failed: $(tail "$WORK/log2")"
sum=$(sha256sum "$c/0.5/particles.vtp" "$c/0.5/state")
mfDictionary "$c/system/controlDict" -entry endTime -set 0.25 > /dev/null
status=0; particleFlight -case "$c" > "$WORK/log3" 2>&1 || status=$?
[ $status -le 1 ] || fail "endTime below the restart time: exit status $status"
[ "$(sha256sum "$c/0.5/particles.vtp" "$c/0.5/state")" = "$sum" ] || fail "endTime 0.25 rewrote the start directory 0.5"
pass "endTime below the restart time leaves 0.5 alone"

# Restart from 0.5 writing every step with two digits: the first step, at 0.5001, would be
# named "0.5". Refused with a message naming writePrecision, and 0.5 keeps its content.
mfDictionary "$c/system/controlDict" -entry endTime -set 0.6 > /dev/null
mfDictionary "$c/system/controlDict" -entry maxDeltaT -set 1e-4 > /dev/null
mfDictionary "$c/system/controlDict" -entry writeControl -set timeStep > /dev/null
mfDictionary "$c/system/controlDict" -entry writeInterval -set 1 > /dev/null
mfDictionary "$c/system/controlDict" -entry writePrecision -set 2 > /dev/null
status=0; particleFlight -case "$c" > "$WORK/log4" 2>&1 || status=$?
[ $status -eq 1 ] || fail "a write named like the start directory: exit status $status, expected 1: $(tail "$WORK/log4")"
grep -q "writePrecision" "$WORK/log4" || fail "the message does not name writePrecision: $(tail -3 "$WORK/log4")"
[ "$(sha256sum "$c/0.5/particles.vtp" "$c/0.5/state")" = "$sum" ] || fail "a write replaced the start directory 0.5"
pass "a later time named like the start directory is refused"
