# The energy-growth stop (conservedQuantities' maxEnergyGrowth, issue 16): a planted instability,
# the oscillating plate at dx = 4 mm (h = 1.3 dx) run at maxCo 1 with the momentum eps4 at 0.02, far below the
# RK2 floor maxCo^3/8 = 0.125 (doc/methods/tl-jst-sph.md App. C: anti-diffusive at short
# wavelengths), grows its energy by orders of magnitude within a few dozen steps (measured: 57-fold
# by step 45). With `maxEnergyGrowth 10;` the run must stop there, with exit status 1, a diagnosis
# that names the growth, the energies, the fastest particle and the remedies, and the state it
# judged written and finite (not a NaN state that the solver's own check would catch later).
source "$(dirname "$0")/common.sh"
c="$WORK/plate"
coarsePlate "$c"
sed -i 's/^maxCo .*/maxCo           1;/; s/^endTime .*/endTime         0.3;/' "$c/system/controlDict"
sed -i 's/type conservedQuantities; writeControl timeStep; writeInterval 200;/type conservedQuantities; writeControl timeStep; writeInterval 5; maxEnergyGrowth 10;/' \
    "$c/system/controlDict"
grep -q "maxEnergyGrowth 10;" "$c/system/controlDict" || fail "could not set maxEnergyGrowth in the tutorial's controlDict"
sed -i 's/momentum (0 0.125)/momentum (0 0.02)/' "$c/constant/tlSphProperties"
grep -q "momentum (0 0.02)" "$c/constant/tlSphProperties" || fail "could not lower the momentum eps4"
# The solver's own energy check (energyGrowthLimit, on by default: tests/cases/tlSph/
# energyGrowthDefault.sh) would stop this run first (4.7-fold at step 40); set far above the growth
# here so that the function object's check is the one measured.
echo "energyGrowthLimit 1e12;" >> "$c/constant/tlSphProperties"
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail "$c/log.particleGen")"
set +e
tlSph -case "$c" > "$c/log.tlSph" 2>&1
status=$?
set -e
[ "$status" -eq 1 ] || fail "exit status $status, expected 1: $(tail -n 20 "$c/log.tlSph")"
log="$c/log.tlSph"
grep -q "^Error: conservedQuantities 'conserved' at step [0-9]*, t = .*: the total energy grew .*-fold (0.00125 -> .*), above maxEnergyGrowth 10\.$" "$log" \
    || fail "no energy-growth diagnosis: $(grep -A4 '^Error' "$log")"
grep -q "^    Now: kineticEnergy .* internalEnergy .* totalEnergy " "$log" || fail "the diagnosis does not give the energies"
grep -q "^    Fastest particle: globalId [0-9]* at (" "$log" || fail "the diagnosis does not name the fastest particle"
grep -q "reduce maxCo (system/controlDict)" "$log" || fail "the diagnosis gives no remedy"
grep -q "has J = \|no longer finite" "$log" && fail "the solver's state check fired, not the energy check"
# Stopped early (within the first 0.01 s of 0.3 s), the state written under the time it stopped at.
stop=$(sed -n "s/^Error: conservedQuantities 'conserved' at step [0-9]*, t = \([0-9.e-]*\):.*/\1/p" "$log")
awk -v t="$stop" 'BEGIN { exit !(t > 0 && t < 0.01) }' || fail "stopped at t = $stop, expected within 0.01 s"
written=$(sed -n 's|^Wrote the failing state to \(.*\)/$|\1|p' "$log")
[ -n "$written" ] && [ -f "$c/$written/particles.vtp" ] || fail "no failing state written: $(tail -n 5 "$log")"
particleInfo -case "$c" -time "$written" > "$c/log.particleInfo" 2>&1 || fail "particleInfo: $(tail "$c/log.particleInfo")"
grep -qi "nan\|inf " "$c/log.particleInfo" && fail "the written state is not finite: $(grep -i 'nan\|inf ' "$c/log.particleInfo")"
grep -q "velocity" "$c/log.particleInfo" || fail "particleInfo lists no velocity"
echo "PASS: energy growth stopped at t = $stop with its diagnosis, state $written finite"
