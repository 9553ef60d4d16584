#!/usr/bin/env bash
# The health check on mpmFsi (issue 20), on the twoDisks tutorial (632 particles, 20 x 20 cells):
# - a NaN planted in particle 3's velocity stops the run: status 1, the log names the health check,
#   the particle, the component (velocity_x), the remedy, and the failing state is written;
# - a speed of 1e8 m/s planted on particle 3 collapses the CFL vote (adjustTimeStep yes): the
#   health check stops the run naming "collapsed" and particle 3 (the vote names its particle);
# - particle 3 planted outside the grid (x = 5, the grid spans [0, 1]) stops the run naming it: the
#   solver's own check (phase preStep of the next step: the particle, its body, the grid's span, the
#   remedies; MpmSolver.hpp says why the grid is not the health check's domain); with a health
#   { domainMin (0 0); domainMax (1 1); } box the health check stops it first, at the end of the
#   step, with the state written;
# - the energy budget of the healthy run to t = 3 (the collision: contact from t = 1.22, the
#   kinetic-energy minimum at 2.145): K + U + D - W (D the transfers' loss, W the grid conditions'
#   and damping's work: none here, W = 0 exactly) stays within the bound of the time integration,
#   |imbalance| <= 2e / (1 - e) (K + U), e = omega_max dt / 2, omega_max = 2 sqrt(2) c_p / dx the
#   highest frequency of the lumped bilinear grid (c_p = 1.16 m/s, dx = 0.05, dt = 1e-4: 6.6e-3):
#   symplectic Euler keeps a modified energy within e of the energy of each mode (the derivation is
#   at the top of MpmSolver.cpp); measured 3.6e-3, all of it at the collision;
# - the health check's cost is reported, not asserted (a timed test fails on a loaded machine:
#   bench/health measures it; 2.9% on the MPM Taylor bar there).
. "$(dirname "$0")/common.sh"

base="$WORK/base"
cp -r "$SOURCE/tutorials/mpmFsi/twoDisks" "$base"
rm -rf "$base"/log.* "$base"/postProcessing "$base"/[0-9]* "$base"/multiField
particleGen -case "$base" > "$base/log.particleGen" 2>&1 || fail "particleGen: $(tail -n 5 "$base/log.particleGen")"

# faultCase <name> <field> <component> <value> [adjust | box]: a copy run to t = 0.05 with the fault
# planted at t = 0.01 (adjust: adjustTimeStep yes; box: the health check's box is the grid's); its
# exit status in $status, its log in $log.
faultCase() {
    local c="$WORK/$1" box=""
    cp -r "$base" "$c"
    sed -i 's/^endTime .*/endTime         0.05;/; s/^writeInterval .*/writeInterval   0.05;/' "$c/system/controlDict"
    [ "${5:-}" = adjust ] && sed -i 's/^adjustTimeStep .*/adjustTimeStep  yes;/' "$c/system/controlDict"
    [ "${5:-}" = box ] && box="domainMin (0 0); domainMax (1 1);"
    # the tutorial's functions replaced: the plant, then the health check that must see it
    plantFault "$c" 0.01 3 "$2" "$3" "$4" "$box"
    runFault mpmFsi "$c" "$1" 3 "$2" "$3" "$4"
}

faultCase nan velocity 0 nan
expectNaNStop "velocity_x = nan"

faultCase speed velocity 0 1e8 adjust
expectCollapse

faultCase outside position 0 5
[ "$status" = 1 ] || fail "outside: exit status $status, not 1"
expect outside "phase preStep" "particle 3 (body lower) at (5 " "has left the grid" "Remedies"
echo "outside: $(grep -m1 -o 'phase preStep.*has left the grid' "$log")"

faultCase box position 0 5 box
[ "$status" = 1 ] || fail "box: exit status $status, not 1"
expect box "health check" "particle 3 at (5 " "left the domain" "Remedy" "Wrote the failing state to"
echo "box: $(grep -m1 -o 'health check.*left the domain [^;]*' "$log")"

