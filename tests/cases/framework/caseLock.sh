# One writer per case: while a solver runs, a second solver and particleGen are refused with a
# message naming the holder's pid (two runs in one case would interleave their time directories
# and drop each other's particles.pvd entries), and change nothing. A lock left by a killed run
# (flock is released when its holder dies) does not stop the next run.
. "$(dirname "$0")/common.sh"
c=$(newCase lock)
startLongRun "$c"
[ -f "$c/.mfdyn.lock" ] || fail "no lock file while running"
grep -q "^$pid particleFlight" "$c/.mfdyn.lock" || fail "the lock file does not name pid $pid: $(cat "$c/.mfdyn.lock")"

status=0; particleFlight -case "$c" > "$WORK/second.log" 2>&1 || status=$?
[ $status -eq 1 ] || { kill -9 $pid; fail "a second solver in the case: exit status $status, expected 1: $(cat "$WORK/second.log")"; }
grep -q "is in use: particleFlight (pid $pid) holds its lock" "$WORK/second.log" || { kill -9 $pid; fail "the refusal does not name pid $pid: $(cat "$WORK/second.log")"; }
grep -q "kill -INT $pid" "$WORK/second.log" || { kill -9 $pid; fail "the refusal does not say how to stop the holder"; }
pass "a second solver is refused, naming pid $pid"

sum0=$(sha256sum "$c/0/particles.vtp")
status=0; particleGen -case "$c" > "$WORK/gen.log" 2>&1 || status=$?
[ $status -eq 1 ] || { kill -9 $pid; fail "particleGen while a solver runs: exit status $status: $(cat "$WORK/gen.log")"; }
grep -q "(pid $pid)" "$WORK/gen.log" || { kill -9 $pid; fail "particleGen's refusal does not name pid $pid: $(cat "$WORK/gen.log")"; }
[ "$(sha256sum "$c/0/particles.vtp")" = "$sum0" ] || { kill -9 $pid; fail "particleGen rewrote 0/ under a running solver"; }
pass "particleGen is refused while the solver runs"

# The first run never noticed: it stops normally and its index lists every time it wrote.
kill -INT $pid
status=0; wait $pid || status=$?
[ $status -eq 130 ] || fail "the first run ended with status $status: $(tail "$c/log")"
[ ! -e "$c/.mfdyn.lock" ] || fail "the lock file outlived its run"
for t in $(ls "$c" | grep -E '^[0-9.e+-]+$'); do
    grep -q "file=\"$t/particles.vtp\"" "$c/particles.pvd" || fail "particles.pvd lost $t"
done

# A killed holder leaves its lock file behind, with a dead pid and no flock: no obstacle.
particleFlight -case "$c" > "$c/log3" 2>&1 &
pid=$!
for _ in $(seq 1 300); do grep -q "Starting time loop" "$c/log3" && break; sleep 0.1; done
grep -q "Starting time loop" "$c/log3" || { kill -9 $pid; fail "the resumed run did not start: $(cat "$c/log3")"; }
kill -9 $pid; wait $pid 2>/dev/null || true
[ -f "$c/.mfdyn.lock" ] || fail "expected the killed run's lock file to stay (this test relies on it)"
mfDictionary "$c/system/controlDict" -entry endTime -set "$(awk -v t="$(latestTime "$c")" 'BEGIN { print t + 0.01 }')" > /dev/null
particleFlight -case "$c" > "$WORK/after.log" 2>&1 || fail "a stale lock stopped the run: $(tail "$WORK/after.log")"
[ ! -e "$c/.mfdyn.lock" ] || fail "the lock file outlived its run"
pass "a stale lock is no obstacle"
