#!/bin/sh
# Old against new neighbour-list build, side by side: bench/neighbours/compare.sh <old-rev> [particles] [rounds]
# Compiles BuildTiming.cpp with the particles sources of <old-rev> (git archive) and of the work
# tree, both linked to build/lib's libmfdyn_core, and runs them alternately `rounds` times, one
# thread each (OMP_NUM_THREADS=1): medians are read off the lines printed (bench/neighbours/README.md).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
old=${1:?usage: compare.sh <old-rev> [particles] [rounds]}
particles=${2:-1000000}
rounds=${3:-3}
lib=${MFDYN_CORE_LIB:-$root/build/lib}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/old"
git -C "$root" archive "$old" libraries | tar -x -C "$work/old"
compile() {  # compile <tree> <out> [flags]
    p=$1/libraries/particles
    ${CXX:-g++} -O3 -DNDEBUG -fopenmp -std=c++20 $3 -I"$1/libraries" -isystem /usr/include/eigen3 -o "$2" \
        "$root/bench/neighbours/BuildTiming.cpp" "$p/NeighbourSearch.cpp" "$p/CellBins.cpp" \
        "$p/NeighbourDomain.cpp" "$p/NeighbourList.cpp" -L"$lib" -lmfdyn_core -Wl,-rpath,"$lib"
}
compile "$work/old" "$work/buildTimingOld" &
compile "$root" "$work/buildTimingNew" -DMFDYN_BENCH_REUSE
wait
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE
for r in $(seq "$rounds"); do
    echo "round $r: old ($old)"; "$work/buildTimingOld" "$particles" 3
    echo "round $r: new (work tree)"; "$work/buildTimingNew" "$particles" 3
done
