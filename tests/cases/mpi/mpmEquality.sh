# mpmFsi on several ranks (issue 21): the same final state serially and on 2 and 3 ranks, every
# field within 1e-12 (particleCompare), for
#   - the two disks (tutorials/mpmFsi/twoDisks: USL, FLIP, linear hats, one node field) through
#     their collision, to t = 1.5;
#   - the same disks with a node field each (contact multiField with friction 0.2), MUSL and APIC
#     (the halo's x, v and C refreshed before MUSL's second map), to t = 1.8, writeGrid on: the
#     ranks' pieces of the grid (grid_<r>.vti, slabs along y, indexed by grid.pvti and listed in
#     particles.pvd) must hold the serial grid.vti's bytes (gridPieces.py), and the summary's peak pair force
#     the serial one (a sum over the nodes each rank counts);
#   - the dam break (quadratic B-splines, flipPic, gravity, slip and fixed grid conditions, a fluid
#     equation of state) with USF (the halo's J and sigma refreshed before the forces), to 0.05 s,
#     and with USL and pressureSmoothing cellJacobian (a cell's mean J over its particles in id
#     order, the halo's x and J refreshed first);
#   - the hanging block that tears (5 x 5 points on the 8 x 8 grid): the torn-body diagnosis on
#     2 and 3 ranks is the serial one, word for word (the pieces joined across ranks);
#   - a restart: the disks to 0.9 on 3 ranks, on to 1.5 on 2, against the serial run straight.
# The node sums are complete on every rank that reads them (the halo is two supports plus a cell
# deep) and their terms come in global-id order within each tile: measured, every case to the bit.
. "$(dirname "$0")/common.sh"

# endTime <case> <end> <writeInterval>
endTime() {
    mfDictionary "$1/system/controlDict" -entry endTime -set "$2" > /dev/null
    mfDictionary "$1/system/controlDict" -entry writeInterval -set "$3" > /dev/null
}
tutorial() {
    mkdir -p "$2" && cp -r "$SOURCE/tutorials/mpmFsi/$1/system" "$SOURCE/tutorials/mpmFsi/$1/constant" "$2/"
}

disks="$WORK/disks"
tutorial twoDisks "$disks"
endTime "$disks" 1.5 1.5
multi="$WORK/multi"
tutorial twoDisks "$multi"
endTime "$multi" 1.8 0.9
sed -i 's/^contact .*/contact         multiField;/; s/^scheme .*/scheme          MUSL;/; s/^velocityUpdate .*/velocityUpdate  APIC;/' \
    "$multi/constant/mpmProperties"
echo 'multiFieldCoeffs { friction 0.2; separation 0.667; }' >> "$multi/constant/mpmProperties"
echo 'writeGrid yes;' >> "$multi/constant/mpmProperties"
dam="$WORK/dam"
tutorial damBreak "$dam"
endTime "$dam" 0.05 0.05
sed -i 's/^scheme .*/scheme          USF;/' "$dam/constant/mpmProperties"
smooth="$WORK/smooth"
tutorial damBreak "$smooth"
endTime "$smooth" 0.05 0.05
sed -i 's/^pressureSmoothing .*/pressureSmoothing cellJacobian;/' "$smooth/constant/mpmProperties"
block="$WORK/block"
tutorial hangingBlock "$block"
mfDictionary "$block/system/particleGenDict" -entry regions/block/lattice/cells -set "(5 5)" > /dev/null
for c in "$disks" "$multi" "$dam" "$smooth" "$block"; do
    grep -q "^scheme" "$c/constant/mpmProperties" || fail "$(basename "$c"): no scheme entry to set"
    particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail -3 "$c/log.particleGen")"
done
grep -q "^scheme          USF;" "$dam/constant/mpmProperties" || fail "the dam break's scheme was not set to USF"
grep -q "^contact         multiField;" "$multi/constant/mpmProperties" || fail "the disks' contact was not set to multiField"
grep -q "^pressureSmoothing cellJacobian;" "$smooth/constant/mpmProperties" || fail "the dam break's pressureSmoothing was not set"

for c in "$disks" "$multi" "$dam" "$smooth"; do againstSerial mpmFsi "$c" "halo width" 2 3; done
# The multi-field disks' grid, in pieces, and their contact force (a sum over the counted nodes).
peak() { grep -o "peak pair force [0-9.e+-]* N" "$1" || echo "none"; }
serial="$WORK/multi.serial"
for n in 2 3; do
    d="$WORK/multi.$n"
    pieces=$(python3 "$(dirname "$0")/gridPieces.py" "$serial/1.8/grid.vti" "$d/1.8" "$n") ||
        fail "multi on $n ranks: $pieces"
    grep -q '"1.8/grid.pvti"' "$d/particles.pvd" || fail "multi on $n ranks: particles.pvd does not list 1.8/grid.pvti"
    [ "$(peak "$serial/log.mpmFsi")" = "$(peak "$d/log.mpmFsi")" ] && [ "$(peak "$d/log.mpmFsi")" != none ] ||
        fail "multi on $n ranks: $(peak "$d/log.mpmFsi") against the serial $(peak "$serial/log.mpmFsi")"
    echo "multi on $n ranks: $pieces, $(peak "$d/log.mpmFsi")"
done

# The torn block: status 1 and the serial diagnosis.
serial=$(copyCase "$block" "$WORK/block.serial")
status=0
mpmFsi -case "$serial" > "$serial/log.mpmFsi" 2>&1 || status=$?
[ "$status" = 1 ] || fail "block serially: status $status, not 1"
expected=$(grep "^Error" "$serial/log.mpmFsi")
echo "$expected" | grep -q "has torn apart" || fail "block serially: not the torn-body diagnosis: $expected"
for n in 2 3; do
    d=$(copyCase "$block" "$WORK/block.$n")
    status=0
    onRanks "$n" mpmFsi -case "$d" > "$d/log.mpmFsi" 2>&1 || status=$?
    [ "$status" = 1 ] || fail "block on $n ranks: status $status, not 1: $(tail -3 "$d/log.mpmFsi")"
    got=$(grep "^Error" "$d/log.mpmFsi")
    [ "$got" = "$expected" ] || fail "block on $n ranks: the diagnosis differs:
$got
serially:
$expected"
done
echo "block on 2 and 3 ranks: ${expected:0:120}..."

# A restart across rank counts.
straight=$(copyCase "$disks" "$WORK/disks.straight")
restarted=$(copyCase "$disks" "$WORK/disks.restarted")
endTime "$straight" 1.5 0.9
mpmFsi -case "$straight" > "$straight/log.mpmFsi" 2>&1 || fail "disks straight: $(tail -5 "$straight/log.mpmFsi")"
endTime "$restarted" 0.9 0.9
onRanks 3 mpmFsi -case "$restarted" > "$restarted/log.mpmFsi" 2>&1 || fail "disks to 0.9 on 3 ranks: $(tail -5 "$restarted/log.mpmFsi")"
endTime "$restarted" 1.5 0.9
mfDictionary "$restarted/system/controlDict" -entry startFrom -set latestTime > /dev/null
onRanks 2 mpmFsi -case "$restarted" > "$restarted/log.restart" 2>&1 || fail "disks restarted on 2 ranks: $(tail -5 "$restarted/log.restart")"
sameState "disks restarted at 0.9 on 2 ranks against the serial run" "$(latest "$straight")" "$(latest "$restarted")"
pass "mpmFsi: the two disks (single and multiField), the dam break and the torn block on 2 and 3 ranks as serially, and across a restart"
