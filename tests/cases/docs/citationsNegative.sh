#!/usr/bin/env bash
# citations.sh must fail on each kind of broken citation, naming the file and line: a tree is
# written here with one good citation and one of each bad kind, and each message is checked.
set -u
check=${1:?usage: citationsNegative.sh <path of citations.sh>}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/doc/methods" "$tmp/libraries/x"
cat > "$tmp/doc/methods/sph-impact.md" <<'NOTE'
# a note
## 1. Kernels
### 1.1 Forms
## 12. Errata
1. first
2. second
NOTE
ok=0
# A tree whose citations are all good passes: the check is not failing on everything.
printf '%s\n' '// good: doc/methods/sph-impact.md §1.1, doc/methods/sph-impact.md 12.2, erratum' \
    '// doc/methods/sph-impact.md erratum 1, doc/methods/sph-impact.md section 1' > "$tmp/libraries/x/Good.cpp"
if ! out=$(bash "$check" "$tmp"); then
    echo "FAIL: a tree of good citations was refused:"; echo "$out"; ok=1
fi
cat > "$tmp/libraries/x/Bad.cpp" <<'CODE'
// line 1: fine, doc/methods/sph-impact.md §1
// line 2: no such section, doc/methods/sph-impact.md §8.1
// line 3: outside the repository, ../shared/methods/sph-impact.md
// line 4: a bare name, tl-jst-sph.md 2.3
// line 5: no such note, doc/methods/mpm.md §1
// line 6: no such erratum, doc/methods/sph-impact.md erratum 7
CODE
out=$(bash "$check" "$tmp"); rc=$?
[ "$rc" = 1 ] || { echo "FAIL: exit status $rc for broken citations, expected 1"; ok=1; }
expect() {
    if ! grep -qF -- "$1" <<< "$out"; then echo "FAIL: no message containing: $1"; ok=1; fi
}
expect 'libraries/x/Bad.cpp:2: doc/methods/sph-impact.md has no section 8.1'
expect 'libraries/x/Bad.cpp:3: cites a note outside the repository'
expect "libraries/x/Bad.cpp:4: 'tl-jst-sph.md' is not a path in the repository; cite doc/methods/tl-jst-sph.md"
expect 'libraries/x/Bad.cpp:5: doc/methods/mpm.md does not exist'
expect 'libraries/x/Bad.cpp:6: doc/methods/sph-impact.md has no section 12.7'
if grep -q 'Bad.cpp:1:\|Good.cpp' <<< "$out"; then echo "FAIL: a good citation was reported:"; ok=1; fi
[ "$ok" = 0 ] && echo "citationsNegative: every broken citation reported" || echo "$out"
exit $ok
