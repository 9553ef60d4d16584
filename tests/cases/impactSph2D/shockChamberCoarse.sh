# The air-air shock chamber (tutorials/impactSph/shockChamber/airAir, N_l = 25) run to t = 0.3:
#  - it reaches its end time without NaN;
#  - mass is exact (the number scheme with fixed particle masses), momentum stays at round-off
#    (the wall particles could absorb momentum, but the flow is symmetric and the shock has not
#    reached the wall by t = 0.3), total energy drifts < 1e-4 relative (the wall does no work as
#    its velocity is zero; the leapfrog's O(dt^2) energy error is 4e-6 at t = 0.5 in the tutorial);
#  - the solution keeps the lattice's symmetries: density and pressure sampled at x1 and -x1 on the
#    x1-axis, and on the x1-axis against the x2-axis (x1 <-> x2), agree within 1e-8. Every particle
#    pair has a mirror pair, so the only asymmetry is the round-off of sums taken in a different
#    order (1e-16 relative per operation, ~100 steps through a dissipative flow); a sign error, a
#    one-sided neighbour search or a biased wall gives differences of order the jumps (0.1-0.3);
#  - the shock is where it should be: ahead of x1 = 1.0 (past the 1D Sod position 0.5 + 1.75*0.3
#    = 1.03 less a smearing) and not beyond x1 = 1.6.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
TUTORIAL="$SOURCE/../../../tutorials/impactSph/shockChamber/airAir"
export PATH="$BUILD/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-2d.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "PASS: $*"; }
c="$WORK/airAir"
mkdir -p "$c" && cp -r "$TUTORIAL/system" "$TUTORIAL/constant" "$c/"
mfDictionary "$c/system/controlDict" -entry endTime -set 0.3 > /dev/null
mfDictionary "$c/system/controlDict" -entry writeInterval -set 0.3 > /dev/null
cat > "$c/system/sampleDict" <<'DICT'
interpolation shepard;
fields (density pressure);
sets
{
    xAxis { type line; start (-3 0 0); end (3 0 0); nPoints 301; }
    yAxis { type line; start (0 -3 0); end (0 3 0); nPoints 301; }
}
plot no;
DICT
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail -5 "$c/log.particleGen")"
impactSph -case "$c" > "$c/log.impactSph" 2>&1 || fail "impactSph: $(tail -5 "$c/log.impactSph")"
grep -q "steps .* to t = 0.3" "$c/log.impactSph" || fail "did not reach t = 0.3: $(grep steps "$c/log.impactSph")"
sample -case "$c" -latestTime > "$c/log.sample" 2>&1 || fail "sample: $(tail -5 "$c/log.sample")"
x="$c/postProcessing/sample/0.3/xAxis.csv"
y="$c/postProcessing/sample/0.3/yAxis.csv"
if grep -qi "nan" "$c/log.impactSph" "$x" "$y"; then fail "NaN in the log or the samples"; fi
drift() { grep "$1" "$c/log.impactSph" | tail -n 1 | awk '{print $4}'; }
mass=$(drift "mass drift"); px=$(drift "momentum_x change"); py=$(drift "momentum_y change"); energy=$(drift "totalEnergy drift")
awk -v m="$mass" -v px="$px" -v py="$py" -v e="$energy" 'BEGIN {
    a = (px < 0 ? -px : px); b = (py < 0 ? -py : py); f = (e < 0 ? -e : e);
    exit !(m == 0 && a < 1e-12 && b < 1e-12 && f < 1e-4) }' \
    || fail "conservation: mass drift $mass, momentum ($px, $py), energy drift $energy"
result=$(awk -F, 'FNR == 1 { next }
    FNR == NR { xr[FNR - 2] = $5; xp[FNR - 2] = $6; xx[FNR - 2] = $2; n = FNR - 1; next }
    { yr[FNR - 2] = $5; yp[FNR - 2] = $6 }
    END {
        s = 0; t = 0
        for (i = 0; i < n; ++i) {
            d = xr[i] - xr[n - 1 - i]; d = d < 0 ? -d : d; if (d > s) s = d
            d = xp[i] - xp[n - 1 - i]; d = d < 0 ? -d : d; if (d > s) s = d
            d = xr[i] - yr[i]; d = d < 0 ? -d : d; if (d > t) t = d
            d = xp[i] - yp[i]; d = d < 0 ? -d : d; if (d > t) t = d
        }
        front = 0
        for (i = 0; i < n; ++i) if (xx[i] > 0 && xr[i] > 0.13) front = xx[i]
        printf "%.3g %.3g %.3f\n", s, t, front
    }' "$x" "$y")
read -r mirror swap front <<< "$result"
awk -v s="$mirror" -v t="$swap" 'BEGIN { exit !(s < 1e-8 && t < 1e-8) }' \
    || fail "symmetry broken: max |f(x1) - f(-x1)| = $mirror, max |f(x1, 0) - f(0, x1)| = $swap"
awk -v f="$front" 'BEGIN { exit !(f > 1.0 && f < 1.6) }' || fail "shock front (rho > 0.13) at x1 = $front, expected in (1.0, 1.6)"
pass "t = 0.3: mass drift $mass, momentum ($px, $py), energy drift $energy; symmetry x1 -> -x1 $mirror, x1 <-> x2 $swap; shock front x1 = $front"
