#!/usr/bin/env bash
# The health check on fpmSolid (issue 20), on the coupled shearing sphere (shear and Euler parts,
# free surface; the coarse lattice of the fpmSolid tests: spacing 1.25, h = 3.75, 280 particles):
# - a NaN planted in particle 3's velocity stops the run: status 1, the log names the health check,
#   the particle, the component (velocity_x), the remedy, and the failing state is written;
# - a speed of 1e8 planted on particle 3 collapses the Courant vote (adjustTimeStep yes): the health
#   check stops the run naming "collapsed" and particle 3 (the vote names its particle);
# - particle 3 planted at x = 50, outside the health check's domainMin/domainMax (the sphere of
#   radius 5 in the box -10 to 10), stops the run naming it;
# - the healthy run's indicators: every particle has at least the fit's minimum of 2(d + 1) = 8
#   neighbours and a reciprocal condition above minReciprocalCondition (counts 0); the health check's
#   cost is reported, not asserted (bench/health measures it);
# - the energy budget's D and W: the imbalance left is forward Euler's first-order gain (halves with
#   dt), on the sphere (free surface) and on the coarse clamped plate (the clamp's W halves too).
. "$(dirname "$0")/common.sh"

base="$WORK/base"
cp -r "$SOURCE/tutorials/fpmSolid/coupledShearingSphere" "$base"
rm -rf "$base"/log.* "$base"/postProcessing "$base"/[0-9]*
sed -i 's/spacing 0.75; }/spacing 1.25; }/' "$base/system/particleGenDict"
sed -i "s/^smoothingLength .*/smoothingLength 3.75;/" "$base/constant/fpmProperties"
grep -q "spacing 1.25; }" "$base/system/particleGenDict" || fail "could not set the spacing"
grep -q "^smoothingLength 3.75;" "$base/constant/fpmProperties" || fail "could not set h"
sed -i 's/^endTime .*/endTime         0.05;/; s/^writeInterval .*/writeInterval   0.05;/' "$base/system/controlDict"
sed -i '/^functions/,/^}/d' "$base/system/controlDict"
particleGen -case "$base" > "$base/log.particleGen" 2>&1 || fail "particleGen: $(tail -n 5 "$base/log.particleGen")"

# faultCase <name> <field> <component> <value> [adjust]: a copy run to t = 0.05 with the fault planted
# at t = 0.01; its exit status in $status, its log in $log.
faultCase() {
    local c="$WORK/$1"
    cp -r "$base" "$c"
    [ "${5:-}" = adjust ] && sed -i 's/^adjustTimeStep .*/adjustTimeStep  yes;\nmaxCo 0.3;/' "$c/system/controlDict"
    plantFault "$c" 0.01 3 "$2" "$3" "$4" "domainMin (-10 -10 -10); domainMax (10 10 10);"
    runFault fpmSolid "$c" "$1" 3 "$2" "$3" "$4"
}

faultCase nan velocity 0 nan
expectNaNStop "velocity_x = nan"

faultCase speed velocity 0 1e8 adjust
expectCollapse

faultCase outside position 0 50
[ "$status" = 1 ] || fail "outside: exit status $status, not 1"
expect outside "health check" "particle 3 at (50 " "left the domain" "Remedy"
echo "outside: $(grep -m1 -o 'particle 3 at [^;]*' "$log")"

# healthyRun <dir> <deltaT> <steps between health writes>: the sphere to t = 0.5 at a fixed step.
healthyRun() {
    cp -r "$base" "$1"
    sed -i "s/^endTime .*/endTime         0.5;/; s/^writeInterval .*/writeInterval   0.5;/; s/^deltaT .*/deltaT $2;/" "$1/system/controlDict"
    echo "functions { health { type health; writeControl timeStep; writeInterval $3; } }" >> "$1/system/controlDict"
    fpmSolid -case "$1" > "$1/log.fpmSolid" 2>&1 || fail "the healthy run at dt $2 failed: $(tail -n 20 "$1/log.fpmSolid")"
}
# The healthy run to t = 0.5 (500 steps), the health check every 50 steps.
c="$WORK/healthy"
healthyRun "$c" 0.001 50
csv="$c/postProcessing/health/0/health.csv"
[ -f "$csv" ] || fail "no $csv"
read -r fewest deficient conditioning illConditioned < <(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) h[$i] = i; next }
    NR == 2 || $h["neighbourDeficiency"] < n { n = $h["neighbourDeficiency"] } NR == 2 || $h["fitConditioning"] < r { r = $h["fitConditioning"] }
    { a += $h["neighbourDeficiency_count"]; b += $h["fitConditioning_count"] }
    END { printf "%s %d %s %d\n", n, a, r, b }' "$csv")
echo "healthy: fewest neighbours $fewest ($deficient below 8), smallest reciprocal condition $conditioning ($illConditioned below 1e-10)"
grep "energy imbalance" "$c/log.fpmSolid" | sed 's/^ *//'
[ "$deficient" = 0 ] && [ "$illConditioned" = 0 ] || fail "the healthy sphere has deficient fits"
awk -v n="$fewest" 'BEGIN { exit !(n >= 8) }' || fail "fewest neighbours $fewest < 8"

