#!/usr/bin/env bash
# R11 of doc/methods/fpm.md §4b on the tutorial rotatingSphere (the reference sphere, 1244 particles,
# to 5 s), as written: the in-plane radius's first extrema at about 1.1 (maximum), 2.0 (minimum) and
# 2.9 s (maximum), each +- 0.2; L_z and the energy printed (the thesis gives none; R11 asserts no
# boundedness). The figures are printed before any assertion. Validation label: minutes.
source "$(dirname "$0")/common.sh"
c="$WORK/rotatingSphere"
runToTheEnd rotatingSphere "$c"
e="$c/postProcessing/shape/0/bodyExtents.csv"
q="$c/postProcessing/budget/0/conservedQuantities.csv"
extrema=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "r") k = i; next }
    !k { exit 1 } { r[++n] = $k; t[n] = $1 }
    END { m = 0; s = ""; for (i = 2; i < n && m < 3; i++)
              if ((r[i] >= r[i - 1] && r[i] > r[i + 1]) || (r[i] <= r[i - 1] && r[i] < r[i + 1])) { s = s " " t[i]; m++ }
          while (m < 3) { s = s " none"; m++ } print s }' "$e") || fail "no r column in $e"
read -r t1 t2 t3 <<< "$extrema"
budget=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "totalEnergy") k = i; if ($i == "angularMomentum_z") z = i } next }
    NR == 2 { e0 = $k; l0 = $z } { e = $k; l = $z; t = $1 } END { print e0, e, l0, l, t }' "$q")
echo "R11: in-plane radius extrema at t = $t1, $t2, $t3 (1.1, 2.0, 2.9 +- 0.2); energy, L_z (start, end) and the end time: $budget (exit $status)${diagnosis:+: $diagnosis}"
for pair in "$t1 1.1" "$t2 2.0" "$t3 2.9"; do
    read -r got want <<< "$pair"
    [ "$got" != none ] && awk -v t="$got" -v w="$want" 'BEGIN { exit !(t >= w - 0.2 && t <= w + 0.2) }' ||
        fail "R11: an extremum of the in-plane radius at t = $got, not $want +- 0.2"
done
exit 0
