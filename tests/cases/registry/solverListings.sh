# The solver registry seen from the built applications. $1 = build directory, $2 = source tree.
#  - each solver application records its method's library as NEEDED: the registration is a
#    static object there that the program never references, so a linker with --as-needed would
#    drop the library and the solver would not be found by name;
#  - `<app> -describe <solver>` gives the solver's dictionary and keywords, and `<app>
#    -listModels` lists them before every family;
#  - impactSph and tlSph name their dictionary, their keywords and their own dissipation family;
#  - `-describe dissipation` lists every method's dissipation family, each by its scoped name;
#  - mfDoc writes doc/models/solver/<name>.md and doc/models/<method>/<family>/<type>.md, and
#    every relative link of every page (a scoped page is one folder deeper) names a file;
#  - installed (cmake --install into a fresh prefix), particleFlight finds its solver and runs;
#  - an unknown name is an error with exit status 1 naming the families.
set -euo pipefail
BUILD="$1"
SOURCE="${2:-}"
export PATH="$BUILD/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-test.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
cd "$WORK"
fail() { echo "FAIL: $*" >&2; exit 1; }

for pair in particleFlight:libmfdyn_ballistics.so impactSph:libmfdyn_sph.so tlSph:libmfdyn_tlSph.so; do
    app=${pair%%:*} lib=${pair#*:}
    readelf -d "$BUILD/bin/$app" | grep -q "NEEDED.*\[$lib\]" ||
        fail "$app does not record $lib as NEEDED: its solver registration would not be loaded"
done

# particleFlight: its keywords, from its schema, with their units.
particleFlight -describe particleFlight > describe.txt 2>&1 || fail "-describe particleFlight failed: $(cat describe.txt)"
grep -q "^solver particleFlight: " describe.txt || fail "no solver heading: $(cat describe.txt)"
grep -q "dictionary: constant/particleFlightProperties" describe.txt || fail "no dictionary: $(cat describe.txt)"
grep -q "lengthScale  \[m\]  required  a real number, > 0" describe.txt || fail "no lengthScale: $(cat describe.txt)"
grep -q "bodyForce  \[-\]  required  a dictionary" describe.txt || fail "no bodyForce: $(cat describe.txt)"

particleFlight -listModels > list.txt 2>&1 || fail "-listModels failed"
[ "$(head -n 1 list.txt)" = "solver particleFlight: Particles in free flight under a body force, velocity Verlet" ] ||
    fail "-listModels does not start with the application's solver: $(head -n 3 list.txt)"
first=$(grep -n "lengthScale" list.txt | head -n 1 | cut -d: -f1)
family=$(grep -n "^equationOfState$" list.txt | cut -d: -f1)
[ -n "$first" ] && [ -n "$family" ] && [ "$first" -lt "$family" ] ||
    fail "the solver's keywords are not listed before the families: $(head -n 8 list.txt)"
[ "$(grep -c "lengthScale" list.txt)" = 1 ] || fail "lengthScale listed more than once"
grep -q "^solver$" list.txt || fail "no solver family in the listing"

# impactSph and tlSph: each describes its own solver with its dictionary and keywords, and lists
# them before the families.
for pair in impactSph:sphProperties tlSph:tlSphProperties; do
    app=${pair%%:*} dict=${pair#*:}
    "$app" -describe "$app" > "describe.$app" 2>&1 || fail "$app -describe $app failed: $(cat "describe.$app")"
    grep -q "^solver $app: " "describe.$app" || fail "$app -describe $app: $(head -n 3 "describe.$app")"
    grep -q "dictionary: constant/$dict" "describe.$app" || fail "$app: no dictionary: $(cat "describe.$app")"
    grep -q "^    keywords:" "describe.$app" || fail "$app -describe $app shows no keywords"
    grep -q "^        dissipation  \[-\]" "describe.$app" || fail "$app: no dissipation keyword: $(cat "describe.$app")"
    grep -q "families of this method.*$app/dissipation" "describe.$app" ||
        fail "$app: its dissipation family is not named: $(cat "describe.$app")"
    "$app" -listModels > "list.$app" 2>&1 || fail "$app -listModels failed"
    head -n 1 "list.$app" | grep -q "^solver $app: " || fail "$app -listModels starts: $(head -n 2 "list.$app")"
    grep -q "^    keywords of constant/$dict:" "list.$app" || fail "$app -listModels: $(head -n 3 "list.$app")"
done

# Scoped families: `dissipation` names each method's, `tlSph/dissipation` only tlSph's.
particleFlight -describe dissipation > dissipation.txt 2>&1 || fail "-describe dissipation failed"
for method in impactSph tlSph; do
    grep -q "^dissipation ($method)$" dissipation.txt ||
        fail "-describe dissipation does not list dissipation ($method): $(grep -v '^ ' dissipation.txt)"
done
particleFlight -describe tlSph/dissipation > tl.txt 2>&1 || fail "-describe tlSph/dissipation failed"
grep -q "^dissipation (tlSph)$" tl.txt && ! grep -q "(impactSph)" tl.txt || fail "tlSph/dissipation: $(cat tl.txt)"

# An unknown name: exit status 1, the families listed by their names.
status=0
particleFlight -describe solver/particleFlite > bad.txt 2>&1 || status=$?
[ "$status" = 1 ] || fail "an unknown -describe gave status $status"
grep -q "no model family or type 'solver/particleFlite'; did you mean 'solver/particleFlight'" bad.txt ||
    fail "unknown -describe message: $(cat bad.txt)"
# mfDoc's layout, and its links resolved from where the pages are committed (doc/models).
if [ -n "$SOURCE" ]; then
    mfDoc -output "$WORK/models" > mfdoc.txt 2>&1 || fail "mfDoc failed: $(cat mfdoc.txt)"
    for page in solver/particleFlight.md solver/impactSph.md solver/tlSph.md \
        impactSph/dissipation/riemann.md tlSph/dissipation/jst.md equationOfState/idealGas.md; do
        [ -f "$WORK/models/$page" ] || fail "mfDoc wrote no $page: $(cd "$WORK/models" && find . -name '*.md' | head)"
    done
    grep -q "(solver/tlSph.md)" "$WORK/models/README.md" || fail "the README does not index solver/tlSph.md"
    grep -q "(tlSph/dissipation/jst.md)" "$WORK/models/README.md" || fail "the README does not index tlSph/dissipation/jst.md"
    grep -q "\[jst\](../tlSph/dissipation/jst.md)" "$WORK/models/solver/tlSph.md" ||
        fail "tlSph's page does not link its dissipation types"
    checked=0
    while IFS= read -r page; do
        rel=${page#"$WORK/models/"}
        dir=$(dirname "$SOURCE/doc/models/$rel")
        for link in $(grep -o '](\.[^)#]*)' "$page" | sed 's/^](//; s/)$//'); do
            [ -e "$dir/$link" ] || fail "$rel links $link, which does not exist"
            checked=$((checked + 1))
        done
    done < <(find "$WORK/models" -name '*.md')
    [ "$checked" -gt 100 ] || fail "only $checked links checked: the link pattern no longer matches the pages"
fi
# Installed: the copy of the program and libraries in a prefix selects its solver by name and runs
# the proof case. LD_LIBRARY_PATH because the installed RUNPATH is the configured
# CMAKE_INSTALL_PREFIX, not the --prefix given here.
if [ -n "$SOURCE" ]; then
    cmake --install "$BUILD" --prefix "$WORK/prefix" > install.txt 2>&1 || fail "install failed: $(tail install.txt)"
    cp -r "$SOURCE/tests/cases/framework/freeFall" "$WORK/installed"
    env -i PATH=/usr/bin:/bin HOME="$WORK" OMP_WAIT_POLICY=PASSIVE LD_LIBRARY_PATH="$WORK/prefix/lib" \
        bash -c "'$WORK/prefix/bin/particleGen' -case '$WORK/installed' && '$WORK/prefix/bin/particleFlight' -case '$WORK/installed'" \
        > installed.txt 2>&1 || fail "the installed particleFlight failed: $(tail installed.txt)"
    grep -q "^End" installed.txt || fail "the installed particleFlight did not finish: $(tail installed.txt)"
fi
echo "PASS: solver registry listings"
