# Mirror ghosts kept between neighbour-list rebuilds (issue 16, the rebuild policy with ghosts):
# the quarter Taylor bar (tutorials/impactSph/taylorBar/quarter3D: mirror planes x = 0, y = 0 and
# the wall z = 0, with the images of images), coarsened to 0.64 mm and run to 20 us, with
# `mirrorGhosts withList` (the default) and `everyStep` (the layer remade each step, as before
# c120773).
#
# Rebuilds. Remade each step, the layer changed the particle indices and the list was rebuilt at
# every step (3066 of 3066 at 0.4 mm to 80 us). Kept, the list is rebuilt as without ghosts: the
# displacement bound 2 D > skin, with D = |v| dt per step, dt = 0.2 h/(c + |v|) (maxCo 0.2) and
# the skin 0.2 of the support 2h (Wendland C2), comes every (c + v)/v steps, a fraction
# v/(c + v) = 227/(3940 + 227) = 0.054 of them while the rod moves as a whole (0.4 mm: 43 in 798,
# 0.054). Asserted: at most 0.1 of the steps (twice that: the layer's own rebuilds, when a
# particle comes within reach of a plane from beyond the layer, add a few), everyStep all of them.
#
# Results. Both see the same ghost pairs within the support, in another order within a row (the
# cell order of the last build), so they agree to round-off grown over the run: measured 2e-12 of
# each field's largest value at 0.4 mm. Asserted: the rim x_max, y_max, the top z_max, the lowest
# particle z_min and the total energy within 1e-10 relative. A ghost pair missed or kept too many
# (a kept ghost its step's layer lacks left in the sums) changes a particle's sums by one of its
# ~70 neighbours and the rim at 1e-5 or more.
. "$(dirname "$0")/common.sh"
bar="$TUTORIALS/taylorBar"
kept=$(newCase "$bar/quarter3D" kept)
every=$(newCase "$bar/quarter3D" every)
for c in "$kept" "$every"; do
    setEntry "$c/system/particleGenDict" regions/bar/lattice/spacing 6.4e-4
    setEntry "$c/system/controlDict" endTime 2e-5
done
echo "mirrorGhosts everyStep;" >> "$every/constant/sphProperties"
tk=$(runCase "$kept")
te=$(runCase "$every")
counts() {  # <log>: "rebuilds steps"
    grep "list rebuilds in" "$1" | sed 's/.*, \([0-9]*\) list rebuilds in \([0-9]*\) steps.*/\1 \2/'
}
read -r rk sk <<< "$(counts "$kept/log.impactSph")"
read -r re se <<< "$(counts "$every/log.impactSph")"
[ -n "$rk" ] && [ -n "$re" ] || fail "no rebuild count in the summaries"
[ "$sk" -gt 300 ] || fail "only $sk steps: the case is not the one measured"
[ "$sk" -eq "$se" ] || fail "withList took $sk steps, everyStep $se"
[ "$re" -eq "$se" ] || fail "everyStep rebuilt $re times in $se steps (expected every step)"
less "$(awk -v r="$rk" -v s="$sk" 'BEGIN { print r / s }')" 0.1 ||
    fail "withList rebuilt the list $rk times in $sk steps (at most 0.1 of the steps: v/(c + v) = 0.054)"
layers=$(awk '/mirror-ghost layers/ { print $3 }' "$kept/log.impactSph")
[ -n "$layers" ] || fail "no mirror-ghost layer count in the summary"
[ "$layers" -le "$rk" ] || fail "$layers ghost layers built but only $rk list rebuilds (each layer rebuilds the list)"
sameOutline "$kept" "$every" 1e-10 withList everyStep
csv=postProcessing/outline/0/fieldMinMax.csv
t=$(column "$kept/$csv" time)
less 1.999e-5 "$t" || fail "withList stopped at t = $t"
ek=$(finalEnergy "$kept"); ee=$(finalEnergy "$every")
less "$(relErr "$ek" "$ee")" 1e-10 || fail "total energy: withList $ek, everyStep $ee"
pass "withList: $rk list rebuilds ($layers ghost layers) in $sk steps, $tk s; everyStep: $re in $se, $te s; rim $(column "$kept/$csv" position_x_max) m, top $(column "$kept/$csv" position_z_max) m, energy $ek J (everyStep $ee J)"
