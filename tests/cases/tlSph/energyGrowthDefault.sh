# The solver's energy-growth stop, on by default (tlSphProperties' energyGrowthLimit 1.5; issue 16:
# "a run whose energy grows by more than a set factor stops with a diagnosis instead of running
# on"): the planted instability of energyGrowth.sh (the 4 mm plate at maxCo 1 with the momentum eps4
# 0.02, far below the RK2 floor maxCo^3/8 = 0.125), with no function object asked to watch it. The
# check compares E = kinetic + internal with the energy put in, E(0) + the work of the boundary
# conditions and body forces (TlSphSolver.cpp): here E(0) = 0.00125 J and the clamp does no work,
# so E > 1.5 E(0) must stop the run within the first 0.01 s of 0.3 s (measured: 4.65 times at step
# 40, t = 0.0021), with exit status 1, a diagnosis naming the growth, the energies, the fastest
# particle and the remedies, and the state it judged written and finite. A stable run of the same
# plate (maxCo 0.3, eps4 1/8: tlSph.oscillatingPlate, tlSph.pFJPlate) never trips it.
source "$(dirname "$0")/common.sh"
c="$WORK/plate"
coarsePlate "$c"
sed -i 's/^maxCo .*/maxCo           1;/; s/^endTime .*/endTime         0.3;/' "$c/system/controlDict"
sed -i 's/momentum (0 0.125)/momentum (0 0.02)/' "$c/constant/tlSphProperties"
grep -q "momentum (0 0.02)" "$c/constant/tlSphProperties" || fail "could not lower the momentum eps4"
grep -q "energyGrowthLimit" "$c/constant/tlSphProperties" && fail "the tutorial sets energyGrowthLimit: this test is of the default"
grep -q "maxEnergyGrowth" "$c/system/controlDict" && fail "the tutorial's conservedQuantities watches the energy: this test is of the solver's check"
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail "$c/log.particleGen")"
set +e
tlSph -case "$c" > "$c/log.tlSph" 2>&1
status=$?
set -e
log="$c/log.tlSph"
[ "$status" -eq 1 ] || fail "exit status $status, expected 1: $(tail -n 20 "$log")"
grep -q "^Error: phase energyGrowth, step [0-9]*, t = .*: the total energy (kinetic + internal) grew to .* times the energy put in 0.00125 J .* above energyGrowthLimit 1.5 (constant/tlSphProperties): the scheme is unstable\.$" "$log" \
    || fail "no energy-growth diagnosis: $(grep -A4 '^Error' "$log")"
grep -q "^    Now: kinetic .* J, internal .* J\.$" "$log" || fail "the diagnosis does not give the energies"
grep -q "^    Fastest particle: global id [0-9]* (reference position" "$log" || fail "the diagnosis does not name the fastest particle"
grep -q "reduce the Courant number (maxCo in system/controlDict" "$log" || fail "the diagnosis gives no remedy"
stop=$(sed -n 's/^Error: phase energyGrowth, step [0-9]*, t = \([0-9.e-]*\):.*/\1/p' "$log")
awk -v t="$stop" 'BEGIN { exit !(t > 0 && t < 0.01) }' || fail "stopped at t = $stop, expected within 0.01 s"
written=$(sed -n 's|^Wrote the failing state to \(.*\)/$|\1|p' "$log")
[ -n "$written" ] && [ -f "$c/$written/particles.vtp" ] || fail "no failing state written: $(tail -n 5 "$log")"
particleInfo -case "$c" -time "$written" > "$c/log.particleInfo" 2>&1 || fail "particleInfo: $(tail "$c/log.particleInfo")"
grep -qi "nan\|inf " "$c/log.particleInfo" && fail "the written state is not finite: $(grep -i 'nan\|inf ' "$c/log.particleInfo")"
echo "PASS: the default energy check stopped the planted instability at t = $stop, state $written finite"
