#!/usr/bin/env bash
# R9 (doc/methods/fpm.md §4b): the minimisation direction (5.27) as the Euler part's upwind direction
# in the thesis's shock tube is detected as unstable by the run's own instabilityCheck ("instability
# detected", exit status 1, the state written); the thesis breaks after 2.2 s. About 3 minutes on one
# thread: the validation label.
source "$(dirname "$0")/common.sh"
k="$WORK/minimisation"
copyTutorial shockTube "$k"
sed -i 's/direction gradient;/direction minimisation;/' "$k/constant/fpmProperties"
grep -q "direction minimisation;" "$k/constant/fpmProperties" || fail "could not set direction minimisation"
run "$k" particleGen
rc=0; fpmSolid -case "$k" > "$k/log.fpmSolid" 2>&1 || rc=$?
[ "$rc" = 1 ] || fail "R9 minimisation: exit status $rc, expected 1 (instability detected)"
grep -q "phase instabilityCheck, step [0-9]*, t = [0-9.]*: instability detected: particle [0-9]* at .* has pressure .*Remedy" "$k/log.fpmSolid" ||
    fail "R9 minimisation: $(grep -m1 Error "$k/log.fpmSolid")"
echo "R9 minimisation: $(grep -m1 -o 'phase instabilityCheck, step [0-9]*, t = [0-9.]*: instability detected: particle [0-9]* at .\{0,40\}' "$k/log.fpmSolid")"
echo "PASS: R9's minimisation direction detected"
