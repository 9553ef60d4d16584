# Issue 17's Taylor bar acceptance (label validation): tutorials/mpmFsi/taylorBar on the fine grid,
# 0.4 mm cells and 0.2 mm material points (32886 points, about 3300 steps), both ways the bar's
# copper is written: the updated-Lagrangian path with impactSph's dictionary (Mie-Grueneisen +
# vonMises) and tlSph's constitutive law j2Plasticity (j2Plasticity/). Final length within 3% of
# 21.5 mm and footprint radius within 5% of 7.0 mm (the axisymmetric FE reference of Kamoulakos
# 1990). Measured at a340468 (README table): updated-Lagrangian 21.49 mm (-0.05%), 7.22 mm
# (+3.1%); j2Plasticity 21.48 mm (-0.1%), 7.21 mm (+3.0%). About 1.5 CPU-minutes a run, 3 in
# all on one thread.
source "$(dirname "$0")/common.sh"
copyTutorial taylorBar "$WORK/bar"
status=0
for variant in . j2Plasticity; do
    base="$WORK/bar/$variant"
    setEntry "$base/constant/mpmProperties" grid/cellSize 4e-4
    setEntry "$base/system/particleGenDict" regions/bar/lattice/spacing 2e-4
done
(cd "$WORK/bar" && MFDYN_DIR="$SOURCE" MFDYN_BUILD="$BUILD" OMP_NUM_THREADS=1 ./Allrun --j2 > log.Allrun 2>&1) ||
    fail "Allrun --j2: $(tail -n 20 "$WORK/bar/log.Allrun")"
for variant in . j2Plasticity; do
    result="$(cat "$WORK/bar/$variant/taylorBar.result")"
    echo "$result"
    length=$(sed -E 's/.*final length ([0-9.]+) mm.*/\1/' <<< "$result")
    footprint=$(sed -E 's/.*footprint radius ([0-9.]+) mm.*/\1/' <<< "$result")
    within "$length" 21.5 0.03 || { echo "FAIL: $variant: final length $length mm not within 3% of 21.5 mm" >&2; status=1; }
    within "$footprint" 7.0 0.05 || { echo "FAIL: $variant: footprint $footprint mm not within 5% of 7.0 mm" >&2; status=1; }
done
[ $status = 0 ] || exit 1
echo "PASS: taylorBarValidation"
