# The planted-fault helpers of the health case scripts (sourced after their set-up: $WORK, fail).

# plantFault <case> <time> <particle> <field> <component> <value> [<health settings>]: replaces the
# case's function objects (from `functions` to the end of its controlDict) by the fault, planted by
# libplantFault.so, and then the health check that must see it in the same step.
plantFault() {
    sed -i '/^functions/,$d' "$1/system/controlDict"
    cat >> "$1/system/controlDict" << EOF
libs ("libplantFault.so");
functions
{
    plant  { type plantFault; time $2; particle $3; field $4; component $5; value "$6"; }
    health { type health; ${7:-} }
}
EOF
}

# runFault <solver> <case> <name> <particle> <field> <component> <value>: runs it; its exit status in
# $status, its log in $log; fails unless the fault was planted.
runFault() {
    status=0
    "$1" -case "$2" > "$2/log.$1" 2>&1 || status=$?
    log="$2/log.$1"
    grep -q "plantFault: $5 component $6 of particle $4 set to $7" "$log" ||
        fail "$3: the fault was not planted: $(tail -n 5 "$log")"
}

# expect <name> <text>...: the log ($log) names every text.
expect() {
    local name="$1"
    shift
    for word in "$@"; do
        grep -q -- "$word" "$log" || fail "$name: the log does not name '$word': $(grep -m1 -A3 "Error" "$log" || tail -n 5 "$log")"
    done
}

# expectStateWritten <name> <case>: exit status 1 and the failing state written where the log says.
expectStateWritten() {
    [ "$status" = 1 ] || fail "$1: exit status $status, not 1"
    expect "$1" "Wrote the failing state to"
    written=$(sed -n 's/.*Wrote the failing state to \([^ ]*\)\/.*/\1/p' "$log" | head -n 1)
    [ -f "$2/$written/particles.vtp" ] || fail "$1: the failing state $written/ was not written"
}

# The three planted faults' common assertions, on the case of faultCase <name> (the script's own
# runner, which sets $status and $log) for particle 3:
# expectNaNStop <component text>: the health check stops the run at the NaN, naming the particle and
# the component, with a remedy, and writes the failing state.
expectNaNStop() {
    expectStateWritten nan "$WORK/nan"
    expect nan "health check" "particle 3 " "$1" "Remedy"
    echo "nan: stopped at $written: $(grep -m1 -o "health check.*particle 3 [^(]*" "$log")"
}
# expectCollapse: a speed of 1e8 collapses the stable step; the health check names the particle.
expectCollapse() {
    [ "$status" = 1 ] || fail "speed: exit status $status, not 1"
    expect speed "health check" "collapsed" "particle 3 " "Remedy"
    echo "speed: $(grep -m1 -o 'the stable time step collapsed[^;]*; the limit: [^.]*' "$log")"
}
