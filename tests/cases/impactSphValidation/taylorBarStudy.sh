# Taylor bar (Kamoulakos 1990) as a refinement study: the quarter model of
# tutorials/impactSph/taylorBar/quarter3D (cubic lattice, mirror planes x = 0, y = 0 and the wall)
# at 0.4, 0.32 and 0.2667 mm (R0/8, R0/10, R0/12: its system/studyDict), each run to 80 µs. For the
# final length and the footprint radius it prints the three values, the observed order p of
# f(s) = f0 + C s^p through them and the Richardson extrapolation f0.
#   Length: within 3% of the FE 21.5 mm at every lattice and, where a positive order exists, its
#   extrapolation too.
#   Footprint: the extrapolation within 5% of 7.0 mm, or else the cause measured in the README
#   ("Why the footprint does not converge") must be what this run shows: the foot torn by hoop
#   cracks, a gap round the rim of the wall layer wider than the kernel's support (2h = 2.6 s)
#   at every lattice (rimGaps.py; a continuous rim has gaps of one spacing). A footprint that
#   neither converges onto 7.0 mm nor shows the cracks fails: then the README's explanation is
#   wrong. Measured (README, 87158dc, the published mass flux): lengths 21.93, 21.72, 21.61 mm
#   (order 2.36, extrapolated 21.41 mm); footprints 7.84, 8.34, 8.61 mm (order 1.97, extrapolated
#   9.23 mm, +32%); rim gaps 6.9, 7.1, 5.7 s: passed on the second branch.
#   With the contact-only mass flux (the default since c69e471; README, "Four lattices with the
#   contact-only mass flux", d9726a6) it FAILS, as designed: footprints 7.67, 7.64, 7.99 mm (no
#   order), rim gaps 6.3, 2.4, 3.2 s, so the 0.32 mm rim is not torn by this criterion, although
#   268 of its 732 particles stretched 0.8-1.2 round the hoop lie below the hoop bound. Beside the
#   extent it reports (footprintMeasures.py, not asserted) the wall layer's radial r_max and r_90,
#   their orders, the lattice rod's cross-section against the circle's and the hoop-bound count.
# About 9 CPU-minutes on one thread (4212, 7979 and 13552 particles: 67, 159 and 294 s).
. "$(dirname "$0")/../impactSph/common.sh"
export OMP_NUM_THREADS="${MFDYN_VALIDATION_THREADS:-1}"
here="$(cd "$(dirname "$0")" && pwd)"
# MFDYN_TAYLOR_STUDY_SPACINGS="6.4e-4 5.3333333e-4 4.5714286e-4" checks the script itself in a minute.
read -r -a spacings <<< "${MFDYN_TAYLOR_STUDY_SPACINGS:-4e-4 3.2e-4 2.6666667e-4}"
[ "${#spacings[@]}" -eq 3 ] || fail "three spacings expected, got ${spacings[*]}"
lengths=(); radii=(); gaps=(); rMaxes=(); r90s=(); report=""
for s in "${spacings[@]}"; do
    c=$(newCase "$TUTORIALS/taylorBar/quarter3D" "q$s")
    setEntry "$c/system/particleGenDict" regions/bar/lattice/spacing "$s"
    setEntry "$c/system/controlDict" writeInterval 8e-5
    wall=$(runCase "$c")
    csv="$c/postProcessing/outline/0/fieldMinMax.csv"
    t=$(column "$csv" time)
    less 7.99e-5 "$t" || fail "s = $s: last outline row at t = $t, expected 8e-5"
    L=$(awk -v z="$(column "$csv" position_z_max)" 'BEGIN { printf "%.4f", z * 1e3 }')
    # The quarter's x_min, y_min are >= 0: its widest extent is x_max or y_max, plus half a spacing.
    R=$(awk -v a="$(column "$csv" position_x_max)" -v b="$(column "$csv" position_y_max)" -v s="$s" \
        'BEGIN { m = a > b ? a : b; printf "%.4f", (m + s / 2) * 1e3 }')
    [ -f "$c/8e-05/particles.vtp" ] || fail "s = $s: no 8e-05/particles.vtp"
    rim=$(python3 "$here/rimGaps.py" "$c/8e-05/particles.vtp" "$s" quarter) || fail "rimGaps.py failed on s = $s: $rim"
    read -r ringCount gap ringRadius <<< "$rim"
    [ -n "$gap" ] || fail "rimGaps.py printed nothing for s = $s"
    # Beside the extent, reported only (README, "Four lattices with the contact-only mass flux"): the
    # lattice rod's cross-section against the circle's, the radial footprint of the wall layer, the
    # radius holding 90% of it, and the particles of the foot below the hoop bound.
    measures=$(python3 "$here/footprintMeasures.py" "$c/0/particles.vtp" "$c/8e-05/particles.vtp" "$s" 3.2e-3) \
        || fail "footprintMeasures.py failed on s = $s: $measures"
    read -r areaRatio rMax r90 layerCount hoopBelow hoopStretched <<< "$measures"
    [ -n "$hoopStretched" ] || fail "footprintMeasures.py printed too little for s = $s: $measures"
    rMax=$(awk -v r="$rMax" 'BEGIN { printf "%.4f", r * 1e3 }'); r90=$(awk -v r="$r90" 'BEGIN { printf "%.4f", r * 1e3 }')
    rMaxes+=("$rMax"); r90s+=("$r90")
    drift=$(awk '/conserved: totalEnergy drift/ { print $4 }' "$c/log.impactSph" | tail -n 1)
    awk -v e="$drift" 'BEGIN { if (e < 0) e = -e; exit !(e < 1e-4) }' || fail "s = $s: total energy drift $drift (the mirror wall does no work)"
    lengths+=("$L"); radii+=("$R"); gaps+=("$gap")
    report+="  s = $s m: length $L mm, footprint $R mm (radial r_max $rMax mm, r_90 $r90 mm of $layerCount wall-layer particles; lattice cross-section $areaRatio of the circle's), $hoopBelow of $hoopStretched particles with hoop strains 0.8-1.2 below the hoop bound, largest rim gap $gap s ($ringCount wall-layer particles at r >= 0.75 R), energy drift $drift, wall time $wall"$'\n'
