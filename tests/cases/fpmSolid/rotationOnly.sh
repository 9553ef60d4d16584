# R4 of doc/methods/fpm.md §4b: the rotation part alone on the reference sphere (§4.9). The
# particles turn rigidly at omega 1 about -z (v0 = (x2, -x1, 0)); sigma0 = diag(10, -10, 0) for
# x1 < 0, 0 elsewhere; S <- exp(dt W) S exp(dt W)^T with W the spin of the fit's grad v. To
# 12.5 s: max |S - S_exact| <= 1e-9 (absolute, every step), |x| preserved to 1e-11, the
# unstressed particles exactly 0. The exact map makes the answer independent of dt, so the
# default test takes a coarse sphere (spacing 1.25, h = 2.5: 280 particles) and dt = 0.005
# (2500 steps); the tutorial runs the thesis's 0.75 / 1.5 / 0.001.
source "$(dirname "$0")/common.sh"
c="$WORK/rotationOnly"
copyTutorial rotationOnly "$c"
coarseSphere "$c" 0.005
grep -q "^endTime *12.5;" "$c/system/controlDict" || fail "the tutorial no longer ends at 12.5 s"
run "$c" particleGen
run "$c" fpmSolid
e="$c/12.5/rotationError"
[ -f "$e" ] || fail "no 12.5/rotationError"
stress=$(entry "$e" runMaxStressError) radius=$(entry "$e" runMaxRadiusChange) zero=$(entry "$e" runMaxZeroStress)
echo "max |S - S_exact| $stress, max ||x| - |x0|| $radius, max |S| unstressed $zero (over 2500 steps)"
awk -v s="$stress" 'BEGIN { exit !(s <= 1e-9) }' || fail "max |S - S_exact| = $stress > 1e-9"
awk -v r="$radius" 'BEGIN { exit !(r <= 1e-11) }' || fail "|x| changed by $radius > 1e-11"
awk -v z="$zero" 'BEGIN { exit !(z == 0) }' || fail "an unstressed particle has |S| = $zero"
# Independently of the solver's own measure, from the written particles: at t = 12.5 the stressed
# half has S11 = 10 cos 25 = 9.91202811863, S21 = -10 sin 25 = 1.32351750098, the other half 0.
read -r lo hi < <(fieldRange "$c" 12.5 deviatoricStress.xx)
awk -v lo="$lo" -v hi="$hi" 'BEGIN { d = hi - 9.912028118634735; exit !(lo == 0 && d < 1e-9 && d > -1e-9) }' ||
    fail "S11 range [$lo, $hi], expected [0, 9.912028118634735]"
read -r lo hi < <(fieldRange "$c" 12.5 deviatoricStress.xy)
awk -v lo="$lo" -v hi="$hi" 'BEGIN { d = hi - 1.3235175009777302; exit !(lo == 0 && d < 1e-9 && d > -1e-9) }' ||
    fail "S21 range [$lo, $hi], expected [0, 1.3235175009777302]"
grep -q "fallbacks: 0 grown supports, 0 Shepard fits" "$c/log.fpmSolid" || fail "the fit took a fallback: $(grep fallbacks "$c/log.fpmSolid")"
echo "PASS: R4 rotation part alone to 12.5 s"
