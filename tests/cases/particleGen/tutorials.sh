# Every particleGenDict shipped (tutorials, test cases, benchmarks) still generates with the
# stricter checks of issue 14 (known field names, counts, finite values), with no warning about
# a misspelt or unread entry. Only particleGen runs, on a copy of each case's system/ and
# constant/; the user-library tutorial is run without its controlDict (its library is built by
# its Allrun, and particleGenDict does not need it).
# $1 = build directory, $2 = source directory.
set -euo pipefail
export PATH="$1/bin:$PATH" OMP_NUM_THREADS=1
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-test.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
count=0
while IFS= read -r dict; do
    src="$(dirname "$(dirname "$dict")")"
    c="$WORK/case$count"
    mkdir -p "$c"
    cp -r "$src/system" "$c/"
    [ -d "$src/constant" ] && cp -r "$src/constant" "$c/"
    case "$src" in */userLibrary/*) rm -f "$c/system/controlDict" ;; esac
    particleGen -case "$c" > "$c/log" 2>&1 || fail "${src#$2/}: $(tail -5 "$c/log")"
    grep -q "Warning" "$c/log" && fail "${src#$2/}: $(grep Warning "$c/log")"
    grep -q "^Wrote [1-9][0-9]* particles" "$c/log" || fail "${src#$2/}: no particles written"
    count=$((count + 1))
done < <(find "$2/tutorials" "$2/tests/cases" "$2/bench" -path '*/system/particleGenDict' | sort)
[ $count -ge 30 ] || fail "only $count particleGenDicts found"
echo "PASS: $count particleGenDicts generate"
