# Shared by the strong-shock tests (strongShockPlateau.sh, strongShockConvergence.sh): the tube of
# strongShockTube/ (equal densities 1, P_L = 1, P_R = 1/ratio, gamma 1.4, Courant-limited step) run
# with the default dissipation, and the figures they assert. Sourced after common.sh.

# strongCase <name> <pressure ratio> <spacing> [dissipation entry value ...]: a copy of the tube with
# P_R = 1/ratio in both the particles and the reference, the spacing on both sides; prints its path.
strongCase() {
    local c
    c=$(newCase "$SOURCE/strongShockTube" "$1")
    # The tests measure the defaults: the case's densityLimiter (written for its studyDict) goes.
    sed -i 's/dissipation     { type riemann; densityLimiter contact; }/dissipation     { type riemann; }/' \
        "$c/constant/sphProperties"
    grep -q '^dissipation     { type riemann; }' "$c/constant/sphProperties" ||
        fail "$c/constant/sphProperties: expected 'dissipation { type riemann; densityLimiter contact; }'"
    local pR
    pR=$(awk -v r="$2" 'BEGIN { printf "%.17g", 1 / r }')
    setEntry "$c/system/particleGenDict" regions/right/fields/pressure "$pR"
    setEntry "$c/system/controlDict" functions/riemann/right/pressure "$pR"
    setEntry "$c/system/particleGenDict" regions/left/lattice/spacing "$3"
    setEntry "$c/system/particleGenDict" regions/right/lattice/spacing "$3"
    shift 3
    while [ $# -ge 2 ]; do setEntry "$c/constant/sphProperties" "dissipation/$1" "$2"; shift 2; done
    echo "$c"
}

# l1Density <case>: L1(rho) on [0, 1] at t = 0.2.
l1Density() {
    local row
    row=$(lastRow "$1/postProcessing/riemann/0/errorNorms.csv" ",density,")
    [ "$(echo "$row" | cut -d, -f1)" = 0.2 ] || fail "$1: last error row not at t = 0.2: $row"
    echo "$row" | cut -d, -f3
}

# plateau <case>: "dRho dP n", the mean relative errors of rho and P over the post-shock plateau at
# t = 0.2 (the particles whose exact state is the right star state: P = P*, rho = rho*R, between the
# contact and the shock), its middle 80% (the contact and the shock smear over a few h at each end),
# and the number of particles averaged. The plateau is where the mass flux's error stays: it is
# deposited at the shock front and carried downstream.
plateau() {
    local ps
    ps=$(column "$1/postProcessing/riemann/0/starState.csv" pStarExact)
    awk -F, -v ps="$ps" '
        NR > 1 && ($7 - ps) * ($7 - ps) < (1e-9 * ps) * (1e-9 * ps) { r[n] = $2; re[n] = $3; p[n] = $6; n++ }
        END {
            if (n == 0) exit 1
            m = 0
            for (i = 0; i < n; ++i) if (re[i] == re[n - 1]) k[m++] = i   # rho*R: the plateau right of the contact
            lo = int(0.1 * m)
            for (q = lo; q < m - lo; ++q) { i = k[q]; dr += r[i] / re[i] - 1; dp += p[i] / ps - 1; c++ }
            if (c < 5) exit 1
            printf "%.5f %.5f %d", dr / c, dp / c, c
        }' "$1/postProcessing/riemann/0/profile_0.2.csv" || fail "$1: no post-shock plateau in profile_0.2.csv"
}

# abs <x>, order <coarse L1> <fine L1> (spacings in ratio 2).
abs() { awk -v a="$1" 'BEGIN { print (a < 0 ? -a : a) }'; }
order() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", log(a / b) / log(2) }'; }
percent() { awk -v a="$1" 'BEGIN { printf "%+.2f%%", 100 * a }'; }
