#!/usr/bin/env bash
# The shearing sphere, the shear part alone (doc/methods/fpm.md §4.5; von Nida 2005 §6.2.1), on the
# coarse sphere (spacing 1.25, h = 3 spacings = 3.75 as the tutorial's h / spacing: 280 particles), to
# t = 2.2 with the tutorial's settings (sigma0 = -10 I, g = 10, traction sigma n = -p_o n with p_o = 10
# keeping the shear part's outgoing characteristic). The thesis: stretched along the bisector x1 = x2,
# "elongation normal to the bisector at 1.2 s, back along the original direction at 1.9 s". Asserted,
# on the elongation d1 - d2 (the extent along the bisector less that normal to it):
# - it runs without a diagnosis and d1 - d2 is largest at first (the stretch along the bisector);
# - the first minimum of d1 - d2 after its first maximum lies at 1.2 +- 0.2 and the maximum after
#   it at 1.9 +- 0.2 (the thesis's times, to the bound R10 and R11 take for its readings);
# - the energy (kinetic + sum m e) falls between every two written times (the upwinded part and the
#   surface condition only dissipate: a rise is an instability).
# Not asserted: that the elongation turns normal to the bisector (d1 - d2 < 0) at 1.2 s; on the
# tutorial's sphere it falls to 0.74 at 1.38 s and first turns negative after 2.4 s (README).
source "$(dirname "$0")/common.sh"
c="$WORK/shearingSphere"
freeSurfaceSphere shearingSphere "$c" 2.2
grep -q "^subsystems *(shear);" "$c/constant/fpmProperties" || fail "the tutorial does not run the shear part alone"
e="$c/postProcessing/shape/0/bodyExtents.csv"
q="$c/postProcessing/budget/0/conservedQuantities.csv"
[ -f "$e" ] && [ -f "$q" ] || fail "no bodyExtents or conservedQuantities output"
extremes=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "l_d1") a = i; if ($i == "l_d2") b = i } next }
    !a || !b { exit 1 } { d[++n] = $a - $b; t[n] = $1 }
    END { k = 0
          for (i = 2; i < n; i++) {
              if (k % 2 == 0 && d[i] > d[i - 1] && d[i] >= d[i + 1]) { e[++k] = t[i]; v[k] = d[i] }
              else if (k % 2 == 1 && d[i] < d[i - 1] && d[i] <= d[i + 1]) { e[++k] = t[i]; v[k] = d[i] }
              if (k == 3) break }
          printf "%s %s %s %s %s %s\n", (k >= 1 ? e[1] : "none"), v[1] + 0, (k >= 2 ? e[2] : "none"), v[2] + 0, (k >= 3 ? e[3] : "none"), v[3] + 0 }' "$e") ||
    fail "no l_d1 or l_d2 column in $e"
read -r tMax1 dMax1 tMin dMin tMax2 dMax2 <<< "$extremes"
echo "elongation d1 - d2: largest $dMax1 at t = $tMax1, then smallest $dMin at t = $tMin (thesis 1.2), then largest $dMax2 at t = $tMax2 (thesis 1.9)"
[ "$tMax1" != none ] && awk -v t="$tMax1" 'BEGIN { exit !(t < 1.0) }' || fail "the elongation along the bisector does not peak first (t = $tMax1)"
[ "$tMin" != none ] && awk -v t="$tMin" 'BEGIN { exit !(t >= 1.0 && t <= 1.4) }' ||
    fail "the elongation's first minimum is at t = $tMin, not 1.2 +- 0.2"
[ "$tMax2" != none ] && awk -v t="$tMax2" 'BEGIN { exit !(t >= 1.7 && t <= 2.1) }' ||
    fail "the elongation's next maximum is at t = $tMax2, not 1.9 +- 0.2"
energyFalls "$q" ""
allRead "$c/log.fpmSolid"
exit 0
