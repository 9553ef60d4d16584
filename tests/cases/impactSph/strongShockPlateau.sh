# Strong shock tubes with the default dissipation (issue 16): equal densities, P_L/P_R = 10, 10^3 and
# 10^5, at spacings 0.0025 and 0.00125 (400 and 800 particles on [0, 1]). At each ratio the mean error
# of rho and P over the post-shock plateau at the finer spacing must be within 0.5% of the exact
# Riemann solution, and L1(rho) must fall with an observed order of at least 0.6 (first order at
# discontinuities, h^1/2 at the contact). The published mass flux (densityLimiter none) leaves the
# plateau off by a fixed fraction that does not shrink with h (+1.1% in rho and P at a ratio of 10 by
# the median, +0.8% by this mean): it is run too and must fail the same 0.5% bound, so that the cause
# stays measured. The three-resolution study:
# strongShockConvergence.sh (validation).
. "$(dirname "$0")/common.sh"
. "$(dirname "$0")/strongShockCommon.sh"
summary=""
for ratio in 10 1e3 1e5; do
    coarse=$(strongCase "r${ratio}_coarse" "$ratio" 0.0025)
    fine=$(strongCase "r${ratio}_fine" "$ratio" 0.00125)
    runCase "$coarse" > /dev/null
    wall=$(runCase "$fine")
    l1c=$(l1Density "$coarse")
    l1f=$(l1Density "$fine")
    read -r dRho dP n <<< "$(plateau "$fine")"
    o=$(order "$l1c" "$l1f")
    echo "ratio $ratio: L1(rho) $l1c, $l1f (order $o); post-shock plateau rho $(percent "$dRho"), P $(percent "$dP") over $n particles; wall time $wall s"
    less "$(abs "$dRho")" 0.005 || fail "ratio $ratio: post-shock density off by $(percent "$dRho") (bound 0.5%)"
    less "$(abs "$dP")" 0.005 || fail "ratio $ratio: post-shock pressure off by $(percent "$dP") (bound 0.5%)"
    less 0.6 "$o" || fail "ratio $ratio: observed order of L1(rho) $o < 0.6 ($l1c -> $l1f)"
    summary="$summary ratio $ratio: plateau $(percent "$dRho"), order $o;"
done
# The published term: the plateau error this default removes.
old=$(strongCase r10_none 10 0.00125 densityLimiter none)
runCase "$old" > /dev/null
read -r dRho dP n <<< "$(plateau "$old")"
echo "ratio 10, densityLimiter none: post-shock plateau rho $(percent "$dRho"), P $(percent "$dP")"
less 0.005 "$dRho" || fail "densityLimiter none: post-shock density $(percent "$dRho"), expected the published term's +0.8% (outside the bound)"
pass "$summary densityLimiter none at ratio 10: $(percent "$dRho")"
