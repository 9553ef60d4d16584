#!/bin/sh
# mpmFsi fluid and contact benchmark (issue 18's Benchmark point; not a test):
#   dam-19200:  the thesis's dam (doc/methods/mpm.md 4.4): water [0,2] x [0,4], rho 997.5, Tait B 2e6,
#               gamma 7, mu 0.01, grid 6 x 8 in 18 x 24 cells, 19 200 points (120 x 160 at the
#               sub-cell centres: about 267 points a cell, as the thesis), slip walls x = 0, 6, y = 0;
#   dam-1e6:    the same column with 707 x 1414 = 999 698 points on a grid refined to 2 x 2 points
#               a cell (dx = 2/353.5 m: 1061 x 1414 cells), the usual MPM density;
#   disks-singleField / disks-multiField: tutorials/mpmFsi/twoDisks scaled to 2 x 49 900 points
#               (as run.sh), with `contact singleField` and `contact multiField` (a velocity field a
#               body, Bardenhagen et al. 2001): the cost of the multi-field contact;
#   collapse3D: tutorials/mpmFsi/columnCollapse3D (issue 18's 3D case: the Martin & Moyce column as a
#               slab, 25 600 points, 120 x 48 x 4 cells, 27-node quadratic B-splines), at the fixed
#               step 5e-5 s (its CFL step at maxCo 0.3 is 5.7e-5 s).
# Each for a fixed number of steps at the fixed step 1e-5 s (dam) / 1e-4 s (disks), USL, FLIP 0.99,
# quadratic B-splines, no function objects, no writes. Prints particle-steps/s per core (wall and
# per CPU-second), the peak RSS per particle and the solver's phase shares. Usage:
#   bench/mpm/fluids.sh [threads=1] [steps=100]
# Environment: MFDYN_BIN (bin/ with mpmFsi and particleGen; default build/bin of this checkout),
# WORK (scratch; default a fresh /tmp/mpmFluids.XXXX), SKIP_1E6 (set: leave out dam-1e6), PEER_CMD
# (with PEER_PARTICLE_STEPS: a peer's command line, timed once; skipped when absent).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
threads=${1:-1}
steps=${2:-100}
MFDYN_BIN=${MFDYN_BIN:-$root/build/bin}
[ -x "$MFDYN_BIN/mpmFsi" ] || { echo "no $MFDYN_BIN/mpmFsi: build first (or set MFDYN_BIN)" >&2; exit 1; }
WORK=${WORK:-$(mktemp -d /tmp/mpmFluids.XXXX)}
mkdir -p "$WORK"
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg) ($(nproc) cores; on a shared machine the per CPU-s column is the firmer one)"

setupDam() {  # name pointsX pointsY cellsX cellsY
    dir=$WORK/$1
    rm -rf "$dir"; mkdir -p "$dir/system" "$dir/constant"
    endTime=$(awk -v s="$steps" 'BEGIN { printf "%.6g", s * 1e-5 }')
    cat >"$dir/system/controlDict" <<DICT
application mpmFsi; startFrom startTime; startTime 0; stopAt endTime; endTime $endTime; deltaT 1e-5;
adjustTimeStep no; writeControl timeStep; writeInterval 1000000000;
DICT
    cat >"$dir/system/particleGenDict" <<DICT
dimension 2;
regions { water { shape { type box; min (0 0); max (2 4); } lattice { type materialPoints; cells ($2 $3); pattern centre; }
          density 997.5; material water; } }
DICT
    cat >"$dir/constant/materialProperties" <<'DICT'
materials { water { equationOfState { type tait; rho0 997.5; B 2e6; gamma 7; } viscosity { type newtonian; mu 0.01; } } }
DICT
    cat >"$dir/constant/mpmProperties" <<DICT
grid { origin (0 0); cellSize ($(awk -v n="$4" 'BEGIN { printf "%.10g", 6 / n }') $(awk -v n="$5" 'BEGIN { printf "%.10g", 8 / n }')); cells ($4 $5); }
shapeFunction quadraticBSpline; scheme USL; velocityUpdate flipPic; flipFraction 0.99;
bodyForce { type uniformGravity; g (0 -9.81); }
outsideGrid remove;
gridBoundaryConditions { walls { type slip; faces (xMin xMax yMin); } }
DICT
    (cd "$dir" && "$MFDYN_BIN/particleGen" >log.particleGen 2>&1)
}

setupDisks() {  # contact
    dir=$WORK/disks-$1
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$root/tutorials/mpmFsi/twoDisks/system" "$root/tutorials/mpmFsi/twoDisks/constant" "$dir/"
    sed -i "s/cells (10 10)/cells (126 126)/g" "$dir/system/particleGenDict"
    sed -i "s/^grid .*/grid            { origin (0 0); cellSize (0.003968253968 0.003968253968); cells (252 252); }/" "$dir/constant/mpmProperties"
    sed -i "s/^shapeFunction .*/shapeFunction   quadraticBSpline;/; /^contact /d" "$dir/constant/mpmProperties"
    [ "$contacts" = singleField ] || echo "contact $1;" >>"$dir/constant/mpmProperties"
    awk '/^functions/ { skip = 1 } !skip { print }' "$dir/system/controlDict" >"$dir/c" && mv "$dir/c" "$dir/system/controlDict"
    endTime=$(awk -v s="$steps" 'BEGIN { printf "%.6g", s * 1e-4 }')
    sed -i "s/^endTime .*/endTime         $endTime;/; s/^writeInterval .*/writeInterval   1e9;/" "$dir/system/controlDict"
    (cd "$dir" && "$MFDYN_BIN/particleGen" >log.particleGen 2>&1)
}

