# Leave out what a scene does not need (issue 20 item 3): for each solver, a scene without strength
# allocates no deviatoric stress, one without plasticity no plastic state, and none allocates a heat
# flux (no method conducts heat yet); each lean scene's memory per particle (the log's field table) is
# exactly the sum of the fields it needs; the summary names the phases a scene skipped; and the scene
# with the model allocates the field (so that the absence is not an accident of naming). Kept: an MPM
# fluid's stored energy density (rho0 e, read by the energy budget; see below).
#   bash leaveOut.sh <build> <source root>
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export PATH="$BUILD/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-leaveOut.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# oneStep <tutorial> <solver> <endTime>: runs the tutorial's case to endTime (a step or two) in
# $WORK/<name>; prints the log's path.
oneStep() {
    local c="$WORK/$(echo "$1" | tr / _)"
    cp -r "$SOURCE/tutorials/$1" "$c"
    rm -rf "$c"/[0-9]* "$c/postProcessing" "$c"/log.* "$c/particles.pvd"
    mfDictionary "$c/system/controlDict" -entry endTime -set "$3" > /dev/null
    particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen on $1: $(tail -3 "$c/log.particleGen")"
    "$2" -case "$c" > "$c/log" 2>&1 || fail "$2 on $1: $(grep -A2 '^Error' "$c/log" | head -3)"
    echo "$c/log"
}
# The field names of the log's table, one line, space-separated.
fieldsOf() { sed -n '/^Fields/,/^    total/p' "$1" | awk 'NR > 2 && $1 != "total" { printf " %s", $1 }'; echo " "; }
bytesOf() { sed -n 's/^Fields (\([0-9]*\) B per particle):.*/\1/p' "$1"; }
absent() {  # absent <log> <what> <field>...
    local log="$1" what="$2"; shift 2
    local fields; fields=$(fieldsOf "$log")
    for f in "$@"; do
        case "$fields" in *" $f "*) fail "$what allocates $f:$fields" ;; esac
    done
}
present() {
    local log="$1" what="$2"; shift 2
    local fields; fields=$(fieldsOf "$log")
    for f in "$@"; do
        case "$fields" in *" $f "*) ;; *) fail "$what does not allocate $f:$fields" ;; esac
    done
}
bytes() {  # bytes <log> <what> <expected bytes per particle>
    local b; b=$(bytesOf "$1")
    [ "$b" = "$3" ] || fail "$2: $b B per particle, expected $3: $(fieldsOf "$1")"
}
heat="heatFlux temperatureGradient temperature"

# impactSph: Sod (a gas: no strength), the HVI disc (von Mises strength and its plastic strain).
log=$(oneStep impactSph/sodShockTube impactSph 1e-4)
absent "$log" "impactSph's Sod tube" deviatoricStress deviatoricStressHalfStep plasticStrain $heat
# 1D: 16 fields of one value each (position, ids, region, material, the gas state, the half step).
bytes "$log" "impactSph's Sod tube" 128
grep -q "^    phases skipped .*strength" "$log" || fail "impactSph's Sod summary does not name the skipped strength phase"
log=$(oneStep impactSph/hviAlAl impactSph 2e-8)
present "$log" "impactSph's HVI" deviatoricStress plasticStrain
absent "$log" "impactSph's HVI" $heat

# tlSph: the elastic spinning cube (no plastic state), the plastic Taylor bar.
log=$(oneStep tlSph/spinningCube tlSph 2e-4)
absent "$log" "tlSph's spinning cube" plasticStrain plasticDeformation jacobian $heat
# 3D {p,F}: 3 + 1 + 1 + 1 + 1 + 1 + 3 + 3 (X) + 9 (F) + 9 (P) + 1 (p) + 1 (h) = 34 values.
bytes "$log" "tlSph's spinning cube" 272
log=$(oneStep tlSph/taylorBar tlSph 2e-8)
present "$log" "tlSph's Taylor bar" plasticStrain plasticDeformation

# mpmFsi: the drop into a pool (fluids only: no deviatoric or plastic state, and no F: the
# updated-Lagrangian path advances J alone), the Taylor bar (von Mises on the same path: no F
# either), its j2Plasticity variant (a constitutive law of F: F and the plastic state). A fluid
# carries storedEnergyDensity (rho0 e, its internal energy).
log=$(oneStep mpmFsi/dropPool mpmFsi 1e-4)
absent "$log" "mpmFsi's drop pool (fluids)" deviatoricStress plasticStrain plasticDeformation deformationGradient $heat
# 2D: 2 + 1 + 1 + 1 + 1 + 1 + 2 (v) + 1 (J) + 1 (e) + 1 (p) + 1 (c) + 3 (sigma) + 1 + 1 = 18 values.
bytes "$log" "mpmFsi's drop pool" 144
log=$(oneStep mpmFsi/taylorBar mpmFsi 2e-8)
present "$log" "mpmFsi's Taylor bar" deviatoricStress plasticStrain jacobian
absent "$log" "mpmFsi's Taylor bar (equation of state and strength)" deformationGradient
log=$(oneStep mpmFsi/taylorBar/j2Plasticity mpmFsi 2e-8)
present "$log" "mpmFsi's Taylor bar (j2Plasticity)" deformationGradient plasticDeformation plasticStrain

# fpmSolid: the shock tube (the Euler part alone: no deviator), the coupled shearing sphere.
log=$(oneStep fpmSolid/shockTube fpmSolid 0.002)
absent "$log" "fpmSolid's shock tube (Euler part alone)" deviatoricStress $heat
grep -q "^    phases skipped .*shear" "$log" || fail "fpmSolid's shock tube summary does not name the skipped shear phase"
# 3D: 3 + 1 + 1 + 1 + 1 + 1 (rho) + 1 (p) + 1 (e) + 3 (v) + 1 (V) = 14 values.
bytes "$log" "fpmSolid's shock tube" 112
log=$(oneStep fpmSolid/coupledShearingSphere fpmSolid 0.002)
present "$log" "fpmSolid's coupled sphere" deviatoricStress
echo "PASS: leave out: no scene allocates what its models do not use"
