#!/usr/bin/env bash
# The coupled shearing sphere (R10's setup, doc/methods/fpm.md §4.7) on the coarse sphere (spacing
# 1.25, h = 3 spacings = 3.75 as the tutorial's h / spacing: 280 particles), to t = 2 with the
# tutorial's settings (free surface p = 0, S n = 0 keeping each part's outgoing characteristic;
# shifts clamped to h / 4). Asserted:
# - it runs through the elongation and its return without a diagnosis;
# - the extent along the bisector x1 = x2 peaks at t = 0.5 +- 0.1 (the thesis's maximal elongation
#   at 0.5 s, given to one decimal);
# - its first minimum after the peak (the motion's reversal) lies at 1.4 +- 0.2 (R10's bound);
# - the energy (kinetic + sum m e) falls between every two written times (each 0.01 s): the upwinded
#   parts and the surface condition only dissipate, so a rise is an instability (the unchanged
#   surface velocity (`velocity unchanged`) first gains energy at t = 1.32 on this sphere and stops
#   at t = 4.13, a particle out of its neighbours).
# R10's figures on the tutorial's sphere (sigma_p in [12, 20] at 0.5, 5 s without loss) are the
# validation test coupledShearingSphereR10.
source "$(dirname "$0")/common.sh"
c="$WORK/coupledShearingSphere"
freeSurfaceSphere coupledShearingSphere "$c" 2
e="$c/postProcessing/shape/0/bodyExtents.csv"
q="$c/postProcessing/budget/0/conservedQuantities.csv"
[ -f "$e" ] && [ -f "$q" ] || fail "no bodyExtents or conservedQuantities output"
# l_d1: the extent along the first direction, (1 1 0); its largest value, then its first minimum
extremes=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "l_d1") k = i; next }
    !k { exit 1 } { l[++n] = $k; t[n] = $1 }
    END { top = 1; for (i = 2; i <= n; i++) if (l[i] > l[top]) top = i; low = "none"
          for (i = top + 1; i < n; i++) if (l[i] <= l[i - 1] && l[i] < l[i + 1]) { low = t[i]; break }
          print t[top], l[top], low }' "$e") || fail "no l_d1 column in $e"
read -r tPeak lPeak tReversal <<< "$extremes"
echo "bisector extent: largest $lPeak at t = $tPeak (thesis 0.5), first minimum after it at t = $tReversal (R10: 1.4 +- 0.2)"
awk -v t="$tPeak" 'BEGIN { exit !(t >= 0.4 && t <= 0.6) }' || fail "the bisector extent peaks at t = $tPeak, not 0.5 +- 0.1"
[ "$tReversal" != none ] && awk -v t="$tReversal" 'BEGIN { exit !(t >= 1.2 && t <= 1.6) }' ||
    fail "the bisector extent's first minimum after its peak is at t = $tReversal, not 1.4 +- 0.2"
energyFalls "$q" ""
allRead "$c/log.fpmSolid"
exit 0
