#!/usr/bin/env bash
# Every citation of a method note resolves in a clone (issue 15 item 9). The notes live in
# doc/methods/; code, tests, tutorials, benchmarks and the generated model pages cite them as
# `doc/methods/<note>.md §N.M` (or "section N.M", or a bare N.M after the name). Fails, naming
# file:line, when
#   - a citation points outside the repository (../shared/..., /work/shared/..., shared/methods/),
#   - a note is named without its doc/methods/ path (a reader of a clone could not find it),
#   - the cited note does not exist, or the cited section is not one of its headings
#     ("## N." / "### N.M"; N.M is also accepted as item M of the numbered list of section N,
#     which is how the errata of sph-impact.md §12 are cited; "erratum M" means §12 item M).
# Usage: citations.sh <source root>. Exit 0 when every citation resolves, 1 otherwise.
set -u
root=${1:?usage: citations.sh <source root>}
cd "$root" || exit 1
export LC_ALL=C
notes='(sph-impact|tl-jst-sph|mpm|fpm)'
scan=()
for p in libraries applications tests tutorials bench doc/models README.md doc/architecture.md; do
    [ -e "$p" ] && scan+=("$p")
done
# files to read: text files under the scanned paths, not the notes themselves and not this
# folder (its negative test writes bad citations on purpose)
files=$(grep -rlIE "shared/|$notes\.md" "${scan[@]}" 2>/dev/null | grep -v '^tests/cases/docs/' | sort)
fail=0
report() { echo "citations: $1"; fail=1; }

# The sections a note has: headings, and N.M for list item M under "## N.".
sections() {
    awk '
        /^#+ [0-9]/ {
            s = $2; sub(/\.$/, "", s)
            if ($1 == "##") { split(s, a, "."); top = a[1] }
            print s; next
        }
        /^[0-9]+\. / && top != "" { n = $1; sub(/\.$/, "", n); print top "." n }
    ' "$1"
}
declare -A known
for f in doc/methods/*.md; do
    [ -e "$f" ] || continue
    name=${f#doc/methods/}
    while read -r s; do known["$name §$s"]=1; done < <(sections "$f")
    known["$name"]=1
done

for f in $files; do
    while IFS=: read -r line text; do
        report "$f:$line: cites a note outside the repository: $text"
    done < <(grep -nE '(\.\./|/work/)shared/|(^|[^a-z/])shared/methods' "$f")
    # every note name must be spelled doc/methods/<note>.md
    while IFS=: read -r line token; do
        case "$token" in
            doc/methods/*) ;;
            *) report "$f:$line: '$token' is not a path in the repository; cite doc/methods/${token##*/}" ;;
        esac
    done < <(grep -noE "[A-Za-z0-9_./-]*$notes\.md" "$f")
    # the note and its section exist
    while IFS=: read -r line cite; do
        name=$(echo "$cite" | grep -oE "$notes\.md" | head -n 1)
        if [ -z "${known[$name]:-}" ]; then
            report "$f:$line: doc/methods/$name does not exist (notes: $(ls doc/methods 2>/dev/null | tr '\n' ' '))"
            continue
        fi
        rest=${cite#doc/methods/$name}
        nums=$(echo "$rest" | sed -E 's/^,? *(§|sections? )?//; s/^erratum ([0-9]+)/12.\1/' |
            grep -oE '^[0-9]+(\.[0-9]+)?((-|–)[0-9]+(\.[0-9]+)?)?' | sed -E 's/(-|–)/ /')
        for n in $nums; do
            [ -n "${known[$name §$n]:-}" ] || report "$f:$line: doc/methods/$name has no section $n ($cite)"
        done
    done < <(grep -noE "doc/methods/$notes\.md,? *(§|sections? |erratum )?[0-9]*(\.[0-9]+)?((-|–)[0-9]+(\.[0-9]+)?)?" "$f")
done
if [ "$fail" = 0 ]; then
    echo "citations: every method-note citation in $(echo "$files" | grep -c .) files resolves"
fi
exit $fail
