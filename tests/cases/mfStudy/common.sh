# Shared by the mfStudy tests: $1 = build directory, $2 = this source directory.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export PATH="$BUILD/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-mfStudy.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "PASS: $*"; }

# newCase <name>: a fresh copy of the Sod fixture in $WORK/<name> (no particles: the study makes them).
newCase() {
    cp -r "$SOURCE/sod" "$WORK/$1"
    echo "$WORK/$1"
}

# column <csv> <header name>: the 1-based index of a column.
column() { head -n 1 "$1" | tr ',' '\n' | grep -nxF -- "$2" | cut -d: -f1; }

# field <csv> <variant> <header name>: one cell (the fixture's cells hold no commas before the diagnosis).
field() { awk -F, -v v="$2" -v c="$(column "$1" "$3")" '$1 == v { print $c }' "$1"; }

# near <a> <b> <relative tolerance>
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; s = b < 0 ? -b : b; exit !(d <= t * s) }'; }
positive() { awk -v a="$1" 'BEGIN { exit !(a + 0 > 0) }'; }
