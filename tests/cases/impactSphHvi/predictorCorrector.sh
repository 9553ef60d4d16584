# The predictor-corrector integrator on Sod's tube meets the same bounds as the leapfrog, and
# allocates none of the leapfrog's half-step fields.
. "$(dirname "$0")/common.sh"
c=$(sodCase sodPC)
mfDictionary "$c/constant/sphProperties" -entry integrator -set predictorCorrector > /dev/null
checkSod "$c" "predictorCorrector Sod"
grep -q "velocityHalfStep" "$c/log" && fail "the predictor-corrector allocated leapfrog half-step fields"
exit 0
