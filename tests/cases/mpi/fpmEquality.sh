# fpmSolid on several ranks (issue 21): the same final state serially and on 2 and 3 ranks, every
# field within 1e-12 (particleCompare), for
#   - the shock tube (tutorials/fpmSolid/shockTube to t = 0.5, 625 particles in 3D): the Euler part,
#     growSupport's rows within 2 h, slip walls, the particles moved with v_uw across the cut;
#   - the coarse oscillating plate (4 mm, 384 particles in 2D, to 0.02 s): the shear and Euler parts
#     with the free surface (characteristic velocity) detected across the cut, the clamp, an
#     adjusted time step;
#   - the rotating cube (tutorials/fpmSolid/rotationOnly to t = 1, 1244 particles): the rotation
#     part under a prescribed rotation of one radian, the particles migrating between ranks;
#   - the shearing sphere (tutorials/fpmSolid/shearingSphere to t = 0.05, 1244 particles in 3D):
#     the shear part alone, its shifted fits' rows within (1 + maxShift) h, the free surface.
# The halo is the widest rows' reach plus h/2, every row of a fit is in global-id order and the halo's
# v, p and S are refreshed after each stage (FpmSolver.cpp, updateDecomposition): the fits sum in the
# serial order, so the states are the serial ones to the bit. Measured: all four bit-identical on 2
# and 3 ranks. Then two cases with particle management (below).
. "$(dirname "$0")/common.sh"

# fpmCase <tutorial> <endTime>: the tutorial with one write at endTime.
fpmCase() {
    local c="$WORK/$1"
    mkdir -p "$c" && cp -r "$SOURCE/tutorials/fpmSolid/$1/system" "$SOURCE/tutorials/fpmSolid/$1/constant" "$c/"
    mfDictionary "$c/system/controlDict" -entry endTime -set "$2" > /dev/null
    mfDictionary "$c/system/controlDict" -entry writeInterval -set "$2" > /dev/null
    echo "$c"
}

tube=$(fpmCase shockTube 0.5)
plate=$(fpmCase oscillatingPlate 0.02)
mfDictionary "$plate/system/particleGenDict" -entry regions/plate/lattice/spacing -set 0.004 > /dev/null
cube=$(fpmCase rotationOnly 1)
sphere=$(fpmCase shearingSphere 0.05)
for c in "$tube" "$plate" "$cube" "$sphere"; do
    particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail -3 "$c/log.particleGen")"
done

for c in "$tube" "$plate" "$cube" "$sphere"; do againstSerial fpmSolid "$c" "Decomposition (" 2 3; done
# The first migration is the start's; the cube turns through its halo's skin several times.
migrations=$(sed -n 's/.*decomposition .*, \([0-9]*\) migrations.*/\1/p' "$WORK/rotationOnly.3/log.fpmSolid")
[ "${migrations:-0}" -gt 2 ] ||
    fail "the rotating cube did not migrate: $(grep "decomposition " "$WORK/rotationOnly.3/log.fpmSolid")"

# Particle management on the whole set gathered in id order (FpmSolver.cpp, manageParticles): the
# serial merges, insertions and ids. The coarse flattening sphere (280 particles, h = 3.75, to 1.5:
# 28 pairs merged) and the shock tube with holes filled (holeSize 0.3: 50 particles inserted by 0.5,
# some at the slip walls). Measured: both bit-identical on 2 and 3 ranks.
flat=$(fpmCase flatteningSphere 1.5)
sed -i 's/spacing 0.75; }/spacing 1.25; }/' "$flat/system/particleGenDict"
sed -i 's/^smoothingLength .*/smoothingLength 3.75;/' "$flat/constant/fpmProperties"
particleGen -case "$flat" > "$flat/log.particleGen" 2>&1 || fail "particleGen: $(tail -3 "$flat/log.particleGen")"
filled=$(copyCase "$tube" "$WORK/filledTube")
echo "particleManagement { insert yes; holeSize 0.3; merge yes; mergeDistance 0.1; }" >> "$filled/constant/fpmProperties"
for c in "$flat" "$filled"; do
    name=$(basename "$c")
    againstSerial fpmSolid "$c" "Decomposition (" 2 3
    managed=$(grep "particle management  " "$WORK/$name.serial/log.fpmSolid")
    case "$managed" in *" 0 inserted, 0 pairs merged"*) fail "$name: no particle inserted or merged: $managed" ;; esac
    for n in 2 3; do
        [ "$(grep "particle management  " "$WORK/$name.$n/log.fpmSolid")" = "$managed" ] ||
            fail "$name on $n ranks: $(grep "particle management  " "$WORK/$name.$n/log.fpmSolid"), serially $managed"
    done
done
pass "fpmSolid: the shock tube, the oscillating plate, the rotating cube, the shearing sphere and, with particle management, the flattening sphere and a filled tube end in the serial state on 2 and 3 ranks"
