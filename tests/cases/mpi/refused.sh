# A solver that does not run on several ranks yet refuses under mpirun before writing anything, with
# one message and status 1 (tlSph's swinging cube).
. "$(dirname "$0")/common.sh"
c="$WORK/cube"
mkdir -p "$c" && cp -r "$SOURCE/tutorials/tlSph/swingingCube/system" "$SOURCE/tutorials/tlSph/swingingCube/constant" "$c/"
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail -3 "$c/log.particleGen")"
status=0
RANKS_TIMEOUT=60 onRanks 2 tlSph -case "$c" > "$c/log" 2>&1 || status=$?
[ "$status" = 1 ] || fail "tlSph on 2 ranks: status $status, not 1: $(tail -5 "$c/log")"
[ "$(grep -c "tlSph does not run on several ranks yet" "$c/log")" = 1 ] || fail "tlSph on 2 ranks: no single refusal: $(grep -m2 Error "$c/log")"
[ ! -e "$c/postProcessing" ] && [ -z "$(cd "$c" && ls -d [1-9]* 0.* 2>/dev/null)" ] || fail "tlSph on 2 ranks: outputs were written before the refusal"
pass "tlSph refuses to run on 2 ranks: $(grep -m1 "does not run" "$c/log")"
