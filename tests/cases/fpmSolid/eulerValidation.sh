#!/usr/bin/env bash
# R6 of doc/methods/fpm.md §4b: the Euler validation (§4.4) in frozen mode. The Euler part alone on
# the reference sphere with frozen particles, v0 = 0.1 (x1, -0.5 x2, -0.5 x3) (divergence- and
# curl-free), rho = 1, p = 2, an ideal gas (gamma 1.4, e = 5): rho, p and v stay at their initial
# values to 1e-10 (the solver's max |rho - rho_0|, |p - p_0|, |v - v_0| over every step). p is
# uniform, so every particle takes the |grad p| ~ 0 branch (central evaluation, counted); the
# upwinded branch is R3's unit test (fpm.EulerPart.*). The default test takes a coarse sphere
# (spacing 1.25, h = 2.5: 280 particles) and dt = 0.005 to 5 s (1000 steps); the tutorial runs the
# thesis's 0.75 / 1.5 / 0.001.
source "$(dirname "$0")/common.sh"
c="$WORK/eulerValidation"
copyTutorial eulerValidation "$c"
coarseSphere "$c" 0.005
grep -q "^endTime *5;" "$c/system/controlDict" || fail "the tutorial no longer ends at 5 s"
run "$c" particleGen
run "$c" fpmSolid
s="$c/5/stateChange"
[ -f "$s" ] || fail "no 5/stateChange"
rho=$(entry "$s" runMaxDensityChange) p=$(entry "$s" runMaxPressureChange) v=$(entry "$s" runMaxVelocityChange)
echo "max |rho - 1| $rho, max |p - 2| $p, max |v - v0| $v (over 1000 steps)"
for q in "rho $rho" "p $p" "v $v"; do
    set -- $q
    awk -v e="$2" 'BEGIN { exit !(e <= 1e-10) }' || fail "max change of $1 = $2 > 1e-10"
done
# Independently, from the written particles at 5 s: rho and p uniform at 1 and 2.
read -r lo hi < <(fieldRange "$c" 5 density)
awk -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(lo - 1 < 1e-10 && 1 - lo < 1e-10 && hi - 1 < 1e-10 && 1 - hi < 1e-10) }' ||
    fail "density range [$lo, $hi], expected 1"
read -r lo hi < <(fieldRange "$c" 5 pressure)
awk -v lo="$lo" -v hi="$hi" 'BEGIN { exit !(lo - 2 < 1e-10 && 2 - lo < 1e-10 && hi - 2 < 1e-10 && 2 - hi < 1e-10) }' ||
    fail "pressure range [$lo, $hi], expected 2"
grep -q "with |grad p| ~ 0, 0 with a shifted fit short of neighbours" "$c/log.fpmSolid" ||
    fail "the Euler part's central evaluations: $(grep "^ *euler " "$c/log.fpmSolid")"
grep -q "fallbacks: 0 grown supports, 0 Shepard fits" "$c/log.fpmSolid" || fail "the fit took a fallback"
allRead "$c/log.fpmSolid"
# R6L, the Lagrangian mode (§4.4's caveat): the same case with `motion { velocity upwind; }`. p stays
# uniform, so v_uw = v, the particles fly ballistically, grad v = A (I + t A)^-1 and mass conservation
# gives rho(t) = 1 / ((1 + 0.1 t)(1 - 0.05 t)^2) = 1.185185 at t = 5; the adiabatic ideal gas then
# p = 2 rho^1.4 = 2.537060 (the boundary p(t) of the ODE is this uniform p: no boundary condition
# is needed). Forward Euler, dt 0.005: 1e-3 relative (R6L's tolerance); rho and p uniform to 1e-9.
l="$WORK/lagrangian"
copyTutorial eulerValidation "$l"
coarseSphere "$l" 0.005
sed -i 's/velocity frozen;/velocity upwind;/' "$l/constant/fpmProperties"
grep -q "velocity upwind;" "$l/constant/fpmProperties" || fail "could not set velocity upwind"
run "$l" particleGen
run "$l" fpmSolid
read -r lo hi < <(fieldRange "$l" 5 density)
awk -v lo="$lo" -v hi="$hi" 'BEGIN { r = 1 / (1.5 * 0.75 * 0.75); e = (lo - r) / r; exit !(e < 1e-3 && e > -1e-3 && hi - lo < 1e-9) }' ||
    fail "R6L: density at 5 in [$lo, $hi], expected 1.185185 (1e-3 relative), uniform"
read -r plo phi < <(fieldRange "$l" 5 pressure)
awk -v lo="$plo" -v hi="$phi" 'BEGIN { r = 2 * (1 / (1.5 * 0.75 * 0.75)) ^ 1.4; e = (lo - r) / r; exit !(e < 1e-3 && e > -1e-3 && hi - lo < 1e-9) }' ||
    fail "R6L: pressure at 5 in [$plo, $phi], expected 2.537060 (1e-3 relative), uniform"
grep -q "motion: the Euler part's upwind velocity" "$l/log.fpmSolid" || fail "R6L: the motion is not logged"
echo "R6L: rho(5) = $lo (exact 1.185185), p(5) = $plo (exact 2.537060), uniform to $(awk -v a="$lo" -v b="$hi" 'BEGIN { print b - a }')"
# The bracket of the Euler part's pressure equation: e = 0 gives the ideal gas c^2 = 0, a RunError
# at step 1 naming the phase, the particle, the field and the remedy, exit 1.
b="$WORK/bracket"
copyTutorial eulerValidation "$b"
sed -i 's/spacing 0.75; }/spacing 2; }/; s/specificInternalEnergy 5;/specificInternalEnergy 0;/' "$b/system/particleGenDict"
sed -i 's/^smoothingLength .*/smoothingLength 4;/' "$b/constant/fpmProperties"
run "$b" particleGen
rc=0; fpmSolid -case "$b" > "$b/log.fpmSolid" 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "bracket: exit status $rc, expected 1"
grep -q "phase euler, step 1, t = 0: particle [0-9]* (material gas): the bracket rho c^2 + g p / rho .* not positive (rho 1, p 2, c^2 0 .*Remedy" "$b/log.fpmSolid" ||
    fail "bracket: $(grep -m1 Error "$b/log.fpmSolid")"
echo "bracket: $(grep -m1 -o 'phase euler.\{0,100\}' "$b/log.fpmSolid")"
echo "PASS: R6 Euler validation, frozen mode, and R6L, the Lagrangian mode, to 5 s"
