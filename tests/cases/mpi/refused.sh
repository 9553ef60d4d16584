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

# A utility under mpirun (here particleGen, which would otherwise write the particles once per
# rank into one case): one message, status 1, nothing written; -help still answers.
g="$WORK/generate"
mkdir -p "$g" && cp -r "$SOURCE/tutorials/mpmFsi/twoDisks/system" "$SOURCE/tutorials/mpmFsi/twoDisks/constant" "$g/"
status=0
RANKS_TIMEOUT=60 onRanks 2 particleGen -case "$g" > "$g/log" 2>&1 || status=$?
[ "$status" = 1 ] || fail "particleGen on 2 ranks: status $status, not 1: $(tail -5 "$g/log")"
[ "$(grep -c "particleGen runs on one process: start it without mpirun" "$g/log")" = 1 ] ||
    fail "particleGen on 2 ranks: no single refusal: $(grep -m2 Error "$g/log")"
[ ! -e "$g/0" ] && [ ! -e "$g/particles.pvd" ] || fail "particleGen on 2 ranks: wrote $(ls "$g")"
RANKS_TIMEOUT=60 onRanks 2 particleGen -help > "$g/log.help" 2>&1 || fail "particleGen -help on 2 ranks: $(tail -3 "$g/log.help")"
pass "particleGen refuses to run on 2 ranks: $(grep -m1 "runs on one process" "$g/log")"
