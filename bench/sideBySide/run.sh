#!/bin/sh
# Speed of this tree against another build (the previous commit, a branch), side by side in one run:
# impactSph on tutorials/impactSph/hviAlAl (0.25 mm, 7202 particles, to t = 2 us) and tlSph on the
# bench's twisting column (bench/tlSph/twistingColumn, 7 x 37 x 7, 1000 steps), one thread each.
# The two builds run in turn, A B A B ..., and the ratio new/old of the Summary's
# particle-steps/s is taken pair by pair (the machine's speed drifts less within a pair than over
# the whole run); the median of the pairs is the figure. Each build runs its cases as its own source
# tree writes them (a keyword may have moved between the two), so the physics must be the same case,
# which the script checks by comparing the steps taken.
# Usage:
#   MFDYN_BASE_BIN=/path/old/build/bin MFDYN_BASE_SRC=/path/old/tree bench/sideBySide/run.sh [pairs=5]
# Environment: MFDYN_BIN (this tree's bin/, default build/bin), MFDYN_BASE_BIN and MFDYN_BASE_SRC (the
# other build and its source tree; the comparison is skipped when absent), WORK (scratch folder).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
pairs=${1:-5}
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive} OMP_NUM_THREADS=1
MFDYN_BIN=${MFDYN_BIN:-$root/build/bin}
if [ -z "$MFDYN_BASE_BIN" ] || [ ! -x "$MFDYN_BASE_BIN/impactSph" ] || [ -z "$MFDYN_BASE_SRC" ]; then
    echo "MFDYN_BASE_BIN / MFDYN_BASE_SRC not set (or no impactSph there): nothing to compare against; skipped"
    exit 0
fi
WORK=${WORK:-$(mktemp -d /tmp/sideBySide.XXXX)}
mkdir -p "$WORK"

val() { awk -v L="$2" 'index($0, "    " L " ") == 1 { s = substr($0, length(L) + 5); split(s, a, " "); print a[1]; exit }' "$1"; }

setup() {  # side bin src
    d=$WORK/$1
    rm -rf "$d"; mkdir -p "$d/sph" "$d/tl"
    cp -r "$3/tutorials/impactSph/hviAlAl/system" "$3/tutorials/impactSph/hviAlAl/constant" "$d/sph/"
    sed -i "s/^endTime .*/endTime 2e-6;/; s/^writeInterval .*/writeInterval 1;/" "$d/sph/system/controlDict"
    cp -r "$3/bench/tlSph/twistingColumn/system" "$3/bench/tlSph/twistingColumn/constant" "$d/tl/"
    sed -i "s/^endTime .*/endTime         2.016e-1;/" "$d/tl/system/controlDict"
    sed -i "s/points (5 25 5);/points (7 37 7);/" "$d/tl/system/particleGenDict"
    (cd "$d/sph" && "$2/particleGen" >log.particleGen 2>&1)
    (cd "$d/tl" && "$2/particleGen" >log.particleGen 2>&1)
}
run() {  # side bin solver case -> particle-steps/s
    d=$WORK/$1/$4
    rm -rf "$d"/[1-9]* "$d"/0.* "$d"/postProcessing
    (cd "$d" && "$2/$3" >log.$3 2>&1) || { echo "run failed: $d/log.$3" >&2; exit 1; }
    echo "$(val "$d/log.$3" particle-steps/s) $(val "$d/log.$3" steps)"
}

setup new "$MFDYN_BIN" "$root"
setup old "$MFDYN_BASE_BIN" "$MFDYN_BASE_SRC"
out=$WORK/results.md
echo "| pair | impactSph new | old | new/old | tlSph new | old | new/old |" >"$out"
echo "|---:|---:|---:|---:|---:|---:|---:|" >>"$out"
for k in $(seq 1 "$pairs"); do
    set -- $(run new "$MFDYN_BIN" impactSph sph); sn=$1; stepsN=$2
    set -- $(run old "$MFDYN_BASE_BIN" impactSph sph); so=$1; stepsO=$2
    [ "$stepsN" = "$stepsO" ] || echo "impactSph: $stepsN steps (new) vs $stepsO (old): not the same case" >&2
    set -- $(run new "$MFDYN_BIN" tlSph tl); tn=$1; stepsN=$2
    set -- $(run old "$MFDYN_BASE_BIN" tlSph tl); to=$1; stepsO=$2
    [ "$stepsN" = "$stepsO" ] || echo "tlSph: $stepsN steps (new) vs $stepsO (old): not the same case" >&2
    echo "| $k | $sn | $so | $(awk "BEGIN{printf \"%.4f\", $sn/$so}") | $tn | $to | $(awk "BEGIN{printf \"%.4f\", $tn/$to}") |" >>"$out"
    tail -n1 "$out"
done
med() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
echo "median new/old: impactSph $(awk -F'|' 'NR>2{print $5}' "$out" | med), tlSph $(awk -F'|' 'NR>2{print $8}' "$out" | med)" >>"$out"
echo "load average at end: $(cut -d' ' -f1-3 /proc/loadavg)" >>"$out"
cat "$out"
echo "Logs under $WORK"
