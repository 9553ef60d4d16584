# One row of the extreme-case suite (doc/stability.md): runs tests/cases/extreme/cases/<row> and
# asserts what its `expected` file says.
#   bash runRow.sh <build> <source root> <row> [<table file>]
# `expected` holds one entry per line, `key: value`:
#   row:        the row's words in the table
#   solver:     the application (impactSph, tlSph, mpmFsi, fpmSolid)
#   outcome:    end (the run reaches endTime, exit 0) | stop (exit 1 with a diagnosis)
#   figure:     <error name> <relative|value> < <bound>   (outcome end: an "error <name> ..." line of
#               the summary, its relative error or value, absolute, below the bound; may repeat)
#   conservation: <quantity> < <bound>   (outcome end: conservedQuantities' summary line for it, its
#               change relative to its first value, absolute, below the bound; may repeat)
#   imbalance:  <bound>   (outcome end: the health line's |energy imbalance| in % below the bound)
#   diagnosis:  <extended regex>   (outcome stop: the log's Error text must match; may repeat)
#   undefined:  <csv file name> <column>   (a column whose NaN means "not defined here"; may repeat)
#   why:        the bound's reason (for the reader; not checked)
# Every row: no written file (CSV, particle state) holds a NaN or an infinity, the run does not
# hang (CTest's timeout), and the row's line (outcome, figures or diagnosis, run time) is appended
# to <table file> when one is given.
set -euo pipefail
BUILD="$1"
SOURCE="$2"
ROW="$3"
TABLE="${4:-}"
export PATH="$BUILD/bin:$PATH"
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-extreme.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $ROW: $*" >&2; exit 1; }
less() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a + 0 < b + 0) }'; }

ROWDIR="$SOURCE/tests/cases/extreme/cases/$ROW"
EXPECTED="$ROWDIR/expected"
[ -f "$EXPECTED" ] || fail "no $EXPECTED"
entry() { { grep -E "^$1:" "$EXPECTED" || true; } | sed -E "s/^$1:[[:space:]]*//"; }
solver=$(entry solver)
outcome=$(entry outcome)
words=$(entry row)
[ -n "$solver" ] && [ -n "$outcome" ] || fail "expected needs solver: and outcome:"

c="$WORK/case"
mkdir -p "$c"
cp -r "$ROWDIR/system" "$ROWDIR/constant" "$c/"
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen failed: $(tail -5 "$c/log.particleGen")"
start=$(date +%s.%N)
set +e
"$solver" -case "$c" > "$c/log.$solver" 2>&1
status=$?
set -e
seconds=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
log="$c/log.$solver"

