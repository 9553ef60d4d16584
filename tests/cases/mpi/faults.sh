# Distributed runs that must stop, every one with a clear message and status 1, never a hang (each
# mpirun has a timeout well under CTest's): a misspelt partitioner, fewer particles than ranks, a
# solver that does not run on several ranks yet, a NaN planted on one rank (the diagnosis is made
# through a global reduction: every rank stops with the same words, the failing state is written),
# and a rank killed outright (mpirun ends the job within seconds).
. "$(dirname "$0")/common.sh"
base=$(sodCase base 0.01)

# expectStop <name> <case> <ranks> <text>: status 1 within 60 s, the text in the log once.
expectStop() {
    local status=0
    RANKS_TIMEOUT=60 onRanks $3 impactSph -case "$2" > "$2/log" 2>&1 || status=$?
    [ "$status" != 124 ] || fail "$1: still running after 60 s (a hang)"
    [ "$status" = 1 ] || fail "$1: exit status $status, not 1: $(tail -5 "$2/log")"
    local count
    count=$(grep -c -- "$4" "$2/log" || true)
    [ "$count" = 1 ] || fail "$1: '$4' appears $count times in the log, not once (every rank the same message, printed by rank 0): $(grep -m3 Error "$2/log")"
    echo "$1: $(grep -m1 -- "$4" "$2/log")"
}

c=$(copyCase "$base" "$WORK/method")
printf 'method rcbb;\n' > "$c/system/decomposeParDict"
expectStop "misspelt method" "$c" 2 "decomposeParDict:1:1: keyword 'method': unknown partitioning method 'rcbb'; valid methods: rcb, hsfc"
[ ! -e "$c/postProcessing" ] || fail "misspelt method: outputs were written"

c="$WORK/few"
mkdir -p "$c" && cp -r "$base/system" "$base/constant" "$c/"
cat > "$c/system/particleGenDict" << 'DICT'
dimension 1;
regions { gas { shape { type box; min (0); max (0.2); } lattice { type cubic; spacing 0.1; } density 1; material gas; fields { pressure 1; velocity (0); } } }
DICT
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen (2 particles)"
expectStop "fewer particles than ranks" "$c" 3 "holds 2 particles, fewer than the 3 ranks of this run: the domain cannot be split"

c=$(copyCase "$base" "$WORK/nan")
sed -i '/^functions/,$d' "$c/system/controlDict"
cat >> "$c/system/controlDict" << 'DICT'
libs ("libplantFault.so");
functions
{
    plant  { type plantFault; time 0.005; particle 800; field velocity; component 0; value nan; }
    health { type health; }
}
DICT
# Particle 800 is on the right of the diaphragm: rank 1's on 2 ranks.
expectStop "NaN on one rank" "$c" 2 "non-finite values: particle 800 at"
grep -q "Wrote the failing state to" "$c/log" || fail "NaN on one rank: the failing state was not written"

# A rank killed: the job ends within seconds (mpirun ends the others), status not 0.
c=$(hviCase killed 200e-6)
inBackground "$c" 2
for _ in $(seq 1 100); do grep -q "^Step " "$c/log" 2>/dev/null && break; sleep 0.1; done
victim=$(pgrep -f "^impactSph -case $c" | tail -n 1)  # a rank, not mpirun or timeout
[ -n "$victim" ] || fail "killed rank: no rank running"
killedAt=$(date +%s.%N)
kill -9 "$victim"
for _ in $(seq 1 300); do [ -f "$c/status" ] && break; sleep 0.1; done
[ -f "$c/status" ] || fail "killed rank: the job still runs 30 s after a rank was killed"
ended=$(awk -v a="$killedAt" -v b="$(date +%s.%N)" 'BEGIN{printf "%.1f", b - a}')
[ "$(cat "$c/status")" != 0 ] || fail "killed rank: exit status 0"
[ "$(cat "$c/status")" != 124 ] || fail "killed rank: a hang (timeout)"
echo "killed rank: the job ended $ended s after the kill, status $(cat "$c/status")"
pass "distributed faults end every rank with one message and status 1"