done
# observedOrder h1 h2 h3 f1 f2 f3: "p f0" of f = f0 + C h^p through the three points (h1 > h2 > h3),
# p by bisection on (f1 - f2)/(f2 - f3) = (h1^p - h2^p)/(h2^p - h3^p) over 0.05 < p < 8; "none" when
# the differences change sign or their ratio needs a p outside that range (no convergence shown).
observedOrder() {
    awk -v h1="$1" -v h2="$2" -v h3="$3" -v f1="$4" -v f2="$5" -v f3="$6" '
        function g(p) { return (h1 ^ p - h2 ^ p) / (h2 ^ p - h3 ^ p) }
        BEGIN {
            d1 = f1 - f2; d2 = f2 - f3
            if (d1 * d2 <= 0) { print "none"; exit }
            q = d1 / d2; lo = 0.05; hi = 8
            # g falls from about ln(h1/h2)/ln(h2/h3) at p -> 0 and grows with p for these ratios.
            if ((g(lo) - q) * (g(hi) - q) > 0) { print "none"; exit }
            for (k = 0; k < 100; ++k) { m = 0.5 * (lo + hi); if ((g(lo) - q) * (g(m) - q) <= 0) hi = m; else lo = m }
            p = 0.5 * (lo + hi)
            printf "%.3f %.4f\n", p, f3 - d2 * h3 ^ p / (h2 ^ p - h3 ^ p)
        }'
}
read -r pL L0 <<< "$(observedOrder "${spacings[@]}" "${lengths[@]}")"
read -r pR R0 <<< "$(observedOrder "${spacings[@]}" "${radii[@]}")"
read -r pM M0 <<< "$(observedOrder "${spacings[@]}" "${rMaxes[@]}")"
read -r p9 R90 <<< "$(observedOrder "${spacings[@]}" "${r90s[@]}")"
summary="length: order ${pL}${L0:+, extrapolated $L0 mm}; footprint: order ${pR}${R0:+, extrapolated $R0 mm} (radial r_max: order ${pM}${M0:+, extrapolated $M0 mm}; r_90: order ${p9}${R90:+, extrapolated $R90 mm})"$'\n'"$report"
for L in "${lengths[@]}"; do less "$(relErr "$L" 21.5)" 0.03 || fail "length $L mm not within 3% of 21.5 mm: $summary"; done
[ "$pL" = none ] || less "$(relErr "$L0" 21.5)" 0.03 || fail "extrapolated length $L0 mm not within 3% of 21.5: $summary"
if [ "$pR" != none ] && less "$(relErr "$R0" 7.0)" 0.05; then
    pass "Taylor bar quarter: the footprint converges onto 7.0 mm within 5%: $summary"
    exit 0
fi
# Not converging onto 7.0 mm: the README's measured cause must hold at every lattice.
for g in "${gaps[@]}"; do
    less 2.6 "$g" || fail "the footprint does not converge onto 7.0 mm, and the rim is not cracked (largest gap $g s, support 2.6 s): the README's explanation does not hold: $summary"
done
pass "Taylor bar quarter: the footprint does not converge onto 7.0 mm (README: the foot tears into petals, hoop cracks wider than the kernel's support at every lattice): $summary"
