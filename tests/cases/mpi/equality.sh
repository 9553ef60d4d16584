# The final state on 1 (mpirun -np 1), 2, 3 and 4 ranks against the serial run, to 1e-12 relative in
# every field (particleCompare), for Sod's tube (1D, 1000 steps) and the Al-Al impact (2D, strength,
# with migrations and a rebalance on the way), and the impact under the Hilbert-curve partition.
# Which fields are the same to the bit is printed (every one, since the neighbour rows are in
# global-id order).
. "$(dirname "$0")/common.sh"
endSod=0.05 endHvi=5e-6
for name in sod hvi; do
    if [ $name = sod ]; then serial=$(sodCase sod.serial $endSod); else serial=$(hviCase hvi.serial $endHvi); fi
    impactSph -case "$serial" > "$serial/log" 2>&1 || fail "$name serial: $(tail -3 "$serial/log")"
    for n in 1 2 3 4; do
        c=$(copyCase "$serial" "$WORK/$name.$n")
        onRanks "$n" impactSph -case "$c" > "$c/log" 2>&1 || fail "$name on $n ranks: $(grep -m1 -A2 Error "$c/log" || tail -3 "$c/log")"
        [ "$n" = 1 ] || grep -q "^Decomposed over $n ranks" "$c/log" || fail "$name on $n ranks: no decomposition in the log"
        sameState "$name, $n ranks against the serial run" "$(latest "$serial")" "$(latest "$c")"
    done
done
# The Hilbert-curve partition (irregular parts: more halo, more migrations) alike.
c=$(copyCase "$WORK/hvi.serial" "$WORK/hvi.hsfc")
printf 'method hsfc;\n' > "$c/system/decomposeParDict"
onRanks 3 impactSph -case "$c" > "$c/log" 2>&1 || fail "hvi with hsfc on 3 ranks: $(grep -m1 -A2 Error "$c/log" || tail -3 "$c/log")"
grep -q "^Decomposition (hsfc, 3 ranks" "$c/log" || fail "hvi with hsfc: no hsfc decomposition in the log"
sameState "hvi, hsfc on 3 ranks against the serial run" "$(latest "$WORK/hvi.serial")" "$(latest "$c")"
pass "Sod and the Al-Al impact on 1-4 ranks (rcb) and 3 (hsfc) equal the serial runs to 1e-12"
