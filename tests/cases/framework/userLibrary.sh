# The template user library builds out of tree with find_package(mfdyn), is loaded by libs (...),
# and its model (harmonicTrap) is selected and used: the orbit matches the exact solution within
# velocity Verlet's phase error A ω³ dt² t / 24 (A = 0.77 m, ω = 2π, dt = 1e-3, t = 1:
# 8e-6 m; the bound below is twice that), and is not exact (the model really ran).
. "$(dirname "$0")/common.sh"
TEMPLATE="$SOURCE/../../../tutorials/userLibrary/harmonicTrap"
cp -r "$TEMPLATE" "$WORK/lib"
rm -rf "$WORK/lib/build" "$WORK/lib/case/log."* 
cmake -S "$WORK/lib" -B "$WORK/lib/build" -DCMAKE_BUILD_TYPE=Release -Dmfdyn_DIR="$BUILD" > "$WORK/cmake.log" 2>&1 \
    || fail "configuring the user library failed: $(cat "$WORK/cmake.log")"
cmake --build "$WORK/lib/build" > "$WORK/build.log" 2>&1 || fail "building the user library failed: $(cat "$WORK/build.log")"
[ -f "$WORK/lib/build/libharmonicTrap.so" ] || fail "no libharmonicTrap.so"
export MFDYN_LIBRARY_PATH="$WORK/lib/build"
c="$WORK/lib/case"
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen failed"
particleFlight -listModels -case "$c" > "$WORK/models" 2>&1 || fail "-listModels failed"
grep -q "harmonicTrap.*libharmonicTrap.so" "$WORK/models" || fail "-listModels does not show harmonicTrap: $(cat "$WORK/models")"
particleFlight -case "$c" > "$c/log" 2>&1 || fail "the case failed: $(tail -20 "$c/log")"
grep -q "Loaded library .*libharmonicTrap.so" "$c/log" || fail "library not reported loaded"
row=$(lastRow "$c/postProcessing/trajectory/0/errorNorms.csv" ",position,")
linf=$(echo "$row" | cut -d, -f5)
less "$linf" 1.6e-5 || fail "harmonicTrap orbit error $linf m exceeds the Verlet bound"
less 1e-9 "$linf" || fail "orbit error $linf m is implausibly small: was the model used?"
pass "user library harmonicTrap: orbit error $linf m"
