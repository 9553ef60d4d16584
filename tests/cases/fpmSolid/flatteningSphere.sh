#!/usr/bin/env bash
# The flattening sphere, the Euler part alone (doc/methods/fpm.md §4.3; von Nida 2005 §6.1.3), on
# the coarse sphere (spacing 1.25, h = 3.75: 280 particles), to t = 1.5 with the tutorial's settings
# (ideal gas, p = p_o = 10, v0 = 0.5 (x1, x2, 0), insertion on). The thesis's observations, each
# asserted: at 0.5 s the radius grows and the sphere flattens along x3 (the x1 extent above and the
# x3 extent below their initial 9), and the interior pressure is low (the least p below p_o = 10, the
# largest p_o: the surface's); at 1.5 s the highest p is inside (the largest p above p_o).
source "$(dirname "$0")/common.sh"
c="$WORK/flatteningSphere"
freeSurfaceSphere flatteningSphere "$c" 1.5
e="$c/postProcessing/shape/0/bodyExtents.csv"
s="$c/postProcessing/stress/0/fieldMinMax.csv"
[ -f "$e" ] && [ -f "$s" ] || fail "no bodyExtents or fieldMinMax output"
at() {  # <csv> <time> <column>: the value in the row of that time
    awk -F, -v t="$2" -v name="$3" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == name) k = i; next }
        k && ($1 - t < 1e-9 && t - $1 < 1e-9) { print $k; found = 1; exit } END { if (!found) exit 1 }' "$1"
}
x0=$(at "$e" 0 l_d1) && z0=$(at "$e" 0 l_d3) && x=$(at "$e" 0.5 l_d1) && z=$(at "$e" 0.5 l_d3) || fail "no extents at 0 and 0.5 in $e"
pLow=$(at "$s" 0.5 pressure_min) && pHigh05=$(at "$s" 0.5 pressure_max) && pHigh=$(at "$s" 1.5 pressure_max) || fail "no pressures at 0.5 and 1.5 in $s"
echo "t = 0.5: x1 extent $x0 -> $x, x3 extent $z0 -> $z; p in [$pLow, $pHigh05]; t = 1.5: largest p $pHigh (p_o 10)"
awk -v a="$x" -v b="$x0" -v c="$z" -v d="$z0" 'BEGIN { exit !(a > b && c < d) }' || fail "at 0.5 s the sphere does not grow in x1 and flatten in x3"
awk -v p="$pLow" -v q="$pHigh05" 'BEGIN { exit !(p < 10 && q <= 10 + 1e-9) }' || fail "at 0.5 s the interior pressure is not below p_o = 10 (range $pLow .. $pHigh05)"
awk -v p="$pHigh" 'BEGIN { exit !(p > 10) }' || fail "at 1.5 s the largest pressure $pHigh is not above p_o = 10 (inside)"
allRead "$c/log.fpmSolid"
exit 0
