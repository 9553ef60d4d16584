# Hiermaier 1997's Al-Pb test (Zisis 2017 §6.2, doc/methods/sph-impact.md §8.8): tutorials/impactSph/hviAlPb
# (1.5 mm lead plate, see its README) refined from the tutorial's 0.25 mm to the thesis's 0.05 mm
# hexagonal lattice (92291 particles) against the experiment: debris L/W at 20 µs within ±10% of
# 1.56, hole diameter within ±15% of 26 mm. About 1.8 hours on one thread, one on two.
# MFDYN_HVI_SPACING sets another lattice spacing [m] (1e-4: 22661 particles, 15 minutes on one).
. "$(dirname "$0")/hviCommon.sh"
runHvi hviAlPb "${MFDYN_HVI_SPACING:-5e-5}"
eR=$(relErr "$ratio" 1.56)
eH=$(relErr "$hole" 26)
less "$eR" 0.10 || fail "Al-Pb L/W $ratio vs experiment 1.56 (error $eR > 10%); $report"
less "$eH" 0.15 || fail "Al-Pb hole $hole mm vs experiment 26 mm (error $eH > 15%); $report"
pass "Al-Pb L/W $ratio (experiment 1.56, error $eR), hole $hole mm (experiment 26, error $eH); $report"
