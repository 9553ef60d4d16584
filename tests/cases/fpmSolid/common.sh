# Shared by the fpmSolid case scripts: $1 = build directory, $2 = source root.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export PATH="$BUILD/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-fpm.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# copyTutorial <name> <destination>: a clean copy of tutorials/fpmSolid/<name>.
copyTutorial() {
    cp -r "$SOURCE/tutorials/fpmSolid/$1" "$2"
    rm -rf "$2"/log.* "$2"/postProcessing "$2"/[0-9]* "$2"/*.png "$2"/particles.pvd
}
# coarseLattice <case> <h>: the reference sphere's lattice coarsened to spacing 1.25 (280 particles)
# with the support h.
coarseLattice() {
    sed -i 's/spacing 0.75; }/spacing 1.25; }/' "$1/system/particleGenDict"
    sed -i "s/^smoothingLength .*/smoothingLength $2;/" "$1/constant/fpmProperties"
    grep -q "spacing 1.25; }" "$1/system/particleGenDict" || fail "could not set the spacing in $1"
    grep -q "^smoothingLength $2;" "$1/constant/fpmProperties" || fail "could not set h in $1"
}
# coarseSphere <case> <deltaT>: the default tests' coarse reference sphere (spacing 1.25, h = 2.5:
# 280 particles, against the tutorials' thesis values 0.75 / 1.5) and the step deltaT.
coarseSphere() {
    coarseLattice "$1" 2.5
    sed -i "s/^deltaT .*/deltaT $2;/" "$1/system/controlDict"
    grep -q "^deltaT $2;" "$1/system/controlDict" || fail "could not set deltaT in $1"
}
# run <case> <application>: runs it with its log in the case.
run() {
    "$2" -case "$1" > "$1/log.$2" 2>&1 || fail "$2 on $1: $(tail -n 20 "$1/log.$2")"
}
# entry <file> <key>: the value of `key value;` in a dictionary file.
entry() {
    awk -v k="$2" '$1 == k { v = $2; sub(/;$/, "", v); print v; found = 1 } END { if (!found) exit 1 }' "$1"
}
# fieldRange <case> <time> <field.component>: "min max" from particleInfo.
fieldRange() {
    particleInfo -case "$1" -time "$2" | awk -v f="$3" '$1 == f { if ($2 ~ /^[a-zA-Z]/) print $3, $4; else print $2, $3; found = 1 } END { if (!found) exit 1 }'
}
# lagrangianVariant <tutorial> <case> <deltaT>: the tutorial on the coarse sphere with the particles
# moved by the split (motion dimensional) and its velocity boundary condition in the start frame
# (v = v0(xi)): the Lagrangian mode of the linear-flow validations (doc/methods/fpm.md §4.6, §4.10).
lagrangianVariant() {
    copyTutorial "$1" "$2"
    coarseSphere "$2" "$3"
    sed -i 's/velocity frozen;/velocity dimensional;/' "$2/constant/fpmProperties"
    sed -i 's/type     linearVelocity;/type     linearVelocity; frame initial;/' "$2/constant/boundaryConditions"
    grep -q "velocity dimensional;" "$2/constant/fpmProperties" || fail "could not set velocity dimensional in $2"
    grep -q "frame initial;" "$2/constant/boundaryConditions" || fail "could not set frame initial in $2"
}
# exactStress <referenceError> <k...>: components k (1-based, xx yy zz xy yz xz) of its exactStress.
exactStress() {
    local f="$1"; shift
    awk -v ks="$*" '$1 == "exactStress" { gsub(/[();]/, ""); n = split(ks, k, " "); s = ""; for (i = 1; i <= n; i++) s = s (i > 1 ? " " : "") $(k[i] + 1); print s }' "$f"
}
# freeSurfaceSphere <tutorial> <case> <endTime>: a free-surface sphere tutorial (coupledShearingSphere,
# rotatingSphere) on the coarse lattice with the tutorials' h / spacing of 3 (spacing 1.25, h 3.75:
# 280 particles), run to endTime, with only the last time written.
freeSurfaceSphere() {
    copyTutorial "$1" "$2"
    coarseLattice "$2" 3.75
    sed -i "s/^endTime .*/endTime $3;/; s/^writeInterval .*/writeInterval 1;/" "$2/system/controlDict"
    grep -q "velocity characteristic;" "$2/constant/fpmProperties" || fail "$1's free surface is not characteristic"
    run "$2" particleGen
    run "$2" fpmSolid
}
# energyRises <conservedQuantities.csv>: "largest-rise time-of-it start end L_z-start L_z-end" of
# totalEnergy between consecutive written times (time "none" when it never rises).
energyRises() {
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "totalEnergy") k = i; if ($i == "angularMomentum_z") z = i } next }
        !k || !z { exit 1 } n++ && $k - prev > worst { worst = $k - prev; t = $1 } { prev = $k; if (n == 1) { e0 = $k; l0 = $z } lz = $z }
        END { print worst + 0, (t == "" ? "none" : t), e0, prev, l0, lz }' "$1"
}
# runToTheEnd <tutorial> <case>: a clean copy of the tutorial run as shipped, particleGen then fpmSolid;
# fpmSolid may stop early (the validation tests print their figures first): its exit status is left
# in $status and the first line of its diagnosis in $diagnosis.
runToTheEnd() {
    copyTutorial "$1" "$2"
    run "$2" particleGen
    status=0
    fpmSolid -case "$2" > "$2/log.fpmSolid" 2>&1 || status=$?
    diagnosis=$(grep -m1 "Error" "$2/log.fpmSolid" | cut -c1-300 || true)
}
# energyFalls <conservedQuantities.csv> <label>: fails unless the total energy falls between every two
# written times (a rise above 1e-12 of the start, round-off, is an instability: the upwinded parts and
# the surface conditions only dissipate); prints the budget.
energyFalls() {
    local worst tRise e0 eEnd l0 lEnd
    read -r worst tRise e0 eEnd l0 lEnd <<< "$(energyRises "$1")" || fail "no totalEnergy or angularMomentum_z in $1"
    [ -n "$e0" ] || fail "no totalEnergy or angularMomentum_z in $1"
    echo "$2energy $e0 -> $eEnd, largest rise between written times $worst (t = $tRise); L_z $l0 -> $lEnd"
    awk -v w="$worst" -v a="$e0" 'BEGIN { exit !(w <= 1e-12 * a) }' || fail "$2the energy rose by $worst at t = $tRise"
}
# allRead <log>: fails when the solver reports an entry it never read.
allRead() {
    grep -q "never read" "$1" && fail "an entry was never read: $(grep -A2 "never read" "$1")"
    return 0
}
# rotatingSphereStart <tutorial>: the rotating sphere tutorial (R11's setup) on the coarse sphere to
# t = 1.5; asserts the in-plane radius's first maximum at 1.1 +- 0.2 (R11's first extremum and bound)
# and the energy falling between every two written times (a rise is an instability); prints L_z.
rotatingSphereStart() {
    c="$WORK/$1"
    freeSurfaceSphere "$1" "$c" 1.5
    grep -q "^subsystems *(shear euler rotation);" "$c/constant/fpmProperties" || fail "the tutorial does not run all three parts"
    e="$c/postProcessing/shape/0/bodyExtents.csv"
    q="$c/postProcessing/budget/0/conservedQuantities.csv"
    [ -f "$e" ] && [ -f "$q" ] || fail "no bodyExtents or conservedQuantities output"
    first=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "r") k = i; next }
        !k { exit 1 } { r[++n] = $k; t[n] = $1 }
        END { for (i = 2; i < n; i++) if (r[i] >= r[i - 1] && r[i] > r[i + 1]) { print t[i], r[i], r[1]; exit } print "none" }' "$e") ||
        fail "no r column in $e"
    read -r tMax rMax r0 <<< "$first"
    echo "in-plane radius: first maximum $rMax at t = $tMax (from $r0; R11: 1.1 +- 0.2)"
    [ "$tMax" != none ] && awk -v t="$tMax" 'BEGIN { exit !(t >= 0.9 && t <= 1.3) }' ||
        fail "the in-plane radius's first maximum is at t = $tMax, not 1.1 +- 0.2"
    energyFalls "$q" ""
}
