#!/bin/sh
# tlSph throughput benchmark: the twisting column (Lee et al. 2016 8.9) at several lattices on 1..maxThreads
# threads, and the oscillating plate side by side with PySPH's oscillating_plate example. Usage:
#   bench/tlSph/run.sh [repeats=3] [maxThreads=2] [lattices="4 5 7 13 25"]
# Environment: MFDYN_BIN (a bin/ folder with tlSph and particleGen; default: configure and build build-bench/),
# WORK (scratch folder; default a fresh /tmp/tlSphBench.XXXX), PLATE_TF (simulated time of the plate runs,
# default 0.02 s), NO_PYSPH=1 to skip PySPH, PYTHON (default /usr/bin/python3, the interpreter of the Debian
# python3-pysph package).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
here=$root/bench/tlSph
repeats=${1:-3}
maxThreads=${2:-2}
lattices=${3:-"4 5 7 13 25"}
plateTf=${PLATE_TF:-0.02}
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
if [ -z "$MFDYN_BIN" ]; then
    build=${MFDYN_BENCH_BUILD:-$root/build-bench}
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
    cmake --build "$build" -j"${JOBS:-2}" --target tlSph particleGen
    MFDYN_BIN=$build/bin
fi
WORK=${WORK:-$(mktemp -d /tmp/tlSphBench.XXXX)}
mkdir -p "$WORK"
PYTHON=${PYTHON:-/usr/bin/python3}
loadStart=$(cut -d' ' -f1-3 /proc/loadavg)
raw=$WORK/raw.tsv
: >"$raw"

# Steps per twisting-column run: enough work to time, a few minutes in all. dt = maxCo h / c_p is
# about 1.21e-3 / (n - 1) s on the n x (6(n-1)+1) x n lattice (3.02e-4 s at 5 x 25 x 5), so endTime
# = steps x that; the steps actually taken are read from the log.
stepsFor() { if [ "$1" -le 7 ]; then echo 1000; elif [ "$1" -le 13 ]; then echo 400; else echo 200; fi; }

setupColumn() {  # n
    dir=$WORK/column$1
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$here/twistingColumn/system" "$here/twistingColumn/constant" "$dir/"
    endTime=$(awk -v s="$(stepsFor "$1")" -v n="$1" 'BEGIN { printf "%.6g", s * 1.2096e-3 / (n - 1) }')
    sed -i "s/^endTime .*/endTime         $endTime;/" "$dir/system/controlDict"
    sed -i "s/points (5 25 5);/points ($1 $((6 * ($1 - 1) + 1)) $1);/" "$dir/system/particleGenDict"
    (cd "$dir" && "$MFDYN_BIN/particleGen" >log.particleGen 2>&1)
}

# The tutorial's oscillating plate (1386 particles, dx = 2 mm) without its function objects, to plateTf.
setupPlate() {
    dir=$WORK/plate
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$root/tutorials/tlSph/oscillatingPlate/system" "$root/tutorials/tlSph/oscillatingPlate/constant" "$dir/"
    awk '/^functions/ { skip = 1 } !skip { print }' "$dir/system/controlDict" >"$dir/controlDict" && mv "$dir/controlDict" "$dir/system/controlDict"
    sed -i "s/^endTime .*/endTime         $plateTf;/; s/^writeInterval .*/writeInterval   100;/" "$dir/system/controlDict"
    (cd "$dir" && "$MFDYN_BIN/particleGen" >log.particleGen 2>&1)
}

# Summary line value: the field after the label
val() { awk -v L="$2" 'index($0, "    " L " ") == 1 { s = substr($0, length(L) + 5); split(s, a, " "); print a[1]; exit }' "$1"; }
phase() { grep -m1 "^    phase $2 " "$1" | sed 's/.*(\([0-9.]*\)%).*/\1/'; }

# One tlSph run: case folder name, threads, repeat. Appends a row to raw.tsv:
# case threads repeat particles steps loop_s cpu_s pss pairs/s neighbours fieldB peakMiB %stress %rates %diss %proj %integrate
runTlSph() {
    dir=$WORK/$1
    rm -rf "$dir"/[1-9]* "$dir"/0.[0-9]*
    log=$dir/log.tlSph.$2.$3
    (cd "$dir" && OMP_NUM_THREADS=$2 /usr/bin/time -f "cpu %U %S" "$MFDYN_BIN/tlSph" >"$log" 2>&1) || { echo "tlSph failed: $log"; tail -5 "$log"; exit 1; }
    particles=$(val "$log" particles)
    steps=$(val "$log" steps)
    pss=$(val "$log" particle-steps/s)
    pairs=$(val "$log" "pair interactions/s")
    nb=$(grep -m1 "pair interactions/s" "$log" | sed 's/.*(\([0-9.]*\) neighbours.*/\1/')
    cpu=$(awk '/^cpu /{ print $2 + $3 }' "$log")
    fieldB=$(grep -m1 "^Fields (" "$log" | sed 's/Fields (\([0-9]*\) B.*/\1/')
    peak=$(val "$log" "peak memory")
    loop=$(awk "BEGIN { printf \"%.4g\", $particles * $steps / $pss }")
    printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n" "$1" "$2" "$3" "$particles" "$steps" "$loop" "$cpu" \
        "$pss" "$pairs" "$nb" "$fieldB" "$peak" "$(phase "$log" computeStress)" "$(phase "$log" computeRates)" \
        "$(phase "$log" dissipation)" "$(phase "$log" projections)" "$(phase "$log" integrate)" >>"$raw"
    echo "  $1, $2 thread(s), repeat $3: $particles particles, $steps steps, $pss particle-steps/s, cpu $cpu s"
}

# One PySPH run (serial Cython: --no-openmp, OMP_NUM_THREADS=1) to plateTf; appends to pysph.tsv:
# repeat plateParticles steps loop_wall_s loop_cpu_s neighbours(self included)
runPysph() {
    log=$WORK/pysph/log.pysph.$1
    (cd "$WORK/pysph" && OMP_NUM_THREADS=1 HOME=$WORK/pysph/home "$PYTHON" "$here/pysph_plate.py" \
        --tf "$plateTf" --no-openmp --disable-output -d out >"$log" 2>&1) || { echo "PySPH run failed: $log"; return 1; }
    grep -m1 "^Timed loop" "$log" | sed 's/[,:]/ /g' | awk -v r="$1" '{
        for (i = 1; i <= NF; ++i) {
            if ($i == "steps") s = $(i + 1); if ($i == "wall") w = $(i + 1); if ($i == "cpu") c = $(i + 1);
            if ($i == "plate" && p == "") p = $(i + 2); if ($i == "neighbours") nb = $(i + 4) }
        printf "%s\t%s\t%s\t%s\t%s\t%s\n", r, p, s, w, c, nb }' >>"$WORK/pysph.tsv"
    echo "  PySPH repeat $1: $(tail -n1 "$WORK/pysph.tsv")"
}

for n in $lattices; do setupColumn "$n"; done
setupPlate
havePysph=
if [ -z "$NO_PYSPH" ]; then
    if "$PYTHON" -c 'import pysph' 2>/dev/null; then
        havePysph=1
        rm -rf "$WORK/pysph"; mkdir -p "$WORK/pysph/home"; : >"$WORK/pysph.tsv"
        # Warm-up: PySPH generates and compiles its Cython code (cached under HOME) outside the timed runs.
        echo "PySPH warm-up (Cython compilation)"
        (cd "$WORK/pysph" && OMP_NUM_THREADS=1 HOME=$WORK/pysph/home "$PYTHON" "$here/pysph_plate.py" \
            --max-steps 2 --no-openmp --disable-output -d out >log.compile 2>&1) || { echo "PySPH failed: $WORK/pysph/log.compile"; havePysph=; }
    else
        echo "PySPH not importable by $PYTHON (apt-get install -y python3-pysph)"
    fi
fi

# Repeats outermost so that a slow spell of the machine spreads over all cases; PySPH and the tlSph plate
# on one thread run back to back in each repeat, and their ratio is taken pair by pair.
for r in $(seq 1 "$repeats"); do
    echo "repeat $r (load average $(cut -d' ' -f1-3 /proc/loadavg))"
    if [ -n "$havePysph" ]; then runPysph "$r" || havePysph=; fi
    for t in $(seq 1 "$maxThreads"); do runTlSph plate "$t" "$r"; done
    for n in $lattices; do
        for t in $(seq 1 "$maxThreads"); do runTlSph "column$n" "$t" "$r"; done
    done
done

