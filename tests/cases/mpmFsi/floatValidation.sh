# Under the validation label, not the default run: it FAILS as the acceptance is written (the
# multiField block sinks: README), and a red default run would block every landing; what it
# measures is unchanged (it was tests/cases/mpmFsi/float.sh in fb3983b).
# The float (tutorials/mpmFsi/float, doc/methods/mpm.md 4.7 / V7; issue 18's acceptance): the
# thesis's elastic triangle (side 0.2, apex up, rho 917, 200 points) dropped from rest onto water
# (rho0 997, kappa 2e3, mu 0.98, 6400 points, 0.2 deep) in the 0.4 x 0.4 box of 15 x 15 cells, run
# as the tutorial does, to T = 10, with one grid velocity field (singleField) and with one per
# body (multiField, frictionless, the surface-gap check with the larger gradient's normal, as the
# tutorial's Allrun sets it). The draft is the
# water's surface at the two side walls less the block's base (Allrun's definition), its mean and
# half its range over t = 5..10. Asserted:
#   multiField  the mean draft within 5% of Archimedes' 0.124 (issue 18, the acceptance as stated:
#               h rho_s / rho_f of the area submerged, incompressible water; the compressed water
#               of kappa 2e3 gives 0.1141, 8% less: README);
#               the contact force on the water from the block, its time mean over t = 5..10,
#               within 5% of the block's weight 155.81 N/m downwards (at rest the contact carries
#               all of it when the block floats; one within reach of the floor is partly held by
#               the floor's grid condition);
#   singleField bounded (doc/methods/mpm.md V7; Archimedes is not asserted for it): the block
#               afloat at every write after t = 1 (its apex above the surface, its base more than a
#               cell, 0.0267, above the floor), and the draft's half range over t = 5..10 below
#               0.01 (0.4 cells);
#   both        mass exact: no particle removed, each body's mass equal to its first write's.
# Measured at the tutorial's settings (the surfaceGap commit): singleField 0.07289, half range
# 0.00038, afloat throughout: its checks pass; multiField 0.10693 (-13.9%: afloat and settled, but
# shallow; -6.3% of this compressible water's 0.1141) with a contact force of -155.77 (the weight
# to 0.03%): THIS TEST FAILS on the draft (the README's study: 30 x 30 gives -2.8% of 0.124 but
# +5.7% of 0.1141, and +8.4% with kappa 2e4; not converged). With the earlier position check at
# 0.667 cells it was 0.18405 (+48%, the block sank) and -144.9 (-7%). About 110 CPU-s.
source "$(dirname "$0")/common.sh"
s="$WORK/single"
m="$WORK/multi"
copyTutorial float "$s"
rm -rf "$s/multiField" "$s"/draft.* "$s"/cpu.txt
run "$s" particleGen
cp -r "$s" "$m"
sed -i 's/^contact .*/contact         multiField;/' "$m/constant/mpmProperties"
printf 'multiFieldCoeffs { friction 0; surfaceGap yes; normal largerGradient; }\n' >> "$m/constant/mpmProperties"
run "$s" mpmFsi
run "$m" mpmFsi
grep -q "contact multiField (friction 0, normal largerGradient, surfaceGap) over 2 bodies" "$m/log.mpmFsi" ||
    fail "the multiField run did not log its contact law"
# draft <case>: "mean halfRange afloatFailures" over t >= 5 (afloat checked from t = 1).
draft() {
    awk -F, 'FNR == 1 { f++; for (i = 1; i <= NF; ++i) c[f, $i] = i; next }
        f == 1 { t[FNR] = $1; low[FNR] = $c[1, "block_lowest"]; top[FNR] = $c[1, "block_highest"]; n = FNR }
        f == 2 { l[FNR] = $c[2, "height"] }
        f == 3 { r[FNR] = $c[3, "height"] }
        END {
            for (i = 2; i <= n; ++i) {
                s = (l[i] + r[i]) / 2 + 0.00132; b = low[i] - 0.00366; d = s - b
                if (t[i] >= 1 && (top[i] <= s || b <= 0.0267)) bad++
                if (t[i] >= 5) { sum += d; k++; if (k == 1 || d < lo) lo = d; if (k == 1 || d > hi) hi = d }
            }
            printf "%.6f %.6f %d\n", sum / k, (hi - lo) / 2, bad
        }' "$1/postProcessing/bodies/0/bodyCentroid.csv" "$1/postProcessing/surfaceLeft/0/frontPosition.csv" \
           "$1/postProcessing/surfaceRight/0/frontPosition.csv"
}
for c in "$s" "$m"; do
    t=$(tail -n 1 "$c/postProcessing/bodies/0/bodyCentroid.csv" | cut -d, -f1)
    [ "$t" = 10 ] || fail "$c: the last write is at t = $t, not 10"
    ! grep -q "outsideGrid remove" "$c/log.mpmFsi" || fail "particles left the grid: $(grep -m1 'outsideGrid remove' "$c/log.mpmFsi")"
    for body in block water; do
        grep -q "body $body: at t = 10 mass \([0-9.e+-]*\) (first write \1, change 0.000e+00)" "$c/log.mpmFsi" ||
            fail "$body mass not exact: $(grep "body $body: at" "$c/log.mpmFsi")"
    done
done
read -r sMean sHalf sBad <<< "$(draft "$s")"
read -r mMean mHalf mBad <<< "$(draft "$m")"
force=$(awk -F, 'NR > 1 && $1 >= 5 { s += $3; n++ } END { printf "%.4f", s / n }' "$m/postProcessing/contact/0/contactForces.csv")
echo "singleField: draft mean $sMean, half range $sHalf over t = 5..10, $sBad writes not afloat"
echo "multiField:  draft mean $mMean (Archimedes 0.124), half range $mHalf; contact force on the water $force N/m (weight 155.81)"
# Every check is reported before the verdict (a failing run says which of them failed).
bad=""
[ "$sBad" = 0 ] || bad="$bad; singleField: the block is not afloat at $sBad writes after t = 1"
less "$sHalf" 0.01 || bad="$bad; singleField: the draft's half range $sHalf over t = 5..10 is not below 0.01"
within "$mMean" 0.12414 0.05 || bad="$bad; multiField: the mean draft $mMean is not within 5% of Archimedes' 0.124"
within "$force" -155.81 0.05 || bad="$bad; multiField: the mean contact force $force is not within 5% of the weight -155.81"
[ -z "$bad" ] || fail "${bad#; }"
echo "PASS: float (singleField $sMean, multiField $mMean)"
