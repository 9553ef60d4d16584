#!/bin/sh
# mpmFsi throughput benchmark (issue 17's Benchmark point; not a test): the 2D disks of
# tutorials/mpmFsi/twoDisks scaled to about 1e5 material points and the 3D Taylor bar quarter of
# tutorials/mpmFsi/taylorBar at about 1e5 points, each with linear hats and quadratic B-splines, on
# 1 and 2 threads. Prints particle-steps/s per core, memory per particle (peak RSS / particles) and
# the solver's phase times (its summary), and the ratios to the issue's goals (2D linear 1.5e6,
# 3D quadraticBSpline 5e5 particle-steps/s per core) and peers (karamelo about 7e5, cb-geo about
# 2.5e5 per core, the issue's figures). Usage:
#   bench/mpm/run.sh [maxThreads=2] [steps=200]
# Environment: MFDYN_BIN (a bin/ folder with mpmFsi and particleGen; default: build/ of this
# checkout), WORK (scratch folder; default a fresh /tmp/mpmBench.XXXX), DISK_CELLS (sub-cells per
# disk diameter, default 126: 2 x 49 900 points), BAR_CELL (the bar's grid cell, default 2.76e-4 m:
# 1.0e5 points), PEER_CMD (optional: a peer code's command line, run once with its wall time and,
# with PEER_PARTICLE_STEPS, its particle-steps/s; skipped when absent).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
maxThreads=${1:-2}
steps=${2:-200}
MFDYN_BIN=${MFDYN_BIN:-$root/build/bin}
[ -x "$MFDYN_BIN/mpmFsi" ] || { echo "no $MFDYN_BIN/mpmFsi: build first (or set MFDYN_BIN)" >&2; exit 1; }
WORK=${WORK:-$(mktemp -d /tmp/mpmBench.XXXX)}
mkdir -p "$WORK"
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
diskCells=${DISK_CELLS:-126}
barCell=${BAR_CELL:-2.76e-4}
raw=$WORK/raw.tsv
: >"$raw"
echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg) (2 cores shared: figures are lower bounds)"

# The disks: the thesis's 10 x 10 Gauss sub-cells per diameter and 20 x 20 grid, both scaled by
# diskCells / 10 (same points per cell, about 4.0), the tutorial's material, the fixed step 1e-4 s
# for `steps` steps (the disks do not meet yet: the cost of a step does not depend on it), no
# function objects, no writes.
setupDisks() {  # shape
    dir=$WORK/disks-$1
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$root/tutorials/mpmFsi/twoDisks/system" "$root/tutorials/mpmFsi/twoDisks/constant" "$dir/"
    gridCells=$((diskCells * 2))
    sed -i "s/cells (10 10)/cells ($diskCells $diskCells)/g" "$dir/system/particleGenDict"
    sed -i "s/^grid .*/grid            { origin (0 0); cellSize ($(awk -v n=$gridCells 'BEGIN { printf "%.10g", 1 / n }') $(awk -v n=$gridCells 'BEGIN { printf "%.10g", 1 / n }')); cells ($gridCells $gridCells); }/" "$dir/constant/mpmProperties"
    sed -i "s/^shapeFunction .*/shapeFunction   $1;/" "$dir/constant/mpmProperties"
    awk '/^functions/ { skip = 1 } !skip { print }' "$dir/system/controlDict" >"$dir/c" && mv "$dir/c" "$dir/system/controlDict"
    endTime=$(awk -v s="$steps" 'BEGIN { printf "%.6g", s * 1e-4 }')
    sed -i "s/^endTime .*/endTime         $endTime;/; s/^writeInterval .*/writeInterval   1e9;/" "$dir/system/controlDict"
    (cd "$dir" && "$MFDYN_BIN/particleGen" >log.particleGen 2>&1)
}

# The bar: the tutorial's quarter with barCell cells and points at half the cell, for about
# `steps` CFL steps (dt = 0.3 dx / (c_p + v0), c_p = 4670 m/s), no function objects, no writes.
# Linear hats run at maxCo 0.05 (at 0.3 the rim particles invert within some 30 steps: the
# tutorial's README); the time per step does not depend on it, the steps are read from the log.
setupBar() {  # shape
    dir=$WORK/bar-$1
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$root/tutorials/mpmFsi/taylorBar/system" "$root/tutorials/mpmFsi/taylorBar/constant" "$dir/"
    rm -f "$dir/system/studyDict"
    co=0.3; [ "$1" = linear ] && co=0.05
    sed -i "s/cellSize 8e-4;/cellSize $barCell;/; s/^shapeFunction .*/shapeFunction   $1;/" "$dir/constant/mpmProperties"
    sed -i "s/spacing 4e-4;/spacing $(awk -v h="$barCell" 'BEGIN { printf "%.6g", h / 2 }');/" "$dir/system/particleGenDict"
    awk '/^functions/ { skip = 1 } !skip { print }' "$dir/system/controlDict" >"$dir/c" && mv "$dir/c" "$dir/system/controlDict"
    endTime=$(awk -v s="$steps" -v h="$barCell" -v co="$co" 'BEGIN { printf "%.6g", s * co * h / 4897 }')
    sed -i "s/^endTime .*/endTime         $endTime;/; s/^writeInterval .*/writeInterval   1;/; s/^maxCo .*/maxCo           $co;/" "$dir/system/controlDict"
    (cd "$dir" && "$MFDYN_BIN/particleGen" >log.particleGen 2>&1)
}