# The healthy run to t = 3, the budget every 100 steps.
c="$WORK/budget"
cp -r "$base" "$c"
sed -i 's/^    conserved .*/    health { type health; writeControl timeStep; writeInterval 100; }/' "$c/system/controlDict"
grep -q "type health; writeControl timeStep" "$c/system/controlDict" || fail "could not set the health check's writes"
mpmFsi -case "$c" > "$c/log.mpmFsi" 2>&1 || fail "the healthy run failed: $(tail -n 20 "$c/log.mpmFsi")"
csv="$c/postProcessing/health/0/health.csv"
[ -f "$csv" ] || fail "no $csv"
read -r largest dissipated work smallMass < <(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) h[$i] = i; next }
    { r = $h["relativeImbalance"]; if (r < 0) r = -r; if (r > w) w = r; d = $h["dissipated"]; x = $h["externalWork"]; s = $h["smallMassNodes"]; if (s > m) m = s }
    END { printf "%.6g %.6g %.6g %.6g\n", w, d, x, m }' "$csv")
bound=$(awk 'BEGIN { E = 1000; nu = 0.3; M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)); c = sqrt(M / 1000); e = sqrt(2) * c / 0.05 * 1e-4; printf "%.4g\n", 2 * e / (1 - e) }')
echo "budget: largest |imbalance| $largest of K + U (bound 2e / (1 - e) = $bound); transfers' loss D = $dissipated J/m, external work $work; smallMassNodes up to $smallMass"
grep "energy imbalance" "$c/log.mpmFsi" | sed 's/^ *//'
awk -v a="$largest" -v b="$bound" 'BEGIN { exit !(a <= b) }' || fail "the energy imbalance $largest exceeds the bound $bound"
awk -v w="$work" 'BEGIN { exit !(w == 0) }' || fail "external work $work without grid conditions or damping"
# spring1D (the hanging bar, gravity, grid damping alpha_d = 15 1/s, v_y = 0 on the top nodes), to
# t = 2: W (the damping's and the fixed nodes') and D measured, the imbalance within the same
# bound for the bar's grid (omega_max = 2 c / dy, c = sqrt(E / rho) = 8.165 m/s at nu = 0, dy =
# 1/21, dt = 1e-4: 2e / (1 - e) = 0.0349) times the largest K + U, and no drift once the bar has
# come to rest (t = 1 to 2: the imbalance changes by less than 1e-6 J; a fixed node's reaction
# on the FLIP particles' persistent velocity there must not count as work).
s="$WORK/spring"
cp -r "$SOURCE/tutorials/mpmFsi/spring1D" "$s"
rm -rf "$s"/log.* "$s"/postProcessing "$s"/[0-9]*
sed -i 's/^    conserved .*/    health { type health; writeControl timeStep; writeInterval 100; }/' "$s/system/controlDict"
grep -q "type health; writeControl timeStep" "$s/system/controlDict" || fail "could not set spring1D's health writes"
particleGen -case "$s" > "$s/log.particleGen" 2>&1 || fail "particleGen on spring1D"
mpmFsi -case "$s" > "$s/log.mpmFsi" 2>&1 || fail "spring1D failed: $(tail -n 20 "$s/log.mpmFsi")"
read -r worst scale drift sW sD < <(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) h[$i] = i; next }
    { r = $h["energyImbalance"]; a = r < 0 ? -r : r; if (a > w) w = a; e = $h["kineticEnergy"] + $h["internalEnergy"]; if (e > m) m = e
      if ($1 + 0 == 1) one = r; if ($1 + 0 == 2) two = r; W = $h["externalWork"]; D = $h["dissipated"] }
    END { d = two - one; if (d < 0) d = -d; printf "%.6g %.6g %.6g %.6g %.6g\n", w, m, d, W, D }' "$s/postProcessing/health/0/health.csv")
springBound=$(awk -v m="$scale" 'BEGIN { e = 8.1649658 / (1 / 21) * 1e-4; printf "%.4g\n", 2 * e / (1 - e) * m }')
echo "spring1D: largest |imbalance| $worst J/m (bound $springBound: 0.0349 of the largest K + U $scale), drift from t = 1 to 2 $drift J/m; W $sW, D $sD"
awk -v a="$worst" -v b="$springBound" 'BEGIN { exit !(a <= b) }' || fail "spring1D's imbalance $worst exceeds $springBound"
awk -v d="$drift" 'BEGIN { exit !(d < 1e-6) }' || fail "spring1D's imbalance drifts by $drift J/m at rest"
awk -v w="$sW" 'BEGIN { exit !(w < -0.1) }' || fail "spring1D's external work $sW: the damping's is missing"

cost=$(sed -n 's/.*; cost \([0-9.e+-]*\)% of the run.*/\1/p' "$c/log.mpmFsi")
echo "health cost $cost% of the run"
[ -n "$cost" ] || fail "no cost in the health summary"
echo "PASS: health.mpmFsi"
