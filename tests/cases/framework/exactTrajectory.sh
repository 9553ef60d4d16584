# The framework case against its exact answer: velocity Verlet integrates uniform gravity exactly,
# so the only error is round-off accumulated over the steps: |x| ~ 5 m, ~700 steps, eps 2.2e-16
# gives ~1e-12 m; 1e-10 m leaves room for summation order and fails on any real integration error
# (a first-order scheme would be off by ~g dt t/2 = 5e-3 m).
. "$(dirname "$0")/common.sh"
c=$(newCase exact)
particleFlight -case "$c" > "$c/log" 2>&1 || fail "particleFlight failed: $(tail "$c/log")"
row=$(lastRow "$c/postProcessing/trajectory/0/errorNorms.csv" ",position,")
t=$(echo "$row" | cut -d, -f1); linf=$(echo "$row" | cut -d, -f5)
[ "$t" = 1 ] || fail "last error row at t = $t, expected 1"
less "$linf" 1e-10 || fail "position Linf $linf >= 1e-10 m"
vrow=$(lastRow "$c/postProcessing/trajectory/0/errorNorms.csv" ",velocity,")
less "$(echo "$vrow" | cut -d, -f5)" 1e-10 || fail "velocity Linf too large: $vrow"
# Energy: kinetic + potential conserved to round-off relative to its size.
grep -q "totalEnergy drift" "$c/log" || fail "no energy drift in the summary"
drift=$(grep "totalEnergy drift" "$c/log" | awk '{print $4}')
less "${drift#-}" 1e-10 || fail "total energy drift $drift"
grep -q "Error norms (bought with" "$c/log" || fail "summary lacks error norms beside run time"
[ -f "$c/postProcessing/runSummary/0/runSummary.csv" ] || fail "no runSummary.csv"
for t in 0.25 0.5 0.75 1; do [ -f "$c/$t/particles.vtp" ] && [ -f "$c/$t/state" ] || fail "time $t not written"; done
grep -q '<DataSet timestep="1"' "$c/particles.pvd" || grep -q 'timestep="1"' "$c/particles.pvd" || fail "particles.pvd lacks t = 1"
# fieldMinMax: every particle moves alike, so at t = 1 min = max of velocity_y = 4 - 9.81.
header=$(head -n 1 "$c/postProcessing/extent/0/fieldMinMax.csv")
[ "$(echo "$header" | cut -d, -f1-5)" = "time,velocity_x_min,velocity_x_minId,velocity_x_max,velocity_x_maxId" ] \
    || fail "fieldMinMax header: $header"
last=$(tail -n 1 "$c/postProcessing/extent/0/fieldMinMax.csv")
vymin=$(echo "$last" | cut -d, -f6); vymax=$(echo "$last" | cut -d, -f8)
awk -v a="$vymin" -v b="$vymax" 'BEGIN { exit !((a + 5.81)^2 < 1e-18 && (b + 5.81)^2 < 1e-18) }' \
    || fail "fieldMinMax velocity_y at t = 1: min $vymin max $vymax, expected -5.81"

# purgeWrite 2 keeps the initial conditions and the newest two written times, in the index too.
p=$(newCase purge)
mfDictionary "$p/system/controlDict" -entry purgeWrite -set 2 > /dev/null
particleFlight -case "$p" > "$p/log" 2>&1 || fail "purgeWrite run failed"
times=$(ls "$p" | grep -E '^[0-9.]+$' | sort -g | tr '\n' ' ')
[ "$times" = "0 0.75 1 " ] || fail "purgeWrite 2 left: $times"
grep -q '0.25/particles.vtp' "$p/particles.pvd" && fail "particles.pvd still lists a purged time"
grep -q '0.75/particles.vtp' "$p/particles.pvd" || fail "particles.pvd lost a kept time"
pass "exact trajectory: position Linf $linf m"
