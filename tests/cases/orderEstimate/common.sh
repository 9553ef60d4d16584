# Shared by the orderEstimate tests: $1 = build directory, $2 = this source directory.
# makeStudy <dir> writes three runs of one 2D box, coarse/medium/fine on cubic lattices of
# spacings 0.1, 0.05, 0.025 (N = 200, 800, 3200, about a second for all three), at times 0 and 0.5
# (and 0.25 in the coarse run only), whose fields are manufactured as
#     phi_k(x) = f(x) + dx_k^p g(x),   f, g linear, dx_k the run's spacing,
# i.e. exactly the error model of the estimate with a known order p per field (OrderEstimate.cpp).
# First-order MLS reproduces linear fields exactly, so the grid values are f + dx_k^p g to
# round-off and the estimate must return p to round-off.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
export PATH="$BUILD/bin:$PATH" OMP_NUM_THREADS=1
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-orderEstimate.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "PASS: $*"; }
setField() { /usr/bin/python3 "$SOURCE/setField.py" "$@" || fail "setField.py $*"; }

# The manufactured fields: p = 2 (pressure), 1.5 (temperature), 1 (velocity_x); velocity_y is the
# same in every run (no difference, no order). The time enters the amplitude only, so the order is
# the same at every time while the values are not.
manufacture() {  # <particles.vtp> <dx> <time>
    setField "$1" pressure 0 "1 + 2*x - y + $2**2 * (3 + x + 0.5*y)"
    setField "$1" temperature 0 "300 - 4*y + $2**1.5 * (1 + $3) * (2 - 0.5*x + y)"
    setField "$1" velocity 0 "0.5*x + $2 * (1 + y)"
    setField "$1" velocity 1 "0.25 + 0*x"
}

writeDict() {  # <study> <dictionary text>
    mkdir -p "$1/system"
    printf '%s\n' "$2" > "$1/system/orderEstimateDict"
}

# The dictionary the tests start from; each bad-input test changes one line of it.
goodDict='runs          (coarse medium fine);
fields        (pressure temperature velocity);
norm          infinity;
grid          { spacing 0.1; }
interior      0.9;
interpolation mls;
kernel        { type wendlandC2; }
h             (0.15 0.075 0.0375);'

makeStudy() {  # <study>
    local study="$1" name spacing
    mkdir -p "$study"
    for run in coarse:0.1 medium:0.05 fine:0.025; do
        name=${run%%:*}
        spacing=${run#*:}
        mkdir -p "$study/$name/system"
        cat > "$study/$name/system/particleGenDict" <<DICT
dimension 2;
regions
{
    box
    {
        shape   { type box; min (0 0); max (2 1); }
        lattice { type cubic; spacing $spacing; }
        density 1000;
        fields  { velocity (0 0); pressure 0; temperature 0; }
    }
}
DICT
        particleGen -case "$study/$name" > "$study/$name/log.particleGen" 2>&1 ||
            fail "particleGen $name: $(cat "$study/$name/log.particleGen")"
        cp -r "$study/$name/0" "$study/$name/0.5"
        manufacture "$study/$name/0/particles.vtp" "$spacing" 0
        manufacture "$study/$name/0.5/particles.vtp" "$spacing" 0.5
    done
    # A time only the coarse run wrote: skipped with a warning.
    cp -r "$study/coarse/0" "$study/coarse/0.25"
    writeDict "$study" "$goodDict"
}

# column <csv> <header name>: the 1-based index of a column.
column() { head -n 1 "$1" | tr ',' '\n' | grep -nxF -- "$2" | cut -d: -f1; }
# cell <csv> <time> <header name>
cell() {
    local c
    c=$(column "$1" "$3")
    [ -n "$c" ] || fail "no column $3 in $1: $(head -n 1 "$1")"
    awk -F, -v t="$2" -v c="$c" 'NR > 1 && $1 + 0 == t + 0 { print $c }' "$1"
}
# near <a> <b> <absolute tolerance>
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }
