# Hydrostatic water column (tutorials/mpmFsi/hydrostaticColumn, doc/methods/mpm.md 5, X1): a
# Tait water column 1 m deep (c0 50 m/s, 1600 points, quadratic B-splines) at rest under gravity
# with mass-proportional grid damping 100 1/s, to t = 0.5 s. hydrostaticPressure bins the pressure
# along the centre line (18 bins below H - 0.1) against rho g (H - h). Asserted at t = 0.5:
#   all 18 bins present, each with particles (a sampling line that misses the column fails);
#   the worst bin within 2% of rho g (H - h) (issue 18's acceptance; measured 0.44%, at the
#       floor), and the Linf norm within 2% of rho g H (errorNorms.csv);
#   the measured surface H within 0.5% of the column's 1 m (Tait compression at the floor 0.4%,
#       so the surface sinks by about 0.2%; measured 0.998058);
#   the transient is seen: at the first write after t = 0 (t = 0.05) the worst bin is off by more
#       than 2% (measured 9.7%: the column has not yet settled, so the norm can fail);
#   mass exact (conservedQuantities drift 0). About 1 CPU-s.
source "$(dirname "$0")/common.sh"
c="$WORK/column"
copyTutorial hydrostaticColumn "$c"
run "$c" particleGen
run "$c" mpmFsi
csv="$c/postProcessing/pressure/0/profile.csv"
norms="$c/postProcessing/pressure/0/errorNorms.csv"
[ -f "$csv" ] || fail "no profile.csv"
t=$(tail -n 1 "$csv" | cut -d, -f1)
[ "$t" = 0.5 ] || fail "the last write is at t = $t, not 0.5"
bins=$(awk -F, '$1 == 0.5 && $6 > 0' "$csv" | wc -l)
[ "$bins" = 18 ] || fail "$bins bins with particles at t = 0.5, expected 18"
worst=$(awk -F, '$1 == 0.5 { r = $5 < 0 ? -$5 : $5; if (r > w) w = r } END { print w }' "$csv")
echo "t = 0.5: worst bin relative error $worst over $bins bins"
less "$worst" 0.02 || fail "worst bin off rho g (H - h) by $worst (> 2%)"
linf=$(awk -F, '$1 == 0.5 { print $5 / (1000 * 9.81) }' "$norms")
[ -n "$linf" ] || fail "no error norms at t = 0.5 in $norms"
less "$linf" 0.02 || fail "Linf norm / rho g H = $linf (> 2%)"
H=$(grep -o "hydrostaticPressure 'pressure': at t = 0.5, H = [0-9.e+-]*" "$c/log.mpmFsi" | awk '{ print $NF }')
[ -n "$H" ] || fail "no hydrostaticPressure summary at t = 0.5 in the log"
within "$H" 1 0.005 || fail "the surface H = $H is not within 0.5% of 1 m"
early=$(awk -F, 'NR > 1 && $1 > 0 { if (t == "") t = $1; if ($1 == t) { r = $5 < 0 ? -$5 : $5; if (r > w) w = r } } END { print w }' "$csv")
less 0.02 "$early" || fail "at the first write after t = 0 the worst bin is $early: the transient was not seen"
grep -q "conserved: mass drift 0.000e+00 relative" "$c/log.mpmFsi" ||
    fail "mass not exact: $(grep 'mass drift' "$c/log.mpmFsi")"
echo "PASS: hydrostaticColumn (worst bin $worst, Linf/rho g H $linf, H $H, t = 0.05 worst $early)"
