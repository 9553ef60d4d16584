# A solver that does not run on several ranks yet refuses under mpirun before writing anything, with
# one message and status 1 (particleFlight's projectile; fpmSolid, the earlier example, runs
# distributed since fpmEquality.sh).
. "$(dirname "$0")/common.sh"
c="$WORK/projectile"
mkdir -p "$c" && cp -r "$SOURCE/tutorials/particleFlight/projectile/system" "$SOURCE/tutorials/particleFlight/projectile/constant" "$c/"
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail -3 "$c/log.particleGen")"
status=0
RANKS_TIMEOUT=60 onRanks 2 particleFlight -case "$c" > "$c/log" 2>&1 || status=$?
[ "$status" = 1 ] || fail "particleFlight on 2 ranks: status $status, not 1: $(tail -5 "$c/log")"
[ "$(grep -c "particleFlight does not run on several ranks yet" "$c/log")" = 1 ] || fail "particleFlight on 2 ranks: no single refusal: $(grep -m2 Error "$c/log")"
[ ! -e "$c/postProcessing" ] && [ -z "$(cd "$c" && ls -d [1-9]* 0.* 2>/dev/null)" ] || fail "particleFlight on 2 ranks: outputs were written before the refusal"
pass "particleFlight refuses to run on 2 ranks: $(grep -m1 "does not run" "$c/log")"
