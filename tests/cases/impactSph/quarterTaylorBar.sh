# Images of images across mirror planes, end to end: the quarter model of the 3D Taylor bar
# (tutorials/impactSph/taylorBar/quarter3D: mirror planes x = 0, y = 0 and the wall z = 0, each
# also mirroring the ghosts of those before it) against the whole rod on the same cubic lattice
# (cell-centred from the origin, so symmetric about both planes; the rod's own wall is bar3D's,
# a mirror plane at z = 0), both coarsened to 0.64 mm (R0/5) and run to 20 µs, when the foot has
# mushroomed to 5.2 mm. The quarter is the rod restricted to x, y > 0, so the two agree to
# round-off amplified over the run: the rim x_max, the top z_max and the lowest particle z_min
# within 1e-8 relative (measured: equal to the 10 digits written), and the rod's total energy
# 4 times the quarter's within 1e-8. Without the corner images (each plane mirroring the real
# particles only) the quarter's rim differs by 1.6e-3 relative and its axis particles move.
. "$(dirname "$0")/common.sh"
bar="$TUTORIALS/taylorBar"
quarter=$(newCase "$bar/quarter3D" quarter)
rod=$(newCase "$bar/quarter3D" rod)
cp "$bar/bar3D/constant/boundaryConditions" "$rod/constant/"
setEntry "$rod/system/particleGenDict" regions/bar/shape \
    "{ type cylinder; point1 (0 0 0.0001); point2 (0 0 0.0325); radius 0.0032; }"
for c in "$quarter" "$rod"; do
    setEntry "$c/system/particleGenDict" regions/bar/lattice/spacing 6.4e-4
    setEntry "$c/system/controlDict" endTime 2e-5
done
tq=$(runCase "$quarter")
tr=$(runCase "$rod")
csv=postProcessing/outline/0/fieldMinMax.csv
nq=$(awk '/^Read [0-9]+ particles/ { print $2 }' "$quarter/log.impactSph")
nr=$(awk '/^Read [0-9]+ particles/ { print $2 }' "$rod/log.impactSph")
[ "$((4 * nq))" -eq "$nr" ] || fail "the rod has $nr particles, not 4 x $nq"
sameOutline "$quarter" "$rod" 1e-8 quarter rod
t=$(column "$quarter/$csv" time)
less 1.999e-5 "$t" || fail "quarter stopped at t = $t"
eq=$(finalEnergy "$quarter"); er=$(finalEnergy "$rod")
less "$(relErr "$(awk -v e="$eq" 'BEGIN { printf "%.15g", 4 * e }')" "$er")" 1e-8 || fail "total energy: 4 x quarter $eq against rod $er"
pass "quarter ($nq particles, $tq s) = rod ($nr particles, $tr s) at 20 µs: rim $(column "$rod/$csv" position_x_max) m, top $(column "$rod/$csv" position_z_max) m, energy 4 x $eq = $er J"
