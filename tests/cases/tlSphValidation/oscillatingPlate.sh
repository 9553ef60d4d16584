# The oscillating plate's shipped tutorial in one run (issue 16): tutorials/tlSph/oscillatingPlate
# as it is (dx = 1.54 mm, 14 particles through the thickness, h = 1.1 dx, ten periods, 2.6 s),
# against thin-plate theory T = 0.254 s (which ignores shear and rotary inertia, about +1% at
# L/H = 10): the mean period over the ten periods within 3%, and the largest tip deflection in the
# tenth period at least 90% of that in the first (no numerical damping, no tensile instability).
# About 23 CPU-minutes on one thread of a loaded machine (379,267 steps; README).
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export PATH="$BUILD/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-tlsph-plate.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
c="$WORK/oscillatingPlate"
cp -r "$SOURCE/tutorials/tlSph/oscillatingPlate" "$c"
rm -rf "$c"/log.* "$c"/postProcessing "$c"/[0-9]* "$c"/*.png "$c"/particles.pvd
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail "$c/log.particleGen")"
tlSph -case "$c" > "$c/log.tlSph" 2>&1 || fail "tlSph: $(tail -n 20 "$c/log.tlSph")"
csv="$c/postProcessing/tip/0/probes.csv"
mapfile -t crossings < <(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "p0_position_y") k = i; next }
    { t = $1; y = $k; if (NR > 2 && (y < 0) != (py < 0) && t > 0.01) printf "%.9g\n", pt + (t - pt) * (-py) / (y - py); pt = t; py = y }' "$csv")
[ "${#crossings[@]}" -ge 20 ] || fail "only ${#crossings[@]} zero crossings in 2.6 s (expected 20 for ten periods)"
# The tip crosses zero at about T/2, T, 3T/2, ...: crossings[0] to crossings[18] span nine periods.
period=$(awk -v a="${crossings[0]}" -v b="${crossings[18]}" 'BEGIN { printf "%.6f\n", (b - a) / 9 }')
first=$(awk -v a="${crossings[0]}" 'BEGIN { printf "%.6f\n", 2 * a }')
awk -v T="$period" 'BEGIN { d = T / 0.254 - 1; exit !(d < 0.03 && d > -0.03) }' \
    || fail "mean period $period s, not within 3% of 0.254 s (first half period x 2: $first s)"
read -r a1 a10 <<< "$(awk -F, -v a="${crossings[1]}" -v b="${crossings[17]}" -v c="${crossings[19]}" '
    NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "p0_position_y") k = i; next }
    { y = $k < 0 ? -$k : $k; if ($1 <= a && y > m1) m1 = y; if ($1 >= b && $1 <= c && y > m10) m10 = y }
    END { print m1, m10 }' "$csv")"
ratio=$(awk -v a="$a1" -v b="$a10" 'BEGIN { printf "%.4f\n", b / a }')
awk -v r="$ratio" 'BEGIN { exit !(r >= 0.9 && r <= 1.01) }' || fail "amplitude in period 10 / period 1 = $ratio ($a10 / $a1)"
echo "PASS: oscillating plate tutorial: mean period $period s ($(awk -v T="$period" 'BEGIN { printf "%+.2f%%", 100 * (T / 0.254 - 1) }')), first $first s, amplitude ratio period 10 / period 1 = $ratio ($a10 / $a1 m)"
grep -E "^ *(steps|wall time|particles) " "$c/log.tlSph" || true
