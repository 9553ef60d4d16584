# The studies shipped with the tutorials of issue 16 item 2 (beside Sod's, shippedStudy.sh) are
# valid against their tutorials: -list checks every entry path and value and writes nothing, and
# the levels set the lattices the READMEs' tables give (the resolution rules of studyDict).
. "$(dirname "$0")/common.sh"
tutorials="$(cd "$SOURCE/../../../tutorials" && pwd)"
check() {  # check <tutorial> <variants> <text the list must hold>...
    local name="$1" t="$tutorials/$1" n="$2" before
    shift 2
    before=$(ls -A "$t" | sort | tr '\n' ' ')
    mfStudy -case "$t" -list > "$WORK/list" 2>&1 || fail "$t: the shipped studyDict is not valid: $(cat "$WORK/list")"
    [ "$(ls -A "$t" | sort | tr '\n' ' ')" = "$before" ] || fail "$t: -list wrote into the tutorial"
    grep -q "^mfStudy: $n variants" "$WORK/list" || fail "$t: expected $n variants: $(head -n 1 "$WORK/list")"
    for text in "$@"; do grep -qF -- "$text" "$WORK/list" || fail "$t: no '$text' in: $(cat "$WORK/list")"; done
    echo "$name: $n variants"
}
check tlSph/swingingCube 12 "lagrangeMultiplier_formulation-pFJ_h0.03125" "lattice/points (33 33 33)" \
    "essentialBoundaryConditions lagrangeMultiplier"
check tlSph/cable 3 "lattice/points (151 4 4)" "lattice/points (201 5 5)"
check tlSph/twistingColumn 5 "lattice/points (4 19 4)" "lattice/points (13 73 13)"
check tlSph/oscillatingPlate 6 "pFJ_h0.0015385" "lattice/spacing 0.0015385" \
    "constant/tlSphProperties/dissipation/jacobian (0 0.125)"
check impactSph/isothermalShockBar 4 "regions/insert/lattice/spacing 0.00125" "system/controlDict/deltaT 2.5e-05"
pass "the shipped studies of the swinging cube, cable, twisting column and isothermal shock-bar are valid"
