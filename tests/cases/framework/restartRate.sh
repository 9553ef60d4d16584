# After a restart the Summary's steps and particle-steps/s count the steps this run took, not
# every step since t = 0: a run to 0.75, restarted to 1.0, must report particles * M / loop time
# with M its own steps (about 0.58 of the total here, so the old figure was 1.7 times too high).
. "$(dirname "$0")/common.sh"
c=$(newCase rate)
mfDictionary "$c/system/controlDict" -entry endTime -set 0.75 > /dev/null || fail "mfDictionary -set failed"
particleFlight -case "$c" > "$c/log1" 2>&1 || fail "first run failed: $(tail "$c/log1")"
mfDictionary "$c/system/controlDict" -entry endTime -set 1.0 > /dev/null
particleFlight -case "$c" > "$c/log2" 2>&1 || fail "restart failed: $(tail "$c/log2")"
k=$(sed -n 's/^Restarting from time 0.75 (step \([0-9]*\))$/\1/p' "$c/log2")
[ -n "$k" ] || fail "the restart did not say 'Restarting from time 0.75 (step N)': $(grep -m1 -i start "$c/log2")"
# Summary lines:  "    steps                M to t = 1 (from step K)", "    particles            n",
# "    wall time ... time loop L s, ...", "    particle-steps/s     R (p threads)".
# M from runSummary.csv (its steps column counted this run's steps before the Summary did).
m=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "steps") c = i; next } { v = $c } END { print v }' \
    "$c/postProcessing/runSummary/0.75/runSummary.csv")
n=$(awk '/^    particles  / { print $2 }' "$c/log2")
loop=$(sed -n 's/.*time loop \([0-9.e+-]*\) s,.*/\1/p' "$c/log2")
rate=$(awk '/^    particle-steps\/s/ { print $2 }' "$c/log2")
[ -n "$m" ] && [ -n "$n" ] && [ -n "$loop" ] && [ -n "$rate" ] ||
    fail "could not read the Summary (particles '$n', loop '$loop', rate '$rate') or the CSV's steps '$m': $(grep -A8 '^Summary' "$c/log2")"
[ "$m" -gt 0 ] || fail "the restart took no steps"
# The loop time is printed to 3 significant digits, the rate to 4: 1% covers both roundings.
awk -v r="$rate" -v n="$n" -v m="$m" -v l="$loop" 'BEGIN { e = r / (n * m / l) - 1; exit !(e < 0.01 && e > -0.01) }' ||
    fail "particle-steps/s $rate is not particles $n * steps $m / loop $loop s = $(awk -v n="$n" -v m="$m" -v l="$loop" 'BEGIN { print n * m / l }') (counting the $k steps before the restart too: $(awk -v n="$n" -v t="$((k + m))" -v l="$loop" 'BEGIN { print n * t / l }'))"
# The steps line: this run's steps, and where they ended.
grep -q "^    steps                $m to t = 1 (from step $k)$" "$c/log2" ||
    fail "the Summary's steps line is not '$m to t = 1 (from step $k)': $(grep '^    steps' "$c/log2")"
pass "after a restart from step $k, $m steps: $rate particle-steps/s = $n * $m / $loop s"
