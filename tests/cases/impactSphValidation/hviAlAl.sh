# Hiermaier 1997's Al-Al test (Zisis 2017 §6.2, doc/methods/sph-impact.md §8.8): tutorials/impactSph/hviAlAl
# refined from the tutorial's 0.25 mm to the thesis's 0.05 mm hexagonal lattice (183491 particles)
# against the experiment: debris L/W at 20 µs within ±10% of 1.39, hole diameter within the
# experiment's 27.5-34.5 mm widened by 15% at each end. About 1.6 hours on two unloaded threads.
# MFDYN_HVI_SPACING sets another lattice spacing [m] (1e-4: 45861 particles, 24 minutes on one).
. "$(dirname "$0")/hviCommon.sh"
runHvi hviAlAl "${MFDYN_HVI_SPACING:-5e-5}"
eR=$(relErr "$ratio" 1.39)
less "$eR" 0.10 || fail "Al-Al L/W $ratio vs experiment 1.39 (error $eR > 10%); $report"
less "$(awk 'BEGIN { print 27.5 * 0.85 }')" "$hole" && less "$hole" "$(awk 'BEGIN { print 34.5 * 1.15 }')" \
    || fail "Al-Al hole $hole mm outside [23.375, 39.675] mm (experiment 27.5-34.5 mm ±15%); $report"
pass "Al-Al L/W $ratio (experiment 1.39, error $eR), hole $hole mm (experiment 27.5-34.5); $report"
