# The rotation-only case (R4, doc/methods/fpm.md §4.9) beyond the default: a restart from a
# written time reproduces the straight run bit for bit, and the 2D disc (the plane rotation of
# S, 2D comes with the 3D method) meets the same reference. Coarse and in large steps (the exact
# map makes the answer independent of dt): a few seconds.
source "$(dirname "$0")/common.sh"
# 3D, spacing 1.25, h 2.5, dt 0.01 to 12.5 (1250 steps), written every 3.125 s.
c="$WORK/straight"
copyTutorial rotationOnly "$c"
coarseSphere "$c" 0.01
run "$c" particleGen
run "$c" fpmSolid
r="$WORK/restart"
cp -r "$c" "$r"
rm -rf "$r/9.375" "$r/12.5"
sed -i 's/^startFrom .*/startFrom latestTime;/' "$r/system/controlDict"
run "$r" fpmSolid
grep -q "at t = 6.25" "$r/log.fpmSolid" || fail "the restart did not start from 6.25: $(grep 'Starting time loop' "$r/log.fpmSolid")"
cmp -s "$c/12.5/particles.vtp" "$r/12.5/particles.vtp" || fail "the restart from 6.25 differs from the straight run at 12.5"
echo "restart from 6.25: 12.5/particles.vtp identical to the straight run's"
# 2D: the disc |x| < 5, spacing 0.5, h 1.25 (2.5 spacings: at 2 a boundary particle has 5
# neighbours, below the fit's 2(d+1) = 6), dt 0.01.
d="$WORK/disc"
copyTutorial rotationOnly "$d"
sed -i 's/^dimension 3;/dimension 2;/; s/spacing 0.75; }/spacing 0.5; }/' "$d/system/particleGenDict"
sed -i 's/^smoothingLength .*/smoothingLength 1.25;/; s/min (-10 -10 -10); max (0 10 10);/min (-10 -10); max (0 10);/' "$d/constant/fpmProperties"
sed -i 's/^deltaT .*/deltaT 0.01;/' "$d/system/controlDict"
grep -q "^dimension 2;" "$d/system/particleGenDict" || fail "could not make the case 2D"
run "$d" particleGen
run "$d" fpmSolid
e="$d/12.5/rotationError"
stress=$(entry "$e" runMaxStressError) radius=$(entry "$e" runMaxRadiusChange) zero=$(entry "$e" runMaxZeroStress)
echo "2D: max |S - S_exact| $stress, max ||x| - |x0|| $radius, max |S| unstressed $zero"
awk -v s="$stress" -v r="$radius" -v z="$zero" 'BEGIN { exit !(s <= 1e-9 && r <= 1e-11 && z == 0) }' ||
    fail "2D: the reference is not met"
read -r lo hi < <(fieldRange "$d" 12.5 deviatoricStress.xx)
awk -v lo="$lo" -v hi="$hi" 'BEGIN { d = hi - 9.912028118634735; exit !(lo == 0 && d < 1e-9 && d > -1e-9) }' ||
    fail "2D: S11 range [$lo, $hi], expected [0, 9.912028118634735]"
# Frozen particles (the thesis's coupled run: the rotation part moves nothing), v from the shared
# initialState family (rigidRotation, the same v = (x2, -x1, 0)): every stressed particle turns its S
# by the same exact map, so at 12.5 S11 = 10 cos 25 and S21 = -10 sin 25 on the stressed half, 0 on
# the other; the positions do not move.
f="$WORK/frozen"
cp -r "$c" "$f"
rm -rf "$f"/[1-9]* "$f/particles.pvd"
sed -i 's/^startFrom .*/startFrom startTime;/' "$f/system/controlDict"
sed -i 's/^motion .*/motion          { velocity frozen; }\ninitialState    { type rigidRotation; omega (0 0 -1); }/' "$f/constant/fpmProperties"
grep -q "velocity frozen" "$f/constant/fpmProperties" || fail "could not freeze the particles"
run "$f" fpmSolid
read -r lo hi < <(fieldRange "$f" 12.5 deviatoricStress.xx)
awk -v lo="$lo" -v hi="$hi" 'BEGIN { d = hi - 9.912028118634735; exit !(lo == 0 && d < 1e-9 && d > -1e-9) }' ||
    fail "frozen: S11 range [$lo, $hi], expected [0, 9.912028118634735]"
