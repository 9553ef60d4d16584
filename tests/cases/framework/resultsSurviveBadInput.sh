# Earlier results survive bad input. A case with results (time directories, particles.pvd,
# postProcessing CSVs) is rerun with each of its dictionaries broken in turn: a wrong model type,
# a syntax error, a bad value, a bad last function object, a misspelt entry under
# strictDictionaries. Every run must end with exit status 1 and a message naming the file, and
# leave every file of the case byte-identical (and no file added or removed): nothing is written,
# moved, truncated or swept before all the input has been read and checked.
# Both ways of rerunning: a fresh start (startFrom startTime, what a user does after editing the
# input) and a restart (startFrom latestTime with a later endTime).
. "$(dirname "$0")/common.sh"

# Every path of the case with each file's sha256, directories listed too.
snapshot() { (cd "$1" && find . | LC_ALL=C sort | while read -r f; do
    if [ -f "$f" ]; then sha256sum "$f"; else echo "$(stat -c %F "$f") $f"; fi; done); }

# breakAndRun <what> <file relative to the case> <sed script | +text to append> <message pattern...>
breakAndRun() {
    local what="$1" file="$c/$2" edit="$3"; shift 3
    cp "$file" "$WORK/original"
    if [ "${edit:0:1}" = + ]; then printf '%s\n' "${edit:1}" >> "$file"; else sed -i "$edit" "$file"; fi
    cmp -s "$file" "$WORK/original" && fail "$what: the edit '$edit' did not change $2"
    # The snapshot is of the case as broken: only the broken dictionary itself may differ.
    local before; before=$(snapshot "$c")
    status=0; $solver -case "$c" > "$WORK/log" 2>&1 || status=$?
    local after; after=$(snapshot "$c")
    cp "$WORK/original" "$file"
    [ "$status" -eq 1 ] || fail "$mode, $what: exit status $status, expected 1: $(tail -n 5 "$WORK/log")"
    grep -q "^Error" "$WORK/log" || fail "$mode, $what: no error message: $(tail -n 5 "$WORK/log")"
    for p in "$@"; do grep -q -- "$p" "$WORK/log" || fail "$mode, $what: the message lacks '$p': $(grep -A3 '^Error' "$WORK/log")"; done
    [ "$before" = "$after" ] || fail "$mode, $what: earlier results changed:
$(diff <(echo "$before") <(echo "$after"))"
    pass "$mode, $what: status 1, every earlier file unchanged"
}

freeFallBreaks() {
    local fo='s/^}$/    last { type noSuchFunction; }\n}/'
    breakAndRun "wrong model type" constant/particleFlightProperties 's/uniformGravity/uniformGravty/' \
        "particleFlightProperties:1:" "unknown bodyForce type 'uniformGravty'" "uniformGravity"
    breakAndRun "syntax error" constant/particleFlightProperties 's/lengthScale 0.02;/lengthScale 0.02/' \
        "particleFlightProperties:"
    breakAndRun "bad value" constant/particleFlightProperties 's/g (0 -9.81)/g (0 fast)/' "particleFlightProperties:"
    breakAndRun "controlDict syntax error" system/controlDict 's/^endTime .*/endTime 1.0/' "controlDict:"
    breakAndRun "controlDict bad value" system/controlDict 's/^maxCo .*/maxCo -0.5;/' "controlDict:" "maxCo"
    breakAndRun "bad last function object (unknown type)" system/controlDict "$fo" "controlDict:" \
        "noSuchFunction" "conservedQuantities"
    breakAndRun "bad last function object (bad keyword value)" system/controlDict \
        's/^}$/    last { type fieldMinMax; fields (velocity); mode sideways; }\n}/' "controlDict:" "sideways"
    breakAndRun "misspelt entry under strictDictionaries" system/controlDict \
        '+purgeWrit 2; strictDictionaries yes;' "'purgeWrit' was never read" "did you mean 'purgeWrite'"
}

solver=particleFlight
c=$(newCase fresh)
mfDictionary "$c/system/controlDict" -entry startFrom -set startTime > /dev/null
particleFlight -case "$c" > "$WORK/log" 2>&1 || fail "the first run failed: $(tail "$WORK/log")"
[ -d "$c/1" ] && [ -s "$c/postProcessing/conserved/0/conservedQuantities.csv" ] || fail "the first run left no results"
mode="fresh start"
freeFallBreaks