setupCollapse3D() {
    dir=$WORK/collapse3D
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$root/tutorials/mpmFsi/columnCollapse3D/system" "$root/tutorials/mpmFsi/columnCollapse3D/constant" "$dir/"
    awk '/^functions/ { skip = 1 } !skip { print }' "$dir/system/controlDict" >"$dir/c" && mv "$dir/c" "$dir/system/controlDict"
    endTime=$(awk -v s="$steps" 'BEGIN { printf "%.6g", s * 5e-5 }')
    sed -i "s/^endTime .*/endTime         $endTime;/; s/^deltaT .*/deltaT          5e-5;/; s/^adjustTimeStep .*/adjustTimeStep  no;/; s/^writeControl .*/writeControl    timeStep;/; s/^writeInterval .*/writeInterval   1000000000;/" "$dir/system/controlDict"
    (cd "$dir" && "$MFDYN_BIN/particleGen" >log.particleGen 2>&1)
}

val() { awk -v L="$2" 'index($0, "    " L " ") == 1 { s = substr($0, length(L) + 5); split(s, a, " "); print a[1]; exit }' "$1"; }
phaseShare() { grep -m1 "^    phase $2 " "$1" | sed 's/.*(\([0-9.]*\)%).*/\1/'; }
raw=$WORK/raw.tsv
: >"$raw"
runMpm() {  # case
    dir=$WORK/$1
    log=$dir/log.mpmFsi
    (cd "$dir" && OMP_NUM_THREADS=$threads /usr/bin/time -f "cpu %U %S maxrss %M" "$MFDYN_BIN/mpmFsi" >"$log" 2>&1) ||
        { echo "  $1: mpmFsi failed: $log"; tail -3 "$log"; return 0; }
    particles=$(val "$log" particles)
    stepsTaken=$(val "$log" steps)
    pss=$(val "$log" particle-steps/s)
    cpu=$(awk '/^cpu /{ print $2 + $3 }' "$log")
    rssKiB=$(awk '/^cpu /{ print $5 }' "$log")
    printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" "$1" "$particles" "$stepsTaken" "$pss" "$cpu" \
        "$(awk -v k="$rssKiB" -v n="$particles" 'BEGIN { printf "%.0f", k * 1024 / n }')" \
        "$(phaseShare "$log" shapeFunctions)" "$(phaseShare "$log" particleToGrid)" "$(phaseShare "$log" gridSolve)" \
        "$(phaseShare "$log" gridToParticle)" "$(phaseShare "$log" stress)" "$(awk -v k="$rssKiB" 'BEGIN { printf "%.1f", k / 1024 }')" >>"$raw"
    echo "  $1: $particles particles, $stepsTaken steps, $pss particle-steps/s (wall, $threads thread(s)), cpu $cpu s"
}

setupDam dam-19200 120 160 18 24
runMpm dam-19200
if [ -z "$SKIP_1E6" ]; then
    setupDam dam-1e6 707 1414 1061 1414
    runMpm dam-1e6
fi
contacts="singleField"
[ -d "$root/libraries/mpm/contact" ] && contacts="singleField multiField"
for c in $contacts; do
    setupDisks "$c"
    runMpm "disks-$c"
done
setupCollapse3D
runMpm collapse3D

echo
echo "case                  particles steps particle-steps/s/core (wall) per CPU-s  RSS/particle peak MiB  shapeFn p2g  grid g2p stress [% of loop]"
awk -F'\t' -v t="$threads" '{ printf "%-21s %9s %5s %28.4g %10.4g %10s B %9s %7s %4s %5s %4s %6s\n", $1, $2, $3, $4 / t, $2 * $3 / $5, $6, $12, $7, $8, $9, $10, $11 }' "$raw"
awk -F'\t' '$1 == "disks-singleField" { s = $2 * $3 / $5 } $1 == "disks-multiField" { m = $2 * $3 / $5 }
            END { if (s && m) printf "multiField / singleField cost per particle-step (CPU-s): %.3g\n", s / m }' "$raw"
if [ -n "$PEER_CMD" ]; then
    start=$(date +%s.%N)
    sh -c "$PEER_CMD" >"$WORK/log.peer" 2>&1 || echo "peer command failed: $WORK/log.peer"
    wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.3g", b - a }')
    echo "peer wall time $wall s"
    [ -n "$PEER_PARTICLE_STEPS" ] && awk -v n="$PEER_PARTICLE_STEPS" -v w="$wall" 'BEGIN { printf "peer: %.3g particle-steps/s\n", n / w }'
else
    echo "peer: skipped (set PEER_CMD, and PEER_PARTICLE_STEPS, to time one)"
fi
echo "raw rows: $raw; logs under $WORK"
