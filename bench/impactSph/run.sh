#!/bin/sh
# impactSph throughput benchmark (2D hviAlAl, 3D sphere on plate) on 1 and 2 threads, and PySPH's
# 2D solid-mechanics impact example side by side. Usage:
#   bench/impactSph/run.sh [pysphSteps=200] [maxThreads=2]
# Environment: MFDYN_BIN (a bin/ folder with impactSph and particleGen; default: configure and build
# build-bench/), WORK (scratch folder; default a fresh /tmp/impactSphBench.XXXX), NO_PYSPH=1 to skip
# PySPH, PYTHON (default /usr/bin/python3, the interpreter of the Debian python3-pysph package).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/bench/impactSph
pysphSteps=${1:-200}
maxThreads=${2:-2}
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
if [ -z "$MFDYN_BIN" ]; then
    build=${MFDYN_BENCH_BUILD:-$root/build-bench}
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMFDYN_BENCH=ON -DMFDYN_TESTS=OFF >/dev/null
    ninja -C "$build" -j"${JOBS:-2}" impactSph particleGen
    MFDYN_BIN=$build/bin
fi
WORK=${WORK:-$(mktemp -d /tmp/impactSphBench.XXXX)}
mkdir -p "$WORK"
PYTHON=${PYTHON:-/usr/bin/python3}
loadStart=$(cut -d' ' -f1-3 /proc/loadavg)

# case name, source folder, endTime, optional spacing substitution (old/new)
setupCase() {
    dir=$WORK/$1
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$2/system" "$2/constant" "$dir/"
    sed -i "s/^endTime .*/endTime $3;/; s/^writeInterval .*/writeInterval 1;/" "$dir/system/controlDict"
    [ -n "$4" ] && sed -i "s/spacing $4;/spacing $5;/g" "$dir/system/particleGenDict"
    (cd "$dir" && "$MFDYN_BIN/particleGen" >log.particleGen 2>&1)
}

# Summary line value: field after the label
val() { awk -v L="$2" 'index($0, "    " L " ") == 1 { s = substr($0, length(L) + 5); split(s, a, " "); print a[1]; exit }' "$1"; }

results=$WORK/results.md
{
    echo "| case | dim | particles | threads | steps | loop s | cpu s | particle-steps/s | particle-steps/s per core | pairs/particle | pair interactions/s per core | field B/particle | peak MiB | peak B/particle |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
} >"$results"

runCase() {  # case dim threads
    dir=$WORK/$1
    rm -rf "$dir"/[0-9]*
    (cd "$dir" && "$MFDYN_BIN/particleGen" >/dev/null 2>&1)
    (cd "$dir" && OMP_NUM_THREADS=$3 /usr/bin/time -f "cpu %U %S" "$MFDYN_BIN/impactSph" >log.impactSph.$3 2>&1)
    log=$dir/log.impactSph.$3
    particles=$(val "$log" particles)
    steps=$(val "$log" steps)
    loop=$(grep -m1 "^    wall time" "$log" | sed 's/.*time loop \([^,]*\),.*/\1/')
    cpu=$(awk '/^cpu /{print $2 + $3}' "$log")
    pss=$(val "$log" particle-steps/s)
    pairs=$(val "$log" "pair interactions/s")
    ppp=$(grep -m1 "pair interactions/s" "$log" | sed 's/.*(\([0-9.]*\) candidate.*/\1/')
    fieldB=$(grep -m1 "^Fields (" "$log" | sed 's/Fields (\([0-9]*\) B.*/\1/')
    peak=$(val "$log" "peak memory")
    echo "| $1 | $2 | $particles | $3 | $steps | $loop | $cpu | $pss | $(awk "BEGIN{printf \"%.4g\", $pss/$3}") | $ppp | $(awk "BEGIN{printf \"%.4g\", $pairs/$3}") | $fieldB | $peak | $(awk "BEGIN{printf \"%.0f\", $peak*1048576/$particles}") |" >>"$results"
    tail -n1 "$results"
}

tut=$root/tutorials/impactSph/hviAlAl
setupCase hviAlAl-0.5mm "$tut" 4e-6 2.5e-4 5e-4
setupCase hviAlAl-0.25mm "$tut" 2e-6
setupCase impact3D "$here/impact3D" 1e-7
for t in $(seq 1 "$maxThreads"); do
    runCase hviAlAl-0.5mm 2 "$t"
    runCase hviAlAl-0.25mm 2 "$t"
    runCase impact3D 3 "$t"
done

# PySPH: pysph.examples.solid_mech.impact at dx = 0.15 mm (7503 particles, Gaussian cut at 3h,
# h = 1.3 dx on a square lattice: pi 3.9^2 = 48 neighbours), serial (--no-openmp), fixed steps.
if [ -z "$NO_PYSPH" ]; then
    if "$PYTHON" -c 'import pysph' 2>/dev/null; then
        mkdir -p "$WORK/pysph"
        (cd "$WORK/pysph" && OMP_NUM_THREADS=1 HOME=$WORK/pysph /usr/bin/time -f "cpu %U %S" "$PYTHON" "$here/pysph_impact.py" 1.5e-4 \
            --max-steps "$pysphSteps" --disable-output --no-openmp -d out >log.pysph 2>&1) || echo "PySPH run failed: $WORK/pysph/log.pysph"
        plog=$WORK/pysph/log.pysph
        pn=$(grep -m1 "Total:" "$plog" | awk '{print $2}')
        prun=$(grep -m1 "Run took" "$plog" | awk '{print $3}')
        psetup=$(grep -m1 "Setup took" "$plog" | awk '{print $3}')
        mlog=$WORK/hviAlAl-0.25mm/log.impactSph.1
        mpss=$(val "$mlog" particle-steps/s)
        {
            echo
            echo "| code | particles | threads | steps | force evaluations/step | set-up s | loop s | particle-steps/s per core | particle-evaluations/s per core |"
            echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
            echo "| PySPH impact (dx 0.15 mm, EPEC) | $pn | 1 | $pysphSteps | 2 | $psetup | $prun | $(awk "BEGIN{printf \"%.4g\", $pn*$pysphSteps/$prun}") | $(awk "BEGIN{printf \"%.4g\", 2*$pn*$pysphSteps/$prun}") |"
            echo "| impactSph hviAlAl 0.25 mm (leapfrog) | $(val "$mlog" particles) | 1 | $(val "$mlog" steps) | 1 | - | - | $mpss | $mpss |"
            echo
            echo "impactSph / PySPH per core: $(awk "BEGIN{printf \"%.2f\", $mpss/($pn*$pysphSteps/$prun)}")x per step, $(awk "BEGIN{printf \"%.2f\", $mpss/(2*$pn*$pysphSteps/$prun)}")x per force evaluation"
        } >>"$results"
    else
        echo "PySPH not importable by $PYTHON (apt-get install -y python3-pysph)" >>"$results"
    fi
fi
echo "load average at start: $loadStart, at end: $(cut -d' ' -f1-3 /proc/loadavg) (2-core machine: $(nproc) cores)" >>"$results"
echo
cat "$results"
echo "Logs under $WORK"
