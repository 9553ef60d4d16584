#!/usr/bin/env bash
# Regenerates the table of doc/stability.md: runs every row of the extreme-case suite
# (tests/cases/extreme/cases/*) with runRow.sh and replaces the lines between the markers
# "<!-- table -->" and "<!-- end of table -->" with one line per row (a failing row says FAILED
# and why). Usage: tests/cases/extreme/stabilityTable.sh [<build directory>] [--quick]
#   --quick: rerun the default suite's rows only; a row labelled validation keeps its line from the
#            last full run
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
build="${1:-$root/build}"
quick="${2:-}"
doc="$root/doc/stability.md"
table="$(mktemp)"
trap 'rm -f "$table"' EXIT
printf '| row | solver | outcome: figures, or the diagnosis | run time (1 thread) |\n|---|---|---|---|\n' > "$table"
for dir in "$here"/cases/*/; do
    row=$(basename "$dir")
    [ -f "$dir/expected" ] || continue
    words=$(grep -E "^row:" "$dir/expected" | sed -E 's/^row:[[:space:]]*//')
    if [ "$quick" = --quick ] && grep -q "^label: *validation" "$dir/expected"; then
        # Not rerun: the line of the last full run stays (none yet: said so).
        line=$(grep -F "| $words |" "$doc" | head -n 1)
        [ -n "$line" ] || line="| $words | $(grep -E '^solver:' "$dir/expected" | sed -E 's/^solver:[[:space:]]*//') | not run yet (validation row: run without --quick) | |"
        echo "$line" >> "$table"
        continue
    fi
    solver=$(grep -E "^solver:" "$dir/expected" | sed -E 's/^solver:[[:space:]]*//')
    if ! out=$(OMP_NUM_THREADS=1 bash "$here/runRow.sh" "$build" "$root" "$row" "$table" 2>&1); then
        printf '| %s | %s | FAILED: %s | |\n' "$words" "$solver" "$(echo "$out" | tail -n 1 | cut -c1-200 | sed 's/|/\\|/g')" >> "$table"
    fi
    echo "$out" | tail -n 1
done
awk -v table="$table" '
    /<!-- table -->/ { print; while ((getline line < table) > 0) print line; skip = 1; next }
    /<!-- end of table -->/ { skip = 0 }
    !skip' "$doc" > "$doc.tmp" && mv "$doc.tmp" "$doc"
echo "wrote $doc"
