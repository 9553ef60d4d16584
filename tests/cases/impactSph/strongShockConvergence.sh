# The strong shock tubes of strongShockPlateau.sh at three spacings, 0.0025, 0.00125 and 0.000625 (400
# to 1600 particles on [0, 1]), with the default dissipation (validation: about a minute on one core).
# At each pressure ratio (10, 10^3, 10^5) the observed order of L1(rho) must be at least 0.6 on both
# refinements and the post-shock plateau within 0.5% in rho and P at the finest spacing, and again
# at the finest spacing with half the Courant number (maxCo 0.1): the published mass flux's plateau
# error shrinks with neither h nor the step (issue 16), so both must meet the bound.
. "$(dirname "$0")/common.sh"
. "$(dirname "$0")/strongShockCommon.sh"
summary=""
for ratio in 10 1e3 1e5; do
    declare -A l1=()
    for dx in 0.0025 0.00125 0.000625; do
        c=$(strongCase "r${ratio}_$dx" "$ratio" "$dx")
        wall=$(runCase "$c")
        l1[$dx]=$(l1Density "$c")
        echo "ratio $ratio spacing $dx: L1(rho) ${l1[$dx]}, wall time $wall s"
    done
    o1=$(order "${l1[0.0025]}" "${l1[0.00125]}")
    o2=$(order "${l1[0.00125]}" "${l1[0.000625]}")
    read -r dRho dP n <<< "$(plateau "$c")"
    half=$(strongCase "r${ratio}_co0.1" "$ratio" 0.000625)
    setEntry "$half/system/controlDict" maxCo 0.1
    runCase "$half" > /dev/null
    read -r hRho hP hn <<< "$(plateau "$half")"
    echo "ratio $ratio: orders $o1, $o2; finest plateau rho $(percent "$dRho"), P $(percent "$dP") ($n particles); at maxCo 0.1 rho $(percent "$hRho"), P $(percent "$hP")"
    less 0.6 "$o1" || fail "ratio $ratio: order $o1 < 0.6 from 0.0025 to 0.00125"
    less 0.6 "$o2" || fail "ratio $ratio: order $o2 < 0.6 from 0.00125 to 0.000625"
    less "$(abs "$dRho")" 0.005 || fail "ratio $ratio: finest post-shock density off by $(percent "$dRho")"
    less "$(abs "$dP")" 0.005 || fail "ratio $ratio: finest post-shock pressure off by $(percent "$dP")"
    less "$(abs "$hRho")" 0.005 || fail "ratio $ratio: at maxCo 0.1 the post-shock density is off by $(percent "$hRho")"
    less "$(abs "$hP")" 0.005 || fail "ratio $ratio: at maxCo 0.1 the post-shock pressure is off by $(percent "$hP")"
    summary="$summary ratio $ratio: orders $o1, $o2, plateau $(percent "$dRho");"
done
pass "$summary"
