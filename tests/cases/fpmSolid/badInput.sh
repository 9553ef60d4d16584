# Bad fpmProperties from a case directory: an unknown keyword, an unknown subsystem or splitting,
# the shear part's conditions and the Euler part's conditions (frozen particles, an equation of state, one
# delta), the free surface's traction condition's (both parts; edgeAngle with it only) are each an input error at their line (file:line, the valid choices),
# exit status 1, the particles untouched and no time directory written.
source "$(dirname "$0")/common.sh"
base="$WORK/base"
copyTutorial rotationOnly "$base"
sed -i 's/spacing 0.75; }/spacing 2; }/' "$base/system/particleGenDict"
sed -i 's/^smoothingLength .*/smoothingLength 4;/' "$base/constant/fpmProperties"
sed -i 's/^endTime .*/endTime 0.01;/' "$base/system/controlDict"
run "$base" particleGen
# refused <name> <entry at the line> <message part> <edit command...>
refused() {
    local name="$1" entry="$2" part="$3" c="$WORK/$1" file=constant/fpmProperties line rc=0
    shift 3
    cp -r "$base" "$c"
    (cd "$c" && "$@")
    line=$(grep -n -- "$entry" "$c/$file" | head -1 | cut -d: -f1)
    [ -n "$line" ] || fail "$name: the edit left no '$entry' in $file"
    fpmSolid -case "$c" > "$c/log.fpmSolid" 2>&1 || rc=$?
    [ "$rc" = 1 ] || fail "$name: exit status $rc, expected 1: $(tail -3 "$c/log.fpmSolid")"
    grep -q -- "$file:$line:.*$part" "$c/log.fpmSolid" || fail "$name: no error at $file:$line saying '$part': $(tail -3 "$c/log.fpmSolid")"
    cmp -s "$base/0/particles.vtp" "$c/0/particles.vtp" || fail "$name: 0/particles.vtp changed"
    ls -d "$c"/[1-9]* "$c"/0.* > /dev/null 2>&1 && fail "$name: a time directory was written"
    echo "$name: refused at $file:$line: $(grep -m1 "$file:$line" "$c/log.fpmSolid")"
}
refused unknownKeyword "^derivates" "unknown keyword 'derivates'.*valid keywords: subsystems | fitWeight | order | derivatives.*did you mean 'derivatives'" \
    sed -i 's/^derivatives /derivates /' constant/fpmProperties
refused unknownSubsystem "^subsystems" "unknown subsystem 'rotaton'; valid choices: euler | shear | rotation; did you mean 'rotation'" \
    sed -i 's/^subsystems .*/subsystems (rotaton);/' constant/fpmProperties
refused eulerPrescribed "^motion" "the Euler part evolves v: it runs on frozen particles" \
    sed -i 's/^subsystems .*/subsystems (euler rotation);/' constant/fpmProperties
refused upwindWithoutEuler "^motion" "velocity upwind is the Euler part's: subsystems with euler" \
    sed -i 's/^motion .*/motion { velocity upwind; }/' constant/fpmProperties
refused eulerNoMaterials "^subsystems" "the Euler part needs constant/materialProperties with an equationOfState" \
    sed -i 's/^subsystems .*/subsystems (euler rotation);/; s/^motion .*/motion { velocity frozen; }/' constant/fpmProperties
refused eulerBothDeltas "^euler" "give delta (a time) or deltaFraction (of h), not both" \
    sh -c "sed -i 's/^subsystems .*/subsystems (euler);/; s/^motion .*/motion { velocity frozen; }/' constant/fpmProperties && echo 'euler { delta 0.3; deltaFraction 0.2; }' >> constant/fpmProperties"
refused shearPrescribed "^motion" "the shear part evolves v: it runs on frozen particles" \
    sed -i 's/^subsystems .*/subsystems (shear rotation);/' constant/fpmProperties
