# Taylor bar (Kamoulakos 1990): final length within 3% of 21.5 mm and footprint radius within 5% of
# 7.0 mm, from the tutorial's own Allrun (tutorials/impactSph/taylorBar, plane strain).
. "$(dirname "$0")/../impactSph/common.sh"
d=$(runTutorial taylorBar)
csv="$d/postProcessing/outline/0/fieldMinMax.csv"
[ -f "$csv" ] || fail "taylorBar wrote no fieldMinMax.csv"
t=$(column "$csv" time)
less 7.99e-5 "$t" || fail "last outline row at t = $t, expected 8e-5"
L=$(awk -v y="$(column "$csv" position_y_max)" 'BEGIN { printf "%.4f", y * 1e3 }')
R=$(awk -v a="$(column "$csv" position_x_min)" -v b="$(column "$csv" position_x_max)" \
    'BEGIN { a = -a; m = (a > b ? a : b) + 2e-4; printf "%.4f", m * 1e3 }')
eL=$(relErr "$L" 21.5); eR=$(relErr "$R" 7.0)
wall=$(awk '/^ *wall time/ { print $3; exit }' "$d/log.impactSph")
report="final length $L mm (reference 21.5, error $eL), footprint radius $R mm (reference 7.0, error $eR), $wall s"
less "$eL" 0.03 || fail "Taylor bar: $report"
less "$eR" 0.05 || fail "Taylor bar: $report"
pass "Taylor bar: $report"
