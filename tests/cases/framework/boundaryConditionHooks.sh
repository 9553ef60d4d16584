# A boundary condition that acts only through a hook the solver does not call is refused at its entry
# of constant/boundaryConditions (BoundaryConditionList::requireHooks), with exit status 1 and no
# time directory written, instead of running without it: prescribedTraction (boundary forces) in
# impactSph and fpmSolid, mirrorPlane (a ghost layer) in tlSph and fpmSolid. Before, each of these
# ran silently without the condition. The controls: the same conditions where the solver applies
# them (mirrorPlane in impactSph, prescribedTraction in tlSph) are accepted.
. "$(dirname "$0")/common.sh"
TUTORIALS="$(cd "$SOURCE/../../../tutorials" && pwd)"
# caseOf <tutorial> <name>: its system/ and constant/ in $WORK/<name>, particles made.
caseOf() {
    mkdir -p "$WORK/$2"
    cp -r "$TUTORIALS/$1/system" "$TUTORIALS/$1/constant" "$WORK/$2/"
    particleGen -case "$WORK/$2" > "$WORK/$2/log.particleGen" 2>&1 || fail "particleGen on $1: $(tail "$WORK/$2/log.particleGen")"
    echo "$WORK/$2"
}
traction='load { type prescribedTraction; all yes; traction (1 0 0); area 1; }'
mirror='image { type mirrorPlane; point (0 0 0); normal (1 0 0); }'
# refused <solver> <case> <condition text> <expected fragment>
refused() {
    printf 'boundaryConditions\n{\n    %s\n}\n' "$3" > "$2/constant/boundaryConditions"
    set +e
    "$1" -case "$2" > "$2/log" 2>&1
    local rc=$?
    set -e
    [ "$rc" -eq 1 ] || fail "$1 with '$3': exit status $rc, expected 1: $(tail -n 3 "$2/log")"
    grep -qF -- "$2/constant/boundaryConditions:3:" "$2/log" || fail "$1 with '$3': no file:line in: $(tail -n 3 "$2/log")"
    grep -qF -- "$4" "$2/log" || fail "$1 with '$3': expected '$4' in: $(tail -n 3 "$2/log")"
    [ "$(ls -d "$2"/[0-9]* | wc -l)" -eq 1 ] || fail "$1 with '$3': a time directory was written"
}
sod=$(caseOf impactSph/sodShockTube sod)
refused impactSph "$sod" "$traction" "boundary condition \`load\` (prescribedTraction) acts through boundary forces, which impactSph does not apply"
cube=$(caseOf tlSph/spinningCube cube)
refused tlSph "$cube" "$mirror" "boundary condition \`image\` (mirrorPlane) acts through a layer of mirror ghost particles, which tlSph does not build"
fpm=$(caseOf fpmSolid/rotationOnly fpm)
refused fpmSolid "$fpm" "$mirror" "(mirrorPlane) acts through a layer of mirror ghost particles, which fpmSolid does not build"
refused fpmSolid "$fpm" "$traction" "(prescribedTraction) acts through boundary forces, which fpmSolid does not apply"
grep -qF "fpmSolid applies the conditions that act on velocities and positions (fixed, prescribedVelocity, symmetryPlane, skewSymmetricPlane, rigidPlanarWall)" "$fpm/log" ||
    fail "fpmSolid's refusal does not name what it applies: $(tail -n 2 "$fpm/log")"
# The controls: one step each where the solver applies the condition.
mfDictionary "$sod/system/controlDict" -entry endTime -set 1e-4 > /dev/null
printf 'boundaryConditions\n{\n    %s\n}\n' "image { type mirrorPlane; point (-0.5 0 0); normal (1 0 0); }" > "$sod/constant/boundaryConditions"
impactSph -case "$sod" > "$sod/log" 2>&1 || fail "impactSph refused a mirrorPlane: $(tail -n 3 "$sod/log")"
mfDictionary "$cube/system/controlDict" -entry endTime -set 1e-5 > /dev/null
printf 'boundaryConditions\n{\n    %s\n}\n' "load { type prescribedTraction; shape { type box; min (0.9 -1 -1); max (2 2 2); } traction (1 0 0); area 1; }" > "$cube/constant/boundaryConditions"
tlSph -case "$cube" > "$cube/log" 2>&1 || fail "tlSph refused a prescribedTraction: $(tail -n 3 "$cube/log")"
pass "prescribedTraction refused by impactSph and fpmSolid, mirrorPlane by tlSph and fpmSolid, at their entries; accepted where applied"