# The energy budget (FpmSolver.cpp, "the energy budget"): D holds each stage's loss at forward
# Euler's left point, the free surface's resets; W the velocity conditions' kinetic jumps. What is
# left is forward Euler's own gain per stage, sum m |dv|^2 / 2 + V (dp^2 / 2K + dS:dS / 4 mu) > 0,
# first order in dt over a run: the same run at dt / 2 halves the imbalance, and the part that does
# not shrink (Richardson, 2 I(dt/2) - I(dt)) is the linearised elastic energy's mismatch and
# anything the budget misses (the surface resets left out of D leave -0.385 of the energy there).
lastRow() { awk -F, -v want="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) h[$i] = i; next } { row = $0; split(row, f, ",") }
    END { n = split(want, w, " "); for (k = 1; k <= n; ++k) printf "%s ", f[h[w[k]]]; print "" }' "$1"; }
half="$WORK/healthyHalfStep"
healthyRun "$half" 0.0005 100
read -r K1 D1 W1 I1 < <(lastRow "$csv" "kineticEnergy dissipated externalWork energyImbalance")
read -r K2 D2 W2 I2 < <(lastRow "$half/postProcessing/health/0/health.csv" "kineticEnergy dissipated externalWork energyImbalance")
E0=$(awk -F, 'NR == 2 { print $5 }' "$csv")
echo "budget at t = 0.5 (E0 $E0): dt 1e-3: D $D1, W $W1, imbalance $I1; dt 5e-4: D $D2, W $W2, imbalance $I2"
awk -v d="$D1" -v e="$E0" 'BEGIN { exit !(d > 0.3 * e) }' || fail "the upwinded sphere dissipates D = $D1, expected > 0.3 E0 (0.65 measured)"
awk -v a="$I1" -v b="$I2" 'BEGIN { r = a / b; printf "imbalance ratio dt / (dt/2): %.3f\n", r; exit !(a > 0 && r > 1.8 && r < 2.2) }' ||
    fail "the imbalance is not forward Euler's first-order gain: $I1 at dt, $I2 at dt / 2"
awk -v a="$I1" -v b="$I2" -v e="$E0" 'BEGIN { r = (2 * b - a) / e; printf "remainder 2 I(dt/2) - I(dt): %.2e of E0\n", r; exit !(r < 1e-3 && r > -1e-3) }' ||
    fail "the budget leaves an imbalance that does not shrink with dt"

# The clamp's work (W) on the coarse oscillating plate of tutorials/fpmSolid (4 mm, to 0.04 s): the
# fixed condition removes each step's velocity change of the clamped particles, a kinetic jump of
# O(dt^2) a step, so W < 0 halves with maxCo, as the imbalance does.
for co in 0.3 0.15; do
    plate="$WORK/plate$co"
    cp -r "$SOURCE/tutorials/fpmSolid/oscillatingPlate" "$plate"
    rm -rf "$plate"/log.* "$plate"/postProcessing "$plate"/[0-9]*
    sed -i 's/spacing 0.002;/spacing 0.004;/' "$plate/system/particleGenDict"
    sed -i "s/^maxCo .*/maxCo $co;/; s/^endTime .*/endTime 0.04;/; s/^writeInterval .*/writeInterval 0.04;/" "$plate/system/controlDict"
    sed -i '/^functions/,/^}/d' "$plate/system/controlDict"
    echo 'functions { health { type health; writeControl adjustableRunTime; writeInterval 0.04; } }' >> "$plate/system/controlDict"
    particleGen -case "$plate" > "$plate/log.particleGen" 2>&1 || fail "particleGen on the plate"
    fpmSolid -case "$plate" > "$plate/log.fpmSolid" 2>&1 || fail "the plate at maxCo $co failed: $(tail -n 20 "$plate/log.fpmSolid")"
done
read -r W1 I1 < <(lastRow "$WORK/plate0.3/postProcessing/health/0/health.csv" "externalWork energyImbalance")
read -r W2 I2 < <(lastRow "$WORK/plate0.15/postProcessing/health/0/health.csv" "externalWork energyImbalance")
echo "plate at 0.04 s: maxCo 0.3: W $W1, imbalance $I1; maxCo 0.15: W $W2, imbalance $I2"
awk -v a="$W1" -v b="$W2" 'BEGIN { r = a / b; printf "clamp work ratio: %.3f\n", r; exit !(a < 0 && r > 1.8 && r < 2.2) }' ||
    fail "the clamp's work is not the kinetic jumps of O(dt^2) a step: $W1, $W2"
awk -v a="$I1" -v b="$I2" 'BEGIN { r = a / b; printf "plate imbalance ratio: %.3f\n", r; exit !(a > 0 && r > 1.7 && r < 2.6) }' ||
    fail "the plate's imbalance is not first order in dt: $I1, $I2"

cost=$(sed -n 's/.*; cost \([0-9.e+-]*\)% of the run.*/\1/p' "$c/log.fpmSolid")
echo "health cost $cost% of the run"
[ -n "$cost" ] || fail "no cost in the health summary"
echo "PASS: health.fpmSolid"
