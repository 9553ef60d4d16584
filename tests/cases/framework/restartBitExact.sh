# A run stopped halfway and restarted with startFrom latestTime writes files identical byte for
# byte to an uninterrupted run.
. "$(dirname "$0")/common.sh"
full=$(newCase full)
particleFlight -case "$full" > "$full/log" 2>&1 || fail "full run failed"
half=$(newCase half)
mfDictionary "$half/system/controlDict" -entry endTime -set 0.5 > /dev/null || fail "mfDictionary -set failed"
particleFlight -case "$half" > "$half/log1" 2>&1 || fail "first half failed"
[ -d "$half/0.5" ] && [ ! -d "$half/0.75" ] || fail "first half did not stop at 0.5"
mfDictionary "$half/system/controlDict" -entry endTime -set 1.0 > /dev/null
particleFlight -case "$half" > "$half/log2" 2>&1 || fail "restart failed: $(tail "$half/log2")"
grep -q "Restarting from time 0.5" "$half/log2" || fail "did not restart from 0.5"
for t in 0.75 1; do
    cmp "$full/$t/particles.vtp" "$half/$t/particles.vtp" || fail "particles.vtp at $t differs after restart"
    cmp "$full/$t/state" "$half/$t/state" || fail "state at $t differs after restart"
done
cmp "$full/particles.pvd" "$half/particles.pvd" || fail "particles.pvd differs"
pass "restart is bit-exact"
