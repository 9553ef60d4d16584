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
