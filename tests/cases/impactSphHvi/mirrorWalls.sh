# Mirror ghost walls: a gas at rest between two mirror planes stays exactly at rest (every
# particle sees a full, symmetric kernel), while the same gas without them runs out of its ends.
. "$(dirname "$0")/common.sh"
c="$WORK/box"
cp -r "$SOURCE/mirrorBox" "$c"
particleGen -case "$c" > /dev/null 2>&1 || fail "particleGen failed"
impactSph -case "$c" > "$c/log" 2>&1 || fail "impactSph failed: $(tail -5 "$c/log")"
row=$(tail -n 1 "$c/postProcessing/range/0/fieldMinMax.csv")
IFS=, read -r t vmin vminId vmax vmaxId rmin rminId rmax rmaxId <<< "$row"
less "$(abs "$vmin")" 1e-10 && less "$(abs "$vmax")" 1e-10 || fail "gas between mirrors moved: v in [$vmin, $vmax]"
less "$(abs "$(awk -v a="$rmin" 'BEGIN { print a - 1 }')")" 1e-10 && less "$(abs "$(awk -v a="$rmax" 'BEGIN { print a - 1 }')")" 1e-10 \
    || fail "density left 1: [$rmin, $rmax]"
free="$WORK/free"
cp -r "$SOURCE/mirrorBox" "$free" && rm "$free/constant/boundaryConditions"
particleGen -case "$free" > /dev/null 2>&1 && impactSph -case "$free" > "$free/log" 2>&1 || fail "free run failed"
vfree=$(tail -n 1 "$free/postProcessing/range/0/fieldMinMax.csv" | cut -d, -f4)
less 0.1 "$vfree" || fail "without mirrors the ends should expand (max v $vfree): the test would not see missing ghosts"
pass "mirror walls hold the gas at rest (|v| <= $(abs "$vmax")); without them max v = $vfree"
