# One code in 1, 2 and 3 dimensions (issue 17: "1D, 2D and 3D from the start").
#   1D: the undamped spring as a 1D bar (uniaxial strain, nu = 0) matches the 2D tutorial's bar in
#       one column of cells (plane strain, nu = 0: the same 1D problem): the lowest particle's
#       position at every 20th step (251 rows; 1D vectors have one column, position_min) to 1e-12 m and the same total-energy drift (-2.812e-05);
#   3D: two neo-Hookean spheres (quadratic B-splines, APIC) collide: mass exact, linear momentum
#       below 1e-12 and angular momentum below 1e-12 of |r| m |v| (APIC with B-splines keeps it),
#       the collision under way (stored energy above 1% of the kinetic at the end).
source "$(dirname "$0")/common.sh"
two="$WORK/bar2"
copyTutorial spring1D "$two"
sed -i 's/^gridDamping .*/gridDamping     none;/; /^dampingCoefficient/d' "$two/constant/mpmProperties"
sed -i 's/^endTime .*/endTime         0.5;/' "$two/system/controlDict"
grep -q "^gridDamping     none;" "$two/constant/mpmProperties" || fail "could not switch the damping off"
run "$two" particleGen
run "$two" mpmFsi
one="$WORK/bar1"
mkdir -p "$one/system" "$one/constant"
cp "$two/constant/materialProperties" "$one/constant/"
cp "$two/system/controlDict" "$one/system/"
cat > "$one/system/particleGenDict" <<'DICT'
dimension 1;
regions { bar { shape { type box; min (0.8); max (1.0); } lattice { type materialPoints; cells (10); pattern centre; }
                density 1500; material bar; } }
DICT
cat > "$one/constant/mpmProperties" <<'DICT'
grid { origin (0); cellSize (0.047619047619047616); cells (21); }
bodyForce { type uniformGravity; g (-9.81); }
gridBoundaryConditions { top { type fixed; faces (xMax); } }
DICT
run "$one" particleGen
run "$one" mpmFsi
paste -d, <(column "$two/postProcessing/tip/0/fieldMinMax.csv" position_y_min) <(column "$one/postProcessing/tip/0/fieldMinMax.csv" position_min) \
    | awk -F, '{ d = $1 - $2; if (d < 0) d = -d; if (d > worst) worst = d; n++ } END { printf "1D vs 2D: %d rows, largest difference %.3e m\n", n, worst; exit !(n > 250 && worst < 1e-12) }' \
    || fail "the 1D bar does not follow the 2D one"
d1=$(grep -o "totalEnergy drift [-0-9.e+]*" "$one/log.mpmFsi" | awk '{ print $3 }')
d2=$(grep -o "totalEnergy drift [-0-9.e+]*" "$two/log.mpmFsi" | awk '{ print $3 }')
[ "$d1" = "$d2" ] || fail "the energy drifts differ: 1D $d1, 2D $d2"
echo "1D and 2D energy drift $d1"

s="$WORK/spheres"
mkdir -p "$s/system" "$s/constant"
cat > "$s/system/controlDict" <<'DICT'
application mpmFsi; startFrom startTime; startTime 0; stopAt endTime; endTime 0.25; deltaT 1e-3; adjustTimeStep no;
writeControl adjustableRunTime; writeInterval 0.25;
functions { conserved { type conservedQuantities; writeControl timeStep; writeInterval 10; } }
DICT
cat > "$s/system/particleGenDict" <<'DICT'
dimension 3;
regions { a { shape { type sphere; centre (0.35 0.35 0.5); radius 0.15; } lattice { type materialPoints; cells (6 6 6); pattern gauss; }
              density 1000; material soft; fields { velocity (0.3 0.3 0); } }
          b { shape { type sphere; centre (0.65 0.65 0.5); radius 0.15; } lattice { type materialPoints; cells (6 6 6); pattern gauss; }
              density 1000; material soft; fields { velocity (-0.3 -0.3 0); } } }
DICT
echo 'materials { soft { rho0 1000; youngsModulus 1e4; poissonRatio 0.3; constitutiveLaw { type neoHookean; } } }' > "$s/constant/materialProperties"
echo 'grid { origin (0 0 0); cellSize (0.05 0.05 0.05); cells (20 20 20); } shapeFunction quadraticBSpline; velocityUpdate APIC;' > "$s/constant/mpmProperties"
run "$s" particleGen
run "$s" mpmFsi
csv="$s/postProcessing/conserved/0/conservedQuantities.csv"
grep -q "conserved: mass drift 0.000e+00" "$s/log.mpmFsi" || fail "3D: the mass changed"
# m |v| of one sphere: 1000 x 4/3 pi 0.15^3 x 0.3 sqrt 2 = 5.997; |r| ~ 0.5
for q in momentum_x momentum_y momentum_z angularMomentum_x angularMomentum_y angularMomentum_z; do
    column "$csv" "$q" | awk -v q="$q" '{ a = $1 < 0 ? -$1 : $1; if (a > 1e-12 * 6) { print q " = " $1; exit 1 } }' || fail "3D: $q left round-off"
done
read -r K U <<< "$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) { if ($i == "kineticEnergy") k = i; if ($i == "internalEnergy") u = i }; next } { K = $k; U = $u } END { print K, U }' "$csv")"
less "$(awk -v k="$K" 'BEGIN { print 0.01 * k }')" "$U" || fail "3D: no collision (stored $U, kinetic $K)"
echo "3D: momenta at round-off, stored energy $U with kinetic $K at t = 0.25"
echo "PASS: dimensions"
