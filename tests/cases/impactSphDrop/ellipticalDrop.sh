# The elliptical drop against its exact solution ($1 = build directory, $2 = source root): the
# tutorial tutorials/impactSph/ellipticalDrop run to t = 0.0076, where the exact semi-axis is
# b = 1.9445 (doc/methods/sph-impact.md §8.1, bisection/RK4 of Monaghan's ODE). Pass ([S] of the note): b within
# 2% (the thesis's SPH gives 1.93, -0.7%; Monaghan 1994 1.91, -1.8%) and ab = 1 within 1% (the drop
# is incompressible; Tait with c0 = 1500 m/s keeps |Δρ/ρ0| ~ 1e-3, so a 1% area error is the scheme's).
# The reference is the unit disc's, literally (ab = 1): the tutorial clips the lattice at r = 0.997
# so that its N cells fill N Δx² = 0.99949 π, the unit disc's area to 0.05% (checked here), and the
# lattice's own disc (R = (N Δx²/π)^½) and the unit disc give the same reference. Clipped at 1 the
# lattice held 1264 Δx² = 1.00586 π and ab = 1.0124 at t = 0.0076, +1.24% against 1.
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
# The area the particles stand for, N Δx² (cells of the cubic lattice), against the unit disc's π.
n=$(awk '/^Wrote [0-9]+ particles/ { print $2 }' "$c/log.particleGen")
dx=$(mfDictionary "$c/system/particleGenDict" -entry regions/drop/lattice/spacing | awk '{ print $1 }')
awk -v n="$n" -v dx="$dx" 'BEGIN { d = n * dx * dx / 3.14159265358979 - 1; exit !(d > -1e-3 && d < 1e-3) }' \
    || fail "the lattice's $n cells of $dx fill $(awk -v n="$n" -v dx="$dx" 'BEGIN { print n * dx * dx }'), not the unit disc's pi within 0.1%"
python3 "$c/setStrainVelocity.py" "$c/0/particles.vtp" 100 > "$c/log.setStrainVelocity" || fail "setStrainVelocity.py"
impactSph -case "$c" > "$c/log.impactSph" 2>&1 || fail "impactSph: $(tail -n 20 "$c/log.impactSph")"

csv="$c/postProcessing/drop/0/semiAxes.csv"
[ "$(head -n 1 "$csv")" = "time,a,b,aExact,bExact,ab,abExact,A" ] || fail "semiAxes.csv header: $(head -n 1 "$csv")"
# The row nearest t = 0.0076.
row=$(awk -F, 'NR > 1 { d = $1 - 0.0076; if (d < 0) d = -d; if (best == "" || d < best) { best = d; r = $0 } } END { print r }' "$csv")
read -r t a b aExact bExact ab abExact <<< "$(echo "$row" | cut -d, -f1-7 | tr , ' ')"
awk -v t="$t" 'BEGIN { exit !(t > 0.00759 && t < 0.00761) }' || fail "no semiAxes row near t = 0.0076 (nearest $t)"
# The reference is the unit disc's: ab = 1 and b(0.0076) = 1.9445 (the function object's radius 1).
awk -v b="$bExact" -v ab="$abExact" 'BEGIN { exit !(ab > 1 - 1e-12 && ab < 1 + 1e-12 && b > 1.9435 && b < 1.9455) }' \
    || fail "exact b($t) = $bExact, ab = $abExact: expected the unit disc's 1.9445 and 1"
awk -v b="$b" 'BEGIN { d = (b - 1.9445) / 1.9445; exit !(d < 0.02 && d > -0.02) }' || fail "b($t) = $b, more than 2% from 1.9445"
awk -v ab="$ab" 'BEGIN { d = ab - 1; exit !(d > -0.01 && d < 0.01) }' \
    || fail "ab($t) = $ab, not 1 within 1% (a = $a, b = $b)"
grep -q "drop *velocity" "$c/log.impactSph" || fail "no velocity error norm in the summary"
drift=$(grep "mass drift" "$c/log.impactSph" | awk '{print $4}')
awk -v d="$drift" 'BEGIN { exit !(d * d < 1e-24) }' || fail "mass drift $drift"
for axis in x y; do
    change=$(grep "momentum_$axis change" "$c/log.impactSph" | awk '{print $4}')
    # |P| ~ Σ m |v| ~ 200 kg m/s: round-off over 7600 steps stays far below 1e-9.
    awk -v d="$change" 'BEGIN { exit !(d * d < 1e-18) }' || fail "momentum_$axis change $change"
done
echo "PASS: elliptical drop at t = $t ($n particles, N dx^2 = $(awk -v n="$n" -v dx="$dx" 'BEGIN { printf "%.5f", n * dx * dx }')): b = $b (exact $bExact), a = $a (exact $aExact), ab = $ab (exact 1)"
