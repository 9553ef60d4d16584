# Shared by the mpmFsi case scripts: $1 = build directory, $2 = source root.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export PATH="$BUILD/bin:$PATH"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-mpm.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
less() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }
# within <value> <reference> <relative tolerance>: |value - reference| <= tol |reference|
within() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; r = b < 0 ? -b : b; exit !(d <= t * r) }'; }
# copyTutorial <name> <destination>: a clean copy of tutorials/mpmFsi/<name>.
copyTutorial() {
    cp -r "$SOURCE/tutorials/mpmFsi/$1" "$2"
    rm -rf "$2"/log.* "$2"/postProcessing "$2"/[0-9]* "$2"/*.png "$2"/particles.pvd "$2"/*.dat
}
# setEntry <dictionary> <scoped entry> <value>
setEntry() { mfDictionary "$1" -entry "$2" -set "$3" > /dev/null || fail "could not set $2 in $1"; }
# run <case> <application>: runs it with its log in the case.
run() {
    "$2" -case "$1" > "$1/log.$2" 2>&1 || fail "$2 on $1: $(tail -n 20 "$1/log.$2")"
}
# column <csv> <name>: the column's values, one per line.
column() {
    awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) k = i; if (!k) exit 1; next } { print $k }' "$1"
}
