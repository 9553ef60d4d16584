# Dam break (tutorials/mpmFsi/damBreak): Martin & Moyce's (1952) n^2 = 2 water column (a wide, 2a
# high, a = 0.05715 m), Tait water c0 = 15 m/s, cells a/20, 3200 points, to T = t sqrt(2g/a) = 3.4.
#   the surge front Z = x/a within 10% of Martin & Moyce's Fig. 3 data (a = 2.25 in, the five
#       points up to T = 3.345) with the tutorial's no-slip floor (measured: largest 5.4%);
#   never faster than the Ritter bound dx/dt <= 2 sqrt(g H), i.e. dZ/dT <= 2 over each write
#       interval Delta T = 0.1, with the no-slip and with a slip floor (measured 0.65 and 0.79 of it);
#   the slip floor's front ahead of the no-slip floor's at T = 3.345 (the floor's drag slows it);
#   mass exact (no particle leaves). About 6 CPU-s.
source "$(dirname "$0")/common.sh"
c="$WORK/dam"
copyTutorial damBreak "$c"
run "$c" particleGen
cp -r "$c" "$WORK/slip"
run "$c" mpmFsi
awk -v a=0.05715 -v g=9.81 -f "$c/frontError.awk" "$c/postProcessing/front/0/frontPosition.csv" | tee "$WORK/noSlip.txt"
read -r unused worst unused ritter unused <<< "$(tail -n 1 "$WORK/noSlip.txt")"
[ "$(grep -c '^T ' "$WORK/noSlip.txt")" = 5 ] || fail "the run did not cover the five data points"
less "$worst" 0.10 || fail "surge front: largest error $worst against Martin & Moyce, not within 10%"
less "$ritter" 1 || fail "surge front faster than the Ritter bound: $ritter of 2 sqrt(g H)"
grep -q "mass drift 0.000e+00" "$c/log.mpmFsi" || fail "mass not exact: $(grep 'mass drift' "$c/log.mpmFsi")"
s="$WORK/slip"
sed -i 's/^    walls { type slip; faces (xMin xMax); }/    walls { type slip; faces (xMin xMax yMin); }/; /^    floor { type fixed; faces (yMin); }/d' "$s/constant/mpmProperties"
grep -q "faces (xMin xMax yMin)" "$s/constant/mpmProperties" || fail "could not set the slip floor"
run "$s" mpmFsi
awk -v a=0.05715 -v g=9.81 -f "$c/frontError.awk" "$s/postProcessing/front/0/frontPosition.csv" | tee "$WORK/slip.txt"
read -r unused unused unused ritterSlip unused <<< "$(tail -n 1 "$WORK/slip.txt")"
less "$ritterSlip" 1 || fail "slip floor: surge front faster than the Ritter bound: $ritterSlip of 2 sqrt(g H)"
zNoSlip=$(awk '$2 == "3.345" { print $6 }' "$WORK/noSlip.txt")
zSlip=$(awk '$2 == "3.345" { print $6 }' "$WORK/slip.txt")
less "$zNoSlip" "$zSlip" || fail "the slip floor's front ($zSlip) is not ahead of the no-slip floor's ($zNoSlip) at T = 3.345"
echo "PASS: damBreak (largest error $worst, Ritter ratio $ritter / slip $ritterSlip, Z(3.345) no-slip $zNoSlip slip $zSlip)"