# Never a NaN written: every CSV under postProcessing and every particle state. A function object
# marks a value it cannot define with NaN (riemannError's star state with no particle in the
# plateau, debrisCloud's length over width before there is debris): the row's `undefined:` entries
# name such columns (<file name> <column>), and only they may hold one.
while IFS= read -r file; do
    base=$(basename "$file")
    columns=$(entry undefined | awk -v f="$base" '$1 == f { print $2 }' | tr '\n' ' ')
    bad=$(awk -F, -v allowed="$columns" '
        NR == 1 { for (k = 1; k <= NF; ++k) name[k] = $k; n = split(allowed, a, " "); for (j = 1; j <= n; ++j) ok[a[j]] = 1; next }
        { for (k = 1; k <= NF; ++k) if (tolower($k) ~ /^[-+]?(nan|inf)/ && !(name[k] in ok)) { print name[k] " at row " NR; exit } }' "$file")
    [ -z "$bad" ] || fail "NaN or inf written in $file: column $bad"
done < <(find "$c/postProcessing" -name '*.csv' 2>/dev/null)
for t in $(ls "$c" | grep -E '^[0-9.e+-]+$'); do
    particleInfo -case "$c" -time "$t" > "$WORK/info" 2>&1 || fail "particleInfo cannot read time $t: $(tail -3 "$WORK/info")"
    if grep -q "non-finite values" "$WORK/info"; then
        fail "time $t holds non-finite values: $(grep -A3 'non-finite values' "$WORK/info" | tr '\n' ' ')"
    fi
done

summary=""
case "$outcome" in
end)
    [ "$status" = 0 ] || fail "expected the run to reach its end, exit status $status: $(grep -A3 '^Error' "$log" | head -5)"
    while read -r name kind op bound; do
        [ -n "$name" ] || continue
        line=$(grep -E "^    error $name " "$log" | tail -n 1)
        [ -n "$line" ] || fail "no 'error $name' line in the summary"
        value=$(echo "$line" | awk '{print $3}')
        relative=$(echo "$line" | sed -E 's/.*relative ([^)]*)\).*/\1/')
        figure="$value"
        [ "$kind" = relative ] && figure="$relative"
        absolute=$(awk -v a="$figure" 'BEGIN { printf "%.6g", a < 0 ? -a : a }')
        less "$absolute" "$bound" || fail "$name $kind $figure: |.| not below $bound"
        summary="$summary; $name $kind $(awk -v a="$figure" 'BEGIN { printf "%.3g", a }')"
    done < <(entry figure | sed 's/</ /' | awk '{ print $1, $2, "<", $3 }')
    while read -r quantity bound; do
        [ -n "$quantity" ] || continue
        line=$(grep -E "^    [A-Za-z]+: $quantity (change|drift) " "$log" | tail -n 1)
        [ -n "$line" ] || fail "no conservation line for $quantity in the summary"
        relative=$(echo "$line" | awk '{
            if ($3 == "drift") { print $4; exit }
            first = $5; sub(/^\(/, "", first); change = $4
            print (first == 0 ? change : change / (first < 0 ? -first : first)) }')
        absolute=$(awk -v a="$relative" 'BEGIN { printf "%.6g", a < 0 ? -a : a }')
        less "$absolute" "$bound" || fail "$quantity relative change $relative: |.| not below $bound"
        summary="$summary; $quantity change $(awk -v a="$relative" 'BEGIN { printf "%.3g", a }') relative"
    done < <(entry conservation | sed 's/</ /' | awk '{ print $1, $2 }')
    if bound=$(entry imbalance) && [ -n "$bound" ]; then
        imbalance=$(grep -E "^    health: energy imbalance" "$log" | sed -E 's/.*energy imbalance ([^%]*)%.*/\1/')
        [ -n "$imbalance" ] || fail "no health line in the summary"
        absolute=$(awk -v a="$imbalance" 'BEGIN { printf "%.6g", a < 0 ? -a : a }')
        less "$absolute" "$bound" || fail "energy imbalance $imbalance% not below $bound%"
        summary="$summary; energy imbalance $imbalance%"
    fi
    steps=$(grep -E "^    steps " "$log" | awk '{print $2}')
    summary="ran to the end ($steps steps)$summary"
    ;;
stop)
    [ "$status" = 1 ] || fail "expected a stop with a diagnosis (exit status 1), got $status"
    error=$(sed -n '/^Error/,/^$/p' "$log")
    [ -n "$error" ] || fail "exit status 1 without an Error text"
    while read -r pattern; do
        [ -n "$pattern" ] || continue
        echo "$error" | grep -qE -- "$pattern" || fail "the diagnosis does not match '$pattern': $error"
    done < <(entry diagnosis)
    # The failing state is written for diagnosis.
    grep -q "Wrote the failing state to" "$log" || fail "the failing state was not written"
    first=$(echo "$error" | sed -E 's/^Error: //' | tr -s ' \n' '  ' | cut -c1-400)
    summary="stopped: $first"
    ;;
*) fail "outcome must be end or stop, found '$outcome'" ;;
esac
echo "PASS: $ROW: $summary (${seconds} s)"
if [ -n "$TABLE" ]; then
    printf '| %s | %s | %s | %s |\n' "$words" "$solver" "${summary//|/\\|}" "$seconds s" >> "$TABLE"
fi
