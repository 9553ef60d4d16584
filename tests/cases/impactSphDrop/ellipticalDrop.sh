# The elliptical drop against its exact solution ($1 = build directory, $2 = source root): the
# tutorial tutorials/impactSph/ellipticalDrop run to t = 0.0076, where the exact semi-axis is
# b = 1.9445 (doc/methods/sph-impact.md §8.1, bisection/RK4 of Monaghan's ODE). Pass ([S] of the note): b within
# 2% (the thesis's SPH gives 1.93, -0.7%; Monaghan 1994 1.91, -1.8%) and ab = 1 within 1% (the drop
# is incompressible; Tait with c0 = 1500 m/s keeps |Δρ/ρ0| ~ 1e-3, so a 1% area error is the scheme's).
# Mass is conserved exactly and momentum to round-off (checked too).
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export PATH="$BUILD/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-drop.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

c="$WORK/ellipticalDrop"
cp -r "$SOURCE/tutorials/impactSph/ellipticalDrop" "$c"
rm -rf "$c"/log.* "$c"/postProcessing "$c"/[0-9]* "$c"/*.png "$c"/particles.pvd
sed -i 's/^endTime .*/endTime         0.0076;/; s/^writeInterval   0.002;/writeInterval   0.0076;/' "$c/system/controlDict"
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail "$c/log.particleGen")"
python3 "$c/setStrainVelocity.py" "$c/0/particles.vtp" 100 > "$c/log.setStrainVelocity" || fail "setStrainVelocity.py"
impactSph -case "$c" > "$c/log.impactSph" 2>&1 || fail "impactSph: $(tail -n 20 "$c/log.impactSph")"

csv="$c/postProcessing/drop/0/semiAxes.csv"
[ "$(head -n 1 "$csv")" = "time,a,b,aExact,bExact,ab,abExact,A" ] || fail "semiAxes.csv header: $(head -n 1 "$csv")"
# The row nearest t = 0.0076.
row=$(awk -F, 'NR > 1 { d = $1 - 0.0076; if (d < 0) d = -d; if (best == "" || d < best) { best = d; r = $0 } } END { print r }' "$csv")
read -r t a b aExact bExact ab abExact <<< "$(echo "$row" | cut -d, -f1-7 | tr , ' ')"
awk -v t="$t" 'BEGIN { exit !(t > 0.00759 && t < 0.00761) }' || fail "no semiAxes row near t = 0.0076 (nearest $t)"
# The exact b scales with the radius R of the disc the particles fill (R = 1.0029: see the function
# object); the unit-disc value is bExact/R = 1.9445.
awk -v b="$bExact" -v ab="$abExact" 'BEGIN { r = b / sqrt(ab); exit !(r > 1.9435 && r < 1.9455) }' \
    || fail "exact b($t) = $bExact for R^2 = $abExact, expected 1.9445 R"
awk -v b="$b" -v e="$bExact" 'BEGIN { d = (b - e) / e; exit !(d < 0.02 && d > -0.02) }' || fail "b($t) = $b, more than 2% from $bExact"
awk -v ab="$ab" -v e="$abExact" 'BEGIN { d = ab / e - 1; exit !(d > -0.01 && d < 0.01) }' \
    || fail "ab($t)/R^2 = $ab/$abExact, not 1 within 1% (a = $a, b = $b)"
grep -q "drop *velocity" "$c/log.impactSph" || fail "no velocity error norm in the summary"
drift=$(grep "mass drift" "$c/log.impactSph" | awk '{print $4}')
awk -v d="$drift" 'BEGIN { exit !(d * d < 1e-24) }' || fail "mass drift $drift"
for axis in x y; do
    change=$(grep "momentum_$axis change" "$c/log.impactSph" | awk '{print $4}')
    # |P| ~ Σ m |v| ~ 200 kg m/s: round-off over 7600 steps stays far below 1e-9.
    awk -v d="$change" 'BEGIN { exit !(d * d < 1e-18) }' || fail "momentum_$axis change $change"
done
echo "PASS: elliptical drop at t = $t: b = $b (exact $bExact), a = $a (exact $aExact), ab/R^2 = $ab/$abExact"
