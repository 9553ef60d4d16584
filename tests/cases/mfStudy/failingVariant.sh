# Variants that fail are rows with their diagnosis (the first error line of their logs), and the
# study goes on: one with an unknown kernel (an input error of the solver), one whose constant
# step is five times the stable one (a run error), and one that works.
. "$(dirname "$0")/common.sh"
c=$(newCase failing)
cat > "$c/system/studyDict" <<'DICT'
run application;
error riemann/density/L1;
variants
{
    noKernel { constant/sphProperties/kernel/type noSuchKernel; }
    unstable { system/controlDict/deltaT 1e-3; }
    good     { system/controlDict/deltaT 2e-4; }
}
DICT
mfStudy -case "$c" > "$c/log.mfStudy" 2>&1 || fail "mfStudy failed: $(cat "$c/log.mfStudy")"
csv="$c/study/results.csv"
grep -q "^noKernel,.*,failed,.*unknown kernel type 'noSuchKernel'" "$csv" || fail "noKernel row: $(cat "$csv")"
grep -q "^unstable,.*,failed,.*exceeds the stable time step" "$csv" || fail "unstable row: $(cat "$csv")"
grep -q "^good,.*,finished," "$csv" || fail "good row: $(cat "$csv")"
positive "$(field "$csv" good riemann/density/L1)" || fail "good has no error norm"
# The good variant sets the fixture's own step: its norm is that of the fixture run by hand, to the
# digit (a deterministic solver on one thread), so the copy changed nothing else.
d=$(newCase byHand)
(cd "$d" && particleGen -case . > log.particleGen 2>&1 && impactSph -case . > log.impactSph 2>&1) || fail "the fixture fails by hand"
byHand=$(grep ',riemann/density,' "$d/postProcessing/runSummary/0/runSummary.csv" | cut -d, -f3)
[ "$(field "$csv" good riemann/density/L1)" = "$byHand" ] || fail "good L1 $(field "$csv" good riemann/density/L1), by hand $byHand"
grep -q "| noKernel |.*| failed |.*unknown kernel type" "$c/study/results.md" || fail "results.md lacks the diagnosis"
grep -q "2 of 3 variants failed" "$c/log.mfStudy" || fail "no count of failures: $(cat "$c/log.mfStudy")"
[ -f "$c/study/noKernel/mfStudy.done" ] && fail "a failed variant was marked finished"
# A run that finished its summary (its "Error norms" line) and then failed, here an Allrun that
# exits 3 after the solver: the diagnosis is the exit status and the runner's last words, not the
# summary's "Error norms (bought with ...)" line, which only looks like an error message.
e=$(newCase afterSummary)
printf '%s\n' 'particleGen -case . > log.particleGen 2>&1 && impactSph -case . > log.impactSph 2>&1' \
    'echo "post-processing failed"' 'exit 3' > "$e/Allrun"
cat > "$e/system/studyDict" <<'DICT'
run allrun;
variants { late { system/controlDict/deltaT 2e-4; } }
DICT
mfStudy -case "$e" > "$e/log.mfStudy" 2>&1 || fail "mfStudy failed: $(cat "$e/log.mfStudy")"
grep -q "^late,.*,failed,.*\"exit status 3: post-processing failed\"" "$e/study/results.csv" ||
    fail "late row: $(grep '^late,' "$e/study/results.csv")"
pass "failing variants reported with their diagnoses; the study went on"
