# The health check's energy budget on tlSph over longer runs (the short ones are in
# tests/cases/health/tlSph.sh, with the bound's derivation):
#   - the spinning cube, ten revolutions at maxCo 0.3 and 0.15: |K + U + D - W| within
#     E (w dt)^2 w T / 3; after the first revolution (the start's transient damped) the imbalance
#     grows by the RK2's energy gain on the cube's elastic oscillation, E (w dt)^4 / 4 a step for a
#     mode of frequency w: O(dt^3) per unit time, so halving maxCo divides that growth by 8 (at least
#     5 asserted), and the JST dissipation removes the same energy (D grows alike);
#   - the oscillating plate on the tutorial's lattice (dx = 1.54 mm, h = 1.1 dx), one period:
#     |imbalance| below 1% of what JST dissipated (about 3 CPU-minutes).
source "$(dirname "$0")/../tlSph/common.sh"
column0() { column "$1" "$2" | awk 'NR == 1'; }
largestAbs() { column "$1" "$2" | awk '{ a = $1 < 0 ? -$1 : $1; if (a > m) m = a } END { printf "%.9g\n", m }'; }
addHealth() {
    sed -i "/^functions/{n;s/^{\$/{\n    health { $2 }/}" "$1/system/controlDict"
    grep -q "health { $2 }" "$1/system/controlDict" || fail "could not add health to $1"
}
spin() {  # spin <case> <maxCo>: ten revolutions
    copyTutorial spinningCube "$1"
    sed -i "s/^maxCo .*/maxCo $2;/; s/^endTime .*/endTime 0.5984;/; s/^writeInterval .*/writeInterval 0.05984;/" \
        "$1/system/controlDict"
    addHealth "$1" "type health; writeControl timeStep; writeInterval 1;"
    particleGen -case "$1" > "$1/log.particleGen" 2>&1 || fail "particleGen"
    run "$1" tlSph
}
# growth <csv>: the imbalance's growth per revolution from the second to the tenth.
growth() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "time") t = i; if ($i == "energyImbalance") k = i }; next }
             $t <= 0.05984 { a = $k } { b = $k } END { printf "%.6g\n", (b - a) / 9 }' "$1"
}
spin "$WORK/s30" 0.3
spin "$WORK/s15" 0.15
csv="$WORK/s30/postProcessing/health/0/health.csv"
E=$(column0 "$csv" kineticEnergy)
dt=$(column "$csv" stableDeltaT | awk 'NR > 1 && $1 > m { m = $1 } END { print m }')
bound=$(awk -v E="$E" -v dt="$dt" 'BEGIN { w = 105; T = 0.5984; printf "%.6g\n", E * (w * dt)^2 * w * T / 3 }')
I=$(largestAbs "$csv" energyImbalance)
awk -v I="$I" -v b="$bound" 'BEGIN { exit !(I < b) }' || fail "ten revolutions: |imbalance| $I above the bound $bound"
g30=$(growth "$csv")
g15=$(growth "$WORK/s15/postProcessing/health/0/health.csv")
awk -v a="$g30" -v b="$g15" 'BEGIN { a = a < 0 ? -a : a; b = b < 0 ? -b : b; exit !(a > 5 * b) }' \
    || fail "imbalance growth per revolution $g30 at maxCo 0.3, $g15 at 0.15: not O(dt^3)"

p="$WORK/plate"
copyTutorial oscillatingPlate "$p"
sed -i 's/^endTime .*/endTime         0.26;/; s/^writeInterval .*/writeInterval   0.026;/' "$p/system/controlDict"
particleGen -case "$p" > "$p/log.particleGen" 2>&1 || fail "particleGen"
run "$p" tlSph  # the default health, at the writes
pcsv="$p/postProcessing/health/0/health.csv"
pD=$(column "$pcsv" dissipated | tail -n 1)
pI=$(largestAbs "$pcsv" energyImbalance)
awk -v I="$pI" -v D="$pD" 'BEGIN { exit !(D > 0 && I < 0.01 * D) }' || fail "plate: |imbalance| $pI not below 1% of D $pD"
echo "PASS: tlSph health budget: ten revolutions |imbalance| <= $I (bound $bound), growth per revolution $g30 (maxCo 0.3) and $g15 (0.15); tutorial plate |imbalance| <= $pI against D $pD; $(grep -o 'cost [0-9.e+-]*% of the run' "$p/log.tlSph")"
