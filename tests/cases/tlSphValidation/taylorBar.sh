# Taylor bar through tlSph (3D, J2 plasticity): tutorials/tlSph/taylorBar (a quarter of the rod,
# mirrored across x = 0 and z = 0) on a 0.2667 mm lattice (12 particles across the radius; the
# tutorial's 0.4 mm gives a footprint 8% short) run to 80 us; final length within 3% of 21.5 mm
# and footprint radius within 5% of 7.0 mm (Kamoulakos 1990). About 47 CPU-minutes (55684 steps).
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export MFDYN_BUILD="$BUILD"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-tlsph-taylor.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cp -r "$SOURCE/tutorials/tlSph/taylorBar" "$WORK/taylorBar"
mkdir -p "$WORK/bin/tools" && cp "$SOURCE/bin/tools/RunFunctions" "$WORK/bin/tools/"
# The tutorial sources ../../../bin/tools/RunFunctions: give it that layout.
mkdir -p "$WORK/tutorials/tlSph" && mv "$WORK/taylorBar" "$WORK/tutorials/tlSph/"
c="$WORK/tutorials/tlSph/taylorBar"
PATH="$BUILD/bin:$PATH" mfDictionary "$c/system/particleGenDict" -entry regions/bar/lattice/spacing -set 2.6666666666666667e-4
(cd "$c" && ./Allclean > /dev/null && ./Allrun > log.Allrun 2>&1) || fail "Allrun: $(tail -n 20 "$c/log.Allrun")"
result=$(cat "$c/taylorBar.result")
echo "$result"
read -r length radius <<< "$(echo "$result" | sed -E 's/.*final length ([0-9.]+) mm.*footprint radius ([0-9.]+) mm.*/\1 \2/')"
awk -v L="$length" 'BEGIN { d = L / 21.5 - 1; exit !(d < 0.03 && d > -0.03) }' || fail "final length $length mm, not within 3% of 21.5 mm"
awk -v R="$radius" 'BEGIN { d = R / 7.0 - 1; exit !(d < 0.05 && d > -0.05) }' || fail "footprint radius $radius mm, not within 5% of 7.0 mm"
echo "PASS: Taylor bar (tlSph): length $length mm, footprint radius $radius mm"
