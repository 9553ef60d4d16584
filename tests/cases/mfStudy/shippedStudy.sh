# The shipped study of Sod's tube (tutorials/impactSph/sodShockTube/system/studyDict). In the
# default run: it is valid against its tutorial (-list checks every entry path and value and
# writes nothing), with 2 kernels x 2 density forms x 3 levels. With "full" (the validation
# label): the study run from scratch in a copy, every scheme finished with an observed L1(rho)
# order in h of at least 0.6 (issue 16's acceptance for Sod), the printed order equal to an awk
# fit of its own CSV rows.
. "$(dirname "$0")/common.sh"
tutorial="$(cd "$SOURCE/../../../tutorials/impactSph/sodShockTube" && pwd)"
before=$(ls -A "$tutorial" | sort | tr '\n' ' ')
mfStudy -case "$tutorial" -list > "$WORK/list" 2>&1 || fail "the shipped studyDict is not valid: $(cat "$WORK/list")"
[ "$(ls -A "$tutorial" | sort | tr '\n' ' ')" = "$before" ] || fail "-list wrote into the tutorial"
grep -q "^mfStudy: 12 variants" "$WORK/list" || fail "expected 12 variants: $(head -n 1 "$WORK/list")"
grep -q "kernel-wendlandC2_density-summation_h0.00125" "$WORK/list" || fail "variant names: $(cat "$WORK/list")"
if [ "${3:-}" != full ]; then
    pass "shipped Sod study valid (12 variants)"
    exit 0
fi
c="$WORK/sod"
mkdir "$c" && cp -r "$tutorial/system" "$tutorial/constant" "$c/"
mfStudy -case "$c" -jobs 2 > "$c/log.mfStudy" 2>&1 || fail "the shipped study failed: $(tail "$c/log.mfStudy")"
csv="$c/study/results.csv"
[ "$(grep -c ',finished,' "$csv")" = 12 ] || fail "not every variant finished: $(cat "$csv")"
hc=$(column "$csv" h); ec=$(column "$csv" riemann/density/L1)
for scheme in kernel-gaussian_density-continuity kernel-gaussian_density-summation \
              kernel-wendlandC2_density-continuity kernel-wendlandC2_density-summation; do
    fit=$(awk -F, -v s="\"$scheme\"" -v hc="$hc" -v ec="$ec" '$2 == s { x = log($hc); y = log($ec); n++; sx += x; sy += y; sxx += x*x; sxy += x*y }
        END { printf "%.10g", (n*sxy - sx*sy) / (n*sxx - sx*sx) }' "$csv")
    printed=$(grep "^| $scheme |" "$c/study/results.md" | awk -F'|' '{ gsub(/ /, "", $4); print $4 }')
    near "$printed" "$fit" 1e-3 || fail "$scheme: printed order $printed, awk $fit"
    awk -v p="$fit" 'BEGIN { exit !(p >= 0.6) }' || fail "$scheme: observed L1 order $fit below 0.6"
    echo "$scheme: order in h $printed"
done
pass "shipped Sod study reproduced: every scheme's order at least 0.6"
