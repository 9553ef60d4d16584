# SIGINT during a run writes the current state and stops cleanly; the written time is complete
# and readable (particleInfo reads it back), and the run resumes from it.
. "$(dirname "$0")/common.sh"
c=$(newCase sig)
# Long enough that the signal arrives mid-run: 1e5 s of flight at small steps.
mfDictionary "$c/system/controlDict" -entry endTime -set 1e5 > /dev/null
mfDictionary "$c/system/controlDict" -entry maxDeltaT -set 1e-4 > /dev/null
particleFlight -case "$c" > "$c/log" 2>&1 &
pid=$!
for _ in $(seq 1 300); do [ -d "$c/0.25" ] && break; sleep 0.1; done
[ -d "$c/0.25" ] || { kill -9 $pid; fail "run never reached its first write"; }
kill -INT $pid
status=0; wait $pid || status=$?
[ $status -eq 0 ] || fail "exit status $status after SIGINT: $(tail "$c/log")"
grep -q "Stopped by SIGINT" "$c/log" || fail "no stop message"
latest=$(ls "$c" | grep -E '^[0-9.e+-]+$' | sort -g | tail -n 1)
[ "$latest" != 0.25 ] || [ -f "$c/$latest/state" ] || fail "no state written"
ls "$c" | grep -q '\.tmp-' && fail "a temporary directory was left behind"
particleInfo -case "$c" -latestTime > "$c/info" 2>&1 || fail "latest time $latest unreadable: $(cat "$c/info")"
grep -q "1250" "$c/info" || fail "particleInfo does not report the 1250 particles: $(cat "$c/info")"
pass "SIGINT wrote a complete time $latest"
