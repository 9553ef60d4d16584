# tlSph keywords that moved (issue 15): each old spelling is an input error at its own line that
# names the new one, exit status 1, the case's particles untouched; a tlSphProperties with the new
# spelling runs. A 5^3 swinging cube, a few steps.
#   alphaCFL (tlSphProperties)  -> maxCo in system/controlDict (one Courant keyword for every method)
#   maxCo above 1               -> refused (the TVD RK2 is unstable above 1)
#   formulation { type pF; }   -> `formulation pF;` (a solver option, one syntax)
#   an equationOfState in a material (MaterialSet with tlSph's models: a constitutive law only;
#                                  it used to be ignored)
source "$(dirname "$0")/common.sh"
base="$WORK/base"
copyTutorial swingingCube "$base"
sed -i "s/points (9 9 9)/points (5 5 5)/" "$base/system/particleGenDict"
sed -i "s/^endTime .*/endTime 2e-5;/" "$base/system/controlDict"
particleGen -case "$base" > "$base/log.particleGen" 2>&1 || fail "particleGen: $(tail "$base/log.particleGen")"
# refused <name> <file (relative)> <text that must be at the line> <message part> <edit command...>
refused() {
    local name="$1" file="$2" entry="$3" part="$4" c="$WORK/$1" line rc=0
    shift 4
    cp -r "$base" "$c"
    (cd "$c" && "$@")
    line=$(grep -n -- "$entry" "$c/$file" | head -1 | cut -d: -f1)
    [ -n "$line" ] || fail "$name: the edit left no '$entry' in $file"
    tlSph -case "$c" > "$c/log.tlSph" 2>&1 || rc=$?
    [ "$rc" = 1 ] || fail "$name: exit status $rc, expected 1: $(tail -3 "$c/log.tlSph")"
    grep -q -- "$file:$line:.*$part" "$c/log.tlSph" || fail "$name: no error at $file:$line saying '$part': $(tail -3 "$c/log.tlSph")"
    cmp -s "$base/0/particles.vtp" "$c/0/particles.vtp" || fail "$name: 0/particles.vtp changed"
    ls -d "$c"/[1-9]* "$c"/0.* > /dev/null 2>&1 && fail "$name: a time directory was written"
    echo "$name: refused at $file:$line"
}
refused alphaCFL constant/tlSphProperties "^alphaCFL" "alphaCFL is now maxCo in system/controlDict" \
    sh -c 'echo "alphaCFL 0.3;" >> constant/tlSphProperties'
refused maxCoAboveOne system/controlDict "^maxCo" "tlSph needs maxCo in (0, 1]" \
    sed -i "s/^maxCo .*/maxCo 1.5;/" system/controlDict
refused formulationDictionary constant/tlSphProperties "^formulation" "formulation is now a word of tlSphProperties, .formulation pFJ;." \
    sed -i 's/^formulation .*/formulation { type pF; }/' constant/tlSphProperties
refused equationOfState constant/materialProperties "equationOfState {" "tlSph takes no equationOfState" \
    sed -i 's/constitutiveLaw { type linearElastic; }/constitutiveLaw { type linearElastic; }\n        equationOfState { type idealGas; gamma 1.4; }/' constant/materialProperties
# The new spelling runs, and without maxCo the method's 0.3 applies: the same steps as maxCo 0.3.
good="$WORK/good"; cp -r "$base" "$good"; run "$good" tlSph
nomax="$WORK/nomax"; cp -r "$base" "$nomax"; sed -i "/^maxCo /d" "$nomax/system/controlDict"; run "$nomax" tlSph
cmp -s "$good/2e-05/particles.vtp" "$nomax/2e-05/particles.vtp" || fail "without maxCo the result differs from maxCo 0.3"
echo "PASS: moved keywords refused at their lines; maxCo defaults to 0.3 for tlSph"
