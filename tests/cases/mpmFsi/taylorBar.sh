# tutorials/mpmFsi/taylorBar as shipped (the coarse grid, 0.8 mm cells, 4212 material points; about
# 15 CPU-seconds): the copper bar of the SPH tutorials through the updated-Lagrangian path
# (Mie-Grueneisen + vonMises, impactSph's material dictionary) against the axisymmetric FE
# reference of Kamoulakos 1990, final length 21.5 mm and footprint radius 7.0 mm. Measured at
# a340468: 21.64 mm (+0.7%) and 7.16 mm (+2.2%); asserted within the acceptance of issue 17 (3%
# and 5%), which the validation test (mpmFsiValidation.taylorBar) asserts on the fine grid.
# Energy: the stored energy of this path is sum m e, plastic work included, so kinetic + stored
# must stay within 5% of the impact's kinetic energy (measured -2.4%: the grid transfers' loss);
# a path that lost the plastic work from e would show about -99% (as j2Plasticity's elastic W
# does). Determinism: the state at 20 us on 2 threads is byte-identical to the 1-thread run's;
# a restart from 40 us reaches 80 us with the same bytes as the run through.
# j2Plasticity/ must keep the parent's system/ and mpmProperties (its README claim).
source "$(dirname "$0")/common.sh"
base="$WORK/bar"
copyTutorial taylorBar "$base"
for f in system/controlDict system/particleGenDict constant/mpmProperties; do
    cmp -s "$base/$f" "$base/j2Plasticity/$f" || fail "j2Plasticity/$f differs from the parent case's"
done
(cd "$base" && MFDYN_DIR="$SOURCE" MFDYN_BUILD="$BUILD" OMP_NUM_THREADS=1 ./Allrun > log.Allrun 2>&1) ||
    fail "Allrun: $(tail -n 20 "$base/log.Allrun")"
result="$(cat "$base/taylorBar.result")"
echo "$result"
length=$(sed -E 's/.*final length ([0-9.]+) mm.*/\1/' <<< "$result")
footprint=$(sed -E 's/.*footprint radius ([0-9.]+) mm.*/\1/' <<< "$result")
within "$length" 21.5 0.03 || fail "final length $length mm is not within 3% of 21.5 mm"
within "$footprint" 7.0 0.05 || fail "footprint radius $footprint mm is not within 5% of 7.0 mm"
drift=$(awk '/conserved: totalEnergy drift/ { print $4 }' "$base/log.mpmFsi")
[ -n "$drift" ] || fail "no totalEnergy drift line in log.mpmFsi"
less "${drift#-}" 0.05 || fail "total energy drift $drift: the stored energy sum m e misses work"
echo "total energy drift $drift relative"
# 2 threads to 20 us from the same particles.
short="$WORK/short"
mkdir -p "$short"
cp -r "$base/system" "$base/constant" "$base/0" "$short/"
sed -i 's/^endTime .*/endTime         20e-6;/' "$short/system/controlDict"
OMP_NUM_THREADS=2 run "$short" mpmFsi
grep -q "threads: 2" "$short/log.mpmFsi" || fail "the second run did not use 2 threads"
cmp "$base/2e-05/particles.vtp" "$short/2e-05/particles.vtp" || fail "1 and 2 threads differ at 20 us"
echo "particles.vtp at t = 2e-05 byte-identical on 1 and 2 threads"
# A restart from 40 us continues bit for bit: the updated-Lagrangian state (e, tau, the plastic
# strain, F and J) is in the particle fields, and p and sigma are recomputed from them at the start.
again="$WORK/restart"
cp -r "$base" "$again"
rm -rf "$again/6e-05" "$again/8e-05" "$again/log.mpmFsi"
sed -i 's/^startFrom .*/startFrom       latestTime;/' "$again/system/controlDict"
run "$again" mpmFsi
grep -q "Restarting from time 4e-05" "$again/log.mpmFsi" || fail "the run did not restart from 4e-05"
cmp "$base/8e-05/particles.vtp" "$again/8e-05/particles.vtp" || fail "the restart from 40 us differs at 80 us"
echo "restart from 4e-05 byte-identical at 8e-05"
echo "PASS: taylorBar"
