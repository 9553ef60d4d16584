#!/bin/bash
# The tlSph Taylor bar quarter (tutorials/tlSph/taylorBar) to 80 us, before and after the time-step
# rule deformedCourant (issue 16 item 3): steps, CPU time, the final step, and the length and
# footprint it reaches (the tutorial's Allrun measures). Usage:
#   bench/tlSph/taylorBar.sh [spacing=4e-4]
# Environment: BEFORE_BUILD (a build folder with bin/tlSph, bin/particleGen of the code before,
# e.g. a worktree at 87158dc; unset: the before run is skipped), AFTER_BUILD (default <repo>/build),
# WORK (default a fresh /tmp/tlSphTaylorBar.XXXX), THREADS (OMP_NUM_THREADS, default 1), RUNS (default
# "before after": the runs to make, e.g. RUNS=after).
# The before run is the tutorial without its deformedCourant line (the old code refuses the
# keyword; without it both codes take the old step, maxCo h / (c_p x stretch)). Runs are one after
# the other, nice -n 5. About 10 CPU-minutes before, 2 after, at 0.4 mm.
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
spacing=${1:-4e-4}
after=${AFTER_BUILD:-$root/build}
WORK=${WORK:-$(mktemp -d /tmp/tlSphTaylorBar.XXXX)}
mkdir -p "$WORK"
export OMP_NUM_THREADS=${THREADS:-1} OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
commit=$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)
table=$WORK/results.md

# runOne <name> <build> <keep deformedCourant: yes|no>
runOne() {
    local name=$1 build=$2 keep=$3 c=$WORK/$1
    rm -rf "$c"
    cp -r "$root/tutorials/tlSph/taylorBar" "$c"
    (cd "$c" && ./Allclean > /dev/null 2>&1 || true)
    [ "$keep" = yes ] || sed -i '/^deformedCourant/d' "$c/constant/tlSphProperties"
    sed -i "s/^\( *lattice *{ *type cubic; *spacing\) [^;]*;/\1 $spacing;/" "$c/system/particleGenDict"
    echo "running $name ($build) in $c"
    (cd "$c" && MFDYN_DIR=$root MFDYN_BUILD=$build /usr/bin/time -f "%U %S %e %M" -o time.txt \
        nice -n 5 bash ./Allrun > log.Allrun 2>&1) || { echo "$name failed: $(tail -5 "$c/log.Allrun")"; return 1; }
    local steps particles user sys wall maxkb dt length radius
    steps=$(awk '$1 == "steps" { print $2 }' "$c/log.tlSph" | tail -1)
    particles=$(awk '$1 == "particles" { print $2 }' "$c/log.tlSph" | tail -1)
    read -r user sys wall maxkb < "$c/time.txt"
    dt=$(grep '^Step ' "$c/log.tlSph" | tail -1 | sed -E 's/.*dt = ([0-9.e+-]+).*/\1/')
    read -r length radius <<< "$(sed -E 's/.*final length ([0-9.]+) mm.*footprint radius ([0-9.]+) mm.*/\1 \2/' "$c/taylorBar.result")"
    printf '| %s | %s | %s | %s | %s | %.1f | %.1f | %s | %s | %s |\n' "$name" "$build" "$spacing" "$particles" "$steps" \
        "$(echo "$user + $sys" | bc)" "$wall" "$dt" "$length" "$radius" >> "$table"
}

{
    echo "Taylor bar quarter (tlSph) to 80 us, $OMP_NUM_THREADS thread(s), tree at $commit, $(date -u +%F), load at start $(cut -d' ' -f1-3 /proc/loadavg)"
    echo
    echo "| run | build | spacing m | particles | steps | cpu s | wall s | last dt s | length mm | footprint mm |"
    echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|"
} > "$table"
runs=${RUNS:-before after}
case " $runs " in *" before "*) if [ -n "$BEFORE_BUILD" ]; then runOne before "$BEFORE_BUILD" no; else echo "BEFORE_BUILD unset: no before run"; fi ;; esac
case " $runs " in *" after "*) runOne after "$after" yes ;; esac
echo >> "$table"
echo "load at end $(cut -d' ' -f1-3 /proc/loadavg). Reference (Kamoulakos 1990 FE): length 21.5 mm, footprint 7.0 mm;" \
    "SPHinXsys total-Lagrangian bar (issue 16): about 2400 steps to 100 us, 14 s on 2 threads, length 21.8 mm, footprint 6.25 mm at 5 particles per radius." >> "$table"
cat "$table"
