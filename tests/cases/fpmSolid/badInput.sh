# Bad fpmProperties from a case directory: an unknown keyword, an unknown subsystem and a
# subsystem not built yet are each an input error at their line (file:line, the valid choices),
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
refused eulerNotBuilt "^subsystems" "the euler part is not built yet" \
    sed -i 's/^subsystems .*/subsystems (euler rotation);/' constant/fpmProperties
refused shearNotBuilt "^subsystems" "the shear part is not built yet" \
    sed -i 's/^subsystems .*/subsystems (shear rotation);/' constant/fpmProperties
refused unknownMotion "velocity rotating" "expected one of prescribed | frozen" \
    sed -i 's/velocity prescribed;/velocity rotating;/' constant/fpmProperties
refused badOrder "^order" "expected a value" \
    sed -i 's/^order .*/order 3;/' constant/fpmProperties
refused initialStateWithPrescribed "^initialState" "velocity prescribed sets v itself: initialState is for" \
    sh -c 'echo "initialState { type rigidRotation; omega (0 0 -1); }" >> constant/fpmProperties'
# The good input runs.
good="$WORK/good"; cp -r "$base" "$good"; run "$good" fpmSolid
[ -f "$good/0.01/rotationError" ] || fail "the good case wrote no 0.01/rotationError"
echo "PASS: bad fpmProperties refused at their lines"
