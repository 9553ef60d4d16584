# runTimeModifiable on several ranks: an edit of controlDict during the run (stopAt writeNow) is
# taken by every rank at the same step (rank 0 watches the file and every rank re-reads its text),
# so the run ends once, with one state in 3 pieces of one time, status 0 -- where ranks that each
# watched the file on their own clock took the edit at different steps and the job hung.
. "$(dirname "$0")/common.sh"
c=$(hviCase modified 200e-6)
inBackground "$c" 3
for _ in $(seq 1 200); do grep -q "^Starting time loop" "$c/log" 2>/dev/null && break; sleep 0.1; done
sleep 1
# Edits of the write interval first (each a chance for ranks on their own clocks to disagree on
# the next write), then the stop.
for interval in 2e-6 3e-6 2e-6 3e-6; do
    mfDictionary "$c/system/controlDict" -entry writeInterval -set "$interval" > /dev/null
    sleep 0.35
done
mfDictionary "$c/system/controlDict" -entry stopAt -set writeNow > /dev/null
for _ in $(seq 1 300); do [ -f "$c/status" ] && break; sleep 0.1; done
[ -f "$c/status" ] || fail "still running 30 s after the edit: $(tail -3 "$c/log")"
[ "$(cat "$c/status")" = 0 ] || fail "status $(cat "$c/status") after the edit: $(tail -5 "$c/log")"
[ "$(grep -c "^stopAt writeNow at t = " "$c/log")" = 1 ] || fail "not one 'stopAt writeNow' line: $(tail -5 "$c/log")"
t=$(latest "$c")
[ "$t" != "$c/0" ] || fail "no state written at the edit"
[ "$(ls "$t"/particles_*.vtp | wc -l)" = 3 ] || fail "$(ls "$t") in $t, not 3 pieces"
grep -q "controlDict re-read: writeInterval" "$c/log" || fail "no writeInterval change in the log: $(grep controlDict "$c/log")"
n0=$(particleInfo -case "$c" -time 0 | awk '$1 == "particles" {print $2; exit}')
nt=$(particleInfo -case "$c" -time "$(basename "$t")" | awk '$1 == "particles" {print $2; exit}')
[ -n "$n0" ] && [ "$n0" = "$nt" ] || fail "the state holds $nt particles, the start $n0"
pass "controlDict edited during a 3-rank run: $(grep "^stopAt writeNow" "$c/log"), one state of $nt particles in 3 pieces"
