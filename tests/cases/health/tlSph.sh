# The health check on tlSph (issue 20): the energy budget K + U + D - W closes to the TVD RK2's
# time error, the indicators read what they should on a healthy run and on one without its
# stabilisation, and planted faults stop the run with a diagnosis (phase, particle, field, remedy)
# and the failing state written. About 15 s on one thread.
#
# The budget's bound (libraries/tlSph/TlSphSolver.cpp, the energy budget): D and W are the
# trapezoid dt/2 (P1 + P2) of the stage powers, and K + U changes by the RK2 update; the two differ
# per step by the trapezoid's error dt^3/12 |P''|. Energy exchanged between K and U at amplitude E
# by a motion of angular frequency w is a power E w sin(2 w t), |P''| <= 4 E w^3: over a time T
#     |imbalance| <= E (w dt)^2 w T / 3,           O(dt^2) per unit time,
# and halving dt divides it by 4 (at least 3 asserted: an unaccounted loss or a first-order error
# would divide it by 1 or 2). A mode that JST damps within a few steps adds a part proportional to
# what it dissipates, (lambda dt)^3 / 8 of it for a damping rate lambda (the trapezoid of a linear
# damped mode against its RK2 update): below 1% for lambda dt < 0.43, which bounds the oscillating
# plate, whose start excites short waves that JST removes in its first milliseconds.
source "$(dirname "$0")/../tlSph/common.sh"
source "$(dirname "$0")/faults.sh"
export MFDYN_LIBRARY_PATH="$BUILD/testLibraries"
# health <case> <entries>: a health entry of its own in the case's functions (replacing the default).
health() {
    sed -i "/^functions/{n;s/^{\$/{\n    health { $2 }/}" "$1/system/controlDict"
    grep -q "health { $2 }" "$1/system/controlDict" || fail "could not add health to $1"
}
csvOf() { echo "$1/postProcessing/health/0/health.csv"; }
largestAbs() { column "$1" "$2" | awk '{ a = $1 < 0 ? -$1 : $1; if (a > m) m = a } END { printf "%.9g\n", m }'; }
last() { column "$1" "$2" | tail -n 1; }

# 1. The spinning cube, one revolution (6^3 particles, 0.06 s): the budget and the indicators.
spin() {  # spin <case> <maxCo>
    copyTutorial spinningCube "$1"
    sed -i "s/^maxCo .*/maxCo $2;/" "$1/system/controlDict"
    health "$1" "type health; writeControl timeStep; writeInterval 1;"
    particleGen -case "$1" > "$1/log.particleGen" 2>&1 || fail "particleGen: $(tail "$1/log.particleGen")"
    run "$1" tlSph
}
c="$WORK/spin"
spin "$c" 0.3
csv=$(csvOf "$c")
E=$(column "$csv" kineticEnergy | awk 'NR == 1')
D=$(last "$csv" dissipated)
I=$(largestAbs "$csv" energyImbalance)
Iend=$(last "$csv" energyImbalance)
dt=$(column "$csv" stableDeltaT | awk 'NR > 1 && $1 > m { m = $1 } END { print m }')
bound=$(awk -v E="$E" -v dt="$dt" 'BEGIN { w = 105; T = 0.05984; printf "%.6g\n", E * (w * dt)^2 * w * T / 3 }')
awk -v D="$D" -v E="$E" 'BEGIN { exit !(D > 0.02 * E && D < 0.1 * E) }' || fail "JST dissipated $D of $E (expected 2-10%)"
awk -v I="$I" -v b="$bound" 'BEGIN { exit !(I < b) }' || fail "spinning cube: largest |imbalance| $I above the bound $bound"
awk -v I="$Iend" -v D="$D" 'BEGIN { a = I < 0 ? -I : I; exit !(a < 0.02 * D) }' \
    || fail "spinning cube: imbalance $Iend after a revolution, not far below the dissipated $D"
# The step's order: maxCo 0.15 and 0.075 (the largest |imbalance| falls 4-fold per halving at O(dt^2)).
spin "$WORK/spin15" 0.15
spin "$WORK/spin075" 0.075
I15=$(largestAbs "$(csvOf "$WORK/spin15")" energyImbalance)
I075=$(largestAbs "$(csvOf "$WORK/spin075")" energyImbalance)
awk -v a="$I15" -v b="$I075" 'BEGIN { exit !(a > 3 * b) }' || fail "imbalance $I15 at maxCo 0.15, $I075 at 0.075: not O(dt^2)"
# Indicators of the healthy run: no hourglass past 0.2, the corner's conditioning (0.316, the unit
# test's), no particle compressed.
[ "$(largestAbs "$csv" hourglass_count)" = 0 ] || fail "hourglass past its threshold on the spinning cube with JST"
hg=$(largestAbs "$csv" hourglass)
cond=$(last "$csv" neighbourDeficiency)
awk -v c="$cond" 'BEGIN { exit !(c > 0.31 && c < 0.32) }' || fail "neighbourDeficiency $cond, expected the corner's 0.316"
[ "$(largestAbs "$csv" neighbourDeficiency_count)" = 0 ] || fail "neighbourDeficiency counted particles"
[ "$(largestAbs "$csv" compression_count)" = 0 ] || fail "compression counted particles"
cost=$(grep -o "cost [0-9.e+-]*% of the run" "$c/log.tlSph") || fail "no cost in the health summary"
# Without JST the hourglass modes are free: the indicator must see them within the revolution.
n="$WORK/noJst"
copyTutorial spinningCube "$n"
sed -i 's/^dissipation .*/dissipation          { type none; }/' "$n/constant/tlSphProperties"
health "$n" "type health; writeControl timeStep; writeInterval 1;"
particleGen -case "$n" > "$n/log.particleGen" 2>&1 || fail "particleGen"
run "$n" tlSph
hgFree=$(largestAbs "$(csvOf "$n")" hourglass)
[ "$(largestAbs "$(csvOf "$n")" hourglass_count)" != 0 ] || fail "no hourglass counted without JST (largest $hgFree)"
grep -q "Warning: health: .* past the hourglass threshold" "$n/log.tlSph" || fail "no hourglass warning without JST"

