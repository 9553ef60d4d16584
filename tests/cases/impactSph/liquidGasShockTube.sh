# The liquid-gas shock tube (doc/methods/sph-impact.md 8.4c, Zisis 2017 Fig. 5.9: stiffened-gas liquid, gamma
# 4.4, P_ref 0.6, against an ideal gas, gamma 1.4; density ratio 1/20, pressure ratio 1/100), run by
# the tutorial's Allrun: star pressure and velocity (riemannError medians) within 5% of the exact
# P* = 0.030814, u* = 0.47143 at t = 0.15. The tutorial's run: -1.6% and +0.07%. Conservation: mass
# exact, momentum to round-off, energy drift below 1e-3 (the run: 1.6e-6).
. "$(dirname "$0")/common.sh"
d=$(runTutorial liquidGasShockTube)
star="$d/postProcessing/riemann/0/starState.csv"
[ "$(column "$star" time)" = 0.15 ] || fail "last star state at t = $(column "$star" time)"
eP=$(relErr "$(column "$star" pStar)" "$(column "$star" pStarExact)")
eU=$(relErr "$(column "$star" uStar)" "$(column "$star" uStarExact)")
less "$eP" 0.05 || fail "star pressure $(column "$star" pStar) off exact $(column "$star" pStarExact) by $eP"
less "$eU" 0.05 || fail "star velocity $(column "$star" uStar) off exact $(column "$star" uStarExact) by $eU"
csv="$d/postProcessing/conserved/0/conservedQuantities.csv"
first=$(sed -n 2p "$csv"); last=$(tail -n 1 "$csv")
[ "$(echo "$first" | cut -d, -f2)" = "$(echo "$last" | cut -d, -f2)" ] || fail "mass changed: $first -> $last"
less "$(echo "$last" | cut -d, -f3 | sed "s/^-//")" 1e-12 || fail "momentum changed: $last"
dE=$(relErr "$(echo "$last" | cut -d, -f6)" "$(echo "$first" | cut -d, -f6)")
less "$dE" 1e-3 || fail "energy drift $dE"
wall=$(awk '/^ *wall time/ { print $3; exit }' "$d/log.impactSph")
pass "liquid-gas tube: P* error $eP, u* error $eU, energy drift $dE, wall time $wall s"
