# Shared by the impact case tests: $1 = build directory, $2 = this source directory.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
TUTORIALS="$SOURCE/../../../tutorials/impactSph"
export PATH="$BUILD/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-hvi.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "PASS: $*"; }
less() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }
abs() { awk -v a="$1" 'BEGIN { print (a < 0 ? -a : a) }'; }

# coarseCase <tutorial> <spacing>: a copy of the tutorial at a coarser lattice, particles generated.
coarseCase() {
    local c="$WORK/$1"
    mkdir -p "$c" && cp -r "$TUTORIALS/$1/system" "$TUTORIALS/$1/constant" "$c/"
    for region in projectile plate; do
        mfDictionary "$c/system/particleGenDict" -entry regions/$region/lattice/spacing -set "$2" > /dev/null
    done
    particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail "$c/log.particleGen")"
    echo "$c"
}

# drift <log> <quantity>: the relative drift the summary reports for totalEnergy / mass.
drift() { grep "$2 drift" "$1" | awk '{print $4}'; }
