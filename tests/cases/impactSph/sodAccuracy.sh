# Sod's tube (gamma = 1.4, equal masses, 400 + 50 particles on [0, 1], Zisis 2017 Fig. 5.7) against
# the exact solution at t = 0.2 (doc/methods/sph-impact.md 8.4a): L1(rho) on [0, 1] below 1.5e-2, and the star
# pressure and velocity (medians over the plateau, riemannError) within 2% of P* = 0.30313,
# u* = 0.92745. The tutorial's run gives L1 4.1e-3 and errors of 0.3% and 0.04%.
. "$(dirname "$0")/common.sh"
c=$(newCase "$SOURCE/sodShockTube" sod)
wall=$(runCase "$c")
l1=$(lastRow "$c/postProcessing/riemann/0/errorNorms.csv" ",density," | cut -d, -f3)
t=$(lastRow "$c/postProcessing/riemann/0/errorNorms.csv" ",density," | cut -d, -f1)
[ "$t" = 0.2 ] || fail "last error row at t = $t, expected 0.2"
less "$l1" 1.5e-2 || fail "L1(rho) = $l1 >= 1.5e-2"
star="$c/postProcessing/riemann/0/starState.csv"
eP=$(relErr "$(column "$star" pStar)" "$(column "$star" pStarExact)")
eU=$(relErr "$(column "$star" uStar)" "$(column "$star" uStarExact)")
less "$eP" 0.02 || fail "star pressure $(column "$star" pStar) off exact $(column "$star" pStarExact) by $eP"
less "$eU" 0.02 || fail "star velocity $(column "$star" uStar) off exact $(column "$star" uStarExact) by $eU"
pass "Sod N = 450: L1(rho) $l1, star pressure error $eP, star velocity error $eU, wall time $wall s"
