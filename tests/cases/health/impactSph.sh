#!/usr/bin/env bash
# The health check on impactSph (issue 20), on Sod's tube (tutorials/impactSph/sodShockTube: 900
# particles in 1D, the leapfrog at dt = 5e-5):
# - a NaN planted in particle 3's velocity stops the run: status 1, the log names the health check,
#   the particle, the component (velocity: in 1D the field has one, unsuffixed), the remedy, and
#   the failing state is written;
# - a speed of 1e8 planted on particle 3 collapses the Courant vote (adjustTimeStep yes, the
#   leapfrog: see faultCase): the health check stops the run before the step naming "collapsed"
#   and particle 3 (the vote names its argmin), with the state written;
# - particle 3 planted at x = 5, outside the health box (-1, 2), stops the run naming it;
# - the energy budget of the healthy run to t = 0.2: D (the rates' non-conservation, measured) is
#   zero to round-off for this scheme (SphSolver.cpp, measurePower: every term of the rates is
#   matched by the work or heat it moves; the artificial mass flux enters dρ/dt only and moves no
#   energy), W is zero (no boundary conditions), so the imbalance K + U + D - W is the leapfrog's
#   energy error, O(dt^2): halving dt must divide it by 4 (3 to 5 asserted; 3.86 measured, and 3.96
#   with the predictor-corrector), i.e. its Richardson limit (4 r(dt/2) - r(dt))/3, what the
#   scheme would lose at dt -> 0, is ~1% of r(dt) (-2e-9 against -1.9e-7). The magnitude is also
#   asserted below (dt/tau)^2 = 1.6e-3, tau = min h/c = 1.5e-3/1.18 s the time a signal takes to
#   cross a support: the local error of a second-order step is (dt/tau)^3 of the energy that
#   changes within tau, summed over the tau/dt steps of each such change; a bound without the
#   cancellation of the symmetric leapfrog's errors, which the run shows (1.9e-7, 1e-4 of it);
# - D is measured, not assumed: with `momentum difference` (not antisymmetric, Zisis 2017 §2.4) the
#   tube to t = 0.01 (dt 2e-5) gains 1.0e-3 of its energy (K + U), which D accounts for
#   (-2.8e-3 J of 2.75): the imbalance stays below 1e-6 (2.4e-8 measured);
# - the indicators of the healthy run at t = 0.2 (SphHealth.cpp): no particle in tension; the
#   Shepard sum below 1/2 only at the outermost particles of the free ends, which detach as the gas
#   expands into vacuum (particle 0 first: its sum is its own term, 0.470); the hourglass measure
#   largest between the contact and the shock (ids 760 to 860: the left gas ends at 799), whose
#   velocity wiggles from particle to particle by ~1e-3 (SPH's contact blip), past 0.7 at a few
#   particles at most (3 asserted; 2 at t = 0.05, 1 at 0.15);
# - the health check's cost is reported (measured by bench/health, not asserted: a timed test fails
#   on a loaded machine).
. "$(dirname "$0")/common.sh"

base="$WORK/base"
mkdir -p "$base"
cp -r "$SOURCE/tutorials/impactSph/sodShockTube/system" "$SOURCE/tutorials/impactSph/sodShockTube/constant" "$base/"
particleGen -case "$base" > "$base/log.particleGen" 2>&1 || fail "particleGen: $(tail -n 5 "$base/log.particleGen")"

# faultCase <name> <field> <component> <value> [adjust]: a copy run to t = 0.02 with the fault
# planted at t = 0.005; its exit status in $status, its log in $log.
faultCase() {
    local c="$WORK/$1"
    cp -r "$base" "$c"
    sed -i 's/^endTime .*/endTime         0.02;/; s/^writeInterval .*/writeInterval   0.02;/' "$c/system/controlDict"
    if [ "${5:-}" = adjust ]; then
        sed -i 's/^adjustTimeStep .*/adjustTimeStep  yes;/' "$c/system/controlDict"
        # The default leapfrog: its kick after a collapse still spans half the step before
        # (weight (dt_{k-1} + dt_k)/2), which broke the state (a density of -2800) before a
        # check after the step could see the collapse; the health check now judges each vote
        # before the step takes it (Health::checkVote).
    fi
    plantFault "$c" 0.005 3 "$2" "$3" "$4" "domainMin (-1); domainMax (2);"
    runFault impactSph "$c" "$1" 3 "$2" "$3" "$4"
}

faultCase nan velocity 0 nan
expectNaNStop "velocity = nan"

faultCase speed velocity 0 1e8 adjust
[ "$status" = 1 ] || fail "speed: exit status $status, not 1"
expect speed "health check" "collapsed" "the limit: Courant, particle 3 " "Remedy"
echo "speed: $(grep -m1 -o 'the stable time step collapsed[^;]*; the limit: [^.]*' "$log")"

faultCase outside position 0 5
[ "$status" = 1 ] || fail "outside: exit status $status, not 1"
expect outside "health check" "particle 3 at (5)" "left the domain" "Remedy"
echo "outside: $(grep -m1 -o 'particle 3 at (5)[^;]*' "$log")"

