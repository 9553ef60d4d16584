# mfDictionary -entry on keys that contain '/' (a studyDict's resolution/scale entries are entry
# paths): `resolution/scale/system/controlDict/deltaT` reads and sets the key
# `system/controlDict/deltaT` of `scale` (the longest run of components that names a key), where
# before it could not be read and -set made nested dictionaries system { controlDict { ... } }
# inside scale without a word; a path that names none of those keys is refused with the file,
# line and the keys that begin like it, the file unchanged; an ordinary new entry is still added.
. "$(dirname "$0")/common.sh"
d="$WORK/studyDict"
cp "$SOURCE/sod/system/studyDict" "$d"
[ "$(mfDictionary "$d" -entry resolution/scale/system/controlDict/deltaT)" = "0.04" ] ||
    fail "cannot read a key containing '/': $(mfDictionary "$d" -entry resolution/scale/system/controlDict/deltaT 2>&1)"
mfDictionary "$d" -entry resolution/scale/system/controlDict/deltaT -set 0.03 || fail "cannot set a key containing '/'"
grep -q '^ *system/controlDict/deltaT  *0.03;$' "$d" || fail "the key was not set in place: $(cat "$d")"
! grep -q '^ *system$' "$d" || fail "nested dictionaries were made: $(cat "$d")"
[ "$(grep -c deltaT "$d")" = 1 ] || fail "deltaT written twice: $(cat "$d")"
[ "$(mfDictionary "$d" -entry resolution/scale/system/particleGenDict/regions/right/lattice/spacing)" = "8" ] || fail "right spacing"
before=$(cat "$d")
rc=0; mfDictionary "$d" -entry resolution/scale/system/controlDict/endTime -set 0.1 > "$WORK/out" 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "a path beside the '/' keys: exit status $rc, expected 1: $(cat "$WORK/out")"
line=$(grep -n '^    scale' "$d" | cut -d: -f1)
grep -q "studyDict:$line:.*no entry 'resolution/scale/system/controlDict/endTime'.*system/controlDict/deltaT" "$WORK/out" ||
    fail "the refusal does not name the file, line $line and the keys: $(cat "$WORK/out")"
[ "$(cat "$d")" = "$before" ] || fail "the refused edit changed the file"
mfDictionary "$d" -entry resolution/scale/other/x -set 1 || fail "a new nested entry is refused"
[ "$(mfDictionary "$d" -entry resolution/scale/other/x)" = 1 ] || fail "new nested entry not readable"
mfStudy -case "$SOURCE/sod" -list > /dev/null || fail "the fixture is broken"
pass "keys containing '/' are read and set in place; a path beside them is refused"
