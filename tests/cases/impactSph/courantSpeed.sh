# The Courant vote of a solid on its longitudinal elastic wave speed (issue 16): the quarter Taylor
# bar (copper: c0 = 3815.5 m/s, G = 43.333333 GPa, rho0 = 8930 kg/m^3, vonMises `deviator three`)
# at 0.64 mm, h = 1.3 x 0.64 mm, set at rest (its wall image overlaps its lower layers at once when it
# moves), so that rho = rho0, e = 0 and P = 0 stay exact and the vote is the closed form:
#   courantSpeed longitudinal (default)  dt = maxCo h/sqrt(c0^2 + 4G/(3 rho0)) = 3.6287e-8 s
#   courantSpeed bulk (the thesis's)     dt = maxCo h/c0                       = 4.3612e-8 s
# each asserted within 1e-9 relative from the health check's stableDeltaT of the third step.
# Without the shear term the vote ran a solid 1.19 times past maxCo: the 0.2 mm quarter gained 1.3%
# of its energy from 49 µs (tutorials/impactSph/taylorBar/README.md).
. "$(dirname "$0")/common.sh"
bar="$TUTORIALS/taylorBar"
for speed in longitudinal bulk; do
    c=$(newCase "$bar/quarter3D" "$speed")
    setEntry "$c/system/particleGenDict" regions/bar/lattice/spacing 6.4e-4
    setEntry "$c/system/particleGenDict" regions/bar/fields/velocity "(0 0 0)"
    setEntry "$c/system/controlDict" endTime 1.5e-7
    setEntry "$c/system/controlDict" health "{ writeControl timeStep; writeInterval 1; }"
    [ "$speed" = longitudinal ] || setEntry "$c/constant/sphProperties" courantSpeed bulk
    runCase "$c" > /dev/null
    got=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "stableDeltaT") k = i; next } $2 == 3 { print $k }' \
        "$c/postProcessing/health/0/health.csv")
    [ -n "$got" ] || fail "$speed: no health row at step 3"
    want=$(awk -v s="$speed" 'BEGIN { c0 = 3815.5; G = 43.333333e9; rho = 8930; h = 1.3 * 6.4e-4
        c = (s == "bulk") ? c0 : sqrt(c0 * c0 + 4 * G / (3 * rho)); printf "%.15g", 0.2 * h / c }')
    less "$(relErr "$got" "$want")" 1e-9 || fail "courantSpeed $speed: stable step $got s, expected $want s"
    echo "courantSpeed $speed: stable step $got s (expected $want s)"
done
pass "the Courant vote of a solid on c_L = sqrt(c0^2 + 4G/(3 rho)) by default, on c0 with courantSpeed bulk"
