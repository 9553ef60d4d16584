# Shared by the impactSph case tests: $1 = build directory, $2 = this source directory.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
TUTORIALS="$(cd "$SOURCE/../../../tutorials/impactSph" && pwd)"
export PATH="$BUILD/bin:$PATH"
# One thread: the runs are small (a few hundred to two thousand particles), a second thread buys
# little there and makes run times erratic when ctest runs tests side by side.
export OMP_NUM_THREADS=1
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-test.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "PASS: $*"; }

# newCase <source case> <name>: a copy of the case's system/ and constant/ in $WORK/<name>.
newCase() {
    mkdir -p "$WORK/$2"
    cp -r "$1/system" "$1/constant" "$WORK/$2/"
    echo "$WORK/$2"
}

# runCase <case>: particleGen then impactSph, logs in the case; prints the wall time in seconds.
runCase() {
    particleGen -case "$1" > "$1/log.particleGen" 2>&1 || fail "particleGen failed on $1: $(tail "$1/log.particleGen")"
    impactSph -case "$1" > "$1/log.impactSph" 2>&1 || fail "impactSph failed on $1: $(tail -n 20 "$1/log.impactSph")"
    awk '/^ *wall time/ { print $3; exit }' "$1/log.impactSph"
}

# setEntry <dictionary> <scoped entry> <value>
setEntry() { mfDictionary "$1" -entry "$2" -set "$3" > /dev/null || fail "could not set $2 in $1"; }

# column <csv> <header name>: that column of the last row.
column() {
    awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i; next }
                          { v = $c } END { if (!c) exit 1; print v }' "$1" || fail "$1 has no column $2"
}

# lastRow <csv> <pattern>: the last line matching pattern.
lastRow() { grep -- "$2" "$1" | tail -n 1; }

# Float comparison a < b; relErr a b = |a - b|/|b|.
less() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }
relErr() { awk -v a="$1" -v b="$2" 'BEGIN { d = (a - b) / b; if (d < 0) d = -d; printf "%.4g", d }'; }

# runTutorial <name>: a copy of tutorials/impactSph/<name> run by its own Allrun (which finds
# bin/tools/RunFunctions three levels up and the applications in $MFDYN_BUILD); prints its path.
runTutorial() {
    local dest="$WORK/tutorials/impactSph/$1"
    mkdir -p "$WORK/tutorials/impactSph"
    [ -e "$WORK/bin" ] || ln -s "$SOURCE/../../../bin" "$WORK/bin"
    cp -r "$TUTORIALS/$1" "$dest"
    (cd "$dest" && ./Allclean > /dev/null 2>&1 || true)
    MFDYN_BUILD="$BUILD" "$dest/Allrun" > "$dest/log.Allrun" 2>&1 || fail "$1/Allrun failed: $(tail -n 20 "$dest/log.Allrun")"
    echo "$dest"
}

# sameOutline <case a> <case b> <relative tolerance> <name a> <name b>: the outline function
# object's rim x_max, y_max, top z_max and lowest z_min of the two runs (last row) agree.
sameOutline() {
    local csv=postProcessing/outline/0/fieldMinMax.csv q a b
    for q in position_x_max position_y_max position_z_max position_z_min; do
        a=$(column "$1/$csv" "$q")
        b=$(column "$2/$csv" "$q")
        less "$(relErr "$a" "$b")" "$3" || fail "$q: $4 $a, $5 $b (relative difference $(relErr "$a" "$b"))"
    done
}

# finalEnergy <case>: the conservedQuantities totalEnergy of the last row, 15 digits.
finalEnergy() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "totalEnergy") c = i; next } { e = $c } END { printf "%.15g", e }' \
        "$1/postProcessing/conserved/0/conservedQuantities.csv"
}
