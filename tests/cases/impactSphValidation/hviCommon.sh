# Shared by hviAlAl.sh and hviAlPb.sh: $1 = build directory, $2 = this source directory.
# runHvi <tutorial> <spacing [m]>: a copy of tutorials/impactSph/<tutorial> with both regions'
# hexagonal lattice set to <spacing> (the rest of the case does not depend on it: h follows the
# particles' number density, Δt the Courant limit, and there are no walls or ghost layers), run by
# its own Allrun; sets L, W, ratio, hole (mm and L/W at 20 µs, from debrisCloud.csv), drift
# (relative total-energy drift), particles, steps and wall (from log.impactSph), and report.
. "$(dirname "$0")/../impactSph/common.sh"
# Two threads unless told otherwise (MFDYN_VALIDATION_THREADS overrides; the results do not depend
# on the thread count).
export OMP_NUM_THREADS="${MFDYN_VALIDATION_THREADS:-2}"
# MFDYN_KEEP_WORK=yes keeps the run's directory (common.sh removes it on exit).
if [ -n "${MFDYN_KEEP_WORK:-}" ]; then trap - EXIT; echo "work directory $WORK"; fi
runHvi() {
    local name="$1" spacing="$2"
    local dest="$WORK/tutorials/impactSph/$name"
    mkdir -p "$dest"
    [ -e "$WORK/bin" ] || ln -s "$SOURCE/../../../bin" "$WORK/bin"
    cp -r "$TUTORIALS/$name/Allrun" "$TUTORIALS/$name/Allclean" "$TUTORIALS/$name/system" "$TUTORIALS/$name/constant" "$dest/"
    setEntry "$dest/system/particleGenDict" regions/projectile/lattice/spacing "$spacing"
    setEntry "$dest/system/particleGenDict" regions/plate/lattice/spacing "$spacing"
    MFDYN_BUILD="$BUILD" "$dest/Allrun" > "$dest/log.Allrun" 2>&1 || fail "$name/Allrun failed: $(tail -n 20 "$dest/log.Allrun")"
    local csv="$dest/postProcessing/debris/0/debrisCloud.csv" log="$dest/log.impactSph" t
    [ -f "$csv" ] || fail "$name wrote no debrisCloud.csv"
    t=$(column "$csv" time)
    less 1.999e-5 "$t" || fail "$name: last debrisCloud row at t = $t, expected 2e-5"
    L=$(awk -v v="$(column "$csv" length)" 'BEGIN { printf "%.2f", v * 1e3 }')
    W=$(awk -v v="$(column "$csv" width)" 'BEGIN { printf "%.2f", v * 1e3 }')
    ratio=$(awk -v v="$(column "$csv" lengthOverWidth)" 'BEGIN { printf "%.3f", v }')
    hole=$(awk -v v="$(column "$csv" holeDiameter)" 'BEGIN { printf "%.2f", v * 1e3 }')
    drift=$(awk '/conserved: totalEnergy drift/ { print $4 }' "$log")
    particles=$(awk '/^ *particles +[0-9]/ { print $2; exit }' "$log")
    steps=$(awk '/^ *steps +[0-9]/ { print $2; exit }' "$log")
    wall=$(awk '/^ *wall time/ { sub(/^ *wall time +/, ""); sub(/ \(.*/, ""); print; exit }' "$log")
    report="spacing $spacing m: L $L mm, W $W mm, L/W $ratio, hole $hole mm, energy drift $drift, $particles particles, $steps steps, wall time $wall ($OMP_NUM_THREADS thread(s))"
    echo "$name: $report"
}
