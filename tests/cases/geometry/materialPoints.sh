# particleGen with the materialPoints lattice and the polygon shape (issue 17 item 7;
# doc/methods/mpm.md sections 4.3 and 4.7): the two disks of radius 0.2, Gauss points on 10 x 10
# sub-cells, give the thesis's 316 points per disk, each disk holding its exact area pi 0.2^2 =
# 0.125664 and mass 125.664 (so that K(0) = 1/2 x 251.327 x 0.02 = 2.51327); 31 x 31 sub-cells give
# 3016; the float's triangle of side 0.2 gives 200. The report prints 6 significant digits.
# $1 = build directory, $2 = this source directory.
set -euo pipefail
export PATH="$1/bin:$PATH" OMP_NUM_THREADS=1
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-test.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cp -r "$2/twoDisks" "$WORK/case"
dict="$WORK/case/system/particleGenDict"

# row <region>: "count volume exact mass" of the report
row() { grep -E "^$1 " "$WORK/log" | awk '{print $2, $3, $4, $5}'; }

particleGen -case "$WORK/case" > "$WORK/log" 2>&1 || fail "particleGen failed: $(cat "$WORK/log")"
grep -q "materialPoints lattice of 10 x 10 sub-cells of (0.04 0.04) m, 2^2 Gauss points each" "$WORK/log" ||
    fail "no lattice line: $(cat "$WORK/log")"
for r in lower upper; do
    [ "$(row $r)" = "316 0.125664 0.125664 125.664" ] || fail "$r: '$(row $r)', expected 316 points of the exact area"
done
grep -qE '^total +632 +251.327$' "$WORK/log" || fail "total: $(grep '^total' "$WORK/log")"
[ -f "$WORK/case/0/particles.vtp" ] || fail "no 0/particles.vtp"

sed -i 's/cells (10 10)/cells (31 31)/' "$dict"
particleGen -case "$WORK/case" > "$WORK/log" 2>&1 || fail "particleGen failed: $(cat "$WORK/log")"
[ "$(row lower)" = "3016 0.125664 0.125664 125.664" ] || fail "31 x 31: '$(row lower)', expected 3016"

cat > "$dict" <<'DICT'
dimension 2;
regions { block { shape { type polygon; vertices ((0.1 0.2) (0.3 0.2) (0.2 0.37320508075688773)); }
                  lattice { type materialPoints; cells (10 10); pattern gauss; } density 917; } }
DICT
particleGen -case "$WORK/case" > "$WORK/log" 2>&1 || fail "particleGen failed: $(cat "$WORK/log")"
[ "$(row block)" = "200 0.0173205 0.0173205 15.8829" ] || fail "triangle: '$(row block)', expected 200 points"
echo "PASS: two disks 316 + 316 (3016 at 31 x 31), triangle 200 material points, exact volumes"
