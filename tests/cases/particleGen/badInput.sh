# particleGen on the worst particleGenDicts found by mutating the tutorials' (issue 14): each must
# exit with status 1 and an "Error: system/particleGenDict:<line>:" message (no "Error (internal)",
# no crash), within seconds, and leave the case's earlier 0/particles.vtp untouched.
# Before: spacing 1e-300 wrote ONE particle, spacing 1e-4 in a 1 m cube ended in std::bad_alloc
# ("Error (internal)"), `velocty` was written as a new field, a fully overridden region was kept
# with no particles, a radius of 1e200 ended in std::bad_alloc.
# $1 = build directory.
set -euo pipefail
export PATH="$1/bin:$PATH" OMP_NUM_THREADS=1
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-test.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
mkdir -p "$WORK/case/system" "$WORK/case/0"
echo "earlier results" > "$WORK/case/0/particles.vtp"

# refuse <what the message must contain> <particleGenDict text> [E: the first is an extended regex]
refuse() {
    printf '%s\n' "$2" > "$WORK/case/system/particleGenDict"
    set +e
    timeout 60 particleGen -case "$WORK/case" > "$WORK/log" 2>&1
    local rc=$?
    set -e
    [ $rc = 1 ] || fail "exit status $rc (expected 1) for: $2"$'\n'"$(cat "$WORK/log")"
    grep -q "Error (internal)" "$WORK/log" && fail "internal error for: $2"$'\n'"$(cat "$WORK/log")"
    grep -q "^Error: $WORK/case/system/particleGenDict:[0-9]*:[0-9]*: " "$WORK/log" ||
        fail "no file:line in the message for: $2"$'\n'"$(cat "$WORK/log")"
    grep -q${3:-F} -- "$1" "$WORK/log" || fail "'$1' not in the message for: $2"$'\n'"$(cat "$WORK/log")"
    [ "$(cat "$WORK/case/0/particles.vtp")" = "earlier results" ] || fail "0/particles.vtp overwritten"
    [ ! -e "$WORK/case/particles.pvd" ] || fail "particles.pvd written"
}

box='shape { type box; min (0 0); max (0.1 0.1); }'
refuse "region 'a' would hold about more than 1e308 particles" \
    "dimension 2; regions { a { $box lattice { type cubic; spacing 1e-300; } density 1000; } }"
refuse "region 'a' would hold about 1e+12 particles (cubic lattice of spacing 0.0001 m" \
    "dimension 3; regions { a { shape { type box; min (0 0 0); max (1 1 1); } lattice { type cubic; spacing 1e-4; } density 1000; } }"
refuse "the particle mass density x volume = 1000 x 0 = 0 (spacing 1e-110 m)" \
    "dimension 3; regions { a { shape { type box; min (0 0 0); max (1e-109 1e-109 1e-109); } lattice { type cubic; spacing 1e-110; } density 1000; } }"
refuse "unknown field 'velocty' (did you mean 'velocity'?)" \
    "dimension 2; regions { a { $box lattice { type cubic; spacing 0.01; } density 1000; fields { velocty (0 -100); } } }"
refuse "region 'a' has no particles left: the later region 'b' took them all" \
    "dimension 2; regions { a { $box lattice { type cubic; spacing 0.01; } density 1000; } b { shape { type box; min (-1 -1); max (1 1); } lattice { type cubic; spacing 0.05; } density 1; } }"
refuse "radius must be positive and at most 1e150 m, found 1e+200" \
    "dimension 2; regions { a { shape { type sphere; centre (0 0); radius 1e200; } lattice { type cubic; spacing 0.01; } density 1000; } }"
# The dictionary reader may refuse the number itself; otherwise particleGen refuses the field.
refuse "number '1e400' is out of range|keyword 'velocity': region 'a': field 'velocity' component 1 is" \
    "dimension 2; regions { a { $box lattice { type cubic; spacing 0.01; } density 1000; fields { velocity (1e400 0); } } }" E
refuse "keyword 'jitter'" \
    "dimension 2; regions { a { $box lattice { type cubic; spacing 0.01; jitter 0.5; } density 1000; } }"
refuse "max must exceed min" \
    "dimension 2; regions { a { shape { type box; min (0 0); max (0.1 -0.1); } lattice { type cubic; spacing 0.01; } density 1000; } }"
refuse "keyword 'spacing'" \
    "dimension 2; regions { a { $box lattice { type cubic; spacing -0.01; } density 1000; } }"
refuse "exactly one of \`cells (n1 n2 n3);\`" \
    "dimension 2; regions { a { $box lattice { type materialPoints; cells (10 10); spacing 0.01; } density 1000; } }"
refuse "the polygon must be simple" \
    "dimension 2; regions { a { shape { type polygon; vertices ((0 0) (1 1) (1 0) (0 1)); } lattice { type materialPoints; cells (10 10); } density 1000; } }"

# A lattice much coarser than its shape still works, with a warning that the mass is off.
printf '%s\n' "dimension 2; regions { a { shape { type sphere; centre (0 0); radius 0.01; } lattice { type cubic; spacing 0.012; } density 1000; } }" \
    > "$WORK/case/system/particleGenDict"
particleGen -case "$WORK/case" > "$WORK/log" 2>&1 || fail "coarse lattice refused: $(cat "$WORK/log")"
grep -q "Warning: .*particleGenDict:1:24: region 'a': its particles stand for a volume of 0.000432 but its shape's is 0.000314159" \
    "$WORK/log" || fail "no coarse-lattice warning: $(cat "$WORK/log")"
echo "PASS: 12 bad particleGenDicts refused at file:line, earlier results kept; coarse lattice warned"
