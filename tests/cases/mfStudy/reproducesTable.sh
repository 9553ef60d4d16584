# A study of three resolutions of the Sod tube (h = 0.01, 0.005, 0.0025; right spacing 8 h; deltaT
# 0.04 h) reproduces its table: the scale rule gives the exact steps and particles, the orders it
# prints agree with an independent least-squares fit and Richardson formula computed here with awk
# from the CSV, a second study from scratch gives the same error norms to the digit, and a report
# without gnuplot still writes the table and says the plots were skipped.
. "$(dirname "$0")/common.sh"
c=$(newCase table)
mfStudy -case "$c" > "$c/log.mfStudy" 2>&1 || fail "mfStudy failed: $(tail "$c/log.mfStudy")"
csv="$c/study/results.csv"
[ "$(grep -c ',finished,' "$csv")" = 3 ] || fail "expected 3 finished rows: $(cat "$csv")"
# endTime 0.2 / (0.04 h) steps; particles on [-0.5, 1.5]: 1/h + 1/(8h) (113 at 0.01: 100 + 12.5, the
# lattice puts 13 on the right).
for row in "h0.01 500 113" "h0.005 1000 225" "h0.0025 2000 450"; do
    set -- $row
    [ "$(field "$csv" "$1" steps)" = "$2" ] || fail "$1: steps $(field "$csv" "$1" steps), expected $2"
    [ "$(field "$csv" "$1" particles)" = "$3" ] || fail "$1: particles $(field "$csv" "$1" particles), expected $3"
    positive "$(field "$csv" "$1" cpuSeconds)" || fail "$1: no CPU time"
done
# The order in h: least squares slope of ln L1 on ln h, computed here.
hc=$(column "$csv" h); ec=$(column "$csv" riemann/density/L1)
fit=$(awk -F, -v hc="$hc" -v ec="$ec" 'NR > 1 { x = log($hc); y = log($ec); n++; sx += x; sy += y; sxx += x*x; sxy += x*y }
    END { printf "%.10g", (n*sxy - sx*sy) / (n*sxx - sx*sx) }' "$csv")
# Richardson with ratio 2: p = ln((e1 - e2)/(e2 - e3))/ln 2.
rich=$(awk -F, -v ec="$ec" 'NR > 1 { e[NR-1] = $ec } END { printf "%.10g", log((e[1]-e[2])/(e[2]-e[3]))/log(2) }' "$csv")
line=$(grep '^| base |' "$c/study/results.md") || fail "no scheme row in results.md"
printedFit=$(echo "$line" | awk -F'|' '{ gsub(/ /, "", $4); print $4 }')
printedRich=$(echo "$line" | awk -F'|' '{ gsub(/ /, "", $6); print $6 }')
# results.md prints 4 significant digits: 1e-3 relative covers the rounding.
near "$printedFit" "$fit" 1e-3 || fail "printed order in h $printedFit, awk fit $fit"
near "$printedRich" "$rich" 1e-3 || fail "printed Richardson order $printedRich, awk $rich"
grep -q "observed order in h $printedFit" "$c/log.mfStudy" || fail "the log does not print the order: $(cat "$c/log.mfStudy")"
# Sod's L1 density error converges at first order at best (the shock and contact are captured over
# a few h); the issue asks at least 0.6. Above 1.2 would mean the levels were not what was asked.
awk -v p="$fit" 'BEGIN { exit !(p >= 0.6 && p <= 1.2) }' || fail "observed L1 order $fit outside [0.6, 1.2]"
if command -v gnuplot > /dev/null; then
    for png in errorVsCpu errorVsResolution; do
        [ -s "$c/study/$png.png" ] || fail "no $png.png"
        [ "$(head -c 4 "$c/study/$png.png" | tail -c 3)" = PNG ] || fail "$png.png is not a PNG"
    done
fi

# From scratch in another directory, two variants side by side (-jobs 2): the same norms (a
# deterministic solver, one thread each), so running side by side changes nothing but the clock.
d=$(newCase again)
mfStudy -case "$d" -jobs 2 > "$d/log.mfStudy" 2>&1 || fail "second study failed"
grep -q "2 at a time" "$d/log.mfStudy" || fail "-jobs 2 not taken: $(head -n 1 "$d/log.mfStudy")"
for v in h0.01 h0.005 h0.0025; do
    for col in riemann/density/L1 riemann/pressure/Linf riemann/velocity/L2; do
        [ "$(field "$csv" $v $col)" = "$(field "$d/study/results.csv" $v $col)" ] ||
            fail "$v $col: $(field "$csv" $v $col) then $(field "$d/study/results.csv" $v $col)"
    done
done

# Everything finished: a rerun only reports. With PATH holding no gnuplot, the plots are skipped.
before=$(stat -c %Y.%y "$c/study/h0.005/log.impactSph")
rm -f "$c/study/results.csv"
PATH="$BUILD/bin" mfStudy -case "$c" > "$c/log.report" 2>&1 || fail "report-only rerun failed: $(cat "$c/log.report")"
[ "$(grep -c 'finished before, not rerun' "$c/log.report")" = 3 ] || fail "a finished variant was rerun"
[ "$(stat -c %Y.%y "$c/study/h0.005/log.impactSph")" = "$before" ] || fail "h0.005 ran again"
grep -q "gnuplot not found: plots skipped" "$c/log.report" || fail "no word of skipped plots: $(cat "$c/log.report")"
[ "$(grep -c ',finished,' "$c/study/results.csv")" = 3 ] || fail "report-only rerun lost rows"
# A changed entry makes the finished variants stale: deltaT 0.03 h reruns every level, and an
# added level runs alone beside them.
sed -i 's#^\( *system/controlDict/deltaT *\)0.04;#\10.03;#' "$c/system/studyDict"
mfStudy -case "$c" > "$c/log.changed" 2>&1 || fail "changed study failed: $(cat "$c/log.changed")"
[ "$(grep -c 'its entries changed in studyDict since it ran: rerun' "$c/log.changed")" = 3 ] ||
    fail "changed entries did not rerun the variants: $(cat "$c/log.changed")"
# 0.2 / (0.03 * 0.01) = 666.7: the last step is cut to land on endTime.
[ "$(field "$c/study/results.csv" h0.01 steps)" = 667 ] || fail "h0.01 after the change: $(field "$c/study/results.csv" h0.01 steps) steps"
pass "table reproduced: order in h $printedFit (awk $fit), Richardson $printedRich (awk $rich)"
