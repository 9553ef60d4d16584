# Bad material input from a case directory (issue 18, acceptance "A fluid given a strength law, a
# contact law between a body and itself, a body with no material: a clear error naming file, line
# and the valid choices"): a water column and a gate of two bodies; each broken variant must stop before the first step with exit status 1,
# the file and line of the offending entry, the valid choices, and no time directory written.
source "$(dirname "$0")/common.sh"
c="$WORK/case"
mkdir -p "$c/system" "$c/constant"
cat > "$c/system/controlDict" <<'DICT'
application mpmFsi; startFrom startTime; startTime 0; stopAt endTime; endTime 5e-4; deltaT 5e-5;
adjustTimeStep no; writeControl timeStep; writeInterval 5;
DICT
cat > "$c/system/particleGenDict" <<'DICT'
dimension 2;
regions
{
    water { shape { type box; min (0 0); max (0.2 0.4); } lattice { type materialPoints; cells (8 16); pattern centre; }
            density 1000; material water; }
    gate  { shape { type box; min (0.3 0); max (0.35 0.3); } lattice { type materialPoints; cells (2 12); pattern centre; }
            density 1100; material rubber; }
}
DICT
echo 'grid { origin (0 0); cellSize (0.05 0.05); cells (12 12); }' > "$c/constant/mpmProperties"
good() {
    cat > "$c/constant/materialProperties" <<'DICT'
materials
{
    water
    {
        equationOfState { type tait; rho0 1000; c0 15; gamma 7; }
        viscosity       { type newtonian; mu 1e-3; }
    }
    rubber
    {
        rho0 1100; youngsModulus 1.2e7; poissonRatio 0.4;
        constitutiveLaw { type neoHookean; }
    }
}
DICT
}
good
run "$c" particleGen
run "$c" mpmFsi
[ -d "$c/0.0005" ] || fail "the good case wrote no 0.0005"
rm -rf "$c"/0.0*[1-9]* "$c/postProcessing"
# expectError <line> <message fragment> [file]: runs mpmFsi on the broken dictionary (default
# constant/materialProperties).
expectError() {
    local file="${3:-materialProperties}"
    set +e
    mpmFsi -case "$c" > "$c/log" 2>&1
    local rc=$?
    set -e
    [ "$rc" -eq 1 ] || fail "$2: exit status $rc, expected 1: $(tail -n 3 "$c/log")"
    grep -qF -- "$c/constant/$file:$1:" "$c/log" || fail "$2: no file:line $1 in: $(tail -n 3 "$c/log")"
    grep -qF -- "$2" "$c/log" || fail "expected '$2' in: $(tail -n 3 "$c/log")"
    [ "$(ls -d "$c"/[0-9]* | wc -l)" -eq 1 ] || fail "$2: a time directory was written"
    echo "error: $(grep -m1 -F -- "$c/constant/$file:" "$c/log")"
}
# A body with no material: the gate's material renamed away; two materials defined, so the
# solver cannot fall back on a single one, and the error lists both.
sed -i 's/^    rubber$/    steel/' "$c/constant/materialProperties"
expectError 1 "has material/region 'rubber', which constant/materialProperties does not define; materials: water steel"
# A fluid given a strength law beside its viscosity.
good
sed -i 's/^        viscosity .*/&\n        strength        { type vonMises; shearModulus 1e6; yieldStress 1e3; }/' "$c/constant/materialProperties"
expectError 6 "a fluid given a strength law"
# A contact law between a body and itself, then one naming a body the case does not have (line 6
# of mpmProperties, the pair's `bodies`): the error lists the run's bodies.
good
contactPair() {
    printf '%s\n' 'grid { origin (0 0); cellSize (0.05 0.05); cells (12 12); }' 'contact multiField;' \
        'multiFieldCoeffs' '{' '    pairs {' "        gateLaw { bodies ($1); friction 0.1; }" '    }' '}' > "$c/constant/mpmProperties"
}
contactPair "gate gate"
expectError 6 "a contact law between body 'gate' and itself: a pair names two different bodies of: water gate" mpmProperties
contactPair "gate wall"
expectError 6 "unknown body 'wall'; the bodies (particleGen regions) of this run are: water gate" mpmProperties
echo "PASS: badMaterials"
