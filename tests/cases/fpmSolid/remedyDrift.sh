#!/usr/bin/env bash
# The remedy, measured (issue 19): the rotating sphere (R11's set-up) over 20 s with the linear basis
# (tutorials/fpmSolid/rotatingSphere) and with the quadratic one (tutorials/fpmSolid/
# rotatingSphereQuadratic: order 2, its shifted fits linear), both run side by side to t = 20. The
# drift is the least-squares slope over 3 .. 20 s (after the first oscillation, where the thesis's
# drift starts) of the in-plane radius and of the height: the radius as r_ring, the mean distance from
# the x3 axis of the particles at 0.8 r or more (the outer ring, the circumference the thesis's
# pictures show; r itself, the largest distance, is one particle's once one leaves). Asserted, as
# the issue writes: both runs reach 20 s, and the quadratic basis's slopes are at least 5 times
# smaller in magnitude than the linear one's, for the radius and for the height. L_z and the energy
# at 20 s are printed for both (the thesis gives none). On 8a6d00d neither reaches 20 s: the linear
# basis stops at 5.73 (a particle out of its neighbours), the quadratic at 4.87 (an ill-conditioned
# quadratic fit); over 3 s to their ends the r_ring slopes are 0.179 and 0.291 per s, the height's
# -0.056 and -0.061: the test fails as written.
source "$(dirname "$0")/common.sh"
slopes() {  # <bodyExtents.csv>: t_end r_ring-slope height-slope r_ring-end height-end
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "height") kh = i; if ($i == "r_ring") kg = i } next }
        !kh || !kg { exit 1 }
        { t = $1; if (t >= 3 - 1e-9) { n++; st += t; stt += t * t; sg += $kg; stg += t * $kg; sh += $kh; sth += t * $kh }
          ge = $kg; he = $kh; te = t }
        END { if (n < 2) { print te, "nan", "nan", ge, he; exit } d = n * stt - st * st
              print te, (n * stg - st * sg) / d, (n * sth - st * sh) / d, ge, he }' "$1"
}
status=()
for tutorial in rotatingSphere rotatingSphereQuadratic; do
    c="$WORK/$tutorial"
    copyTutorial "$tutorial" "$c"
    sed -i "s/^endTime .*/endTime         20;/; s/^writeInterval .*/writeInterval   5;/" "$c/system/controlDict"
    run "$c" particleGen
    (rc=0; fpmSolid -case "$c" > "$c/log.fpmSolid" 2>&1 || rc=$?; echo "$rc" > "$c/status") &
done
wait
declare -A tEnd ringSlope heightSlope
for tutorial in rotatingSphere rotatingSphereQuadratic; do
    c="$WORK/$tutorial"
    e="$c/postProcessing/shape/0/bodyExtents.csv"
    q="$c/postProcessing/budget/0/conservedQuantities.csv"
    [ -f "$e" ] && [ -f "$q" ] || fail "$tutorial: no bodyExtents or conservedQuantities output"
    read -r t g h gEnd hEnd <<< "$(slopes "$e")" || fail "$tutorial: no height or r_ring column in $e"
    tEnd[$tutorial]=$t; ringSlope[$tutorial]=$g; heightSlope[$tutorial]=$h
    budget=$(tail -n 1 "$q" | awk -F, '{ print $8, $NF }')
    echo "$tutorial: reached t = $t (exit status $(cat "$c/status")); over 3 .. $t s: r_ring slope $g, height slope $h; at the end r_ring $gEnd, height $hEnd; L_z and energy $budget"
done
for tutorial in rotatingSphere rotatingSphereQuadratic; do
    awk -v t="${tEnd[$tutorial]}" 'BEGIN { exit !(t >= 20 - 1e-6) }' || fail "$tutorial stopped at t = ${tEnd[$tutorial]}, before 20 s: $(grep -m1 Error "$WORK/$tutorial/log.fpmSolid" | cut -c1-300)"
done
awk -v a="${ringSlope[rotatingSphere]}" -v b="${ringSlope[rotatingSphereQuadratic]}" 'BEGIN { exit !((a < 0 ? -a : a) >= 5 * (b < 0 ? -b : b)) }' ||
    fail "the radius drifts ${ringSlope[rotatingSphereQuadratic]} per s with the quadratic basis, ${ringSlope[rotatingSphere]} with the linear: not 5 times less"
awk -v a="${heightSlope[rotatingSphere]}" -v b="${heightSlope[rotatingSphereQuadratic]}" 'BEGIN { exit !((a < 0 ? -a : a) >= 5 * (b < 0 ? -b : b)) }' ||
    fail "the height drifts ${heightSlope[rotatingSphereQuadratic]} per s with the quadratic basis, ${heightSlope[rotatingSphere]} with the linear: not 5 times less"
exit 0
