# A particle leaving the grid (issue 17 item 8, doc/methods/mpm.md 2.1): a block thrown at 2 m/s
# towards the grid's right edge stops the run with exit status 1 and a diagnosis naming the
# particle, its body, the time and the remedies, having written the time before; with
# `outsideGrid remove;` the run goes on, the particles are removed and the mass lost is
# reported (log and summary) and leaves the conservedQuantities mass. A particle separated from
# every other particle (a one-particle fragment three cells from the block) stops the run with
# the extension-instability diagnosis.
source "$(dirname "$0")/common.sh"
c="$WORK/throw"
mkdir -p "$c/system" "$c/constant"
cat > "$c/system/controlDict" <<'DICT'
application mpmFsi; startFrom startTime; startTime 0; stopAt endTime; endTime 0.3; deltaT 1e-3;
adjustTimeStep no; writeControl adjustableRunTime; writeInterval 0.1;
functions { conserved { type conservedQuantities; writeControl timeStep; writeInterval 10; } }
DICT
cat > "$c/system/particleGenDict" <<'DICT'
dimension 2;
regions { block { shape { type box; min (0.6 0.4); max (0.8 0.6); } lattice { type materialPoints; cells (8 8); pattern centre; }
          density 1000; material soft; fields { velocity (2 0); } } }
DICT
echo 'materials { soft { rho0 1000; youngsModulus 1e4; poissonRatio 0.3; constitutiveLaw { type neoHookean; } } }' > "$c/constant/materialProperties"
echo 'grid { origin (0 0); cellSize (0.1 0.1); cells (10 10); }' > "$c/constant/mpmProperties"
run "$c" particleGen
cp -r "$c" "$WORK/remove"
cp -r "$c" "$WORK/fragment"
if mpmFsi -case "$c" > "$c/log.mpmFsi" 2>&1; then fail "the run went on with a particle outside the grid"; fi
grep -q "has left the grid, which spans (0 0) to (1 1)" "$c/log.mpmFsi" || fail "no diagnosis: $(tail -3 "$c/log.mpmFsi")"
grep -q "(body block)" "$c/log.mpmFsi" || fail "the diagnosis does not name the body"
grep -q "outsideGrid remove;" "$c/log.mpmFsi" || fail "the diagnosis does not give the remedies"
grep -qE "phase preStep, step [0-9]+, t = 0.1" "$c/log.mpmFsi" || fail "the diagnosis does not give the time: $(grep Error "$c/log.mpmFsi")"
[ -f "$c/0.1/particles.vtp" ] || fail "the write at t = 0.1 before the exit is missing"
echo "stop: $(grep -o 'particle [0-9]* (body block) at ([^)]*) has left the grid' "$c/log.mpmFsi")"

r="$WORK/remove"
echo 'outsideGrid remove;' >> "$r/constant/mpmProperties"
run "$r" mpmFsi
grep -q "outsideGrid remove: .* particle(s) of block left the grid" "$r/log.mpmFsi" || fail "no removal line in the log"
grep -q "outsideGrid remove   64 particles, 40 kg (100% of the initial mass)" "$r/log.mpmFsi" \
    || fail "the summary does not report the whole block removed: $(grep 'outsideGrid remove  ' "$r/log.mpmFsi")"
mass=$(column "$r/postProcessing/conserved/0/conservedQuantities.csv" mass | tail -n 1)
less "$mass" 1e-12 || fail "the conservedQuantities mass at the end is $mass, not 0"
echo "remove: $(grep 'outsideGrid remove  ' "$r/log.mpmFsi")"

f="$WORK/fragment"
cat > "$f/system/particleGenDict" <<'DICT'
dimension 2;
regions { block { shape { type box; min (0.2 0.4); max (0.4 0.6); } lattice { type materialPoints; cells (8 8); pattern centre; }
          density 1000; material soft; }
          chip { shape { type box; min (0.7 0.45); max (0.725 0.475); } lattice { type materialPoints; cells (1 1); pattern centre; }
          density 1000; material soft; } }
DICT
run "$f" particleGen
if mpmFsi -case "$f" > "$f/log.mpmFsi" 2>&1; then fail "the run went on with an isolated particle"; fi
grep -q "particle 64 (body chip) at (0.7125 0.4625) shares no grid node with any other particle" "$f/log.mpmFsi" \
    || fail "no extension-instability diagnosis: $(grep Error "$f/log.mpmFsi")"
grep -q "extension instability" "$f/log.mpmFsi" || fail "the diagnosis does not name the extension instability"
echo "PASS: outsideGrid"
