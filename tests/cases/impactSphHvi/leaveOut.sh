# A scene allocates only what its models use: a gas has no deviatoric stress, plastic strain or
# stress rate terms; the log lists the fields and the bytes per particle.
. "$(dirname "$0")/common.sh"
c="$WORK/sod"
mkdir -p "$c" && cp -r "$TUTORIALS/sodShockTube/system" "$TUTORIALS/sodShockTube/constant" "$c/"
mfDictionary "$c/system/controlDict" -entry endTime -set 0.01 > /dev/null
particleGen -case "$c" > /dev/null 2>&1 || fail "particleGen failed"
impactSph -case "$c" > "$c/log" 2>&1 || fail "impactSph failed: $(tail -5 "$c/log")"
grep -q "^Fields (.* per particle)" "$c/log" || fail "no field list with bytes per particle"
for field in deviatoricStress plasticStrain temperature; do
    grep -q "^    $field " "$c/log" && fail "a gas allocated $field"
done
grep -q "phase strength" "$c/log" && grep "phase strength" "$c/log" | grep -qv " 0 s" && fail "a gas ran strength terms"
bytes=$(grep "^Fields (" "$c/log" | sed 's/Fields (\([0-9]*\) B.*/\1/')
pass "gas case: $bytes bytes per particle, no stress fields"
