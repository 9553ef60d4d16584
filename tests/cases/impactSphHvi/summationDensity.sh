# Summation density with h solved per particle by Newton (number scheme) meets the Sod bounds:
# L1(rho) on [0, 1] below 1.5e-2, star pressure and velocity within 2%, energy drift below 1e-4.
. "$(dirname "$0")/common.sh"
c="$WORK/sodSum"
mkdir -p "$c" && cp -r "$TUTORIALS/sodShockTube/system" "$TUTORIALS/sodShockTube/constant" "$c/"
mfDictionary "$c/constant/sphProperties" -entry densityScheme/form -set summation > /dev/null
mfDictionary "$c/constant/sphProperties" -entry smoothingLength -set "{ type summation; eta 1.2; }" > /dev/null
particleGen -case "$c" > /dev/null 2>&1 || fail "particleGen failed"
impactSph -case "$c" > "$c/log" 2>&1 || fail "impactSph failed: $(tail -5 "$c/log")"
l1=$(grep ",density," "$c/postProcessing/riemann/0/errorNorms.csv" | tail -n 1 | cut -d, -f3)
less "$l1" 1.5e-2 || fail "L1(rho) $l1"
row=$(tail -n 1 "$c/postProcessing/riemann/0/starState.csv")
IFS=, read -r t p pe u ue <<< "$row"
less "$(abs "$(awk -v a="$p" -v b="$pe" 'BEGIN { print (a - b) / b }')")" 0.02 || fail "P* $p vs $pe"
less "$(abs "$(awk -v a="$u" -v b="$ue" 'BEGIN { print (a - b) / b }')")" 0.02 || fail "u* $u vs $ue"
energy=$(drift "$c/log" totalEnergy)
less "$(abs "$energy")" 1e-4 || fail "energy drift $energy"
pass "summation density and smoothing length (Newton) on Sod: L1(rho) $l1, P* $p ($pe), u* $u ($ue), energy drift $energy"
