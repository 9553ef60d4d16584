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

# sodCase <name>: a copy of tutorials/impactSph/sodShockTube (γ = 1.4, N ≈ 450 on [0, 1]).
sodCase() {
    local c="$WORK/$1"
    mkdir -p "$c" && cp -r "$TUTORIALS/sodShockTube/system" "$TUTORIALS/sodShockTube/constant" "$c/"
    echo "$c"
}

# checkSod <case> <label>: run it and hold it to the Sod bounds of the issue: L1(ρ) on [0, 1] below
# 1.5e-2, star pressure and velocity within 2% of the exact values, energy drift below 1e-4.
checkSod() {
    local c="$1" label="$2"
    particleGen -case "$c" > /dev/null 2>&1 || fail "particleGen failed"
    impactSph -case "$c" > "$c/log" 2>&1 || fail "impactSph failed: $(tail -5 "$c/log")"
    local l1 row t p pe u ue energy
    l1=$(grep ",density," "$c/postProcessing/riemann/0/errorNorms.csv" | tail -n 1 | cut -d, -f3)
    less "$l1" 1.5e-2 || fail "L1(rho) $l1"
    row=$(tail -n 1 "$c/postProcessing/riemann/0/starState.csv")
    IFS=, read -r t p pe u ue <<< "$row"
    less "$(abs "$(awk -v a="$p" -v b="$pe" 'BEGIN { print (a - b) / b }')")" 0.02 || fail "P* $p vs $pe"
    less "$(abs "$(awk -v a="$u" -v b="$ue" 'BEGIN { print (a - b) / b }')")" 0.02 || fail "u* $u vs $ue"
    energy=$(drift "$c/log" totalEnergy)
    less "$(abs "$energy")" 1e-4 || fail "energy drift $energy"
    pass "$label: L1(rho) $l1, P* $p ($pe), u* $u ($ue), energy drift $energy"
}
