#!/bin/sh
# fpmSolid throughput benchmark (issue 19; not a test): the reference sphere (radius 5, doc/methods/fpm.md
# §4.9) at about 4500 and 1e5 particles (cubic lattice, spacing (4/3 pi 5^3 / N)^(1/3), h = 2 spacings),
# frozen particles in the Euler validation's state (tutorials/fpmSolid/eulerValidation) with
# subsystems (euler rotation), and the shear validation's state (tutorials/fpmSolid/shearValidation,
# when the tree has it) with subsystems (shear); each with the first-order basis and the second-order
# one (fitFallback growSupport at h = 2 spacings), on 1 .. maxThreads threads. Prints particle-steps/s
# per core, memory per particle (the summary's peak memory / particles), the solver's phase times and
# the fit assembly's flop rate (the flops of fitPoint per neighbour with a positive weight, order 1 and 2,
# full derivative, see README.md, times the pairs fitted per second). Usage:
#   bench/fpm/run.sh [maxThreads=2] [sizes="4500 100000"] [configs="euler1 euler2 shear1 shear2"]
# Environment: MFDYN_BIN (a bin/ folder with fpmSolid and particleGen; default: build/ of this checkout),
# WORK (scratch folder; default a fresh /tmp/fpmBench.XXXX), STEPS_SMALL (steps below 1e4 particles,
# default 20), STEPS_LARGE (steps above, default 2), PERF=1 (perf record the first run of each config at
# the smallest size, 1 thread; perf report head in $WORK/perf.<case>.txt).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
maxThreads=${1:-2}
sizes=${2:-"4500 100000"}
configs=${3:-"euler1 euler2 shear1 shear2"}
MFDYN_BIN=${MFDYN_BIN:-$root/build/bin}
[ -x "$MFDYN_BIN/fpmSolid" ] || { echo "no $MFDYN_BIN/fpmSolid: build first (or set MFDYN_BIN)" >&2; exit 1; }
WORK=${WORK:-$(mktemp -d /tmp/fpmBench.XXXX)}
mkdir -p "$WORK"
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
stepsSmall=${STEPS_SMALL:-20}
stepsLarge=${STEPS_LARGE:-2}
raw=$WORK/raw.tsv
: >"$raw"
echo "load average at start: $(cut -d' ' -f1-3 /proc/loadavg) (shared cores: figures are lower bounds)"
echo "commit $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown), $(date -u +%Y-%m-%d)"

# Flops of fitPoint per neighbour with a positive weight (README.md: the count, 3D value form,
# full derivative: order 1 m = 4, order 2 m = 10), for the assembly's flop rate.
flopsFor() { if [ "$1" = 1 ]; then echo 392; else echo 2319; fi; }

setupCase() {  # config N -> $dir
    cfg=$1; n=$2
    case $cfg in euler*) tut=eulerValidation ;; shear*) tut=shearValidation ;; esac
    order=${cfg#euler}; order=${order#shear}
    src=$root/tutorials/fpmSolid/$tut
    [ -d "$src/constant" ] || return 1
    dir=$WORK/$cfg.$n
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$src/system" "$src/constant" "$dir/"
    spacing=$(awk -v n="$n" 'BEGIN { printf "%.4g", (4.0 / 3.0 * 3.14159265358979 * 125 / n) ^ (1.0 / 3.0) }')
    h=$(awk -v s="$spacing" 'BEGIN { printf "%.6g", 2 * s }')
    steps=$stepsSmall; [ "$n" -gt 10000 ] && steps=$stepsLarge
    end=$(awk -v s="$steps" 'BEGIN { printf "%.6g", s * 0.001 }')
    sed -i "s/spacing [0-9.]*; }/spacing $spacing; }/" "$dir/system/particleGenDict"
    grep -q "spacing $spacing; }" "$dir/system/particleGenDict" || { echo "cannot set the spacing in $dir" >&2; exit 1; }
    sed -i "s/^deltaT .*/deltaT 0.001;/; s/^endTime .*/endTime $end;/; s/^writeInterval .*/writeInterval $end;/" "$dir/system/controlDict"
    p=$dir/constant/fpmProperties
    sed -i "s/^smoothingLength .*/smoothingLength $h;/; s/^order .*/order $order;/" "$p"
    [ "$order" = 2 ] && sed -i "s/^fitFallback .*/fitFallback growSupport;/" "$p"
    case $cfg in euler*) sed -i "s/^subsystems .*/subsystems      (euler rotation);/" "$p" ;; esac
    (cd "$dir" && "$MFDYN_BIN/particleGen" >log.particleGen 2>&1)
    return 0
}

