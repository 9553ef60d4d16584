# Two elastic disks (doc/methods/mpm.md 4.3, the note's V3 - V3e): r = 0.2, StVK E = 1000, nu = 0.3,
# rho = 1000, 316 particles per disk, the unit grid in 20 x 20 cells, linear hats, USL, FLIP.
#   V3  K(0) = rho pi r^2 |v|^2 = 2.51327412 to 1e-10 relative;
#   V3b the total momentum stays below 1e-10 of one disk's m |v| = 17.77 (measured 5e-15);
#   V3c symmetry through (0.5, 0.5): x_p + x_p' = (1, 1) and v_p + v_p' = 0 for each particle and
#       its mirror image, and P_x = P_y per disk, to 1e-8, at t = 3;
#   V3d contact onset within 0.05 of the thesis's 1.21 (measured 1.22); the kinetic-energy
#       minimum within 0.05 of 1.65 with the author's notebook's E = 1e4 (measured 1.655): with the
#       thesis text's E = 1000 it comes at 2.145 (a softer disk takes longer to stop; README);
#   V3e the largest energy error |K + U - E0| / E0 over [0, 2] (U = sum V0 W(F), exact) smaller with
#       3016 particles per disk than with 316 (measured 4.2e-5 and 7.6e-4).
source "$(dirname "$0")/common.sh"
c="$WORK/disks"
copyTutorial twoDisks "$c"
run "$c" particleGen
cp -r "$c" "$WORK/stiff"
run "$c" mpmFsi
csv="$c/postProcessing/conserved/0/conservedQuantities.csv"
K0=$(column "$csv" kineticEnergy | sed -n 1p)  # sed reads to the end: head would break the pipe
echo "V3: K(0) = $K0"
within "$K0" 2.51327412287 1e-10 || fail "V3: K(0) = $K0, not 2.51327412287 to 1e-10"
for axis in x y; do
    column "$csv" "momentum_$axis" | awk '{ p = $1 < 0 ? -$1 : $1; if (p > 1e-10 * 17.7715) { print "momentum " $1; exit 1 } }' \
        || fail "V3b: the total momentum_$axis left round-off"
done
# onset: K below K(0) by 1e-6 relative; K minimum (the CSV every 50 steps, 0.005 s)
events() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "kineticEnergy") k = i; if ($i == "totalEnergy") e = i }; next }
        NR == 2 { K0 = $k; E0 = $e }
        { if (on == "" && $k < K0 * (1 - 1e-6)) on = $1; if (tmin == "" || $k < kmin) { kmin = $k; tmin = $1 }
          if ($1 <= 2 + 1e-9) { d = ($e - E0) / E0; if (d < 0) d = -d; if (d > dmax) dmax = d } }
        END { printf "%s %s %.6g\n", on, tmin, dmax }' "$1"
}
read -r onset tmin error316 <<< "$(events "$csv")"
echo "V3d: contact onset $onset, K minimum at $tmin (E = 1000); V3e: energy error over [0, 2] $error316"
less "$(awk -v t="$onset" 'BEGIN { d = t - 1.21; print d < 0 ? -d : d }')" 0.05 || fail "V3d: contact onset at $onset, not within 0.05 of 1.21"
python3 - "$c/3/particles.vtp" "$HERE" <<'PY' || fail "V3c: the disks are not symmetric to 1e-8"
import sys
sys.path.insert(0, sys.argv[2])
from vtp import read
d = read(sys.argv[1])
x, v, m, r = d['position'], d['velocity'], d['mass'], d['region']
n = len(x)
worst = max(max(abs(x[i][k] + x[n - 1 - i][k] - 1) for k in (0, 1)) for i in range(n // 2))
worstV = max(max(abs(v[i][k] + v[n - 1 - i][k]) for k in (0, 1)) for i in range(n // 2))
P = {}
for i in range(n):
    P.setdefault(r[i][0], [0.0, 0.0])
    for k in (0, 1): P[r[i][0]][k] += m[i][0] * v[i][k]
worstP = max(abs(p[0] - p[1]) for p in P.values())
print('V3c: |x + x\' - 1| %.2e, |v + v\'| %.2e, |P_x - P_y| per disk %.2e' % (worst, worstV, worstP))
sys.exit(0 if worst < 1e-8 and worstV < 1e-8 and worstP < 1e-8 * 17.7715 else 1)
PY
# V3d with the notebook's E = 1e4, to t = 2
s="$WORK/stiff"
sed -i 's/youngsModulus   1000;/youngsModulus   1e4;/' "$s/constant/materialProperties"
sed -i 's/^endTime .*/endTime         2;/' "$s/system/controlDict"
grep -q "youngsModulus   1e4;" "$s/constant/materialProperties" || fail "could not set E = 1e4"
run "$s" mpmFsi
read -r onsetStiff tminStiff unused <<< "$(events "$s/postProcessing/conserved/0/conservedQuantities.csv")"
echo "V3d: E = 1e4: contact onset $onsetStiff, K minimum at $tminStiff"
less "$(awk -v t="$tminStiff" 'BEGIN { d = t - 1.65; print d < 0 ? -d : d }')" 0.05 || fail "V3d: K minimum at $tminStiff with E = 1e4, not within 0.05 of 1.65"
# V3e: 3016 particles per disk (31 x 31 sub-cells), to t = 2
f="$WORK/fine"
copyTutorial twoDisks "$f"
sed -i 's/cells (10 10)/cells (31 31)/g' "$f/system/particleGenDict"
sed -i 's/^endTime .*/endTime         2;/' "$f/system/controlDict"
run "$f" particleGen
grep -q "lower *3016" "$f/log.particleGen" || fail "31 x 31 sub-cells did not give 3016 particles per disk"
run "$f" mpmFsi
read -r unused unused error3016 <<< "$(events "$f/postProcessing/conserved/0/conservedQuantities.csv")"
echo "V3e: energy error over [0, 2]: 316 particles $error316, 3016 particles $error3016"
less "$error3016" "$error316" || fail "V3e: the energy error with 3016 particles ($error3016) is not below that with 316 ($error316)"
echo "PASS: twoDisks"
