# The 3D case of issue 18 (tutorials/mpmFsi/columnCollapse3D, validation label, about 60 CPU-s):
# Martin & Moyce's (1952) n^2 = 2 column as a slab a/5 deep between slip side walls, computed in
# 3D (27-node quadratic B-splines, 25 600 points, cells a/20).
#   the surge front within 10% of Martin & Moyce's Fig. 3 (the five points up to T = 3.345), never
#       faster than the Ritter bound (dZ/dT <= 2 over each write interval);
#   the flow is plane: the front within 1% of the 2D tutorial damBreak's (the same column, cells and
#       floor) at each data point (measured: within 0.1%), the z-momentum zero to round-off;
#   mass exact.
source "$(dirname "$0")/common.sh"
frontError="$SOURCE/tutorials/mpmFsi/damBreak/frontError.awk"
c="$WORK/slab"
copyTutorial columnCollapse3D "$c"
run "$c" particleGen
run "$c" mpmFsi
awk -v a=0.05715 -v g=9.81 -f "$frontError" "$c/postProcessing/front/0/frontPosition.csv" | tee "$WORK/3d.txt"
read -r unused worst unused ritter unused <<< "$(tail -n 1 "$WORK/3d.txt")"
[ "$(grep -c '^T ' "$WORK/3d.txt")" = 5 ] || fail "the run did not cover the five data points"
less "$worst" 0.10 || fail "surge front: largest error $worst against Martin & Moyce, not within 10%"
less "$ritter" 1 || fail "surge front faster than the Ritter bound: $ritter of 2 sqrt(g H)"
grep -q "mass drift 0.000e+00" "$c/log.mpmFsi" || fail "mass not exact: $(grep 'mass drift' "$c/log.mpmFsi")"
pz=$(column "$c/postProcessing/conserved/0/conservedQuantities.csv" momentum_z | awk '{ v = $1 < 0 ? -$1 : $1; if (v > m) m = v } END { print m + 0 }')
less "$pz" 1e-12 || fail "z-momentum $pz kg m/s: the slab's flow is not plane (x-momentum about 0.04)"
d="$WORK/plane"
copyTutorial damBreak "$d"
run "$d" particleGen
run "$d" mpmFsi
awk -v a=0.05715 -v g=9.81 -f "$frontError" "$d/postProcessing/front/0/frontPosition.csv" > "$WORK/2d.txt"
paste -d' ' <(grep '^T ' "$WORK/3d.txt") <(grep '^T ' "$WORK/2d.txt") | awk '
    { z3 = $6; z2 = $14; e = (z3 - z2) / z2; printf "T %s  Z(3D) %s  Z(2D) %s  difference %+.2f%%\n", $2, z3, z2, 100 * e
      if (e < 0) e = -e; if (e > worst) worst = e }
    END { exit !(worst <= 0.01) }' || fail "the 3D slab's front is not within 1% of the 2D column's"
echo "PASS: columnCollapse3D (largest error $worst against Martin & Moyce, Ritter ratio $ritter)"
