# A study stopped (SIGTERM) after its first variant resumes without rerunning it: the first
# variant's marker and log keep their modification times, the others finish, the table has every
# row. The case gets an Allrun (so this also runs a study through the case's Allrun, with
# RunFunctions found through MFDYN_DIR) in which every level but the coarsest waits for a gate
# file: the stop lands while the second variant runs, however loaded the machine.
. "$(dirname "$0")/common.sh"
c=$(newCase killed)
cat > "$c/Allrun" <<'ALLRUN'
#!/usr/bin/env bash
cd "${0%/*}" || exit 1
. "$MFDYN_DIR/bin/tools/RunFunctions"
runApplication particleGen
case "$PWD" in */h0.01) ;; *) while [ ! -f ../gate ]; do sleep 0.05; done ;; esac
runApplication impactSph
ALLRUN
chmod +x "$c/Allrun"
mfDictionary "$c/system/studyDict" -entry run -set auto > /dev/null
mfStudy -case "$c" > "$c/log.first" 2>&1 &
pid=$!
for _ in $(seq 1 3000); do [ -f "$c/study/h0.01/mfStudy.done" ] && [ -f "$c/study/h0.005/log.particleGen" ] && break; sleep 0.02; done
[ -f "$c/study/h0.005/log.particleGen" ] || { kill -9 $pid; fail "the second variant never started: $(cat "$c/log.first")"; }
grep -q "run by the case's Allrun" "$c/log.first" || fail "the study did not use the Allrun: $(cat "$c/log.first")"
# A second study of the same case while this one runs is refused, naming the holder.
status=0; mfStudy -case "$c" > "$c/log.second" 2>&1 || status=$?
[ "$status" = 1 ] && grep -q "mfStudy" "$c/log.second" && grep -q "$pid" "$c/log.second" ||
    { kill -9 $pid; fail "a second study was not refused (exit $status): $(cat "$c/log.second")"; }
kill -TERM $pid
status=0; wait $pid || status=$?
[ "$status" = 143 ] || fail "stopped study exited $status, expected 143 (128 + SIGTERM): $(cat "$c/log.first")"
grep -q "run mfStudy again to resume" "$c/log.first" || fail "no resume hint: $(cat "$c/log.first")"
[ -f "$c/study/h0.005/mfStudy.done" ] && fail "the variant running at the stop was marked finished"
marker=$(stat -c %y "$c/study/h0.01/mfStudy.done"); log=$(stat -c %y "$c/study/h0.01/log.impactSph")
cpu=$(cat "$c/study/h0.01/mfStudy.done")
# Nothing of the stopped variant outlives the stop: each runs in its own process group, which
# mfStudy stops and waits for.
for p in $(pgrep -x bash || true) $(pgrep -x sleep || true); do
    case "$(readlink "/proc/$p/cwd" 2>/dev/null)" in "$c"/study/*) fail "process $p survived the stop";; esac
done

touch "$c/study/gate"
mfStudy -case "$c" > "$c/log.resumed" 2>&1 || fail "resumed study failed: $(tail "$c/log.resumed")"
grep -q "h0.01: finished before, not rerun" "$c/log.resumed" || fail "h0.01 was not recognised as finished"
grep -q "h0.01: running" "$c/log.resumed" && fail "h0.01 ran again"
[ "$(stat -c %y "$c/study/h0.01/mfStudy.done")" = "$marker" ] || fail "h0.01's marker was rewritten"
[ "$(stat -c %y "$c/study/h0.01/log.impactSph")" = "$log" ] || fail "h0.01's log was rewritten"
[ "$(cat "$c/study/h0.01/mfStudy.done")" = "$cpu" ] || fail "h0.01's recorded CPU time changed"
for v in h0.01 h0.005 h0.0025; do
    [ -f "$c/study/$v/mfStudy.done" ] || fail "$v did not finish after the resume"
    grep -q '^End' "$c/study/$v/log.impactSph" || fail "$v's log has no End"
done
[ "$(grep -c ',finished,' "$c/study/results.csv")" = 3 ] || fail "results.csv: $(cat "$c/study/results.csv")"
ls "$c/study" | grep -q '\.partial$' && fail "a half-made variant directory was left"
pass "stopped while h0.005 ran (exit 143), resumed without rerunning h0.01"
