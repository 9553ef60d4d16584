#!/bin/sh
# Distributed impactSph (issue 21): strong scaling of the 3D impact (bench/impactSph/impact3D, a
# sphere on a plate, ~36 000 particles) from 1 to 2 ranks of one thread each on this machine, beside
# 1 rank of 2 threads (the same two cores through OpenMP), and the figures of a weak-scaling model
# (model.awk) from the measured halo traffic. Usage:
#   bench/mpi/run.sh [endTime=1e-7]
# Environment: MFDYN_BIN (a bin/ folder with impactSph and particleGen built with MPI; default:
# configure and build build-bench/ from this tree), WORK (scratch; default a fresh
# /tmp/mpiBench.XXXX), MPIRUN (default: mpirun --oversubscribe, with --allow-run-as-root as root).
# Not a test: the machine is shared, so compare the ratios of one run, never absolute times.
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/bench/mpi
endTime=${1:-1e-7}
if [ -z "$MFDYN_BIN" ]; then
    build=${MFDYN_BENCH_BUILD:-$root/build-bench}
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMFDYN_BENCH=ON -DMFDYN_TESTS=OFF >/dev/null
    ninja -C "$build" -j"${JOBS:-2}" impactSph particleGen
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

case=$WORK/impact3D
rm -rf "$case" && mkdir -p "$case" && cp -r "$root/bench/impactSph/impact3D/system" "$root/bench/impactSph/impact3D/constant" "$case/"
sed -i "s/^endTime .*/endTime $endTime;/" "$case/system/controlDict"
(cd "$case" && "$MFDYN_BIN/particleGen" > log.particleGen 2>&1)

val() { awk -v L="$2" 'index($0, "    " L " ") == 1 { s = substr($0, length(L) + 5); split(s, a, " "); print a[1]; exit }' "$1"; }
loopSeconds() { grep -m1 "^    wall time" "$1" | sed 's/.*time loop \([0-9.]*\) s.*/\1/'; }

results=$WORK/results.md
{
    echo "| run | ranks x threads | particles | steps | loop s | speed-up over 1 x 1 | halo / owned | halo bytes per particle per evaluation | messages per rank per evaluation |"
    echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
} > "$results"
base=""
for run in "1 1" "1 2" "2 1"; do
    set -- $run
    ranks=$1 threads=$2
    rm -rf "$case"/[1-9]* "$case"/0.* "$case/postProcessing" "$case/particles.pvd"
    log=$case/log.$ranks.$threads
    if [ "$ranks" = 1 ]; then
        (cd "$case" && OMP_NUM_THREADS=$threads "$MFDYN_BIN/impactSph" > "$log" 2>&1)
    else
        (cd "$case" && OMP_NUM_THREADS=$threads $MPIRUN -x OMP_NUM_THREADS -x OMP_WAIT_POLICY -np "$ranks" "$MFDYN_BIN/impactSph" > "$log" 2>&1)
    fi
    loop=$(loopSeconds "$log")
    [ -z "$base" ] && base=$loop
    halo=$(grep -m1 "^    decomposition " "$log" | sed 's/.*(\([0-9.e+-]*\) of the owned).*/\1/')
    bytes=$(grep -m1 "^    halo traffic" "$log" | awk '{print $3}')
    messages=$(grep -m1 "^    halo traffic" "$log" | awk '{print $9}')
    echo "| impact3D | $ranks x $threads | $(val "$log" particles) | $(val "$log" steps) | $loop | $(awk "BEGIN{printf \"%.2f\", $base/$loop}") | ${halo:--} | ${bytes:--} | ${messages:--} |" >> "$results"
    tail -n 1 "$results"
done
echo "twisting column (tlSph): not run, tlSph does not run on several ranks yet (issue 21)" >> "$results"

# The weak-scaling model from the 2-rank run's halo (model.awk: the assumptions).
log2=$case/log.2.1
awk -v loop1="$base" -v steps="$(val "$case/log.1.1" steps)" -v particles="$(val "$case/log.1.1" particles)" \
    -v halo="$(grep -m1 "^    decomposition " "$log2" | sed 's/.*(\([0-9.e+-]*\) of the owned).*/\1/')" \
    -v bytes="$(grep -m1 "^    halo traffic" "$log2" | awk '{print $3}')" \
    -v messages="$(grep -m1 "^    halo traffic" "$log2" | awk '{print $9}')" \
    -f "$here/model.awk" >> "$results"
echo "load average before: $loadStart, after: $(cut -d' ' -f1-3 /proc/loadavg); commit $(git -C "$root" rev-parse --short HEAD)" >> "$results"
cat "$results"
