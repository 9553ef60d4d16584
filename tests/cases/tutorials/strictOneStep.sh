#!/usr/bin/env bash
# Every case of every impactSph and tlSph tutorial, run for about one step under
# 'strictDictionaries yes;': a correct tutorial must pass, so no entry of a tutorial's dictionaries
# may be reported as never read (an entry read after the never-read check, or the switch itself,
# would fail the run). $1 = build directory, $2 = this source directory; optional $3 = a pattern
# that selects cases (for a quick rerun by hand).
set -euo pipefail
BUILD="$1"
SOURCE="$2"
ONLY="${3:-}"
TUTORIALS="$(cd "$SOURCE/../../../tutorials" && pwd)"
export PATH="$BUILD/bin:$PATH"
export OMP_NUM_THREADS=1
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-strict.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
set1() { mfDictionary "$1" -entry "$2" -set "$3" > /dev/null || fail "could not set $2 in $1"; }

# Cases whose tutorial lattice is too fine for a test: the spacing (every lattice of the case) is
# scaled by this factor in the copy. The dictionaries read are the same, only the count changes.
declare -A coarsen=(
    [impactSph/hviAlAl]=4 [impactSph/hviAlCu]=4 [impactSph/hviAlPb]=4
    [impactSph/laminatePlate/homogenized]=4 [impactSph/laminatePlate/laminate]=4
    [impactSph/laminatePlate/monolithic]=4 [impactSph/taylorBar/bar3D]=3 [impactSph/taylorBar/quarter3D]=2
)

count=0
failed=()
for control in $(cd "$TUTORIALS" && find impactSph tlSph -path '*/system/controlDict' | sort); do
    name="${control%/system/controlDict}"
    [ -z "$ONLY" ] || [[ "$name" == *$ONLY* ]] || continue
    dest="$WORK/$name"
    mkdir -p "$dest"
    cp -r "$TUTORIALS/$name/system" "$TUTORIALS/$name/constant" "$dest/"
    solver=$(mfDictionary "$dest/system/controlDict" -entry application)
    # One step: the end time is the first step (deltaT), written at once.
    dt=$(mfDictionary "$dest/system/controlDict" -entry deltaT)
    set1 "$dest/system/controlDict" endTime "$dt"
    set1 "$dest/system/controlDict" writeInterval "$dt"
    printf '\nstrictDictionaries yes;\n' >> "$dest/system/controlDict"
    # No tutorial sets neighbourSkin, which impactSph used to read on the first step only (after
    # the check), so that a correct entry was reported never read: Sod's copy sets one.
    if [ "$name" = impactSph/sodShockTube ]; then
        printf '\nneighbourSkin 0.25;\n' >> "$dest/constant/sphProperties"
    fi
    if [ -n "${coarsen[$name]:-}" ]; then
        awk -v f="${coarsen[$name]}" '/lattice/ { for (i = 1; i < NF; ++i) if ($i == "spacing") $(i + 1) = ($(i + 1) * f) ";" } { print }' \
            "$dest/system/particleGenDict" > "$dest/system/particleGenDict.new"
        mv "$dest/system/particleGenDict.new" "$dest/system/particleGenDict"
    fi
    ((++count))
    start=$SECONDS
    if ! particleGen -case "$dest" > "$dest/log.particleGen" 2>&1; then
        failed+=("$name (particleGen: $(grep -m1 -A3 Error "$dest/log.particleGen" | tr '\n' ' '))")
        continue
    fi
    if ! "$solver" -case "$dest" > "$dest/log.$solver" 2>&1; then
        failed+=("$name ($solver: $(grep -A8 '^Error' "$dest/log.$solver" | tr '\n' ' '))")
        continue
    fi
    if grep -q "never read" "$dest/log.$solver"; then
        failed+=("$name (a 'never read' warning under strictDictionaries: $(grep -A4 'never read' "$dest/log.$solver" | tr '\n' ' '))")
        continue
    fi
    n=$(awk '/^ *particles  / { print $2; exit }' "$dest/log.$solver")
    echo "passed: $name ($solver, $n particles, $((SECONDS - start)) s)"
done
[ "$count" -gt 0 ] || fail "no tutorial case found under $TUTORIALS"
# Every case of both solvers was run: 29 at the time of writing; fewer means the search broke.
[ -n "$ONLY" ] || [ "$count" -ge 29 ] || fail "only $count tutorial cases found (expected 29 or more)"
if [ ${#failed[@]} -gt 0 ]; then
    printf 'FAIL: %s\n' "${failed[@]}" >&2
    fail "${#failed[@]} of $count tutorial cases fail under strictDictionaries yes"
fi
echo "PASS: all $count impactSph and tlSph tutorial cases run one step under strictDictionaries yes"
