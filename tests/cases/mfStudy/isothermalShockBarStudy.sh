# The shipped study of tutorials/impactSph/isothermalShockBar (4 levels, h = 0.01 ... 0.00125,
# about 6 CPU-s) run through mfStudy: the order in h that it prints for L1(rho) equals an awk fit
# of its CSV and is at least 0.9 (measured 1.03: a captured shock and contact each leave an O(h)
# band, so L1 falls at first order; below 0.9 the waves would be smeared over a width that does not
# shrink with h), the finest relative L1(rho) is under 0.5% (measured 0.33%), and the CPU time to
# 1% that it prints is the log-log interpolation of its rows, computed here.
. "$(dirname "$0")/common.sh"
tutorial="$(cd "$SOURCE/../../../tutorials/impactSph/isothermalShockBar" && pwd)"
c="$WORK/bar"
mkdir "$c" && cp -r "$tutorial/system" "$tutorial/constant" "$c/"
mfStudy -case "$c" > "$c/log.mfStudy" 2>&1 || fail "the study failed: $(tail "$c/log.mfStudy")"
csv="$c/study/results.csv"
[ "$(grep -c ',finished,' "$csv")" = 4 ] || fail "expected 4 finished runs: $(cat "$csv")"
hc=$(column "$csv" h); ec=$(column "$csv" bar/density/L1); rc=$(column "$csv" relativeError); cc=$(column "$csv" cpuSeconds)
fit=$(awk -F, -v hc="$hc" -v ec="$ec" 'NR > 1 { x = log($hc); y = log($ec); n++; sx += x; sy += y; sxx += x*x; sxy += x*y }
    END { printf "%.10g", (n*sxy - sx*sy) / (n*sxx - sx*sx) }' "$csv")
row=$(grep '^| base |' "$c/study/results.md") || fail "no scheme row in results.md"
printed=$(echo "$row" | awk -F'|' '{ gsub(/ /, "", $4); print $4 }')
near "$printed" "$fit" 1e-3 || fail "printed order $printed, awk fit $fit"
awk -v p="$fit" 'BEGIN { exit !(p >= 0.9) }' || fail "observed L1(rho) order $fit below 0.9"
finest=$(field "$csv" h0.00125 relativeError)
awk -v r="$finest" 'BEGIN { exit !(r > 0 && r < 0.005) }' || fail "finest relative L1(rho) $finest not under 0.5%"
to1=$(awk -F, -v cc="$cc" -v rc="$rc" 'NR > 1 { c[NR-1] = $cc; e[NR-1] = $rc; n = NR-1 }
    END { for (i = 2; i <= n; ++i) if (e[i] <= 0.01 && e[i-1] > 0.01) {
              s = (log(0.01) - log(e[i-1])) / (log(e[i]) - log(e[i-1]))
              printf "%.10g", exp(log(c[i-1]) + s * (log(c[i]) - log(c[i-1]))); exit } }' "$csv")
[ -n "$to1" ] || fail "1% is not crossed between two levels: $(cut -d, -f"$rc" "$csv" | tr '\n' ' ')"
near "$(field "$csv" h0.01 "schemeCpuSecondsTo1%")" "$to1" 1e-6 || fail "CPU s to 1%: $(field "$csv" h0.01 "schemeCpuSecondsTo1%"), awk $to1"
pass "isothermal shock-bar study: L1(rho) order $printed, finest relative $finest, 1% at $to1 CPU-s"
