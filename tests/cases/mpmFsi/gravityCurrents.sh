# Gravity currents (tutorials/mpmFsi/gravityCurrents, doc/methods/mpm.md 4.6 / V6): a light
# (1000 kg/m^3) and a heavy (1500) fluid, each 0.06 x 0.06, released side by side in a 0.12 wide
# box, kappa 2e4 (the thesis's text), 3600 points each, to T = 2. Asserted at T = 2:
#   the light fluid's mean height (its centroid's y) above the heavy one's by more than 0.02 m
#       (fully layered at rest: 0.045 against 0.015, a difference of 0.03; side by side, as at
#       t = 0, the difference is 0; measured 0.0294);
#   each mean height within 5% of the layered one (measured -1.0% and +1.2%; with half the
#       step, maxCo 0.15, README);
#   mass exact: no particle left through the open top, each body's summary mass equal to its
#       first write's to 17 digits. About 22 CPU-s.
source "$(dirname "$0")/common.sh"
c="$WORK/currents"
copyTutorial gravityCurrents "$c"
run "$c" particleGen
run "$c" mpmFsi
csv="$c/postProcessing/fluids/0/bodyCentroid.csv"
t=$(tail -n 1 "$csv" | cut -d, -f1)
[ "$t" = 2 ] || fail "the last write is at t = $t, not 2"
light=$(column "$csv" light_height | tail -n 1)
heavy=$(column "$csv" heavy_height | tail -n 1)
echo "T = 2: mean height light $light, heavy $heavy"
less 0.02 "$(awk -v a="$light" -v b="$heavy" 'BEGIN { print a - b }')" ||
    fail "the light fluid ($light) is not above the heavy one ($heavy) by 0.02"
within "$light" 0.045 0.05 || fail "light mean height $light not within 5% of the layered 0.045"
within "$heavy" 0.015 0.05 || fail "heavy mean height $heavy not within 5% of the layered 0.015"
! grep -q "outsideGrid remove" "$c/log.mpmFsi" || fail "particles left the grid: $(grep -m1 'outsideGrid remove' "$c/log.mpmFsi")"
for body in light heavy; do
    grep -q "body $body: at t = 2 mass \([0-9.e+-]*\) (first write \1, change 0.000e+00)" "$c/log.mpmFsi" ||
        fail "$body mass not exact: $(grep "body $body: at" "$c/log.mpmFsi")"
done
echo "PASS: gravityCurrents (light $light, heavy $heavy)"
