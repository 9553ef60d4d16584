# Monaghan's artificial stress on the coarse Al-Al impact: momentum kept to round-off (its pair
# force is antisymmetric) and total energy within 1e-3 (its work enters the energy equation;
# without that term the drift was 3e-3).
. "$(dirname "$0")/common.sh"
c=$(coarseCase hviAlAl 5e-4)
echo "artificialStress { epsilon 0.3; exponent 4; }" >> "$c/constant/sphProperties"
impactSph -case "$c" > "$c/log" 2>&1 || fail "impactSph failed: $(tail -5 "$c/log")"
energy=$(drift "$c/log" totalEnergy)
less "$(abs "$energy")" 1e-3 || fail "total energy drift $energy"
dp=$(grep "momentum_y change" "$c/log" | awk '{print $4}')
less "$(abs "$dp")" 1.35e-9 || fail "momentum_y change $dp"
pass "artificial stress: energy drift $energy, momentum change $dp"
