# tlSph on several ranks (issue 21): the same final state serially and on 2 and 3 ranks, every field
# within 1e-12 (particleCompare), for the swinging cube (9^3 nodal lattice, six symmetry and
# skew-symmetric planes, {p,F}), a coarse Taylor bar quarter (0.8 mm, three symmetry planes,
# {p,F,J} with J2 plasticity and the D(J) mean projection) and the coarse oscillating plate (4 mm,
# 384 particles in 2D, {p,F,J} with jacobian (0 0.125): the momentum and D(J) projections every
# stage, 1134 steps). The body is cut once in X and its halo is two supports deep, with the rows of
# every sum in the serial order (TlSphSolver.cpp, "Several ranks"): the pair sums have the serial
# bits, and the projections' global sums are exact (GlobalReduce::exactSum, rounded once), so
# they have the serial bits too. Measured: all three to the bit on 2 and 3 ranks. Before the exact
# sums (per-rank partials added in rank order) the bar differed by 2.4e-13 in the pressure and the
# plate by 6.1e-12 (2 ranks) and 9.1e-12 (3 ranks) in the pressure at 0.0143 s, 3.5e-11 at 0.3 s.
# Then a restart across rank counts, cut in X.
. "$(dirname "$0")/common.sh"

# controlDict <case> <endTime>: one write at the end, no function objects.
controlDict() {
    cat > "$1/system/controlDict" <<DICT
application     tlSph;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         $2;
deltaT          1e-9;
adjustTimeStep  yes;
maxCo           0.3;
writeControl    adjustableRunTime;
writeInterval   $2;
DICT
}

cube="$WORK/cube"
mkdir -p "$cube" && cp -r "$SOURCE/tutorials/tlSph/swingingCube/system" "$SOURCE/tutorials/tlSph/swingingCube/constant" "$cube/"
controlDict "$cube" 0.003
bar="$WORK/bar"
mkdir -p "$bar" && cp -r "$SOURCE/tutorials/tlSph/taylorBar/system" "$SOURCE/tutorials/tlSph/taylorBar/constant" "$bar/"
mfDictionary "$bar/system/particleGenDict" -entry regions/bar/lattice/spacing -set 8e-4 > /dev/null
controlDict "$bar" 1e-5
plate="$WORK/plate"
mkdir -p "$plate" && cp -r "$SOURCE/tutorials/tlSph/oscillatingPlate/system" "$SOURCE/tutorials/tlSph/oscillatingPlate/constant" "$plate/"
mfDictionary "$plate/system/particleGenDict" -entry regions/plate/lattice/spacing -set 0.004 > /dev/null
mfDictionary "$plate/constant/tlSphProperties" -entry formulation -set pFJ > /dev/null
mfDictionary "$plate/constant/tlSphProperties" -entry dissipation/jacobian -set "(0 0.125)" > /dev/null
controlDict "$plate" 0.02
for c in "$cube" "$bar" "$plate"; do
    particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail -3 "$c/log.particleGen")"
done

for c in "$cube" "$bar" "$plate"; do againstSerial tlSph "$c" "Halo: " 2 3; done
# A restart: the cube to 3 ms on 2 ranks, on to 6 ms on 3 ranks (a state with its reference
# configuration: the cut is made in X), against the serial run straight to 6 ms.
straight=$(copyCase "$cube" "$WORK/cube.straight")
restarted=$(copyCase "$cube" "$WORK/cube.restarted")
controlDict "$straight" 0.006
mfDictionary "$straight/system/controlDict" -entry writeInterval -set 0.003 > /dev/null
tlSph -case "$straight" > "$straight/log.tlSph" 2>&1 || fail "cube to 6 ms serially: $(tail -5 "$straight/log.tlSph")"
onRanks 2 tlSph -case "$restarted" > "$restarted/log.tlSph" 2>&1 || fail "cube to 3 ms on 2 ranks: $(tail -5 "$restarted/log.tlSph")"
controlDict "$restarted" 0.006
mfDictionary "$restarted/system/controlDict" -entry writeInterval -set 0.003 > /dev/null
mfDictionary "$restarted/system/controlDict" -entry startFrom -set latestTime > /dev/null
onRanks 3 tlSph -case "$restarted" > "$restarted/log.restart" 2>&1 || fail "cube restarted on 3 ranks: $(tail -5 "$restarted/log.restart")"
grep -q "cut in the reference configuration" "$restarted/log.restart" || fail "the restart was not cut in X"
sameState "cube restarted at 3 ms on 3 ranks against the serial run" "$straight/0.006" "$restarted/0.006"
pass "tlSph: the swinging cube, the Taylor bar quarter and the oscillating plate end in the serial state on 2 and 3 ranks, and across a restart"