# Summary line value: the field after the label; a phase's seconds and share.
val() { awk -v L="$2" 'index($0, "    " L " ") == 1 { s = substr($0, length(L) + 5); split(s, a, " "); print a[1]; exit }' "$1"; }
phaseShare() { grep -m1 "^    phase $2 " "$1" | sed 's/.*(\([0-9.]*\)%).*/\1/'; }

# One run: case, threads. Appends a row to raw.tsv:
# case threads particles steps pss pssPerCore cpu_s peakMiB bytesPerParticle %shape %p2g %grid %g2p %stress
runMpm() {
    dir=$WORK/$1
    rm -rf "$dir"/[1-9]* "$dir"/0.[0-9]* "$dir"/postProcessing "$dir"/particles.pvd
    log=$dir/log.mpmFsi.$2
    (cd "$dir" && OMP_NUM_THREADS=$2 /usr/bin/time -f "cpu %U %S maxrss %M" "$MFDYN_BIN/mpmFsi" >"$log" 2>&1) ||
        { echo "  $1, $2 thread(s): mpmFsi failed: $log"; tail -3 "$log"; return 0; }
    particles=$(val "$log" particles)
    stepsTaken=$(val "$log" steps)
    pss=$(val "$log" particle-steps/s)
    cpu=$(awk '/^cpu /{ print $2 + $3 }' "$log")
    rssKiB=$(awk '/^cpu /{ print $5 }' "$log")
    peak=$(awk -v k="$rssKiB" 'BEGIN { printf "%.1f", k / 1024 }')
    perParticle=$(awk -v k="$rssKiB" -v n="$particles" 'BEGIN { printf "%.0f", k * 1024 / n }')
    perCore=$(awk -v p="$pss" -v t="$2" 'BEGIN { printf "%.4g", p / t }')
    printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" "$1" "$2" "$particles" "$stepsTaken" "$pss" "$perCore" \
        "$cpu" "$peak" "$perParticle" "$(phaseShare "$log" shapeFunctions)" "$(phaseShare "$log" particleToGrid)" \
        "$(phaseShare "$log" gridSolve)" "$(phaseShare "$log" gridToParticle)" "$(phaseShare "$log" stress)" >>"$raw"
    echo "  $1, $2 thread(s): $particles particles, $stepsTaken steps, $pss particle-steps/s ($perCore per core), cpu $cpu s, peak RSS $peak MiB"
}

for shape in linear quadraticBSpline; do
    setupDisks $shape
    setupBar $shape
done
for case in disks-linear disks-quadraticBSpline bar-linear bar-quadraticBSpline; do
    t=1
    while [ $t -le "$maxThreads" ]; do
        runMpm $case $t
        t=$((t + 1))
    done
done

echo
# Per core two ways: the solver's particle-steps/s (by wall time) / threads, and particle-steps per
# CPU-second of the whole process (user + system): on a machine shared with other jobs the wall
# time counts the time the process waited for a core, the CPU time does not (with
# OMP_WAIT_POLICY=passive idle threads burn none), so the second is the per-core figure of a
# dedicated core; on an idle machine the two agree to the set-up's share.
echo "case                     threads particles steps  particle-steps/s  per core  per CPU-s  RSS/particle  shapeFn p2g  grid g2p stress [% of loop]"
awk -F'\t' '{ printf "%-24s %7s %9s %5s %17s %9s %10.4g %10s B %7s %4s %5s %4s %6s\n", $1, $2, $3, $4, $5, $6, $3 * $4 / $7, $9, $10, $11, $12, $13, $14 }' "$raw"
echo
# Goals and peers, per core (per CPU-second, and by wall time in brackets), on the 1-thread runs.
awk -F'\t' 'function line(label, goal) { c = $3 * $4 / $7
                 printf "%s %.3g per CPU-s (wall %.3g) = %.2f x the goal %.2g, %.2f x karamelo (7e5), %.2f x cb-geo (2.5e5)\n", label, c, $6, c / goal, goal, c / 7e5, c / 2.5e5 }
            $2 == 1 && $1 == "disks-linear" { line("2D linear:          ", 1.5e6) }
            $2 == 1 && $1 == "bar-quadraticBSpline" { line("3D quadraticBSpline:", 5e5) }' "$raw"
if [ -n "$PEER_CMD" ]; then
    echo "peer: $PEER_CMD"
    start=$(date +%s.%N)
    sh -c "$PEER_CMD" >"$WORK/log.peer" 2>&1 || echo "peer command failed: $WORK/log.peer"
    wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.3g", b - a }')
    echo "peer wall time $wall s"
    [ -n "$PEER_PARTICLE_STEPS" ] && awk -v n="$PEER_PARTICLE_STEPS" -v w="$wall" 'BEGIN { printf "peer: %.3g particle-steps/s\n", n / w }'
else
    echo "peer build: skipped (set PEER_CMD, and PEER_PARTICLE_STEPS, to time one)"
fi
echo "raw rows: $raw; logs under $WORK"