# Medians over the repeats (of each column separately).
median() { sort -g | awk '{ a[NR] = $1 } END { if (NR % 2) print a[(NR + 1) / 2]; else print (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
col() { awk -F'\t' -v c="$1" -v k="$2" -v t="$3" '$1 == c && $2 == t { print $k }' "$raw" | median; }

results=$WORK/results.md
{
    echo "Medians of $repeats repeats. per core = divided by the threads; cpu = user + system seconds of the whole tlSph process."
    echo
    echo "| case | lattice | particles | threads | steps | loop s | cpu s | particle-steps/s | particle-steps/s per core | particle-steps per cpu s | neighbours | pair interactions/s per core | field B/particle | peak MiB | peak B/particle |"
    echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    for c in plate $(for n in $lattices; do echo "column$n"; done); do
        case $c in plate) lattice="plate dx 2 mm (2D)" ;; *) n=${c#column}; lattice="${n}x$((6 * (n - 1) + 1))x$n" ;; esac
        for t in $(seq 1 "$maxThreads"); do
            p=$(col "$c" 4 "$t"); s=$(col "$c" 5 "$t"); pss=$(col "$c" 8 "$t"); cpu=$(col "$c" 7 "$t"); peak=$(col "$c" 12 "$t")
            echo "| $c | $lattice | $p | $t | $s | $(col "$c" 6 "$t") | $cpu | $pss | $(awk "BEGIN { printf \"%.3g\", $pss / $t }") | $(awk "BEGIN { printf \"%.3g\", $p * $s / $cpu }") | $(col "$c" 10 "$t") | $(awk "BEGIN { printf \"%.3g\", $(col "$c" 9 "$t") / $t }") | $(col "$c" 11 "$t") | $peak | $(awk "BEGIN { printf \"%.0f\", $peak * 1048576 / $p }") |"
        done
    done
    echo
    echo "Phase shares of the time loop (Summary, 1 thread, medians):"
    echo
    echo "| case | particles | neighbours | computeStress | computeRates | dissipation | projections | integrate | rest |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
    for c in plate $(for n in $lattices; do echo "column$n"; done); do
        a=$(col "$c" 13 1); b=$(col "$c" 14 1); d=$(col "$c" 15 1); e=$(col "$c" 16 1); f=$(col "$c" 17 1)
        echo "| $c | $(col "$c" 4 1) | $(col "$c" 10 1) | $a% | $b% | $d% | $e% | $f% | $(awk "BEGIN { printf \"%.1f\", 100 - $a - $b - $d - $e - $f }")% |"
    done
} >"$results"

if [ -n "$havePysph" ] && [ -s "$WORK/pysph.tsv" ]; then
    # Pair by pair: repeat r of PySPH against repeat r of the tlSph plate on one thread.
    awk -F'\t' 'NR == FNR { if ($1 == "plate" && $2 == 1) { tp[$3] = $4; ts[$3] = $5; tl[$3] = $6; tc[$3] = $7; tn[$3] = $10 } next }
        { r = $1; printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n", r, $2, $3, $4, $5, $6, tp[r], ts[r], tl[r], tc[r], tn[r] }' \
        "$raw" "$WORK/pysph.tsv" >"$WORK/pairs.tsv"
    m() { awk -F'\t' "{ print $1 }" "$WORK/pairs.tsv" | median | awk '{ printf "%.4g", $1 }'; }
    {
        echo
        echo "Oscillating plate to t = $plateTf s, serial (PySPH --no-openmp, tlSph OMP_NUM_THREADS=1), medians of $repeats pairs:"
        echo
        echo "| code | particles | steps | dt s | evaluations/step | neighbours (self excluded) | loop wall s | loop cpu s | particle-steps/s per core (wall) | particle-steps/s per core (cpu) |"
        echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
        echo "| PySPH oscillating_plate (EPEC, dt fixed) | $(m '$2') + 207 wall | $(m '$3') | $(awk "BEGIN { printf \"%.4g\", $plateTf / $(m '$3') }") | 2 | $(m '$6 - 1') | $(m '$4') | $(m '$5') | $(m '$2 * $3 / $4') | $(m '$2 * $3 / $5') |"
        echo "| tlSph oscillatingPlate (RK2, CFL dt) | $(m '$7') | $(m '$8') | $(awk "BEGIN { printf \"%.4g\", $plateTf / $(m '$8') }") | 2 | $(m '$11') | $(m '$9') | $(m '$10') | $(m '$7 * $8 / $9') | $(m '$7 * $8 / $10') |"
        echo
        echo "tlSph / PySPH, medians of the pairwise ratios:"
        echo "- throughput per core (particle-steps/s): $(m '($7 * $8 / $9) / ($2 * $3 / $4)') x by wall, $(m '($7 * $8 / $10) / ($2 * $3 / $5)') x by cpu (tlSph process cpu includes its set-up)"
        echo "- time to simulate $plateTf s: PySPH / tlSph wall $(m '$4 / $9') x, cpu $(m '$5 / $10') x"
        echo "- pairwise ratios by wall: $(awk -F'\t' '{ printf "%.3g ", ($7 * $8 / $9) / ($2 * $3 / $4) }' "$WORK/pairs.tsv")"
    } >>"$results"
fi
echo >>"$results"
echo "load average at start: $loadStart, at end: $(cut -d' ' -f1-3 /proc/loadavg) ($(nproc) cores)" >>"$results"
echo
cat "$results"
echo "Logs under $WORK"
