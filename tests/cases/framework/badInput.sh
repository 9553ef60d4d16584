# Bad input ends with a clear message and exit status 1, and leaves earlier results alone.
. "$(dirname "$0")/common.sh"
c=$(newCase bad)
cp -r "$c/0" "$WORK/0.orig"

expectFailure() {  # <what> <pattern...>: the last run must exit 1 and print every pattern
    local what="$1"; shift
    [ "$status" -eq 1 ] || fail "$what: exit status $status, expected 1: $(cat "$c/log")"
    for p in "$@"; do grep -q -- "$p" "$c/log" || fail "$what: message lacks '$p': $(cat "$c/log")"; done
    pass "$what"
}

# A wrong model type names the file and line and lists the valid types.
sed -i 's/uniformGravity/uniformGravty/' "$c/constant/particleFlightProperties"
status=0; particleFlight -case "$c" > "$c/log" 2>&1 || status=$?
expectFailure "wrong bodyForce type" "particleFlightProperties:1:" "unknown bodyForce type 'uniformGravty'" \
    "did you mean 'uniformGravity'" "valid bodyForce types" "uniformGravity"
sed -i 's/uniformGravty/uniformGravity/' "$c/constant/particleFlightProperties"

# A wrong function object type.
sed -i 's/type conservedQuantities/type conservedQuantity/' "$c/system/controlDict"
status=0; particleFlight -case "$c" > "$c/log" 2>&1 || status=$?
expectFailure "wrong functionObject type" "controlDict:" "conservedQuantities" "fieldMinMax" "trajectoryError"
sed -i 's/type conservedQuantity;/type conservedQuantities;/' "$c/system/controlDict"

# A library that cannot be loaded: every path tried and the loader's message.
mfDictionary "$c/system/controlDict" -entry libs -set '("libnoSuchModels.so")' > /dev/null
status=0; particleFlight -case "$c" > "$c/log" 2>&1 || status=$?
expectFailure "missing library" "cannot load library 'libnoSuchModels.so'" "$c/libnoSuchModels.so: no such file" \
    "system loader path" "controlDict:"
sed -i '/libnoSuchModels/d' "$c/system/controlDict"

# A misspelt keyword: a warning by default, fatal under strictDictionaries, with a suggestion.
mfDictionary "$c/system/controlDict" -entry writeInterval -set 0.25 > /dev/null
echo "purgeWrit 2;" >> "$c/system/controlDict"
mfDictionary "$c/system/controlDict" -entry endTime -set 0.1 > /dev/null
status=0; particleFlight -case "$c" > "$c/log" 2>&1 || status=$?
[ $status -eq 0 ] || fail "misspelt keyword without strictDictionaries should only warn: $(cat "$c/log")"
grep -q "'purgeWrit' was never read (did you mean 'purgeWrite'?)" "$c/log" || fail "no did-you-mean warning: $(cat "$c/log")"
rm -rf "$c/0.1" "$c/particles.pvd" "$c/postProcessing"
echo "strictDictionaries yes;" >> "$c/system/controlDict"
status=0; particleFlight -case "$c" > "$c/log" 2>&1 || status=$?
expectFailure "strictDictionaries" "never read" "did you mean 'purgeWrite'"
sed -i '/purgeWrit /d;/strictDictionaries/d' "$c/system/controlDict"

# A syntax error: file:line:column.
echo "endTime 0.2" >> "$c/system/controlDict"
status=0; particleFlight -case "$c" > "$c/log" 2>&1 || status=$?
expectFailure "missing semicolon" "controlDict:"

diff -r "$c/0" "$WORK/0.orig" > /dev/null || fail "the initial conditions were modified by failed runs"
pass "bad input"
