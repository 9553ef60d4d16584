# A restart keeps the time it restarts from in particles.pvd even when the exact time (from the
# state) is above the directory's name, which writePrecision rounds: the index is cut after the
# exact time, not after the name's value.
. "$(dirname "$0")/common.sh"

# Deterministic: the run ends at 0.0123, written as "0.012" (two digits) with the exact time in
# the state; its pvd entry has timestep 0.0123 > 0.012.
c=$(newCase exact)
mfDictionary "$c/system/controlDict" -entry writePrecision -set 2 > /dev/null
mfDictionary "$c/system/controlDict" -entry endTime -set 0.0123 > /dev/null
particleFlight -case "$c" > "$WORK/log1" 2>&1 || fail "first run failed: $(tail "$WORK/log1")"
grep -q 'timestep="0.0123" part="0" file="0.012/particles.vtp"' "$c/particles.pvd" \
    || fail "the end time is not indexed as expected: $(cat "$c/particles.pvd")"
mfDictionary "$c/system/controlDict" -entry endTime -set 0.5 > /dev/null
particleFlight -case "$c" > "$WORK/log2" 2>&1 || fail "restart failed: $(tail "$WORK/log2")"
grep -q "Restarting from time 0.012" "$WORK/log2" || fail "did not restart from 0.012"
grep -q 'file="0.012/particles.vtp"' "$c/particles.pvd" || fail "the restart dropped 0.012 from particles.pvd: $(cat "$c/particles.pvd")"
[ "$(grep -c '<DataSet' "$c/particles.pvd")" -eq 4 ] || fail "expected 0, 0.012, 0.25, 0.5: $(cat "$c/particles.pvd")"
pass "a restart at 0.0123 (directory 0.012) keeps it in particles.pvd"

# Stopped by a signal at whatever time it reached, three digits in the name (an end time of 9
# keeps every regular write time distinct in three digits).
c=$(newCase signal)
mfDictionary "$c/system/controlDict" -entry writePrecision -set 3 > /dev/null
mfDictionary "$c/system/controlDict" -entry endTime -set 9 > /dev/null
mfDictionary "$c/system/controlDict" -entry maxDeltaT -set 1e-4 > /dev/null
particleFlight -case "$c" > "$c/log" 2>&1 &
pid=$!
for _ in $(seq 1 300); do [ -d "$c/0.25" ] && break; sleep 0.1; done
[ -d "$c/0.25" ] || { kill -9 $pid; fail "the run never reached its first write: $(tail "$c/log")"; }
kill -INT $pid
status=0; wait $pid || status=$?
[ $status -eq 130 ] || fail "exit status $status after SIGINT"
latest=$(latestTime "$c")
mfDictionary "$c/system/controlDict" -entry endTime -set "$(awk -v t="$latest" 'BEGIN { print t + 0.01 }')" > /dev/null
particleFlight -case "$c" > "$WORK/log3" 2>&1 || fail "resume failed: $(tail "$WORK/log3")"
grep -q "file=\"$latest/particles.vtp\"" "$c/particles.pvd" || fail "the restart dropped the stop time $latest: $(cat "$c/particles.pvd")"
pass "a restart from the signal's stop time $latest keeps it in particles.pvd"
