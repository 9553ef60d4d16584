# SIGINT or SIGTERM during a run writes the current state and stops cleanly with exit status
# 128 + the signal number (130, 143: what a shell reports for a process killed by it, so a script
# or batch system sees that the run did not finish); the written time is complete and readable
# (particleInfo reads it back), particles.pvd lists it, and the run resumes from it.
. "$(dirname "$0")/common.sh"

for sig in INT TERM; do
    expected=$([ $sig = INT ] && echo 130 || echo 143)
    c=$(newCase sig$sig)
    startLongRun "$c"
    kill -$sig $pid
    status=0; wait $pid || status=$?
    [ $status -eq $expected ] || fail "exit status $status after SIG$sig, expected $expected: $(tail "$c/log")"
    grep -q "Stopped by SIG$sig" "$c/log" || fail "no stop message after SIG$sig"
    grep -q "End (stopped by SIG$sig, exit status $expected)" "$c/log" || fail "no end line naming the status: $(tail -3 "$c/log")"
    latest=$(latestTime "$c")
    [ -f "$c/$latest/state" ] || fail "SIG$sig: no state in $latest"
    ls "$c" | grep -q '\.tmp-' && fail "a temporary directory was left behind"
    [ ! -e "$c/.mfdyn.lock" ] || fail "the case lock was left behind"
    grep -q "file=\"$latest/particles.vtp\"" "$c/particles.pvd" || fail "particles.pvd does not list $latest"
    particleInfo -case "$c" -latestTime > "$c/info" 2>&1 || fail "latest time $latest unreadable: $(cat "$c/info")"
    grep -q "1250" "$c/info" || fail "particleInfo does not report the 1250 particles: $(cat "$c/info")"
    # The interrupted run resumes from the time the signal wrote, and keeps it in the index.
    mfDictionary "$c/system/controlDict" -entry endTime -set "$(awk -v t="$latest" 'BEGIN { print t + 0.1 }')" > /dev/null
    particleFlight -case "$c" > "$c/log2" 2>&1 || fail "resume failed: $(tail "$c/log2")"
    grep -q "Restarting from time $latest" "$c/log2" || fail "did not resume from $latest: $(head -20 "$c/log2")"
    grep -q "file=\"$latest/particles.vtp\"" "$c/particles.pvd" || fail "the restart dropped $latest from particles.pvd"
    pass "SIG$sig wrote a complete time $latest and exited with $expected"
done
