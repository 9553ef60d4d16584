#!/usr/bin/env bash
# The clamped plate's period with FPM (tutorials/fpmSolid/oscillatingPlate, the tlSph plate of Gray,
# Monaghan & Swift 2001): the tutorial as shipped, 0.6 s, the period from the zero crossings of the
# tip's velocity (period.awk) asserted within 5% of thin-plate theory's 0.254 s (the issue's bound;
# the theory ignores shear and rotary inertia, about +1% at L/H = 10, and the lattice's own error is
# about +3% for tlSph at this dx: tutorials/tlSph/oscillatingPlate). On 06a91a5 it measures 0.623 s
# (+145%, the thesis's free-surface conditions leave the bending stress out of the surface layers;
# README), so this test fails as written until a free-surface condition that keeps it is stable.
source "$(dirname "$0")/common.sh"
c="$WORK/oscillatingPlate"
copyTutorial oscillatingPlate "$c"
run "$c" particleGen
run "$c" fpmSolid
read -r period crossings first < <(awk -F, -f "$c/period.awk" "$c/postProcessing/tip/0/probes.csv")
echo "period $period s from $crossings zero crossings of the tip's v_y (the first at $first s); thin-plate theory 0.254 s"
[ "$period" != nan ] || fail "fewer than two zero crossings of the tip's velocity by 0.6 s"
awk -v T="$period" 'BEGIN { exit !(T >= 0.254 * 0.95 && T <= 0.254 * 1.05) }' || fail "the period $period s is not within 5% of 0.254 s"
exit 0
