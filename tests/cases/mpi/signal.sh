# SIGTERM to mpirun: every rank stops at the same step and one consistent state is written (its
# pieces all of the same time, every particle once), and the run restarts from it.
. "$(dirname "$0")/common.sh"
c=$(hviCase signal 200e-6)
inBackground "$c" 2
# Once the loop runs (the first progress or the decomposition's line), signal mpirun (the launcher).
for _ in $(seq 1 200); do grep -q "^Starting time loop" "$c/log" 2>/dev/null && break; sleep 0.1; done
sleep 2
launcher=$(pgrep -f "^$MPIEXEC .*impactSph -case $c" | head -n 1)
[ -n "$launcher" ] || fail "no mpirun to signal"
kill -TERM "$launcher"
for _ in $(seq 1 300); do [ -f "$c/status" ] && break; sleep 0.1; done
[ -f "$c/status" ] || fail "still running 30 s after SIGTERM"
echo "status after SIGTERM: $(cat "$c/status")"
grep -q "Stopped by SIGTERM" "$c/log" || fail "no 'Stopped by SIGTERM' in the log: $(tail -8 "$c/log")"
t=$(latest "$c")
[ "$t" != "$c/0" ] || fail "no state written after SIGTERM"
[ -f "$t/particles.pvtp" ] || fail "the state $t has no particles.pvtp"
pieces=$(ls "$t"/particles_*.vtp | wc -l)
[ "$pieces" = 2 ] || fail "$pieces pieces in $t, not 2"
particleCompare "$t" "$t" > /dev/null || fail "the written state does not read back"
# Every particle once, and the state restarts: on 3 ranks to a little later.
n0=$(particleInfo -case "$c" -time 0 | awk '$1 == "particles" {print $2; exit}')
nt=$(particleInfo -case "$c" -time "$(basename "$t")" | awk '$1 == "particles" {print $2; exit}')
[ -n "$n0" ] && [ "$n0" = "$nt" ] || fail "the state holds $nt particles, the start $n0"
mfDictionary "$c/system/controlDict" -entry startFrom -set latestTime > /dev/null
later=$(awk -v t="$(basename "$t")" 'BEGIN{printf "%.6g", t + 1e-6}')
mfDictionary "$c/system/controlDict" -entry endTime -set "$later" > /dev/null
onRanks 3 impactSph -case "$c" > "$c/log.restart" 2>&1 || fail "restart from the signalled state: $(tail -3 "$c/log.restart")"
grep -q "Restarting from time $(basename "$t")" "$c/log.restart" || fail "the restart did not start from $(basename "$t")"
pass "SIGTERM to mpirun: one state written at $(basename "$t") in $pieces pieces"
