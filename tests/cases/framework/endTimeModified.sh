# runTimeModifiable: changing endTime in a running case changes when it stops.
. "$(dirname "$0")/common.sh"
c=$(newCase modify)
startLongRun "$c"
# Far enough ahead that the run cannot pass it before the change is seen (checked twice a second,
# the run covers ~1 s of simulated time per second of wall time here).
latest=$(latestTime "$c")
target=$(awk -v t="$latest" 'BEGIN { print int(t) + 4 }')
mfDictionary "$c/system/controlDict" -entry endTime -set $target > /dev/null
for _ in $(seq 1 1200); do kill -0 $pid 2> /dev/null || break; sleep 0.1; done
if kill -0 $pid 2> /dev/null; then kill -9 $pid; fail "run did not stop after endTime was changed to $target"; fi
wait $pid || fail "run failed: $(tail "$c/log")"
grep -q "endTime 100000 -> $target" "$c/log" || fail "the change was not reported: $(grep -i controlDict "$c/log")"
latest=$(latestTime "$c")
[ "$latest" = "$target" ] || fail "stopped at $latest, expected $target"
pass "endTime change stopped the run at $target"
