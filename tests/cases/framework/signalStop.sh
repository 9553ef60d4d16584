# SIGINT during a run writes the current state and stops cleanly; the written time is complete
# and readable (particleInfo reads it back), and the run resumes from it.
. "$(dirname "$0")/common.sh"
c=$(newCase sig)
startLongRun "$c"
kill -INT $pid
status=0; wait $pid || status=$?
[ $status -eq 0 ] || fail "exit status $status after SIGINT: $(tail "$c/log")"
grep -q "Stopped by SIGINT" "$c/log" || fail "no stop message"
latest=$(latestTime "$c")
[ "$latest" != 0.25 ] || [ -f "$c/$latest/state" ] || fail "no state written"
ls "$c" | grep -q '\.tmp-' && fail "a temporary directory was left behind"
particleInfo -case "$c" -latestTime > "$c/info" 2>&1 || fail "latest time $latest unreadable: $(cat "$c/info")"
grep -q "1250" "$c/info" || fail "particleInfo does not report the 1250 particles: $(cat "$c/info")"
# The interrupted run resumes from the time the signal wrote.
mfDictionary "$c/system/controlDict" -entry endTime -set "$(awk -v t="$latest" 'BEGIN { print t + 0.1 }')" > /dev/null
particleFlight -case "$c" > "$c/log2" 2>&1 || fail "resume failed: $(tail "$c/log2")"
grep -q "Restarting from time $latest" "$c/log2" || fail "did not resume from $latest: $(head -20 "$c/log2")"
pass "SIGINT wrote a complete time $latest"
