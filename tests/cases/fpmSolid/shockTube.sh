#!/usr/bin/env bash
# R8 and R9 (central) of doc/methods/fpm.md §4b: the thesis's 3D shock tube (§4.1), the Euler part
# alone with upwinding along grad p (delta 0.3), particles moved with v_uw, slip walls on all faces,
# an ideal gas with gamma 1.4 (isentropic c^2), (rho, u, p) = (1, 0, 10) | (1, 0, 1). R8 at t = 2:
# the shock within +-h of the exact 2.5422 t = 5.0845 (the largest x with p above (p* + p_R)/2,
# riemannError's shock.csv), the plateau (the median between the waves) within 10% of p* = 5.2191,
# and no particle pressure outside [0.8, 11] up to t = 2 (fieldMinMax). The run to 10.5 s is the
# validation test fpmSolidValidation.shockTube. R9: the central scheme (`euler { direction central; }`)
# is detected as unstable by the run's own instabilityCheck (p outside (-5, 30)): "instability
# detected", exit status 1, the state written; the thesis has p > 20 or < -5 by about 1 s.
source "$(dirname "$0")/common.sh"
c="$WORK/shockTube"
copyTutorial shockTube "$c"
sed -i 's/^endTime .*/endTime 2;/' "$c/system/controlDict"
run "$c" particleGen
run "$c" fpmSolid
s="$c/postProcessing/riemann/0/shock.csv"
[ -f "$s" ] || fail "no shock.csv"
read -r front exact < <(awk -F, '$1 == 2 { print $2, $3 }' "$s")
echo "R8 t = 2: shock at $front (exact $exact, h 1.6)"
awk -v a="$front" -v b="$exact" 'BEGIN { d = a - b; exit !(d <= 1.6 && d >= -1.6 && (b - 5.0845)^2 < 1e-6) }' ||
    fail "R8: shock at $front, exact $exact: not within h = 1.6"
read -r pstar pexact < <(awk -F, '$1 == 2 { print $2, $3 }' "$c/postProcessing/riemann/0/starState.csv")
echo "R8 t = 2: plateau p $pstar (exact $pexact)"
awk -v a="$pstar" -v b="$pexact" 'BEGIN { exit !((a - b) / b <= 0.1 && (b - a) / b <= 0.1 && (b - 5.2191)^2 < 1e-8) }' ||
    fail "R8: plateau p $pstar against $pexact: more than 10% off"
read -r lo hi < <(awk -F, 'NR > 1 && $1 <= 2.0000001 { if (n == 0 || $2 < lo) lo = $2; if (n == 0 || $4 > hi) hi = $4; n++ } END { print lo, hi }' "$c/postProcessing/range/0/fieldMinMax.csv")
echo "R8: particle pressures in [$lo, $hi] up to t = 2"
awk -v a="$lo" -v b="$hi" 'BEGIN { exit !(a >= 0.8 && b <= 11) }' || fail "R8: a particle pressure outside [0.8, 11]: [$lo, $hi]"
allRead "$c/log.fpmSolid"
# R9: the central scheme
k="$WORK/central"
copyTutorial shockTube "$k"
sed -i 's/direction gradient;/direction central;/' "$k/constant/fpmProperties"
sed -i 's/^endTime .*/endTime 3;/' "$k/system/controlDict"
run "$k" particleGen
rc=0; fpmSolid -case "$k" > "$k/log.fpmSolid" 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "R9 central: exit status $rc, expected 1 (instability detected)"
grep -q "phase instabilityCheck, step [0-9]*, t = [0-9.]*: instability detected: particle [0-9]* at .* has pressure .*Remedy" "$k/log.fpmSolid" ||
    fail "R9 central: $(grep -m1 Error "$k/log.fpmSolid")"
ls -d "$k"/[0-9]* | grep -qv "/0$" || fail "R9 central: the state was not written"
echo "R9 central: $(grep -m1 -o 'phase instabilityCheck, step [0-9]*, t = [0-9.]*: instability detected: particle [0-9]* at .\{0,40\}' "$k/log.fpmSolid")"
echo "PASS: R8 at t = 2 and R9's central scheme detected"
