# Hanging block, the extension instability (doc/methods/mpm.md 4.2, Tables 8-9: the note's V2b):
# the tutorial's block on the 8 x 8 grid with 5 x 5 points, 0.012 apart on a 0.0225 grid. Two
# rows share a node row only while they are less than one to two cells apart; the top row, held
# by the fixed top nodes, lets go of the falling rest at t = 0.0087 (measured: step 563 at maxCo 0.01, a piece
# of 5 particles against 20). The run must stop with exit status 1 and
# the extension-instability diagnosis naming the body and the piece, before any particle leaves
# the grid and with no NaN. Before the piece check (MpmSolver::checkTorn) the isolated-particle
# check saw nothing (each particle of a row shares nodes with its neighbours) and the run went on
# until the detached part fell out of the grid at t = 0.016 ("has left the grid": the wrong remedy).
source "$(dirname "$0")/common.sh"
c="$WORK/block"
copyTutorial hangingBlock "$c"
setEntry "$c/system/particleGenDict" regions/block/lattice/cells "(5 5)"
grep -q "cells (5 5)" "$c/system/particleGenDict" || fail "could not set 5 x 5 points"
grep -q "cells (8 8)" "$c/constant/mpmProperties" || fail "the tutorial's grid is no longer 8 x 8"
run "$c" particleGen
if mpmFsi -case "$c" > "$c/log.mpmFsi" 2>&1; then status=0; else status=$?; fi
[ "$status" = 1 ] || fail "mpmFsi exited with $status, not 1: $(tail -n 5 "$c/log.mpmFsi")"
msg=$(grep "^Error" "$c/log.mpmFsi") || fail "no error line: $(tail -n 5 "$c/log.mpmFsi")"
echo "$msg"
echo "$msg" | grep -q "body block has torn apart" || fail "not the torn-body diagnosis"
echo "$msg" | grep -q "extension instability of doc/methods/mpm.md section 6.2" || fail "the diagnosis does not name the extension instability"
echo "$msg" | grep -q "more particles per cell" || fail "the diagnosis gives no remedy"
echo "$msg" | grep -qE "in a piece of [0-9]+ particle\(s\)" || fail "the diagnosis does not size the piece"
echo "$msg" | grep -qi "nan" && fail "the diagnosis reports a NaN"
t=$(echo "$msg" | sed -n 's/.*step [0-9]*, t = \([0-9.e-]*\):.*/\1/p')
[ -n "$t" ] || fail "no time in the diagnosis"
# Free fall from y = 0.12 to the grid's floor takes sqrt(2 0.12 / 1400) = 0.013 s: the tear must
# be seen before any particle could leave.
less "$t" 0.013 || fail "the tear was reported at t = $t, after a falling piece could have left the grid"
echo "PASS: hangingBlockInstability (t = $t)"
