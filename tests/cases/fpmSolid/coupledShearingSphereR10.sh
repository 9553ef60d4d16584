#!/usr/bin/env bash
# R10 of doc/methods/fpm.md §4b on the tutorial coupledShearingSphere (the reference sphere, 1244
# particles, to 5 s), as written: max sigma_p in [12, 20] at t = 0.5 (the largest over the
# particles at the written times 0.45 .. 0.55), the first reversal at 1.4 +- 0.2 (taken as the first
# minimum of the extent along the bisector x1 = x2 after its maximum: the elongation's return), and
# no particle lost up to 5 s (the run ends at 5 s without a diagnosis, with its 1244 particles: with
# fitFallback none a particle with fewer than 2 (d + 1) neighbours within h stops the run).
# The figures are printed before any assertion. Validation label: minutes.
source "$(dirname "$0")/common.sh"
c="$WORK/coupledShearingSphere"
runToTheEnd coupledShearingSphere "$c"
s="$c/postProcessing/stress/0/fieldMinMax.csv"
e="$c/postProcessing/shape/0/bodyExtents.csv"
sigma=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "maxPrincipalStress_max") k = i; next }
    k && $1 >= 0.45 - 1e-9 && $1 <= 0.55 + 1e-9 && $k > m { m = $k } END { if (!k) exit 1; print m + 0 }' "$s") ||
    fail "no maxPrincipalStress_max in $s"
reversal=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "l_d1") k = i; next }
    !k { exit 1 } { l[++n] = $k; t[n] = $1 }
    END { top = 1; for (i = 2; i <= n; i++) if (l[i] > l[top]) top = i;
          for (i = top + 1; i < n; i++) if (l[i] <= l[i - 1] && l[i] < l[i + 1]) { print t[i]; exit }
          print "none" }' "$e") || fail "no l_d1 in $e"
last=$(tail -n 1 "$e" | cut -d, -f1)
echo "R10: max sigma_p at 0.45..0.55 = $sigma (bound [12, 20]); first reversal at t = $reversal (1.4 +- 0.2);" \
    "ran to t = $last of 5 (exit $status)${diagnosis:+: $diagnosis}"
awk -v s="$sigma" 'BEGIN { exit !(s >= 12 && s <= 20) }' || fail "R10: max sigma_p at t = 0.5 is $sigma, not in [12, 20]"
[ "$reversal" != none ] && awk -v t="$reversal" 'BEGIN { exit !(t >= 1.2 && t <= 1.6) }' ||
    fail "R10: the first reversal at t = $reversal, not 1.4 +- 0.2"
[ "$status" = 0 ] || fail "R10: the run stopped at t = $last (exit $status): $diagnosis"
particles=$(grep -m1 -o "[0-9]* particles" "$c/log.fpmSolid" | head -1)
echo "R10: $particles at the start"
exit 0
