# particles.pvd is read once, at the start, and rewritten from memory at each write: re-reading
# it at every write made a long run's writing quadratic in its number of writes. Seen from
# outside: an index spoilt during the run (here overwritten with garbage after the first write)
# is rewritten whole at the next write instead of ending the run.
. "$(dirname "$0")/common.sh"
c=$(newCase pvd)
startLongRun "$c"
echo "not a pvd file" > "$c/particles.pvd"
for _ in $(seq 1 300); do [ -d "$c/0.5" ] && break; kill -0 $pid 2>/dev/null || break; sleep 0.1; done
kill -INT $pid 2>/dev/null || true
status=0; wait $pid || status=$?
[ $status -eq 130 ] || fail "exit status $status, expected 130 (stopped by SIGINT): $(tail -5 "$c/log")"
[ -d "$c/0.5" ] || fail "the run never wrote 0.5"
for t in 0 0.25 0.5; do
    grep -q "file=\"$t/particles.vtp\"" "$c/particles.pvd" || fail "particles.pvd lacks $t: $(cat "$c/particles.pvd")"
done
pass "particles.pvd is kept in memory and rewritten whole"
