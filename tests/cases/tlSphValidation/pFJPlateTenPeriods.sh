# Issue 16's acceptance for tlSph {p,F,J}: "the oscillating plate in {p,F,J} with dissipation on J
# runs 10 periods at nu = 0.45 and 0.499 without blowing up, energy drift below 1%". The plate of
# tests/cases/tlSph (dx = 4 mm, h = 1.3 dx, 384 particles), {p,F,J}, jacobian (0 0.125) (the
# nearly incompressible punch's setting), the momentum JST term on the shear-wave speed
# (`momentumSpeed shear`: on c_p it loses 2.39% by 0.1 s at nu 0.499, tests/cases/tlSph/
# pFJPlateShearSpeed.sh), to t = 2.9 s: ten periods at both nu (4 mm periods 0.284 and 0.270 s).
# Asserted for each nu: the run reaches 2.9 s, the total energy never rises above its start by
# more than 0.1% (no blow-up), the tip still oscillates (at least 20 zero crossings) and the energy
# drift (E(2.9) - E(0))/E(0) is above -1%. Measured on the 4 mm plate (tutorials/tlSph/
# oscillatingPlate/README.md, issue 16 section): the drift bound is NOT met (measured at c3f46b5:
# -5.54% at nu 0.45, -18.90% at 0.499 by 2.9 s), so this test fails until the scheme or the
# lattice does better; the other assertions hold (energy never above the start; 20 and 21 zero
# crossings, periods 0.2838 and 0.2702 s). 287 CPU-seconds on one thread (0.499: about 1.4e6 steps).
source "$(dirname "$0")/../tlSph/common.sh"
failures=()
for nu in 0.45 0.499; do
    c="$WORK/nu$nu"
    pFJPlate "$c" "$nu" 2.9 shear 0.125
    tlSph -case "$c" > "$c/log.tlSph" 2>&1 || fail "nu $nu: tlSph: $(tail -n 20 "$c/log.tlSph")"
    grep -q "steps *[0-9]* to t = 2.9$" "$c/log.tlSph" || fail "nu $nu: did not reach t = 2.9"
    read -r highest final <<< "$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "totalEnergy") k = i; next }
        NR == 2 { e0 = $k; m = $k } { if ($k > m) m = $k; e = $k } END { printf "%.6f %.6f\n", m / e0 - 1, e / e0 - 1 }' \
        "$c/postProcessing/conserved/0/conservedQuantities.csv")"
    read -r crossings period <<< "$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "p0_position_y") k = i; next }
        { t = $1; y = $k; if (NR > 2 && (y < 0) != (py < 0) && t > 0.01) { c = pt + (t - pt) * (-py) / (y - py); if (!n) f = c; l = c; ++n }
          pt = t; py = y } END { printf "%d %.6f\n", n, (n > 1 ? 2 * (l - f) / (n - 1) : 0) }' "$c/postProcessing/tip/0/probes.csv")"
    echo "nu $nu: energy highest $highest, final $final relative to the start; $crossings zero crossings, mean period $period s"
    awk -v h="$highest" 'BEGIN { exit !(h <= 0.001) }' || fail "nu $nu: the energy grew by $highest (blow-up)"
    [ "$crossings" -ge 20 ] || fail "nu $nu: only $crossings zero crossings by 2.9 s (ten periods give 20)"
    awk -v f="$final" 'BEGIN { exit !(f >= -0.01) }' || failures+=("nu $nu: energy drift $final below -1%")
done
[ "${#failures[@]}" -eq 0 ] || fail "${failures[*]}"
echo "PASS: {p,F,J} plate, ten periods at nu 0.45 and 0.499, energy drift within 1%"
