# Sod's tube: the SPH sums are pairwise antisymmetric and the dissipation total-energy consistent
# (doc/methods/sph-impact.md 3, 4.28), so mass is exact (particle masses never change), momentum changes only
# by round-off (~900 pair sums of O(1) terms, eps 2.2e-16: ~1e-16..1e-15; bound 1e-12 x total mass
# x a typical speed of 1), and the leapfrog's total-energy drift is second order in dt (the run
# gives 1.9e-7 relative; bound 1e-4).
. "$(dirname "$0")/common.sh"
c=$(newCase "$SOURCE/sodShockTube" sod)
wall=$(runCase "$c")
csv="$c/postProcessing/conserved/0/conservedQuantities.csv"
[ "$(head -n 1 "$csv")" = "time,mass,momentum_x,kineticEnergy,internalEnergy,totalEnergy" ] || fail "header: $(head -n 1 "$csv")"
first=$(sed -n 2p "$csv"); last=$(tail -n 1 "$csv")
[ "$(echo "$last" | cut -d, -f1)" = 0.2 ] || fail "last conserved row at t = $(echo "$last" | cut -d, -f1)"
m0=$(echo "$first" | cut -d, -f2); m1=$(echo "$last" | cut -d, -f2)
[ "$m0" = "$m1" ] || fail "mass changed: $m0 -> $m1"
p0=$(echo "$first" | cut -d, -f3); p1=$(echo "$last" | cut -d, -f3)
dp=$(awk -v a="$p0" -v b="$p1" 'BEGIN { d = b - a; if (d < 0) d = -d; printf "%.3e", d }')
less "$dp" "$(awk -v m="$m0" 'BEGIN { print 1e-12 * m * 1 }')" || fail "momentum change $dp"
E0=$(echo "$first" | cut -d, -f6); E1=$(echo "$last" | cut -d, -f6)
dE=$(relErr "$E1" "$E0")
less "$dE" 1e-4 || fail "total energy drift $dE relative ($E0 -> $E1)"
grep -q "totalEnergy drift" "$c/log.impactSph" || fail "the log's Diagnostics lack the energy drift"
pass "Sod conservation: mass $m0 -> $m1, momentum change $dp, energy drift $dE relative, wall time $wall s"