c=$(newCase restart)
mfDictionary "$c/system/controlDict" -entry endTime -set 0.5 > /dev/null
particleFlight -case "$c" > "$WORK/log" 2>&1 || fail "the first half failed: $(tail "$WORK/log")"
mfDictionary "$c/system/controlDict" -entry endTime -set 1.0 > /dev/null
mode="restart"
freeFallBreaks

# A tlSph case with a boundary condition (tests/cases/tlSph/tractionCube, 216 particles).
tlSphBreaks() {
    breakAndRun "wrong boundary condition type" constant/boundaryConditions 's/prescribedTraction/prescribedTractoin/' \
        "boundaryConditions:" "prescribedTraction"
    breakAndRun "boundary condition bad value" constant/boundaryConditions 's/traction (1e5 0 0)/traction (1e5 0)/' \
        "boundaryConditions:"
    breakAndRun "wrong constitutive law" constant/materialProperties 's/neoHookean/neoHooke/' \
        "materialProperties:" "neoHookean"
    breakAndRun "wrong kernel" constant/tlSphProperties 's/wendlandC2/wendlandC9/' "tlSphProperties:" "wendlandC2"
    breakAndRun "bad material value" constant/materialProperties 's/youngsModulus   17e6/youngsModulus   -17e6/' \
        "materialProperties:" "youngsModulus"
    breakAndRun "bad last function object" system/controlDict 's/^}$/    last { type noSuchFunction; }\n}/' \
        "controlDict:" "noSuchFunction"
}
# sphCase <source case> <solver> <breaks function> <half end time> <end time> [entry value ...]:
# the case run whole from startTime, and run halfway then restarted, each broken in turn.
sphCase() {
    local source="$1" breaks="$3" half="$4" end="$5"; solver="$2"; shift 5
    for mode in "fresh start" restart; do
        c="$WORK/$solver-${mode% *}"
        mkdir -p "$c"
        cp -r "$source/system" "$source/constant" "$c/"
        local args=("$@")
        for ((k = 0; k < ${#args[@]}; k += 2)); do
            mfDictionary "$c/system/controlDict" -entry "${args[k]}" -set "${args[k + 1]}" > /dev/null
        done
        mfDictionary "$c/system/controlDict" -entry endTime -set "$end" > /dev/null
        particleGen -case "$c" > "$WORK/log" 2>&1 || fail "particleGen failed on $c: $(tail "$WORK/log")"
        if [ "$mode" = restart ]; then
            mfDictionary "$c/system/controlDict" -entry startFrom -set latestTime > /dev/null
            mfDictionary "$c/system/controlDict" -entry endTime -set "$half" > /dev/null
            $solver -case "$c" > "$WORK/log" 2>&1 || fail "the first half failed: $(tail "$WORK/log")"
            mfDictionary "$c/system/controlDict" -entry endTime -set "$end" > /dev/null
        else
            mfDictionary "$c/system/controlDict" -entry startFrom -set startTime > /dev/null
            $solver -case "$c" > "$WORK/log" 2>&1 || fail "the first run failed: $(tail "$WORK/log")"
        fi
        $breaks
    done
}
sphCase "$SOURCE/../tlSph/tractionCube" tlSph tlSphBreaks 0.005 0.01

# An impactSph case: Sod's shock tube (900 particles), 200 steps, with the riemannError and
# conservedQuantities function objects.
impactSphBreaks() {
    breakAndRun "wrong equation of state" constant/materialProperties 's/type idealGas/type idealGass/' \
        "materialProperties:" "idealGas"
    breakAndRun "wrong kernel" constant/sphProperties 's/type gaussian/type gausian/' "sphProperties:" "gaussian"
    breakAndRun "bad value" constant/sphProperties 's/eta 1.2/eta -1.2/' "sphProperties:" "eta"
    breakAndRun "syntax error" constant/sphProperties 's/{ type number;/{ type number/' "sphProperties:"
    breakAndRun "bad last function object" system/controlDict 's/writeInterval 100;/writeInterval -100;/' \
        "controlDict:" "writeInterval"
    breakAndRun "bad function object reference" system/controlDict 's/right           { density 0.125;/right           { density -0.125;/' \
        "controlDict:" "density"
}
sphCase "$SOURCE/../impactSph/sodShockTube" impactSph impactSphBreaks 0.005 0.01 writeInterval 0.005
