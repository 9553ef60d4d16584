# An application started without OMP_WAIT_POLICY or GOMP_SPINCOUNT runs its OpenMP threads with the
# passive wait policy (doc/architecture.md, "Threads"): libgomp reports its settings at start-up
# under OMP_DISPLAY_ENV=verbose, and the image that does the work (the last report) must say
# GOMP_SPINCOUNT = '0' (libgomp's default, 300000 spins, is what made runs beside other work
# 100-200 times slower). A policy the user chose is kept, with no second start.
. "$(dirname "$0")/common.sh"
report() { env -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT -u MFDYN_WAIT_POLICY_SET OMP_DISPLAY_ENV=verbose "$@" 2>&1; }
for app in particleFlight impactSph tlSph particleGen mfDictionary; do
    out=$(report "$app" -version) || fail "$app -version failed: $out"
    last=$(grep "GOMP_SPINCOUNT" <<< "$out" | tail -n 1)
    [[ "$last" == *"GOMP_SPINCOUNT = '0'"* ]] ||
        fail "$app without OMP_WAIT_POLICY: the OpenMP runtime that runs it reports $last (expected '0': passive)"
    grep -q "(mfdyn " <<< "$out" || fail "$app -version did not print its version after the restart: $out"
done
out=$(report env OMP_WAIT_POLICY=active particleFlight -version)
[ "$(grep -c "GOMP_SPINCOUNT" <<< "$out")" -eq 1 ] || fail "a policy set by the user started the program twice: $out"
grep -q "GOMP_SPINCOUNT = '30000000000'" <<< "$out" || fail "OMP_WAIT_POLICY=active was not kept: $out"
# A run: passive too, and it runs to its end.
c=$(newCase run)
report particleFlight -case "$c" > "$c/log" || fail "particleFlight failed: $(tail "$c/log")"
[ "$(grep "GOMP_SPINCOUNT" "$c/log" | tail -n 1 | tr -d ' ')" = "GOMP_SPINCOUNT='0'" ] || fail "the run was not passive"
grep -q "^End$" "$c/log" || fail "the run did not end: $(tail "$c/log")"
pass "applications started without OMP_WAIT_POLICY run passive; a user's policy is kept"
