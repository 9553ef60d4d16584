# Shared by the tlSph case scripts: $1 = build directory, $2 = source root.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export PATH="$BUILD/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-tlsph.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# copyTutorial <name> <destination>: a clean copy of tutorials/tlSph/<name>.
copyTutorial() {
    cp -r "$SOURCE/tutorials/tlSph/$1" "$2"
    rm -rf "$2"/log.* "$2"/postProcessing "$2"/[0-9]* "$2"/*.png "$2"/particles.pvd
}
# run <case> <application>: runs it with its log in the case.
run() {
    "$2" -case "$1" > "$1/log.$2" 2>&1 || fail "$2 on $1: $(tail -n 20 "$1/log.$2")"
}
# column <csv> <name>: the column's values, one per line.
column() {
    awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) k = i; if (!k) exit 1; next } { print $k }' "$1"
}
