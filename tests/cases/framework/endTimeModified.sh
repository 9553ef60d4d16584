# runTimeModifiable: changing endTime in a running case changes when it stops.
. "$(dirname "$0")/common.sh"
c=$(newCase modify)
startLongRun "$c"
# Freeze the run, change endTime a little ahead of where it can be, and let it go on: the first
# step after the pause re-reads controlDict (more than half a second has passed), so the test does
# not depend on how fast this machine steps. The run is short of latest + 0.25 (the next write).
kill -STOP $pid
sleep 1
latest=$(latestTime "$c")
target=$(awk -v t="$latest" 'BEGIN { print t + 1 }')
mfDictionary "$c/system/controlDict" -entry endTime -set $target > /dev/null
kill -CONT $pid
for _ in $(seq 1 1200); do kill -0 $pid 2> /dev/null || break; sleep 0.1; done
if kill -0 $pid 2> /dev/null; then kill -9 $pid; fail "run did not stop after endTime was changed to $target"; fi
wait $pid || fail "run failed: $(tail "$c/log")"
grep -q "endTime 100000 -> $target" "$c/log" || fail "the change was not reported: $(grep -i controlDict "$c/log")"
latest=$(latestTime "$c")
[ "$latest" = "$target" ] || fail "stopped at $latest, expected $target"
pass "endTime change stopped the run at $target"
