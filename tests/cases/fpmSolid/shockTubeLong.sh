#!/usr/bin/env bash
# R8's last point (doc/methods/fpm.md §4b): the thesis's shock tube (tutorial shockTube, §4.1) runs to
# 10.5 s without breakdown: through the shock's reflection at the right wall (t = 3.93, the exact
# reflected pressure 18.96) and the rarefaction's at the left (t = 2.67), every particle pressure
# inside instabilityCheck's (-5, 30) (the run stops with "instability detected" otherwise) and
# finite. About 6 minutes on one thread: the validation label.
source "$(dirname "$0")/common.sh"
c="$WORK/shockTube"
copyTutorial shockTube "$c"
grep -q "^endTime *10.5;" "$c/system/controlDict" || fail "the tutorial no longer ends at 10.5 s"
run "$c" particleGen
run "$c" fpmSolid
[ -f "$c/10.5/particles.vtp" ] || fail "no 10.5/particles.vtp"
read -r lo hi < <(awk -F, 'NR > 1 { if (n == 0 || $2 < lo) lo = $2; if (n == 0 || $4 > hi) hi = $4; n++ } END { print lo, hi }' "$c/postProcessing/range/0/fieldMinMax.csv")
echo "R8: reached 10.5 s; particle pressures over the run in [$lo, $hi]"
awk -v a="$lo" -v b="$hi" 'BEGIN { exit !(a > -5 && b < 30) }' || fail "R8: pressures [$lo, $hi] outside (-5, 30)"
echo "PASS: the shock tube to 10.5 s"
