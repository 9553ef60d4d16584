# A solver that does not run on several ranks yet refuses under mpirun before writing anything, with
# one message and status 1 (fpmSolid's oscillating plate).
. "$(dirname "$0")/common.sh"
c="$WORK/plate"
mkdir -p "$c" && cp -r "$SOURCE/tutorials/fpmSolid/oscillatingPlate/system" "$SOURCE/tutorials/fpmSolid/oscillatingPlate/constant" "$c/"
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail -3 "$c/log.particleGen")"
status=0
RANKS_TIMEOUT=60 onRanks 2 fpmSolid -case "$c" > "$c/log" 2>&1 || status=$?
[ "$status" = 1 ] || fail "fpmSolid on 2 ranks: status $status, not 1: $(tail -5 "$c/log")"
[ "$(grep -c "fpmSolid does not run on several ranks yet" "$c/log")" = 1 ] || fail "fpmSolid on 2 ranks: no single refusal: $(grep -m2 Error "$c/log")"
[ ! -e "$c/postProcessing" ] && [ -z "$(cd "$c" && ls -d [1-9]* 0.* 2>/dev/null)" ] || fail "fpmSolid on 2 ranks: outputs were written before the refusal"
pass "fpmSolid refuses to run on 2 ranks: $(grep -m1 "does not run" "$c/log")"
