# particleInfo on damaged particle files: $1 = build directory, $2 = the freeFall case to copy.
set -euo pipefail
export PATH="$1/bin:$PATH" OMP_NUM_THREADS=1
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-particleInfo.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
pass() { echo "PASS: $*"; }

c="$WORK/case"
cp -r "$2" "$c"
particleGen -case "$c" > "$WORK/log" 2>&1 || fail "particleGen: $(cat "$WORK/log")"
file="$c/0/particles.vtp"
cp "$file" "$WORK/good.vtp"

# run <what>: particleInfo on the case, with a timeout so that a reader that blocks fails the
# test instead of hanging it; sets $status, output in $WORK/log.
run() {
    status=0
    timeout 20 particleInfo -case "$c" -time 0 > "$WORK/log" 2>&1 || status=$?
    [ "$status" -ne 124 ] || fail "$1: particleInfo hung"
}
expectError() {  # <what> <pattern...>
    local what="$1"; shift
    run "$what"
    [ "$status" -eq 1 ] || fail "$what: exit status $status, expected 1: $(cat "$WORK/log")"
    for p in "$@"; do grep -qF -- "$p" "$WORK/log" || fail "$what: message lacks '$p': $(cat "$WORK/log")"; done
    ! grep -q "internal" "$WORK/log" || fail "$what: an internal error: $(cat "$WORK/log")"
    pass "$what"
}

# Byte offset in the file of the data of array <name> (after its 8-byte count).
dataOffset() {
    local underscore offset
    underscore=$(grep -boa '^ *_' "$file" | head -n 1 | cut -d: -f1)
    underscore=$((underscore + $(grep -boa '^ *_' "$file" | head -n 1 | cut -d: -f2 | tr -d '\n' | wc -c) - 1))
    offset=$(grep -ao "Name=\"$1\" NumberOfComponents=\"[0-9]*\" format=\"appended\" offset=\"[0-9]*\"" "$file" |
        sed 's/.*offset="\([0-9]*\)"/\1/')
    echo $((underscore + 1 + offset + 8))
}
# poke <array> <particle> <8 bytes as \x escapes>: overwrite one value in place.
poke() {
    printf "$3" | dd of="$file" bs=1 seek=$(($(dataOffset "$1") + 8 * $2)) conv=notrunc status=none
}

run "good file"
[ "$status" -eq 0 ] || fail "good file: $(cat "$WORK/log")"
grep -q "particles   1250" "$WORK/log" || fail "good file: no particle count: $(cat "$WORK/log")"
pass "good file"

# A region id of 4e8 made particleInfo allocate a 3.2 GB table of region counts.
poke region 7 '\x00\x84\xd7\x17\x00\x00\x00\x00'
expectError "region id 4e8" "$file" "particle 7 has region id 400000000" "region ids run from 0 to 1249"
cp "$WORK/good.vtp" "$file"

# A NaN density: the min/max reduction skipped it silently; it is now counted and located.
poke density 41 '\x00\x00\x00\x00\x00\x00\xf8\x7f'
run "NaN density"
[ "$status" -eq 0 ] || fail "NaN density: $(cat "$WORK/log")"
grep -q "field 'density' holds 1 NaN or infinite value, the first at particle 41" "$WORK/log" ||
    fail "NaN density not reported: $(cat "$WORK/log")"
grep -Eq "density +scalar +1000 +1000" "$WORK/log" || fail "NaN density: finite range lost: $(cat "$WORK/log")"
pass "NaN density"
cp "$WORK/good.vtp" "$file"

# NumberOfPoints near 2^61: the size check wrapped around and the reader ran on.
sed -i 's/NumberOfPoints="1250"/NumberOfPoints="2305843009213693952"/' "$file"
expectError "NumberOfPoints 2^61" "$file" "2305843009213693952 tuples" "bytes left in the file"
cp "$WORK/good.vtp" "$file"

# 100 000 nested elements in the header overflowed the parser's stack (SIGSEGV).
{ head -c 200 "$WORK/good.vtp" | head -n 3; for _ in $(seq 1 1000); do printf '<a><a><a><a><a><a><a><a><a><a>%.0s' $(seq 1 10); done; } > "$file"
expectError "deep nesting" "$file:" "nested more than 256 deep"

# A FIFO in place of the file blocked particleInfo in open().
rm "$file"
mkfifo "$file"
expectError "FIFO" "'$file' is not a regular file"
