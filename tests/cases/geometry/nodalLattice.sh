# particleGen with the nodal lattice (doc/methods/tl-jst-sph.md 2.1): 31 x 11 x 6 nodes on 0.03 x 0.01 x 0.005 at
# 1 mm, the adjusted spacing logged, and the tributary volumes filling the box exactly (the report
# prints 6 significant digits: volume 1.5e-06 m^3 and mass 1100 x 1.5e-6 = 0.00165 kg).
# $1 = build directory, $2 = this source directory.
set -euo pipefail
export PATH="$1/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-test.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cp -r "$2/nodalBar" "$WORK/case"
particleGen -case "$WORK/case" > "$WORK/log" 2>&1 || fail "particleGen failed: $(cat "$WORK/log")"
grep -q "nodal lattice of 31 x 11 x 6 nodes, spacing (0.001 0.001 0.001) m" "$WORK/log" || fail "no spacing line: $(cat "$WORK/log")"
row=$(grep -E '^bar ' "$WORK/log") || fail "no report row"
read -r _ count volume exact mass _ <<< "$row"
[ "$count" = 2046 ] || fail "expected 2046 = 31 x 11 x 6 particles, found $count"
[ "$volume" = "$exact" ] && [ "$volume" = 1.5e-06 ] || fail "volume $volume, exact $exact"
[ "$mass" = 0.00165 ] || fail "mass $mass, expected 0.00165"
[ -f "$WORK/case/0/particles.vtp" ] || fail "no 0/particles.vtp"
echo "PASS: nodal lattice 2046 particles, volume $volume m^3"
