#!/usr/bin/env bash
# OpenMP beside other work (issue 15, item 10): Sod's shock tube (tutorials/impactSph/sodShockTube,
# 900 particles, 4000 steps) timed alone and beside one busy process ('yes > /dev/null'), with no
# OpenMP variable in the environment, on all cores (OMP_NUM_THREADS unset, as a user runs it).
# Acceptance: at most 2.5 times slower beside the busy process than alone. Before the fix, libgomp's
# default wait policy made the threads spin at every barrier while the core they wait for runs the
# other process.
#
#     bench/oversubscription/run.sh [repeats [endTime]]   (default 3 repeats to t = 0.2, the tutorial's;
#                                                     MFDYN_BIN selects another build's bin/)
#
# A shorter endTime (0.02: 400 steps) keeps a build without the fix from running for many minutes.
#
# Prints each run's wall time of the impactSph process, the medians and their ratio. Not a test: the
# figures depend on the machine and on what else runs on it (run it on an otherwise idle machine).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
BIN="${MFDYN_BIN:-$ROOT/build/bin}"
REPEATS="${1:-3}"
END="${2:-0.2}"
[ -x "$BIN/impactSph" ] || { echo "no $BIN/impactSph: build first (or set MFDYN_BIN)" >&2; exit 1; }
unset OMP_WAIT_POLICY GOMP_SPINCOUNT OMP_NUM_THREADS OMP_PROC_BIND OMP_PLACES MFDYN_WAIT_POLICY_SET
WORK="$(mktemp -d "${TMPDIR:-/tmp}/mfdyn-oversub.XXXXXX")"
busy=
cleanup() { [ -z "$busy" ] || kill "$busy" 2> /dev/null || true; rm -rf "$WORK"; }
trap cleanup EXIT
mkdir -p "$WORK/sod"
cp -r "$ROOT/tutorials/impactSph/sodShockTube/system" "$ROOT/tutorials/impactSph/sodShockTube/constant" "$WORK/sod/"
"$BIN/mfDictionary" "$WORK/sod/system/controlDict" -entry endTime -set "$END" > /dev/null
"$BIN/particleGen" -case "$WORK/sod" > "$WORK/log.particleGen"

# One run: wall seconds of impactSph on a fresh copy of the generated case.
runOnce() {
    rm -rf "$WORK/run" && cp -r "$WORK/sod" "$WORK/run"
    local t0 t1
    t0=$(date +%s.%N)
    "$BIN/impactSph" -case "$WORK/run" > "$WORK/log.impactSph" 2>&1 || { tail "$WORK/log.impactSph" >&2; exit 1; }
    t1=$(date +%s.%N)
    awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }'
}
median() { tr ' ' '\n' | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

threads=$(awk '/threads\)/ { gsub(/[()]/, ""); print $(NF - 1); exit }' < <(runOnce > /dev/null; cat "$WORK/log.impactSph"))
alone=() beside=()
for r in $(seq 1 "$REPEATS"); do
    # Alone and beside in turn, so that a drift of the machine's speed affects both.
    alone+=("$(runOnce)")
    yes > /dev/null &
    busy=$!
    beside+=("$(runOnce)")
    kill "$busy" && wait "$busy" 2> /dev/null || true
    busy=
    echo "repeat $r: alone ${alone[-1]} s, beside a busy process ${beside[-1]} s"
done
a=$(echo "${alone[*]}" | median)
b=$(echo "${beside[*]}" | median)
echo "impactSph sodShockTube to t = $END, $(nproc) cores, $threads threads, no OMP_* variable set ($BIN):"
echo "  median alone $a s, beside a busy process $b s, ratio $(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.2f", b / a }') (acceptance: at most 2.5)"