val() { awk -v L="$2" 'index($0, "    " L " ") == 1 { s = substr($0, length(L) + 5); split(s, a, " "); print a[1]; exit }' "$1"; }
phase() { grep -m1 "^    phase $2 " "$1" | sed 's/.*(\([0-9.]*\)%).*/\1/'; }

for n in $sizes; do
    for cfg in $configs; do
        setupCase "$cfg" "$n" || { echo "skip $cfg: no tutorial"; continue; }
        t=1
        while [ "$t" -le "$maxThreads" ]; do
            log=$dir/log.fpmSolid.$t
            (cd "$dir" && rm -rf 0.0* && OMP_NUM_THREADS=$t "$MFDYN_BIN/fpmSolid" >"$log" 2>&1) ||
                { echo "fpmSolid failed in $dir:"; tail -5 "$log"; exit 1; }
            if [ -n "$PERF" ] && [ "$t" = 1 ] && [ "$n" = "${sizes%% *}" ]; then
                (cd "$dir" && rm -rf 0.0* && OMP_NUM_THREADS=1 perf record -q -g -o "$WORK/perf.$cfg.data" \
                    "$MFDYN_BIN/fpmSolid" >/dev/null 2>&1 &&
                    perf report -q --no-children -i "$WORK/perf.$cfg.data" --stdio 2>/dev/null |
                    grep -E '^ +[0-9.]+%' | head -25 >"$WORK/perf.$cfg.txt") || true
            fi
            parts=$(val "$log" particles)
            steps=$(val "$log" steps)
            pss=$(val "$log" particle-steps/s)
            peak=$(grep -m1 '^    peak memory' "$log" | awk '{ v = $3; if ($4 == "GiB") v *= 1024; if ($4 == "KiB") v /= 1024; print v }')
            rows=$(grep -m1 '^    fit  ' "$log" | awk '{ print $2 }')
            loop=$(awk -v n="$parts" -v s="$steps" -v r="$pss" 'BEGIN { printf "%.3g", n * s / r }')
            fitFrac=$(phase "$log" fit); shearFrac=$(phase "$log" shear); eulerFrac=$(phase "$log" euler)
            nbFrac=$(phase "$log" neighbours)
            printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$cfg" "$parts" "$t" "$steps" "$loop" "$pss" \
                "$peak" "$rows" "$nbFrac" "$fitFrac" "$eulerFrac" "$shearFrac" "$spacing" >>"$raw"
            t=$((t + 1))
        done
    done
done

# Table. Fits per particle-step: 1 central (euler: + 2 per shifted particle, none in the validation's
# uniform p), shear: 1 + 2 d = 7 in 3D. Pairs with a positive weight: the rows, except with growSupport
# (rows to 2 h, weights to h unless grown): rows / 8. Flop rate = pairs/s x flops per pair / threads, over
# the fit's phases (fit + euler + shear) share of the loop.
echo
echo "| case | particles | spacing | threads | steps | loop s | particle-steps/s | per core | peak MiB | B/particle | rows | neighbours % | fit % | euler % | shear % | fit GFLOP/s per core |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
awk -F'\t' '{
    cfg = $1; order = substr(cfg, length(cfg)); fits = (cfg ~ /^shear/) ? 7 : 1
    flops = (order == 1) ? 392 : 2319; pos = (order == 1) ? $8 : $8 / 8
    frac = ($10 + $11 + $12) / 100
    gf = (frac > 0) ? $6 * fits * pos * flops / ($3 * frac) / 1e9 : 0
    printf "| %s | %d | %s | %d | %d | %s | %.4g | %.4g | %s | %.0f | %s | %s | %s | %s | %s | %.2f |\n",
        cfg, $2, $13, $3, $4, $5, $6, $6 / $3, $7, $7 * 1048576 / $2, $8, $9, $10, $11, $12, gf
}' "$raw" | tee "$WORK/results.md"
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "raw: $raw, logs in $WORK/<case>.<N>/log.fpmSolid.<threads>"
