# tlSphProperties' deformedCourant (issue 16 item 3; tutorials/tlSph/taylorBar/README.md): with
# waveSpeed current the step is min(maxCo h / c_p, deformedCourant h / (c_p x stretch)).
#   - not given, the step is the old one, maxCo h / (c_p x stretch): given equal to maxCo, the run
#     is byte-identical to the run without it, and its log names the deformed speed's limit;
#   - given 1 on the little-deformed swinging cube (stretch 1.0015), the deformed limit does not
#     bind: every step is maxCo h / c_p (the log says so), and the result differs from the default;
#   - below maxCo, above 1, or with waveSpeed reference: an input error at its line, exit status 1,
#     nothing written.
# A 5^3 swinging cube to 20 ms (about 50 steps: the step reaches the CFL limit after 25).
source "$(dirname "$0")/common.sh"
base="$WORK/base"
copyTutorial swingingCube "$base"
sed -i "s/points (9 9 9)/points (5 5 5)/" "$base/system/particleGenDict"
# Written every 10 steps (not at set times, which would cut the steps alike in every run).
sed -i "s/^endTime .*/endTime 2e-2;/; s/^writeControl .*/writeControl timeStep;/; s/^writeInterval .*/writeInterval 10;/" "$base/system/controlDict"
particleGen -case "$base" > "$base/log.particleGen" 2>&1 || fail "particleGen: $(tail "$base/log.particleGen")"
variant() {  # variant <name> <tlSphProperties line or ''>: a copy of the base case, run
    local c="$WORK/$1"
    cp -r "$base" "$c"
    [ -z "$2" ] || echo "$2" >> "$c/constant/tlSphProperties"
    run "$c" tlSph
}
variant default ''
variant equal 'deformedCourant 0.3;'
variant one 'deformedCourant 1;'
grep -q '^Step .*\[CFL (maxCo h / c_p, deformed: c_p x 1\.00' "$WORK/default/log.tlSph" ||
    fail "default: no step limited by the deformed wave speed at maxCo: $(grep '^Step' "$WORK/default/log.tlSph" | tail -2)"
grep -q '^Step .*\[CFL (deformedCourant h / (c_p x 1\.00' "$WORK/equal/log.tlSph" ||
    fail "deformedCourant 0.3: the log does not name the deformed limit: $(grep '^Step' "$WORK/equal/log.tlSph" | tail -2)"
times() { (cd "$1" && ls -d [0-9]* | sort -g | tr '\n' ' '); }
[ "$(times "$WORK/default")" = "$(times "$WORK/equal")" ] ||
    fail "deformedCourant equal to maxCo wrote at other times: $(times "$WORK/default") against $(times "$WORK/equal")"
last=$(times "$WORK/default" | awk '{ print $NF }')
cmp -s "$WORK/default/$last/particles.vtp" "$WORK/equal/$last/particles.vtp" ||
    fail "deformedCourant equal to maxCo changed the result: the default is not the old step"
# With deformedCourant 1 the deformed limit (1 / 1.0015 of h / c_p) is above maxCo h / c_p: every
# CFL-limited step is the undeformed one.
if grep '^Step ' "$WORK/one/log.tlSph" | grep -v '\[CFL (maxCo h / c_p)\]' | grep -q .; then
    fail "deformedCourant 1: a step not at maxCo h / c_p: $(grep '^Step ' "$WORK/one/log.tlSph" | grep -v '\[CFL (maxCo h / c_p)\]' | head -1)"
fi
# Its CFL-limited steps are 1.0013 times as long: step 40 (the start's ramp from deltaT ends
# near step 25) is written at a later time.
step40() { times "$1" | awk '{ print $5 }'; }
awk -v a="$(step40 "$WORK/default")" -v b="$(step40 "$WORK/one")" 'BEGIN { exit !(b > a * 1.0003) }' ||
    fail "deformedCourant 1: step 40 at t = $(step40 "$WORK/one"), not later than the default's $(step40 "$WORK/default")"
# refused <name> <tlSphProperties line> <message part> [extra line]
refused() {
    local c="$WORK/$1" line rc=0
    cp -r "$base" "$c"
    echo "$2" >> "$c/constant/tlSphProperties"
    [ -z "${4:-}" ] || echo "$4" >> "$c/constant/tlSphProperties"
    line=$(grep -n "^deformedCourant" "$c/constant/tlSphProperties" | cut -d: -f1)
    tlSph -case "$c" > "$c/log.tlSph" 2>&1 || rc=$?
    [ "$rc" = 1 ] || fail "$1: exit status $rc, expected 1: $(tail -3 "$c/log.tlSph")"
    grep -q "constant/tlSphProperties:$line:.*$3" "$c/log.tlSph" ||
        fail "$1: no error at constant/tlSphProperties:$line saying '$3': $(tail -3 "$c/log.tlSph")"
    ls -d "$c"/0.* > /dev/null 2>&1 && fail "$1: a time directory was written"
    echo "$1: refused at constant/tlSphProperties:$line"
}
refused belowMaxCo 'deformedCourant 0.2;' 'deformedCourant must lie in \[maxCo, 1\] = \[0.3, 1\], found 0.2'
refused aboveOne 'deformedCourant 1.5;' 'deformedCourant'
refused reference 'deformedCourant 1;' 'deformedCourant needs .waveSpeed current;.' 'waveSpeed reference;'
echo "PASS: deformedCourant: default = the old step (byte-identical), 1 lifts it to maxCo h / c_p below a stretch of 3.3, bad values refused at their line"
