# Sod's tube at three resolutions: spacings x2, x1 and x1/2 of the tutorial's (225, 450 and 900
# particles on [0, 1]; both regions scaled, so the masses stay equal). For a shock problem the L1
# error of a first-order-at-discontinuities scheme falls like h^1 at best (contacts smear like
# h^(1/2)), so the observed order log2(L1(2D)/L1(D)) must be at least 0.6 on both refinements.
. "$(dirname "$0")/common.sh"
declare -A l1
for f in 2 1 0.5; do
    c=$(newCase "$SOURCE/sodShockTube" "sod$f")
    setEntry "$c/system/particleGenDict" regions/left/lattice/spacing "$(awk -v f=$f 'BEGIN { print 0.00125 * f }')"
    setEntry "$c/system/particleGenDict" regions/right/lattice/spacing "$(awk -v f=$f 'BEGIN { print 0.01 * f }')"
    wall=$(runCase "$c")
    l1[$f]=$(lastRow "$c/postProcessing/riemann/0/errorNorms.csv" ",density," | cut -d, -f3)
    echo "spacing x$f: L1(rho) ${l1[$f]}, wall time $wall s"
done
order() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", log(a / b) / log(2) }'; }
o1=$(order "${l1[2]}" "${l1[1]}"); o2=$(order "${l1[1]}" "${l1[0.5]}")
echo "observed orders of L1(rho): $o1 (x2 -> x1), $o2 (x1 -> x1/2)"
less 0.6 "$o1" || fail "order $o1 < 0.6 from spacing x2 to x1"
less 0.6 "$o2" || fail "order $o2 < 0.6 from spacing x1 to x1/2"
pass "Sod L1(rho) ${l1[2]}, ${l1[1]}, ${l1[0.5]}: orders $o1, $o2"