s11="$hi"
read -r lo hi < <(fieldRange "$f" 12.5 deviatoricStress.xy)
awk -v lo="$lo" -v hi="$hi" 'BEGIN { d = hi - 1.3235175009777302; exit !(lo == 0 && d < 1e-9 && d > -1e-9) }' ||
    fail "frozen: S21 range [$lo, $hi], expected [0, 1.3235175009777302]"
[ "$(fieldRange "$f" 12.5 position.x)" = "$(fieldRange "$f" 0 position.x)" ] || fail "frozen: the particles moved"
echo "frozen: S11 max $s11 at 12.5 (exact 10 cos 25 = 9.912028118634735), positions unchanged"
# The CFL rule (adjustTimeStep yes, maxCo 0.1): dt = maxCo spacing / max |v| = 0.1 x 1.25 / max |x|,
# and the exact map keeps R4 at any step (an angle of 0.026 rad a step here).
a="$WORK/adjustable"
cp -r "$c" "$a"
rm -rf "$a"/[1-9]* "$a/particles.pvd"
sed -i 's/^startFrom .*/startFrom startTime;/; s/^adjustTimeStep .*/adjustTimeStep  yes;\nmaxCo           0.1;/' "$a/system/controlDict"
run "$a" fpmSolid
read -r vlo vhi < <(fieldRange "$a" 12.5 "|velocity|")
dt=$(awk '/^Step .* t = 12.5 / { for (i = 1; i <= NF; ++i) if ($i == "dt") print $(i + 2) }' "$a/log.fpmSolid")
awk -v dt="$dt" -v v="$vhi" 'BEGIN { e = 0.1 * 1.25 / v; exit !(dt > 0.999 * e && dt < 1.001 * e) }' ||
    fail "adjustTimeStep: dt $dt, expected 0.1 x 1.25 / $vhi"
stress=$(entry "$a/12.5/rotationError" runMaxStressError)
awk -v s="$stress" 'BEGIN { exit !(s <= 1e-9) }' || fail "adjustTimeStep: max |S - S_exact| = $stress > 1e-9"
echo "adjustTimeStep: dt $dt = 0.1 x 1.25 / $vhi, max |S - S_exact| $stress"
# A fit that cannot be made is a run error with the step, the time, the particle (its index here and
# its global id) and the remedies:
# the quadratic basis at h = 2 spacings has too few neighbours for its 10 terms at the surface.
q="$WORK/order2"
cp -r "$c" "$q"
rm -rf "$q"/[1-9]* "$q/particles.pvd"
sed -i 's/^startFrom .*/startFrom startTime;/' "$q/system/controlDict"
sed -i 's/^order .*/order 2;/' "$q/constant/fpmProperties"
rc=0; fpmSolid -case "$q" > "$q/log.fpmSolid" 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "order 2 at h = 2 spacings: exit status $rc, expected 1"
grep -q "phase fit, step 1, t = [0-9.e-]*: LeastSquaresOperators: point [0-9]* (particle [0-9]*) at (.*neighbours.*fitFallback growSupport | shepard" "$q/log.fpmSolid" ||
    fail "order 2: no diagnosis with step, time, point and remedy: $(tail -3 "$q/log.fpmSolid")"
grep -q nan "$q/log.fpmSolid" && fail "order 2: NaN in the log"
echo "order 2 at h = 2 spacings: $(grep -o 'phase fit, step 1.\{0,120\}' "$q/log.fpmSolid")"
echo "PASS: restart bit for bit; 2D disc, frozen particles and the CFL step to 12.5 s; a failing fit diagnosed"
