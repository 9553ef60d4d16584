# Davison's asymmetric impact, the three rows of doc/methods/sph-impact.md 8.3 (Zisis 2017 §5.1), run by the
# tutorial's Allrun: the star pressure (median over the shocked plateaus, riemannError against the
# exact two-shock solution of the linear barotropic Riemann problem) within 3% of the exact value
# P* = 0.21142, 0.34056, 0.18623 in each row; the tutorial's runs are within 0.2%.
. "$(dirname "$0")/common.sh"
d=$(runTutorial asymmetricImpact)
report=""
for row in row1 row2 row3; do
    star="$d/$row/postProcessing/riemann/0/starState.csv"
    [ -f "$star" ] || fail "$row wrote no starState.csv"
    [ "$(column "$star" time)" = 0.3 ] || fail "$row: last star state at t = $(column "$star" time)"
    p=$(column "$star" pStar); pe=$(column "$star" pStarExact)
    e=$(relErr "$p" "$pe")
    less "$e" 0.03 || fail "$row: P* $p off exact $pe by $e"
    wall=$(awk '/^ *wall time/ { print $3; exit }' "$d/$row/log.impactSph")
    report="$report $row P* $p (exact $pe, error $e, $wall s);"
done
pass "asymmetric impact:$report"
