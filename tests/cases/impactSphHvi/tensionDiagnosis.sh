# A state out of the equation of state's range in tension is diagnosed as tension, not as the
# compressed case. The coarse Al-Al impact with a tension cut-off (minimumPressure -1.2 GPa): the
# particles held at the cut-off in the back of the debris cloud expand freely (the cut-off clamps P,
# not c^2, MieGruneisen.cpp) until mieGruneisen's c^2 turns negative, at about 0.78 us at 0.5 mm
# (density about 1470, 0.53 of rho0). The run must stop with exit status 1 and say tension; before,
# the message named "strong compression with little heating" for this expanded state.
. "$(dirname "$0")/common.sh"
c=$(coarseCase hviAlAl 5e-4)
mfDictionary "$c/constant/materialProperties" -entry materials/aluminium/equationOfState/minimumPressure -set -1.2e9 > /dev/null
mfDictionary "$c/system/controlDict" -entry endTime -set 2e-6 > /dev/null
status=0
impactSph -case "$c" > "$c/log" 2>&1 || status=$?
[ "$status" = 1 ] || fail "expected exit status 1, got $status: $(tail -5 "$c/log")"
grep -q "c^2 <= 0" "$c/log" || fail "no c^2 diagnosis: $(tail -5 "$c/log")"
grep -q "range of validity in tension" "$c/log" || fail "the expanded state is not called tension: $(grep -A1 '^Error' "$c/log")"
grep -q "little heating" "$c/log" && fail "the compression advice is given for an expanded state"
ratio=$(grep -o '[0-9.e+-]* of rho0' "$c/log" | head -1 | awk '{print $1}')
less "$ratio" 1 || fail "density ratio $ratio is not below 1"
pass "tension diagnosed at density ratio $ratio"