# budgetRun <name> <deltaT>: the healthy tube to t = 0.2, health.csv every 0.05; prints the last
# row's relativeImbalance, the largest |dissipated| and |externalWork| relative to the energy.
budgetRun() {
    local c="$WORK/$1"
    cp -r "$base" "$c"
    sed -i "s/^deltaT .*/deltaT          $2;/" "$c/system/controlDict"
    impactSph -case "$c" > "$c/log.impactSph" 2>&1 || fail "$1: the healthy run failed: $(tail -n 20 "$c/log.impactSph")"
    local csv="$c/postProcessing/health/0/health.csv"
    [ -f "$csv" ] || fail "$1: no $csv"
    awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) h[$i] = i; next }
             { E = $h["kineticEnergy"] + $h["internalEnergy"]; d = $h["dissipated"]; w = $h["externalWork"]
               if (d < 0) d = -d; if (w < 0) w = -w; if (d / E > D) D = d / E; if (w / E > W) W = w / E
               r = $h["relativeImbalance"]; t = $h["time"]
               s = $h["neighbourDeficiency"] " " $h["neighbourDeficiency_count"] " " $h["neighbourDeficiency_worstId"]
               if ($h["hourglass_count"] > gc) gc = $h["hourglass_count"]
               g = $h["hourglass"] " " gc " " $h["hourglass_worstId"]
               k = $h["tensileInstability_count"] }
             END { printf "%s %.6e %.3e %.3e %s %s %s\n", t, r, D, W, k, s, g }' "$csv"
}
read -r t1 r1 d1 w1 k1 s1 sc1 sw1 g1 gc1 gw1 < <(budgetRun coarse 5e-5)
read -r t2 r2 d2 w2 k2 s2 sc2 sw2 g2 gc2 gw2 < <(budgetRun fine 2.5e-5)
log="$WORK/coarse/log.impactSph"
[ "$t1" = 0.2 ] || fail "the last health row is at t = $t1, not 0.2"
# D and W: round-off of sums of O(1) terms over 4000 steps (|D|/E ~ 1e-14 measured).
awk -v d="$d1" -v w="$w1" 'BEGIN { exit !(d < 1e-10 && w == 0) }' || fail "dissipated $d1, external work $w1 (relative): not zero"
bound=$(awk 'BEGIN { tau = 1.5e-3 / 1.1832; printf "%.3g", (5e-5 / tau)^2 }')
awk -v r="$r1" -v b="$bound" 'BEGIN { exit !((r < 0 ? -r : r) < b) }' || fail "energy imbalance $r1 above the bound $bound"
ratio=$(awk -v a="$r1" -v b="$r2" 'BEGIN { printf "%.3g", a / b }')
awk -v q="$ratio" 'BEGIN { exit !(q > 3 && q < 5) }' || fail "imbalance $r1 at dt 5e-5, $r2 at 2.5e-5: ratio $ratio, not second order"
[ "$k1" = 0 ] || fail "tensileInstability counts $k1 particles in Sod's tube, where none is in tension"
[ "$sw1" = 0 ] && [ "$sc1" -le 2 ] || fail "neighbourDeficiency: $sc1 particles, the worst $sw1 (expected particle 0, at most 2)"
awk -v s="$s1" 'BEGIN { exit !(s > 0.469 && s < 0.471) }' || fail "neighbourDeficiency $s1: not particle 0's own term 0.470"
[ "$gw1" -ge 760 ] && [ "$gw1" -le 860 ] && [ "$gc1" -le 3 ] || fail "hourglass: up to $gc1 particles, the worst $gw1 (expected between the contact and the shock, 760 to 860, at most 3)"
grep -q "health: indicator neighbourDeficiency" "$log" || fail "the indicators' definitions are not logged"
c="$WORK/difference"
cp -r "$base" "$c"
echo "momentum difference;" >> "$c/constant/sphProperties"
sed -i 's/^endTime .*/endTime         0.01;/; s/^writeInterval .*/writeInterval   0.0025;/; s/^deltaT .*/deltaT          2e-5;/' "$c/system/controlDict"
impactSph -case "$c" > "$c/log.impactSph" 2>&1 || fail "difference: the run failed: $(tail -n 20 "$c/log.impactSph")"
read -r dd dr < <(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) h[$i] = i; next }
    { d = $h["dissipated"] / ($h["kineticEnergy"] + $h["internalEnergy"]); r = $h["relativeImbalance"] }
    END { printf "%.3e %.3e\n", d, r }' "$c/postProcessing/health/0/health.csv")
awk -v d="$dd" -v r="$dr" 'BEGIN { exit !(d < -5e-4 && (r < 0 ? -r : r) < 1e-6) }' ||
    fail "difference form: dissipated $dd of the energy (expected below -5e-4), imbalance $dr (expected below 1e-6)"
echo "difference form: D = $dd of the energy (energy made by the scheme), imbalance $dr"
summary=$(grep -m1 "energy imbalance" "$log") || fail "no health summary line"
cost=$(echo "$summary" | sed -n 's/.*cost \([0-9.e+-]*\)% of the run.*/\1/p')
[ -n "$cost" ] || fail "no cost in the health summary"
limit=$(awk -v a="$r1" -v b="$r2" 'BEGIN { printf "%.3g", (4 * b - a) / 3 }')
echo "budget: relative imbalance $r1 at dt 5e-5 (bound $bound), $r2 at 2.5e-5 (ratio $ratio, limit dt -> 0: $limit); dissipated $d1, work $w1"
echo "indicators at t = 0.2: smallest Shepard sum $s1 ($sc1 particles below 1/2, particle $sw1), largest hourglass $g1 (particle $gw1; at most $gc1 past 0.7 at a write), none in tension"
echo "summary: $summary"
echo "PASS: health.impactSph"
