# Nearly incompressible punch (Lee et al. 2016 8.6): at nu = 0.499, {p,F,J} JST-SPH runs to
# t = 14 ms without NaN (the solver stops with a diagnosis otherwise) and its pressure
# oscillation measure sum V |L[p]| h^2 / sum V |p| is below the {p,F} one.
source "$(dirname "$0")/common.sh"
c="$WORK/pFJ"
copyTutorial nearlyIncompressiblePunch "$c"
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail "$c/log.particleGen")"
cp -r "$c" "$WORK/pF"
sed -i 's/^formulation          pFJ;/formulation          pF;/' "$WORK/pF/constant/tlSphProperties"
grep -q "^formulation *pF;" "$WORK/pF/constant/tlSphProperties" || fail "could not switch to pF"
run "$c" tlSph
run "$WORK/pF" tlSph
grep -q "steps *[0-9]* to t = 0.014$" "$c/log.tlSph" || fail "{p,F,J} did not reach t = 0.014: $(grep steps "$c/log.tlSph")"
measure() { grep "pressure oscillation" "$1/log.tlSph" | awk '{print $3}'; }
mixed=$(measure "$c")
plain=$(measure "$WORK/pF")
awk -v a="$mixed" -v b="$plain" 'BEGIN { exit !(a > 0 && a < b) }' \
    || fail "pressure oscillation {p,F,J} $mixed is not below {p,F} $plain"
echo "PASS: nearly incompressible punch, pressure oscillation {p,F,J} $mixed < {p,F} $plain"
