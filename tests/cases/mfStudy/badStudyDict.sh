# A bad studyDict is an input error before any run: exit status 1, the message names studyDict's
# file and line (where the bad entry is) and the valid choices, and nothing is written (no study/).
. "$(dirname "$0")/common.sh"

# expectError <name> <studyDict text> <line> <text the message must hold>
expectError() {
    local c status=0
    c=$(newCase "$1")
    printf '%s\n' "$2" > "$c/system/studyDict"
    mfStudy -case "$c" > "$c/log.mfStudy" 2>&1 || status=$?
    [ "$status" = 1 ] || fail "$1: exit status $status, expected 1: $(cat "$c/log.mfStudy")"
    grep -qF "Error: $c/system/studyDict:$3:" "$c/log.mfStudy" || fail "$1: no studyDict:$3 in: $(cat "$c/log.mfStudy")"
    grep -qF -- "$4" "$c/log.mfStudy" || fail "$1: message lacks '$4': $(cat "$c/log.mfStudy")"
    [ -e "$c/study" ] && fail "$1: study/ was written before the error"
    ls "$c" | grep -qE '^(0|log\.particleGen)$' && fail "$1: something ran"
    echo "ok $1: $(grep Error "$c/log.mfStudy")"
}
scale='resolution { spacing (0.01 0.005); scale { system/particleGenDict/regions/left/lattice/spacing 1; } }'

expectError missingEntry "$scale
axes
{
    side { entry system/particleGenDict/regions/rigth/lattice/spacing; values (0.04 0.08); }
}" 4 "has no entry 'regions/rigth'; valid choices at regions: left | right"

expectError missingFile "run application;
variants { a { system/controlDic/deltaT 1e-4; } }" 2 \
    "valid choices: constant/materialProperties | constant/sphProperties | system/controlDict | system/particleGenDict"

expectError emptySpacing "resolution
{
    spacing ();
    scale { system/controlDict/deltaT 0.04; }
}" 3 "empty list of spacings"

expectError emptyValues "axes
{
    kernel { entry constant/sphProperties/kernel/type; values (); }
}" 3 "empty list of values"

expectError emptyVariants "variants
{
}" 1 "empty list of variants"

expectError wordForNumber "axes
{
    step { entry system/controlDict/deltaT; values (1e-4 fast); }
}" 3 "'fast' is not a number, and system/controlDict/deltaT is one"

expectError badSpacing "resolution
{
    spacing (0.01 fine);
    scale { system/controlDict/deltaT 0.04; }
}" 3 "expected a list of reals"

expectError badScale "resolution
{
    spacing (0.01 0.005);
    scale { system/controlDict/deltaT fast; }
}" 4 "valid forms: factor (value = factor h), (factor power)"

expectError syntax "variants
{
    a { system/controlDict/deltaT 1e-4 }
}" 3 ""

expectError unknownKeyword "$scale
job 2;" 2 "unknown keyword 'job' (did you mean 'jobs'?); valid choices: run | jobs | error | resolution | axes | variants"

expectError badRun "$scale
run sometimes;" 2 "valid choices: auto | allrun | application"
expectError unknownFunctionObject "$scale
error riemman/density/L1;" 2 "'riemman' is not a function object of system/controlDict; valid choices: riemann"
# The quantities (values no summary prints) are quoted shell commands; the scale rules of a list
# entry give as many components as it has.
expectError unquotedQuantity "$scale
quantities
{
    twist awk;
}" 4 "quantity 'twist' must be one quoted shell command"
expectError scaleComponents "resolution { spacing (0.01 0.005); scale { system/particleGenDict/regions/left/shape/min ((1 -1 0) 0); } }" 1 \
    "gives 2 components, and it has 1"
pass "every bad studyDict stopped before any run with its file, line and choices"
