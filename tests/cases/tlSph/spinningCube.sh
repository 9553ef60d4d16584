# Spinning cube (Lee et al. 2016 8.3; doc/methods/tl-jst-sph.md 8.3): one revolution of the free unit cube at
# 105 rad/s. With the projections the angular momentum drifts by less than 1e-10 relative and the
# linear momentum stays at round-off; switched off, the drift is measurably larger (the negative
# control: at least 100 times, and above 1e-9). {p,F} without boundaries also keeps F equal to the
# discrete gradient of the positions (1e-12).
source "$(dirname "$0")/common.sh"
c="$WORK/spinningCube"
copyTutorial spinningCube "$c"
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail "$c/log.particleGen")"
cp -r "$c" "$WORK/unprojected"
run "$c" tlSph
csv="$c/postProcessing/conserved/0/conservedQuantities.csv"
# Relative drift of L_z over the run, from the summary's exact difference (the CSV carries 10
# digits, too few for 1e-10): "conserved: angularMomentum_z change <dL> (<L0> -> <L1>)".
drift() {
    grep "angularMomentum_z change" "$1" | awk '{ d = $4; l = $5; sub(/\(/, "", l); r = d / l; printf "%.6e\n", r < 0 ? -r : r }'
}
L0=$(column "$csv" angularMomentum_z | head -n 1)
# The continuum L_z = rho0 omega / 6 = 19250; the tributary-volume lattice gives the discrete sum.
awk -v l="$L0" 'BEGIN { exit !(l > 0.9 * 19250 && l < 1.1 * 19250) }' || fail "L_z(0) = $L0, expected about 19250"
projected=$(drift "$c/log.tlSph")
awk -v d="$projected" 'BEGIN { exit !(d < 1e-10) }' || fail "angular momentum drift $projected with the projection (limit 1e-10)"
for axis in x y z; do
    column "$csv" "momentum_$axis" | awk -v l="$L0" -v a="$axis" '{ p = $1 < 0 ? -$1 : $1; if (p > 1e-12 * l) { print "momentum_" a " = " $1; exit 1 } }' \
        || fail "linear momentum not at round-off"
done
t=$(column "$csv" time | tail -n 1)
awk -v t="$t" 'BEGIN { exit !(t > 0.0598 && t < 0.0599) }' || fail "the run ended at $t, not after one revolution (0.05984 s)"
compat=$(grep "compatibility" "$c/log.tlSph" | awk '{print $2}')
awk -v e="$compat" 'BEGIN { exit !(e < 1e-12) }' || fail "F differs from grad~ x by $compat (limit 1e-12)"

u="$WORK/unprojected"
sed -i 's/^projection .*/projection           { momentum no; dissipation no; }/' "$u/constant/tlSphProperties"
run "$u" tlSph
unprojected=$(drift "$u/log.tlSph")
awk -v d="$unprojected" -v p="$projected" 'BEGIN { exit !(d > 1e-9 && d > 100 * p) }' \
    || fail "without the projection the drift $unprojected is not measurably larger than $projected"
echo "PASS: spinning cube, one revolution: angular momentum drift $projected with the projection, $unprojected without; F - grad~x $compat"
