# A fresh start keeps no time directory of an earlier run later than its start: a shorter rerun
# from startTime, or a rerun of particleGen, moves them into abandoned.<N>/ (unchanged, with
# their own particles.pvd) and says so, so that startFrom latestTime cannot resume from a state
# that does not follow from the current one; particles.pvd keeps no entry pointing into them.
. "$(dirname "$0")/common.sh"
c=$(newCase later)
particleFlight -case "$c" > "$WORK/log1" 2>&1 || fail "first run failed: $(tail "$WORK/log1")"
sum1=$(cd "$c" && sha256sum 1/particles.vtp 1/state)

mfDictionary "$c/system/controlDict" -entry startFrom -set startTime > /dev/null
mfDictionary "$c/system/controlDict" -entry endTime -set 0.5 > /dev/null
particleFlight -case "$c" > "$WORK/log2" 2>&1 || fail "the shorter rerun failed: $(tail "$WORK/log2")"
for t in 0.75 1; do [ ! -e "$c/$t" ] || fail "the earlier run's $t is still in the case"; done
grep -q "Moved 4 time directories later than the start time 0 (0.25 0.5 0.75 1), left by an earlier run, to $c/abandoned.1/" "$WORK/log2" \
    || fail "the log does not say what was moved where: $(grep -i moved "$WORK/log2")"
[ "$(cd "$c/abandoned.1" && sha256sum 1/particles.vtp 1/state)" = "$sum1" ] || fail "the moved time 1 changed"
grep -q 'file="1/particles.vtp"' "$c/abandoned.1/particles.pvd" || fail "abandoned.1 has no index of its times"
grep -q 'file="0/' "$c/abandoned.1/particles.pvd" && fail "abandoned.1's index lists 0, which was not moved"
[ "$(grep -c '<DataSet' "$c/particles.pvd")" -eq 3 ] || fail "particles.pvd should list 0, 0.25, 0.5: $(cat "$c/particles.pvd")"
grep -qE 'file="(0.75|1)/' "$c/particles.pvd" && fail "particles.pvd points into moved times"
[ "$(latestTime "$c")" = 0.5 ] || fail "latest time $(latestTime "$c"), expected 0.5"
pass "a shorter rerun moved the later times aside"

# particleGen writes new initial conditions: every later time is moved aside too.
particleGen -case "$c" > "$WORK/log3" 2>&1 || fail "particleGen failed: $(tail "$WORK/log3")"
[ "$(latestTime "$c")" = 0 ] || fail "after particleGen the latest time is $(latestTime "$c"), expected 0"
[ -d "$c/abandoned.2/0.5" ] || fail "particleGen did not move 0.5 into abandoned.2"
grep -q "abandoned.2" "$WORK/log3" || fail "particleGen does not say where the times went"
mfDictionary "$c/system/controlDict" -entry startFrom -set latestTime > /dev/null
particleFlight -case "$c" > "$WORK/log4" 2>&1 || fail "the run after particleGen failed: $(tail "$WORK/log4")"
grep -q "Starting from time 0" "$WORK/log4" || fail "startFrom latestTime resumed from a stale time: $(grep -E 'Start|Restart' "$WORK/log4")"
pass "particleGen moved the later times aside"
