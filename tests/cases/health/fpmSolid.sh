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
#   cost is reported, not asserted (bench/health measures it).
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

# The healthy run to t = 0.5 (500 steps), the health check every 50 steps.
c="$WORK/healthy"
cp -r "$base" "$c"
sed -i 's/^endTime .*/endTime         0.5;/; s/^writeInterval .*/writeInterval   0.5;/' "$c/system/controlDict"
cat >> "$c/system/controlDict" << EOF
functions { health { type health; writeControl timeStep; writeInterval 50; } }
EOF
fpmSolid -case "$c" > "$c/log.fpmSolid" 2>&1 || fail "the healthy run failed: $(tail -n 20 "$c/log.fpmSolid")"
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
cost=$(sed -n 's/.*; cost \([0-9.e+-]*\)% of the run.*/\1/p' "$c/log.fpmSolid")
echo "health cost $cost% of the run"
[ -n "$cost" ] || fail "no cost in the health summary"
echo "PASS: health.fpmSolid"
