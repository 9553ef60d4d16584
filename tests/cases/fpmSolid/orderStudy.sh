#!/usr/bin/env bash
# The approximation-order study (doc/methods/fpm.md §4.11, the thesis's §7.2.3 on the rotating
# sphere of §4.8): tutorials/fpmSolid/orderStudy runs the rotating sphere at lattice spacings 1.25,
# 1 and 0.75 (280, 552, 1244 particles; h = 3 spacings each; insertion off) and orderEstimate
# compares them on the grid of spacing 0.5 inside all three bodies in L-infinity (Lemma 7.1).
# The window is 0.1 to 2.7 s: the thesis's is 20 s, but the first-order runs do not hold that long
# here (on 63c9498: the medium run's energy first rises at t = 2.76 and it stops at 4.51, a particle
# out of its neighbours; the coarse one's first rises at 9.58); each run's energy is asserted to fall
# between every two written times over the window, so the orders compare states not yet unstable. Asserted, as the issue writes: the
# time-averaged orders of density and pressure with the linear basis are both above 1 (the thesis:
# "both above 1", "a rough estimate"; expected 1). ORDER=2 (the quadratic basis) is reported by the
# tutorial's README, not asserted.
source "$(dirname "$0")/common.sh"
c="$WORK/orderStudy"
copyTutorial orderStudy "$c"
copyTutorial rotatingSphere "$WORK/rotatingSphere"
(cd "$c" && MFDYN_DIR="$SOURCE" END=2.7 ./Allrun > log.Allrun 2>&1) || fail "the study failed: $(tail -20 "$c/log.Allrun")"
for run in coarse medium fine; do
    q="$c/runs/$run/postProcessing/budget/0/conservedQuantities.csv"
    [ -f "$q" ] || fail "$run: no conservedQuantities output"
    energyFalls "$q" "$run: "
done
summary="$c/postProcessing/orderEstimate/summary.txt"
[ -f "$summary" ] || fail "no orderEstimate summary"
cat "$summary"
for field in density pressure; do
    mean=$(awk -v f="$field" '$1 == f { print $2 }' "$summary")
    [ -n "$mean" ] || fail "no $field row in the summary"
    awk -v m="$mean" 'BEGIN { exit !(m > 1) }' || fail "the time-averaged order of $field is $mean, not above 1"
done
exit 0
