#!/bin/sh
# What the health check costs (issue 20; not a test): each case is run with the health check on (the
# default) and off (`health off;`), in alternating pairs so that a change of the machine's load hits
# both alike; prints per case the median time-loop seconds of each, their ratio, and the health line's
# own measured cost (its seconds in check and write against the run). The goal is below 3%.
#   bench/health/run.sh [pairs=3] [cases="sod hvi cube mpmBar fpmTube"]
# Environment: MFDYN_BIN (a bin/ folder with the solvers, particleGen, mfDictionary; default build/
# of this checkout), WORK (scratch folder; default a fresh /tmp/healthBench.XXXX), OMP_NUM_THREADS
# (default 1: one core, the figure least disturbed by a shared machine).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
pairs=${1:-3}
cases=${2:-"sod hvi cube mpmBar fpmTube"}
MFDYN_BIN=${MFDYN_BIN:-$root/build/bin}
export PATH="$MFDYN_BIN:$PATH"
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
WORK=${WORK:-$(mktemp -d /tmp/healthBench.XXXX)}
mkdir -p "$WORK"
echo "commit $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown), $(date -u +%Y-%m-%d), $OMP_NUM_THREADS thread(s), load $(cut -d' ' -f1-3 /proc/loadavg)"

# setup <case> -> $dir, $solver: the tutorial's case, shortened where a whole run takes long.
setup() {
    case $1 in
    sod) tut=impactSph/sodShockTube solver=impactSph end= ;;
    hvi) tut=impactSph/hviAlAl solver=impactSph end=4e-6 ;;
    cube) tut=tlSph/spinningCube solver=tlSph end= ;;
    mpmBar) tut=mpmFsi/taylorBar solver=mpmFsi end=20e-6 ;;
    fpmTube) tut=fpmSolid/shockTube solver=fpmSolid end=0.3 ;;
    *) echo "unknown case $1" >&2; exit 1 ;;
    esac
    dir=$WORK/$1
    rm -rf "$dir"
    cp -r "$root/tutorials/$tut" "$dir"
    rm -rf "$dir"/[0-9]* "$dir/postProcessing" "$dir"/log.* "$dir/particles.pvd"
    [ -n "$end" ] && mfDictionary "$dir/system/controlDict" -entry endTime -set "$end" > /dev/null
    mfDictionary "$dir/system/controlDict" -entry startFrom -set startTime > /dev/null
    particleGen -case "$dir" > "$dir/log.particleGen" 2>&1
    cp -r "$dir" "$dir.off"
    echo "health off;" >> "$dir.off/system/controlDict"
}
loopSeconds() { sed -n 's/.*time loop \([0-9.e+-]*\) \(s\|ms\).*/\1 \2/p' "$1" | awk '{ print ($2 == "ms") ? $1 / 1000 : $1 }'; }
median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }

printf '%-8s %6s %12s %12s %8s %s\n' case pairs "on [s]" "off [s]" "on/off" "health's own cost"
for c in $cases; do
    setup "$c"
    : > "$WORK/$c.timesOn"; : > "$WORK/$c.timesOff"
    for k in $(seq 1 "$pairs"); do
        for side in "" .off; do
            rm -rf "$dir$side"/[1-9]* "$dir$side"/0.* "$dir$side/postProcessing" "$dir$side/particles.pvd"
            "$solver" -case "$dir$side" > "$dir$side/log" 2>&1 || { echo "$c$side failed: $(grep -A2 '^Error' "$dir$side/log")" >&2; exit 1; }
            if [ -z "$side" ]; then loopSeconds "$dir/log" >> "$WORK/$c.timesOn"; else loopSeconds "$dir$side/log" >> "$WORK/$c.timesOff"; fi
        done
    done
    on=$(median < "$WORK/$c.timesOn"); off=$(median < "$WORK/$c.timesOff")
    own=$(sed -n 's/.*health: .*; cost \([^;]*\) of the run.*/\1/p' "$dir/log")
    printf '%-8s %6s %12s %12s %8s %s\n' "$c" "$pairs" "$on" "$off" "$(awk -v a="$on" -v b="$off" 'BEGIN { printf "%.3f", a / b }')" "$own"
done
