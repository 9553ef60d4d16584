# Cable (Lee et al. 2016 8.1; doc/methods/tl-jst-sph.md 8.1): a 10 m steel cable, 100 x 3 x 3 particles,
# fixed at X = 0, 5 m/s on X <= 2.5 m; tip velocity and displacement against d'Alembert
# (c = 5000 m/s). For eps2_p = 1/32 (the tutorial) and the paper's extremes 0 and 1/8:
#   - the front reaches the tip (v >= 2.5 m/s) within 3 dx / c = 61 us of 1.5 ms;
#   - the plateau (mean tip velocity over 1.6-1.9 ms) is within 10% of 5 m/s;
# for eps2_p = 1/32: the peak tip displacement is within 10% of 2.5 mm; and the overshoot
# max v - 5 on (1.5, 2.0) ms with eps2_p = 1/8 is smaller than with 0.
source "$(dirname "$0")/common.sh"
base="$WORK/base"
copyTutorial cable "$base"
particleGen -case "$base" > "$base/log.particleGen" 2>&1 || fail "particleGen: $(tail "$base/log.particleGen")"
sed -i 's/^endTime .*/endTime         0.0025;/' "$base/system/controlDict"
declare -A OVERSHOOT
for e2 in 0 0.03125 0.125; do
    c="$WORK/eps$e2"
    cp -r "$base" "$c"
    sed -i "s/momentum (0.03125 0.125)/momentum ($e2 0.125)/" "$c/constant/tlSphProperties"
    grep -q "momentum ($e2 0.125)" "$c/constant/tlSphProperties" || fail "could not set eps2 = $e2"
    run "$c" tlSph
    csv="$c/postProcessing/cable/0/cable.csv"
    read -r arrival plateau overshoot peak <<< "$(awk -F, 'NR > 1 {
            if (arrival == "" && $2 >= 2.5) arrival = $1
            if ($1 > 0.0016 && $1 < 0.0019) { sum += $2; count++ }
            if ($1 > 0.0015 && $1 < 0.002 && $2 - 5 > over) over = $2 - 5
            d = $4 < 0 ? -$4 : $4; if (d > peak) peak = d
        } END { printf "%s %.6g %.6g %.6g\n", arrival, sum / count, over, peak }' "$csv")"
    echo "eps2 = $e2: arrival $arrival s, plateau $plateau m/s, overshoot $overshoot m/s, peak displacement $peak m"
    awk -v t="$arrival" 'BEGIN { exit !(t != "" && t > 0.0015 - 6.1e-5 && t < 0.0015 + 6.1e-5) }' \
        || fail "eps2 = $e2: the front reached the tip at $arrival s, not within 61 us of 1.5 ms"
    awk -v v="$plateau" 'BEGIN { exit !(v > 4.5 && v < 5.5) }' || fail "eps2 = $e2: plateau $plateau m/s, not within 10% of 5"
    OVERSHOOT[$e2]=$overshoot
    if [ "$e2" = 0.03125 ]; then
        awk -v u="$peak" 'BEGIN { exit !(u > 0.00225 && u < 0.00275) }' \
            || fail "peak tip displacement $peak m, not within 10% of 2.5 mm"
    fi
done
awk -v a="${OVERSHOOT[0.125]}" -v b="${OVERSHOOT[0]}" 'BEGIN { exit !(a < b) }' \
    || fail "the overshoot with eps2 = 1/8 (${OVERSHOOT[0.125]}) is not smaller than with 0 (${OVERSHOOT[0]})"
echo "PASS: cable: overshoot ${OVERSHOOT[0]} (eps2 0), ${OVERSHOOT[0.03125]} (1/32), ${OVERSHOOT[0.125]} (1/8) m/s"
