# Shared by the framework case tests: $1 = build directory, $2 = this source directory.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export PATH="$BUILD/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-test.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "PASS: $*"; }

# newCase <name>: a fresh copy of freeFall in $WORK/<name>, with particles generated.
newCase() {
    cp -r "$SOURCE/freeFall" "$WORK/$1"
    particleGen -case "$WORK/$1" > "$WORK/$1/log.particleGen" || fail "particleGen failed: $(cat "$WORK/$1/log.particleGen")"
    echo "$WORK/$1"
}

# lastRow <csv> <pattern>: the last line matching pattern.
lastRow() { grep -- "$2" "$1" | tail -n 1; }

# Float comparison a < b.
less() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }

# startLongRun <case>: particleFlight on <case> in the background with an end time far away and
# small steps, returning once its first write (0.25) exists; sets $pid and $latest.
startLongRun() {
    mfDictionary "$1/system/controlDict" -entry endTime -set 1e5 > /dev/null
    mfDictionary "$1/system/controlDict" -entry maxDeltaT -set 1e-4 > /dev/null
    particleFlight -case "$1" > "$1/log" 2>&1 &
    pid=$!
    for _ in $(seq 1 300); do [ -d "$1/0.25" ] && break; sleep 0.1; done
    [ -d "$1/0.25" ] || { kill -9 $pid; fail "run never reached its first write"; }
    latest=$(latestTime "$1")
}

# latestTime <case>: the newest time directory name.
latestTime() { ls "$1" | grep -E '^[0-9.e+-]+$' | sort -g | tail -n 1; }
