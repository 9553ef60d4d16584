# tlSph on several ranks (issue 21): the same final state serially and on 2 and 3 ranks, every field
# within 1e-12 (particleCompare), for the swinging cube (9^3 nodal lattice, six symmetry and
# skew-symmetric planes, {p,F}) and a coarse Taylor bar quarter (0.8 mm, three symmetry planes,
# {p,F,J} with J2 plasticity and the D(J) mean projection). The body is cut once in X and its halo
# is two supports deep, with the rows of every sum in the serial order (TlSphSolver.cpp, "Several
# ranks"): the pair sums have the serial bits, and only the global sums (the D(J) projection) may
# differ in their last bits.
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
for c in "$cube" "$bar"; do
    particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail -3 "$c/log.particleGen")"
done

for c in "$cube" "$bar"; do
    name=$(basename "$c")
    serial=$(copyCase "$c" "$WORK/$name.serial")
    tlSph -case "$serial" > "$serial/log.tlSph" 2>&1 || fail "$name serially: $(tail -5 "$serial/log.tlSph")"
    for n in 2 3; do
        d=$(copyCase "$c" "$WORK/$name.$n")
        onRanks "$n" tlSph -case "$d" > "$d/log.tlSph" 2>&1 || fail "$name on $n ranks: $(tail -5 "$d/log.tlSph")"
        grep -q "Halo: " "$d/log.tlSph" || fail "$name on $n ranks: no halo in the log"
        sameState "$name on $n ranks against the serial run" "$(latest "$serial")" "$(latest "$d")"
    done
done
pass "tlSph: the swinging cube and the Taylor bar quarter end in the serial state on 2 and 3 ranks"