# 2. The oscillating plate on the 4 mm lattice, one period (0.26 s).
p="$WORK/plate"
coarsePlate "$p"
sed -i 's/^endTime .*/endTime         0.26;/' "$p/system/controlDict"
health "$p" "type health; writeControl timeStep; writeInterval 20;"
particleGen -case "$p" > "$p/log.particleGen" 2>&1 || fail "particleGen"
run "$p" tlSph
pcsv=$(csvOf "$p")
pD=$(last "$pcsv" dissipated)
pI=$(largestAbs "$pcsv" energyImbalance)
pE=$(column "$pcsv" kineticEnergy | awk 'NR == 1')
awk -v D="$pD" -v E="$pE" 'BEGIN { exit !(D > 1e-3 * E) }' || fail "plate: dissipated $pD of $pE"
awk -v I="$pI" -v D="$pD" 'BEGIN { exit !(I < 0.01 * D) }' || fail "plate: largest |imbalance| $pI not below 1% of the dissipated $pD"
[ "$(largestAbs "$pcsv" hourglass_count)" = 0 ] || fail "hourglass past its threshold on the plate"
pcost=$(grep -o "cost [0-9.e+-]*% of the run" "$p/log.tlSph")

# 3. Planted faults at t = 0.01 on particle 43 of the spinning cube (inside, next to a corner).
plant() {  # plant <name> <field> <component> <value>
    local f="$WORK/$1"
    copyTutorial spinningCube "$f"
    particleGen -case "$f" > "$f/log.particleGen" 2>&1 || fail "particleGen"
    plantFault "$f" 0.01 43 "$2" "$3" "$4" "domainMin (-2 -2 -2); domainMax (3 3 3);"
    if tlSph -case "$f" > "$f/log.tlSph" 2>&1; then fail "$1: the run did not stop"; else status=$?; fi
    [ "$status" = 1 ] || fail "$1: exit status $status, not 1"
}
plant nan velocity 0 nan
l="$WORK/nan/log.tlSph"
for word in "health check" "particle 43" "velocity_x = nan" "Remedy"; do
    grep -q "$word" "$l" || fail "the NaN's diagnosis does not name '$word': $(grep -A2 Error "$l")"
done
[ -d "$WORK/nan/0.01" ] || fail "the NaN's failing state was not written"
# A velocity of 1e8: tlSph's step is the CFL of c_p (x stretch), which the speed does not enter, so
# the next stage's F inverts the planted particle's neighbours: tlSph's own state check stops it.
plant fast velocity 0 1e8
l="$WORK/fast/log.tlSph"
for word in "phase stage 1" "particle " "J = -" "Remedies"; do
    grep -q -- "$word" "$l" || fail "the fast particle's diagnosis does not name '$word': $(grep -A2 Error "$l")"
done
ls -d "$WORK"/fast/0.01?* > /dev/null 2>&1 || fail "the fast particle's failing state was not written"
# A stretch of 1e5 collapses the step (c_p x stretch): the vote names the particle.
plant stretched deformationGradient 0 1e5
l="$WORK/stretched/log.tlSph"
for word in "health check" "collapsed" "particle 43" "Remedy"; do
    grep -q "$word" "$l" || fail "the collapse's diagnosis does not name '$word': $(grep -A2 Error "$l")"
done
plant outside position 0 5
l="$WORK/outside/log.tlSph"
for word in "health check" "particle 43 at (5 " "left the domain" "Remedy"; do
    grep -q "$word" "$l" || fail "the domain's diagnosis does not name '$word': $(grep -A2 Error "$l")"
done
echo "PASS: tlSph health: spinning cube |imbalance| <= $I (bound $bound, end $Iend against D $D of E $E; $I15 at maxCo 0.15, $I075 at 0.075), hourglass $hg ($hgFree without JST), conditioning $cond, $cost; plate |imbalance| <= $pI against D $pD, $pcost; NaN, collapse, domain diagnosed, the 1e8 speed by tlSph's state check"
