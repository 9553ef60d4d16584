# constant/sphProperties is read through impactSph's keyword schema (SphSolver::keywords): a bad
# word, a negative skin or rate limit, a bad artificialStress entry and artificial stress without
# a solid are each an input error at the file and line, naming the valid choices or bounds, with
# exit status 1 and nothing written beyond the start. (Before the schema the words were checked
# by hand with other messages, and a negative densityRateLimit was taken silently as off.)
# constant/materialProperties goes through MaterialSet with impactSph's models (equation of state
# required, strength optional, constitutive law refused): a constitutiveLaw, ignored before, is an
# error at its entry naming what impactSph takes.
. "$(dirname "$0")/common.sh"
c=$(newCase "$SOURCE/sodShockTube" bad)
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen failed"
cp "$c/constant/sphProperties" "$c/sphProperties.good"
lines=$(wc -l < "$c/sphProperties.good")
line=$((lines + 1))
# expectError <entry appended to sphProperties> <expected message fragment>
expectError() {
    cp "$c/sphProperties.good" "$c/constant/sphProperties"
    echo "$1" >> "$c/constant/sphProperties"
    set +e
    impactSph -case "$c" > "$c/log" 2>&1
    local rc=$?
    set -e
    [ "$rc" -eq 1 ] || fail "'$1': exit status $rc, expected 1: $(tail -n 3 "$c/log")"
    grep -qF -- "$c/constant/sphProperties:$line:" "$c/log" || fail "'$1': no file:line $line in: $(tail -n 3 "$c/log")"
    grep -qF -- "$2" "$c/log" || fail "'$1': expected '$2' in: $(tail -n 3 "$c/log")"
    [ "$(ls -d "$c"/[0-9]* | wc -l)" -eq 1 ] || fail "'$1': a time directory was written"
}
expectError "momentum variatonal;" "keyword 'momentum': expected one of variational | difference, found 'variatonal'"
expectError "integrator rungeKutta;" "keyword 'integrator': expected one of leapfrog | predictorCorrector, found 'rungeKutta'"
expectError "neighbourSkin -0.1;" "keyword 'neighbourSkin': expected a value >= 0, found -0.1"
expectError "densityRateLimit -0.2;" "keyword 'densityRateLimit': expected a value >= 0, found -0.2"
expectError "artificialStress { epsilon -1; }" "in 'artificialStress': keyword 'epsilon': expected a value >= 0, found -1"
expectError "artificialStress { epsilon 0.3; }" "artificial stress acts on solids: no material has a strength law"
cp "$c/sphProperties.good" "$c/constant/sphProperties"
cp "$c/constant/materialProperties" "$c/materialProperties.good"
printf 'materials\n{\n    gas { equationOfState { type idealGas; gamma 1.4; } constitutiveLaw { type neoHookean; } }\n}\n' \
    > "$c/constant/materialProperties"
set +e
impactSph -case "$c" > "$c/log" 2>&1
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "constitutiveLaw in an impactSph material: exit status $rc, expected 1"
grep -qF -- "$c/constant/materialProperties:3:" "$c/log" || fail "constitutiveLaw: no file:line 3 in: $(tail -n 3 "$c/log")"
grep -qF -- "impactSph takes no constitutiveLaw; it takes equationOfState and optionally strength" "$c/log" ||
    fail "constitutiveLaw: unexpected message: $(tail -n 3 "$c/log")"
cp "$c/materialProperties.good" "$c/constant/materialProperties"
pass "six bad sphProperties entries: each an input error at sphProperties:$line with its choices or bound; a constitutiveLaw refused at materialProperties:3"
