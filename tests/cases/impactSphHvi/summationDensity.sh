# Summation density with h solved per particle by Newton (number scheme) meets the Sod bounds.
. "$(dirname "$0")/common.sh"
c=$(sodCase sodSum)
mfDictionary "$c/constant/sphProperties" -entry densityScheme/form -set summation > /dev/null
mfDictionary "$c/constant/sphProperties" -entry smoothingLength -set "{ type summation; eta 1.2; }" > /dev/null
checkSod "$c" "summation density and smoothing length (Newton) on Sod"
