#!/bin/sh
# Builds and runs the neighbour-list benchmark: bench/neighbours/run.sh [particles] [neighbours] [repeats] [maxThreads]
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${MFDYN_BENCH_BUILD:-$root/build-bench}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMFDYN_BENCH=ON -DMFDYN_TESTS=OFF >/dev/null
ninja -C "$build" -j"${JOBS:-2}" neighbourBench
exec "$build/bin/neighbourBench" "$@"