refused shearNoMaterials "^subsystems" "the shear part needs constant/materialProperties with a strength law" \
    sed -i 's/^subsystems .*/subsystems (shear rotation);/; s/^motion .*/motion { velocity frozen; }/' constant/fpmProperties
refused dimensionalWithoutShear "^motion" "velocity dimensional is the shear part's: subsystems with shear" \
    sed -i 's/^motion .*/motion { velocity dimensional; }/' constant/fpmProperties
refused unknownSplitting "^splitting" "unknown splitting (fpmSolid) type 'lei'; did you mean 'lie'" \
    sh -c "echo 'splitting { type lei; }' >> constant/fpmProperties"
refused shearBothDeltas "^shear" "give delta (a time) or deltaFraction (of h), not both" \
    sh -c "sed -i 's/^subsystems .*/subsystems (shear);/; s/^motion .*/motion { velocity frozen; }/' constant/fpmProperties && echo 'shear { delta 0.3; deltaFraction 0.2; }' >> constant/fpmProperties"
refused unknownMotion "velocity rotating" "expected one of prescribed | frozen" \
    sed -i 's/velocity prescribed;/velocity rotating;/' constant/fpmProperties
refused badOrder "^order" "expected a value" \
    sed -i 's/^order .*/order 3;/' constant/fpmProperties
refused initialStateWithPrescribed "^initialState" "velocity prescribed sets v itself: initialState is for" \
    sh -c 'echo "initialState { type rigidRotation; omega (0 0 -1); }" >> constant/fpmProperties'
refused tractionWithoutShear "^freeSurface" "condition traction acts on the total stress S - p I: subsystems with both shear and euler" \
    sh -c "sed -i 's/^subsystems .*/subsystems (euler);/; s/^motion .*/motion { velocity frozen; }/' constant/fpmProperties && echo 'freeSurface { pressure 0; condition traction; }' >> constant/fpmProperties"
refused edgeAngleWithThesis "^freeSurface" "edgeAngle picks the particles that take the thesis's conditions under condition traction" \
    sh -c "sed -i 's/^subsystems .*/subsystems (euler);/; s/^motion .*/motion { velocity frozen; }/' constant/fpmProperties && echo 'freeSurface { pressure 0; edgeAngle 30; }' >> constant/fpmProperties"
# constant/materialProperties (optional) through the shared MaterialSet: a constitutive law is not
# fpmSolid's model (an equation of state and a strength law are).
m="$WORK/constitutiveLaw"
cp -r "$base" "$m"
printf 'materials\n{\n    body\n    {\n        constitutiveLaw { type linearElastic; youngsModulus 1; poissonRatio 0.3; }\n    }\n}\n' > "$m/constant/materialProperties"
rc=0; fpmSolid -case "$m" > "$m/log.fpmSolid" 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "constitutiveLaw: exit status $rc, expected 1"
grep -q "constant/materialProperties:5:.*fpmSolid takes no constitutiveLaw; it takes optionally equationOfState, strength" "$m/log.fpmSolid" ||
    fail "constitutiveLaw: $(tail -2 "$m/log.fpmSolid")"
ls -d "$m"/[1-9]* "$m"/0.* > /dev/null 2>&1 && fail "constitutiveLaw: a time directory was written"
echo "constitutiveLaw: refused at constant/materialProperties:5"
# The good input runs, with and without a materialProperties.
mg="$WORK/materials"
cp -r "$base" "$mg"
printf 'materials\n{\n    body\n    {\n        equationOfState { type idealGas; gamma 1.4; }\n        strength { type hookean; shearModulus 50; }\n    }\n}\n' > "$mg/constant/materialProperties"
run "$mg" fpmSolid
grep -q "Material body: equationOfState idealGas, strength hookean" "$mg/log.fpmSolid" || fail "materials: not logged"
good="$WORK/good"; cp -r "$base" "$good"; run "$good" fpmSolid
[ -f "$good/0.01/rotationError" ] || fail "the good case wrote no 0.01/rotationError"
echo "PASS: bad fpmProperties refused at their lines"
