# The solver summary's error lines (issue 16 item 4: "the summary states the error reached and the
# CPU time it took"), which mfStudy reads: one per norm and per compared value, in the fixed form
#     error <name>  <value> (exact <x>, relative <r>) at CPU <s> s, step <n>, t = <t>
# under a heading with the process CPU time at the end of the run. Checked on impactSph (the
# Sod fixture: riemannError's norms and star state) and tlSph (the swinging cube at 5^3): every
# line parses; a norm's relative error is its value over the exact norm, a value's is
# (value - exact)/|exact|; the values are those of errorNorms.csv and starState.csv; the step is
# the run's last, the CPU time positive and not beyond the heading's.
. "$(dirname "$0")/common.sh"
check() {  # check <log> <steps>: every error line well formed and consistent
    local log="$1" steps="$2"
    local total
    total=$(sed -n 's/^Compared with the reference (process CPU time at the end of the run \([^ ]*\) s):$/\1/p' "$log")
    positive "$total" || fail "$log: no heading with the CPU time: $(tail -n 30 "$log")"
    awk -v total="$total" -v steps="$steps" '
        /^    error / {
            n++
            if (!match($0, /^    error [^ ]+  [^ ]+ \(exact [^,]+, relative [^)]+\) at CPU [^ ]+ s, step [0-9]+, t = [^ ]+$/)) { print "malformed: " $0; bad = 1; next }
            name = $2; value = $3; exact = $5; sub(/,$/, "", exact); rel = $7; sub(/\)$/, "", rel); cpu = $10; step = $13; sub(/,$/, "", step)
            if (name ~ /\/(L1|L2|Linf)$/) want = value / exact; else want = (value - exact) / (exact < 0 ? -exact : exact)
            d = rel - want; if (d < 0) d = -d; s = want < 0 ? -want : want
            if (d > 1e-5 * s + 1e-12) { print "relative " rel " but expected " want ": " $0; bad = 1 }
            if (step != steps) { print "step " step ", the run took " steps ": " $0; bad = 1 }
            if (!(cpu > 0 && cpu <= total)) { print "CPU " cpu " not in (0, " total "]: " $0; bad = 1 }
        }
        END { if (n == 0) { print "no error lines"; bad = 1 } exit bad }' "$log" || fail "$log: the error lines above"
}

c="$WORK/sod"
newCase sod > /dev/null
(cd "$c" && particleGen -case . > log.particleGen 2>&1 && impactSph -case . > log.impactSph 2>&1) || fail "impactSph: $(tail "$c/log.impactSph")"
check "$c/log.impactSph" 1000
# The values are the function object's own: the norm of errorNorms.csv, the star pressure of starState.csv.
l1=$(awk -F, '$2 == "density" { v = $3 } END { print v }' "$c/postProcessing/riemann/0/errorNorms.csv")
printed=$(awk '$2 == "riemann/density/L1" { print $3 }' "$c/log.impactSph")
near "$printed" "$l1" 1e-9 || fail "density L1: summary $printed, errorNorms.csv $l1"
grep -q '^    error riemann/starPressure  [^ ]* (exact 0.303130178, relative ' "$c/log.impactSph" ||
    fail "no star pressure against Sod's exact 0.303130178: $(grep '^    error' "$c/log.impactSph")"
pStar=$(tail -n 1 "$c/postProcessing/riemann/0/starState.csv" | cut -d, -f2)
near "$(awk '$2 == "riemann/starPressure" { print $3 }' "$c/log.impactSph")" "$pStar" 1e-9 || fail "star pressure is not starState.csv's $pStar"

s="$WORK/cube"
cp -r "$SOURCE/../../../tutorials/tlSph/swingingCube" "$s"
sed -i 's/points (9 9 9)/points (5 5 5)/' "$s/system/particleGenDict"
(cd "$s" && particleGen -case . > log.particleGen 2>&1 && tlSph -case . > log.tlSph 2>&1) || fail "tlSph: $(tail "$s/log.tlSph")"
steps=$(awk '$1 == "steps" { print $2 }' "$s/log.tlSph")
check "$s/log.tlSph" "$steps"
for f in momentum firstPiolaStress; do
    csvL2=$(awk -F, -v f=$f '$2 == f { v = $4 } END { print v }' "$s/postProcessing/swingingCube/0/errorNorms.csv")
    logL2=$(awk -v n="swingingCube/$f/L2" '$2 == n { print $3 }' "$s/log.tlSph")
    near "$logL2" "$csvL2" 1e-9 || fail "$f L2: summary $logL2, errorNorms.csv $csvL2"
    # The exact field is not small: the relative error of a 5^3 cube is a few per cent, not 1e-9 or 1e3.
    rel=$(awk -v n="swingingCube/$f/L2" '$2 == n { r = $7; sub(/\)$/, "", r); print r }' "$s/log.tlSph")
    awk -v r="$rel" 'BEGIN { exit !(r > 0.005 && r < 0.5) }' || fail "$f: relative L2 error $rel outside (0.5%, 50%)"
done
pass "summary error lines: impactSph $(grep -c '^    error' "$c/log.impactSph"), tlSph $(grep -c '^    error' "$s/log.tlSph"), each consistent"
