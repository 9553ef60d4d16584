# Shared by the distributed-run scripts (issue 21): $1 = build directory, $2 = source root,
# $3 = the MPI launcher (CMake's MPIEXEC_EXECUTABLE).
set -euo pipefail
BUILD="$1"
SOURCE="$2"
MPIEXEC="$3"
export PATH="$BUILD/bin:$PATH"
export MFDYN_LIBRARY_PATH="$BUILD/testLibraries"
export OMP_NUM_THREADS=1
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-mpi.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "PASS: $*"; }

# onRanks <n> <application> <args...>: the application on n ranks (more ranks than the 2 cores
# of CI: --oversubscribe; root in a container: --allow-run-as-root), its status returned; after
# $RANKS_TIMEOUT seconds (default 300) it is stopped with status 124: a hang.
onRanks() {
    local n="$1"
    shift
    local root=()
    [ "$(id -u)" = 0 ] && root=(--allow-run-as-root)
    timeout "${RANKS_TIMEOUT:-300}" "$MPIEXEC" "${root[@]}" --oversubscribe -x OMP_NUM_THREADS -x MFDYN_LIBRARY_PATH \
        -x PATH -np "$n" "$@"
}

# sodCase <name> <endTime>: Sod's tube (tutorials/impactSph/sodShockTube, 900 particles in 1D).
sodCase() {
    local c="$WORK/$1"
    mkdir -p "$c" && cp -r "$SOURCE/tutorials/impactSph/sodShockTube/system" \
        "$SOURCE/tutorials/impactSph/sodShockTube/constant" "$c/"
    mfDictionary "$c/system/controlDict" -entry endTime -set "$2" > /dev/null
    particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail -3 "$c/log.particleGen")"
    echo "$c"
}

# hviCase <name> <endTime>: the Al-Al hypervelocity impact at a 0.5 mm lattice (1803 particles, 2D,
# Mie-Grüneisen with von Mises strength and plastic strain).
hviCase() {
    local c="$WORK/$1"
    mkdir -p "$c" && cp -r "$SOURCE/tutorials/impactSph/hviAlAl/system" "$SOURCE/tutorials/impactSph/hviAlAl/constant" "$c/"
    for region in projectile plate; do
        mfDictionary "$c/system/particleGenDict" -entry regions/$region/lattice/spacing -set 5e-4 > /dev/null
    done
    mfDictionary "$c/system/controlDict" -entry endTime -set "$2" > /dev/null
    mfDictionary "$c/system/controlDict" -entry writeInterval -set "$2" > /dev/null
    particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail -3 "$c/log.particleGen")"
    echo "$c"
}

# copyCase <from> <to>: the case with its initial time only.
copyCase() {
    mkdir -p "$2" && cp -r "$1/system" "$1/constant" "$1/0" "$2/"
    echo "$2"
}

# sameState <name> <a> <b>: particleCompare's verdict at 1e-12, its table kept in the test's output.
sameState() {
    local out
    out=$(particleCompare "$2" "$3" -tolerance 1e-12 2>&1) || fail "$1: the states differ:
$out"
    echo "$1:"
    echo "$out" | sed 's/^/    /'
}

# The log's boundary-condition lines ("wall: symmetryPlane on all particles, 4212 particles"):
# their counts are over every rank.
conditionLines() { grep -E "^[^ ]+: [A-Za-z]+ on .*[0-9]+ particles" "$1" || true; }

# againstSerial <application> <case> <report> <ranks...>: the case run serially (copy
# <name>.serial) and on each number of ranks (copies <name>.<n>), each distributed log holding
# <report> (the decomposition's) and the serial run's boundary-condition lines, each final state
# the serial one (sameState).
againstSerial() {
    local app="$1" c="$2" report="$3" name serial d n
    shift 3
    name=$(basename "$c")
    serial=$(copyCase "$c" "$WORK/$name.serial")
    "$app" -case "$serial" > "$serial/log.$app" 2>&1 || fail "$name serially: $(tail -5 "$serial/log.$app")"
    for n in "$@"; do
        d=$(copyCase "$c" "$WORK/$name.$n")
        onRanks "$n" "$app" -case "$d" > "$d/log.$app" 2>&1 || fail "$name on $n ranks: $(tail -5 "$d/log.$app")"
        grep -q "$report" "$d/log.$app" || fail "$name on $n ranks: no '$report' in the log"
        [ "$(conditionLines "$d/log.$app")" = "$(conditionLines "$serial/log.$app")" ] ||
            fail "$name on $n ranks: boundary conditions $(conditionLines "$d/log.$app"), serially $(conditionLines "$serial/log.$app")"
        sameState "$name on $n ranks against the serial run" "$(latest "$serial")" "$(latest "$d")"
    done
}

# latest <case>: its latest time directory.
latest() {
    local t
    t=$(cd "$1" && ls -d [0-9]* 2>/dev/null | grep -E '^[0-9.e+-]+$' | sort -g | tail -n 1)
    [ -n "$t" ] || fail "no time directory in $1"
    echo "$1/$t"
}

# inBackground <case> <n>: impactSph on n ranks in the background (log in <case>/log), its exit
# status written to <case>/status when it ends. (set -e holds in the subshell too: the status is
# caught, or the subshell would end at the failure without writing it.)
inBackground() {
    (
        code=0
        RANKS_TIMEOUT=120 onRanks "$2" impactSph -case "$1" > "$1/log" 2>&1 || code=$?
        echo $code > "$1/status"
    ) &
}
