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
# coarsePlate <destination>: the oscillating plate's tutorial on the 4 mm lattice with h = 1.3 dx
# (6 particles through the thickness: the cheap plate of the amplitude, {p,F,J} and energy tests),
# whatever spacing and h the tutorial ships with.
coarsePlate() {
    copyTutorial oscillatingPlate "$1"
    sed -i 's/spacing [0-9.e-]*; }/spacing 0.004; }/' "$1/system/particleGenDict"
    sed -i 's/^smoothingLengthRatio .*/smoothingLengthRatio 1.3;/' "$1/constant/tlSphProperties"
    grep -q "spacing 0.004; }" "$1/system/particleGenDict" || fail "could not set dx = 4 mm"
    grep -q "^smoothingLengthRatio 1.3;" "$1/constant/tlSphProperties" || fail "could not set h = 1.3 dx"
}
# pFJPlate <destination> <nu> <endTime> <momentumSpeed> <jacobian eps4>: the coarse plate in {p,F,J}
# with jst momentum (0 0.125) on that speed and jacobian (0 eps4), Poisson's ratio nu, run to
# endTime with one write at its end and the conserved quantities every 50 steps; particles made.
pFJPlate() {
    coarsePlate "$1"
    sed -i "s/^formulation .*/formulation          pFJ;/; s/momentum (0 0.125);\( jacobian (0 0);\)\? }/momentum (0 0.125); jacobian (0 $5); momentumSpeed $4; }/" \
        "$1/constant/tlSphProperties"
    grep -q "jacobian (0 $5); momentumSpeed $4; }" "$1/constant/tlSphProperties" || fail "could not set the dissipation in $1"
    sed -i "s/poissonRatio    0.3975;/poissonRatio    $2;/" "$1/constant/materialProperties"
    grep -q "poissonRatio    $2;" "$1/constant/materialProperties" || fail "could not set nu = $2"
    sed -i "s/^endTime .*/endTime         $3;/; s/^writeInterval .*/writeInterval   $3;/; s/writeInterval 200;/writeInterval 50;/" \
        "$1/system/controlDict"
    grep -q "^endTime         $3;" "$1/system/controlDict" || fail "could not set the end time"
    particleGen -case "$1" > "$1/log.particleGen" 2>&1 || fail "particleGen: $(tail "$1/log.particleGen")"
}
# energyDrift <case>: "highest final" total energy relative to the start.
energyDrift() {
    column "$1/postProcessing/conserved/0/conservedQuantities.csv" totalEnergy |
        awk 'NR == 1 { e0 = $1; m = $1 } { if ($1 > m) m = $1; e = $1 } END { printf "%.6f %.6f\n", m / e0 - 1, e / e0 - 1 }'
}
# run <case> <application>: runs it with its log in the case.
run() {
    "$2" -case "$1" > "$1/log.$2" 2>&1 || fail "$2 on $1: $(tail -n 20 "$1/log.$2")"
}
# column <csv> <name>: the column's values, one per line.
column() {
    awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) k = i; if (!k) exit 1; next } { print $k }' "$1"
}
