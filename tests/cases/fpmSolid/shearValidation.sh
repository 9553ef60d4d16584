#!/usr/bin/env bash
# R5 and R5L of doc/methods/fpm.md §4b: the shear validation (§4.6), and von Mises plasticity on it. The shear part alone on the
# reference sphere, v0 = 0.1 (x2, x1, 0), rho = 1, p = 0, S = 0, mu = 50, g = 0, v = v0(x) on the
# boundary shell (|x| > 4.4, the thesis's velocity Dirichlet condition), dimensional upwinding with
# delta 0.3 (l = 0.3 c_S clamped to 0.5 h). Frozen particles (R5): S21 = 0.2 mu t = 50 at t = 5 and
# everything else constant, to 1e-8 relative (forward Euler is exact for a constant rate: what
# remains is round-off and its growth). The solver's reference linearFlow integrates the uniform
# state's ODE (fpm/LinearFlowReference.hpp) and writes the errors to each time's referenceError.
# R5L, the Lagrangian mode: the particles moved with the dimensional velocity v_D, the boundary
# v = v0(xi); the flow is ballistic, grad v = A (I + t A)^-1, and S21 = 2 mu artanh(0.1 t) =
# 54.9306, S11 = (mu/3) ln(1 - 0.01 t^2) = -4.7947 at t = 5 (the note's table): 1e-3 relative
# (forward Euler, O(dt)). The default test takes the coarse sphere (spacing 1.25, h 2.5: 280
# particles, dt 0.005, 1000 steps); the tutorial runs the thesis's 0.75 / 1.5 / 0.001.
source "$(dirname "$0")/common.sh"
c="$WORK/shearValidation"
copyTutorial shearValidation "$c"
coarseSphere "$c" 0.005
grep -q "^endTime *5;" "$c/system/controlDict" || fail "the tutorial no longer ends at 5 s"
run "$c" particleGen
run "$c" fpmSolid
r="$c/5/referenceError"
[ -f "$r" ] || fail "no 5/referenceError"
exact=$(exactStress "$r" 4)
awk -v e="$exact" 'BEGIN { exit !(e - 50 < 1e-9 && 50 - e < 1e-9) }' || fail "R5: the reference's S21(5) = $exact, expected 0.2 mu t = 50"
s=$(entry "$r" relativeStressError) rho=$(entry "$r" densityError) p=$(entry "$r" pressureError)
echo "R5 (frozen): S21(5) exact $exact; relative S error $s, |rho - 1| $rho, |p| $p"
awk -v e="$s" 'BEGIN { exit !(e <= 1e-8) }' || fail "R5: relative stress error $s > 1e-8"
awk -v a="$rho" -v b="$p" 'BEGIN { exit !(a <= 1e-12 && b <= 1e-12) }' || fail "R5: rho or p changed ($rho, $p)"
v=$(entry "$c/5/stateChange" runMaxVelocityChange)
awk -v e="$v" 'BEGIN { exit !(e <= 1e-8) }' || fail "R5: max |v - v0| = $v > 1e-8 (div S_D must vanish)"
grep -q "0 with a shifted fit short of neighbours, 0 with mu = 0" "$c/log.fpmSolid" ||
    fail "R5: central shear evaluations: $(grep "^ *shear " "$c/log.fpmSolid")"
allRead "$c/log.fpmSolid"
# R5L
l="$WORK/lagrangian"
lagrangianVariant shearValidation "$l" 0.005
run "$l" particleGen
run "$l" fpmSolid
r="$l/5/referenceError"
read -r s11 s21 < <(exactStress "$r" 1 4)
awk -v a="$s21" -v b="$s11" 'BEGIN { exit !(a - 54.9306 < 1e-4 && 54.9306 - a < 1e-4 && b + 4.7947 < 1e-4 && -4.7947 - b < 1e-4) }' ||
    fail "R5L: the reference's S21(5) = $s21, S11(5) = $s11, expected 54.9306 and -4.7947 (the note's table)"
s=$(entry "$r" relativeStressError) rho=$(entry "$r" densityError)
echo "R5L (Lagrangian): S21(5) exact $s21, S11(5) $s11; relative S error $s, |rho - 1| $rho"
awk -v e="$s" 'BEGIN { exit !(e <= 1e-3) }' || fail "R5L: relative stress error $s > 1e-3"
awk -v a="$rho" 'BEGIN { exit !(a <= 1e-12) }' || fail "R5L: rho changed ($rho): the shear part keeps it"
grep -q "motion: the shear part's dimensional velocity" "$l/log.fpmSolid" || fail "R5L: the motion is not logged"
echo "R5 and R5L pass"
# Von Mises plasticity from the strength family (the thesis's named future work), on the frozen
# validation: strength vonMises with yieldStress 20 (perfectly plastic). Pure shear has
# sigma_eq = sqrt(3) |S21|, so S21 = 10 t until t = 2/sqrt(3) = 1.1547 and then the yield value
# 20/sqrt(3) = 11.5470 (the radial return), every other component 0, plasticStrain > 0.
y="$WORK/plastic"
copyTutorial shearValidation "$y"
coarseSphere "$y" 0.005
sed -i 's/strength { type hookean; shearModulus 50; }/strength { type vonMises; shearModulus 50; yieldStress 20; }/' "$y/constant/materialProperties"
grep -q "type vonMises" "$y/constant/materialProperties" || fail "could not set vonMises"
sed -i '/^reference/d' "$y/constant/fpmProperties"
run "$y" particleGen
run "$y" fpmSolid
for t in 1 5; do
    read -r lo hi < <(fieldRange "$y" $t deviatoricStress.xy)
    exact=$(awk -v t=$t 'BEGIN { s = 10 * t; y = 20 / sqrt(3); printf "%.15g", (s < y ? s : y) }')
    echo "vonMises: S21($t) in [$lo, $hi], exact $exact"
    awk -v lo="$lo" -v hi="$hi" -v e="$exact" 'BEGIN { exit !((lo - e) / e < 1e-8 && (e - lo) / e < 1e-8 && (hi - e) / e < 1e-8 && (e - hi) / e < 1e-8) }' ||
        fail "vonMises: S21($t) in [$lo, $hi], expected $exact (1e-8 relative)"
done
read -r lo hi < <(fieldRange "$y" 5 plasticStrain)
awk -v lo="$lo" 'BEGIN { exit !(lo > 0) }' || fail "vonMises: plasticStrain at 5 in [$lo, $hi], expected > 0 everywhere"
echo "PASS: von Mises, S21 held at the yield value 20/sqrt(3)"
