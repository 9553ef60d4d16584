# A coarse Al-Pb impact (density ratio 4) runs to 20 µs without NaN or a collapsing time step.
. "$(dirname "$0")/common.sh"
c=$(coarseCase hviAlPb 5e-4)
impactSph -case "$c" > "$c/log" 2>&1 || fail "impactSph failed: $(tail -5 "$c/log")"
grep -q "wrote 2e-05" "$c/log" || fail "did not reach 20 us: $(tail -5 "$c/log")"
# The last step may not have shrunk below a tenth of the first adjusted one.
first=$(grep "^Step" "$c/log" | head -n 1 | awk '{print $8}')
last=$(grep "^Step" "$c/log" | tail -n 2 | head -n 1 | awk '{print $8}')
less "$(awk -v a="$first" 'BEGIN { print a / 10 }')" "$last" || fail "time step collapsed from $first to $last"
energy=$(drift "$c/log" totalEnergy)
less "$(abs "$energy")" 1e-3 || fail "total energy drift $energy"
pass "hviAlPb coarse: reached 20 us, dt $first -> $last, energy drift $energy"
