#!/bin/sh
# Distributed runs (issue 21): strong scaling of the 3D impact (impactSph, bench/impactSph/impact3D,
# a sphere on a plate, 33 024 particles), the twisting column (tlSph, bench/tlSph/twistingColumn),
# the dam break (mpmFsi, tutorials/mpmFsi/damBreak at half its spacing: 12 800 points) and
# the rotating sphere (fpmSolid, tutorials/fpmSolid/rotatingSphere, 1244 particles) from 1 to 2
# ranks of one thread each on this machine, beside 1 rank of 2 threads (the same two cores through
# OpenMP), and for each a weak-scaling model (model.awk) from the measured halo traffic. Usage:
#   bench/mpi/run.sh [impactEndTime=5e-8] [columnEndTime=0.01] [damEndTime=0.01] [sphereEndTime=0.1]
# (13 steps of the impact, 100 of the column at 13 x 73 x 13, about 190 of the dam, 100 of the sphere). CASES (default
# "impact3D twistingColumn damBreak rotatingSphere") picks some of them.
# Environment: MFDYN_BIN (a bin/ folder with impactSph and particleGen built with MPI; default:
# configure and build build-bench/ from this tree), WORK (scratch; default a fresh
# /tmp/mpiBench.XXXX), MPIRUN (default: mpirun --oversubscribe, with --allow-run-as-root as root).
# Not a test: the machine is shared, so compare the ratios of one run, never absolute times.
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/bench/mpi
impactEndTime=${1:-5e-8}
columnEndTime=${2:-0.01}
damEndTime=${3:-0.01}
sphereEndTime=${4:-0.1}
CASES=${CASES:-"impact3D twistingColumn damBreak rotatingSphere"}
if [ -z "$MFDYN_BIN" ]; then
    build=${MFDYN_BENCH_BUILD:-$root/build-bench}
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMFDYN_BENCH=ON -DMFDYN_TESTS=OFF >/dev/null
    ninja -C "$build" -j"${JOBS:-2}" impactSph tlSph mpmFsi fpmSolid particleGen
    MFDYN_BIN=$build/bin
fi
if [ -z "$MPIRUN" ]; then
    MPIRUN="mpirun --oversubscribe"
    [ "$(id -u)" = 0 ] && MPIRUN="$MPIRUN --allow-run-as-root"
fi
WORK=${WORK:-$(mktemp -d /tmp/mpiBench.XXXX)}
mkdir -p "$WORK"
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
loadStart=$(cut -d' ' -f1-3 /proc/loadavg)

val() { awk -v L="$2" 'index($0, "    " L " ") == 1 { s = substr($0, length(L) + 5); split(s, a, " "); print a[1]; exit }' "$1"; }
loopSeconds() { grep -m1 "^    wall time" "$1" | sed 's/.*time loop \([0-9.]*\) s.*/\1/'; }
haloFraction() { grep -m1 "^    decomposition " "$1" | sed 's/.*(\([0-9.e+-]*\) of the owned).*/\1/'; }
haloBytes() { grep -m1 "^    halo traffic" "$1" | awk '{print $3}'; }
haloMessages() { grep -m1 "^    halo traffic" "$1" | awk '{print $8}'; }

results=$WORK/results.md
{
    echo "| case | solver | ranks x threads | particles | steps | loop s | speed-up over 1 x 1 | halo / owned | halo bytes per particle per evaluation | messages per rank per evaluation |"
    echo "|---|---|---|---:|---:|---:|---:|---:|---:|---:|"
} > "$results"
models=""

# benchCase <name> <solver> <source> <endTime> [<sed script for its particleGenDict>]
benchCase() {
    name=$1 solver=$2
    case=$WORK/$name
    rm -rf "$case" && mkdir -p "$case" && cp -r "$3/system" "$3/constant" "$case/"
    sed -i "s/^endTime .*/endTime $4;/; s/^writeInterval .*/writeInterval 1e9;/" "$case/system/controlDict"
    [ -n "${5:-}" ] && sed -i "$5" "$case/system/particleGenDict"
    (cd "$case" && "$MFDYN_BIN/particleGen" > log.particleGen 2>&1)
    base=""
    for run in "1 1" "1 2" "2 1"; do
        set -- $run
        ranks=$1 threads=$2
        rm -rf "$case"/[1-9]* "$case"/0.* "$case/postProcessing"
        log=$case/log.$ranks.$threads
        if [ "$ranks" = 1 ]; then
            (cd "$case" && OMP_NUM_THREADS=$threads "$MFDYN_BIN/$solver" > "$log" 2>&1)
        else
            (cd "$case" && OMP_NUM_THREADS=$threads $MPIRUN -x OMP_NUM_THREADS -x OMP_WAIT_POLICY -np "$ranks" "$MFDYN_BIN/$solver" > "$log" 2>&1)
        fi
        loop=$(loopSeconds "$log")
        [ -z "$base" ] && base=$loop
        echo "| $name | $solver | $ranks x $threads | $(val "$log" particles) | $(val "$log" steps) | $loop | $(awk "BEGIN{printf \"%.2f\", $base/$loop}") | $(haloFraction "$log") | $(haloBytes "$log") | $(haloMessages "$log") |" >> "$results"
        tail -n 1 "$results"
    done
    # The weak-scaling model from the 2-rank run's halo (model.awk: the assumptions).
    log2=$case/log.2.1
    models="$models$(awk -v name="$name" -v loop1="$base" -v steps="$(val "$case/log.1.1" steps)" \
        -v particles="$(val "$case/log.1.1" particles)" -v halo="$(haloFraction "$log2")" \
        -v bytes="$(haloBytes "$log2")" -v messages="$(haloMessages "$log2")" -f "$here/model.awk")
"
}

picked() { case " $CASES " in *" $1 "*) return 0 ;; esac; return 1; }
picked impact3D && benchCase impact3D impactSph "$root/bench/impactSph/impact3D" "$impactEndTime"
# The column at 13 x 73 x 13 (12 337 particles; dt about 1e-4 s: 100 steps to 0.01 s).
picked twistingColumn &&
    benchCase twistingColumn tlSph "$root/bench/tlSph/twistingColumn" "$columnEndTime" 's/points (5 25 5);/points (13 73 13);/'
# The dam break's water column at half the tutorial's spacing (12 800 points, 4 a cell; the grid unchanged).
damLattice='s/cells (40 80);/cells (80 160);/'
picked damBreak && benchCase damBreak mpmFsi "$root/tutorials/mpmFsi/damBreak" "$damEndTime" "$damLattice"
picked rotatingSphere && benchCase rotatingSphere fpmSolid "$root/tutorials/fpmSolid/rotatingSphere" "$sphereEndTime"

echo "$models" >> "$results"
echo "load average before: $loadStart, after: $(cut -d' ' -f1-3 /proc/loadavg); commit $(git -C "$root" rev-parse --short HEAD)" >> "$results"
cat "$results"
