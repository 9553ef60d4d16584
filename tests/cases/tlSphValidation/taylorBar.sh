# Taylor bar through tlSph (3D, J2 plasticity): the study of tutorials/tlSph/taylorBar
# (system/studyDict, run by mfStudy): a quarter of the rod, mirrored across x = 0 and z = 0, on
# lattices of 0.5333, 0.4 and 0.2667 mm (6, 8 and 12 particles across the radius) to 80 us,
# with the tutorial's step (deformedCourant 1). Asserted against the FE reference (Kamoulakos
# 1990: final length 21.5 mm, footprint radius 7.0 mm):
#   - every lattice runs to the end; the length is within 3% of 21.5 mm on each;
#   - the footprint grows with each refinement (the rim is a few particles thick on the coarse
#     lattices) and the finest is within 5% of 7.0 mm;
#   - Richardson's extrapolation of the three (Q(h) = Q0 + C h^p, ratios 1.333 and 1.5) has an
#     order p in (0, 4] and Q0 within 5% of 7.0 mm.
# About 16 CPU-minutes (the 0.2667 mm lattice: 13552 particles, 16954 steps, 13 of them; README.md).
# Measured: 5.89, 6.45, 6.80 mm; order 2.40, extrapolated 7.01 mm; lengths 21.80, 21.69, 21.51 mm.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export MFDYN_BUILD="$BUILD" MFDYN_DIR="$SOURCE"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-tlsph-taylor.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
c="$WORK/taylorBar"
cp -r "$SOURCE/tutorials/tlSph/taylorBar" "$c"
(cd "$c" && ./Allclean > /dev/null 2>&1 || true)
rm -rf "$c/study"
OMP_NUM_THREADS=${OMP_NUM_THREADS:-1} "$BUILD/bin/mfStudy" -case "$c" > "$WORK/log.mfStudy" 2>&1 ||
    fail "mfStudy: $(tail -n 20 "$WORK/log.mfStudy")"
csv="$c/study/results.csv"
[ -f "$csv" ] || fail "no $csv: $(tail -n 20 "$WORK/log.mfStudy")"
cat "$c/study/results.md"
# h, status, footprint, length, one row per lattice, coarsest first.
rows=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) k[$i] = i; next }
    { print $k["h"], $k["status"], $k["outline/footprintRadius"], $k["outline/finalLength"] }' "$csv" | sort -g -r)
[ "$(echo "$rows" | wc -l)" = 3 ] || fail "expected 3 lattices in $csv, found: $rows"
echo "$rows" | awk '$2 != "finished" { exit 1 }' || fail "a lattice did not finish: $rows"
echo "$rows" | awk '{ d = $4 / 21.5 - 1; if (!(d < 0.03 && d > -0.03)) { print "h " $1 ": length " $4 " mm"; exit 1 } }' ||
    fail "a final length not within 3% of 21.5 mm: $rows"
echo "$rows" | awk 'NR > 1 && !($3 > previous) { exit 1 } { previous = $3 }' ||
    fail "the footprint does not grow with each refinement: $rows"
finest=$(echo "$rows" | tail -1 | awk '{ print $3 }')
awk -v R="$finest" 'BEGIN { d = R / 7.0 - 1; exit !(d < 0.05 && d > -0.05) }' ||
    fail "finest footprint $finest mm, not within 5% of 7.0 mm"
# Richardson on the three: p solves (q1 - q2)/(q2 - q3) = (h1^p - h2^p)/(h2^p - h3^p)
# (bisection; the right side grows with p for h1 > h2 > h3), then Q0 = q3 - (q2 - q3)/((h2/h3)^p - 1).
read -r p Q0 <<< "$(echo "$rows" | tail -3 | awk '{ h[NR] = $1; q[NR] = $3 }
    END { r = (q[1] - q[2]) / (q[2] - q[3]); if (!(r > 0)) { print "nan nan"; exit }
          lo = 1e-6; hi = 20
          for (it = 0; it < 200; ++it) { m = (lo + hi) / 2
              g = (h[1] ^ m - h[2] ^ m) / (h[2] ^ m - h[3] ^ m)
              if (g > r) hi = m; else lo = m }
          p = (lo + hi) / 2; printf "%.4f %.4f\n", p, q[3] - (q[2] - q[3]) / ((h[2] / h[3]) ^ p - 1) }')"
echo "Richardson on the three lattices: order $p, extrapolated footprint $Q0 mm"
awk -v p="$p" 'BEGIN { exit !(p > 0 && p <= 4) }' || fail "observed order $p, not in (0, 4]"
awk -v R="$Q0" 'BEGIN { d = R / 7.0 - 1; exit !(d < 0.05 && d > -0.05) }' ||
    fail "extrapolated footprint $Q0 mm (order $p), not within 5% of 7.0 mm"
echo "PASS: Taylor bar (tlSph): footprint $finest mm at the finest lattice, extrapolated $Q0 mm (order $p)"
