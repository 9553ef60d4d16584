# A restart continues the run bit for bit: the two disks written at t = 1.5 (in contact: F, the
# stress and APIC's affine velocity are all in play) and restarted from there reach t = 1.7 with
# the same particles.vtp as the run that went through (the state is the particle fields alone:
# the grid is rebuilt each step and the stress recomputed from F at the start).
source "$(dirname "$0")/common.sh"
for update in FLIP APIC; do
    c="$WORK/$update"
    copyTutorial twoDisks "$c"
    sed -i 's/^endTime .*/endTime         1.7;/; s/^writeInterval .*/writeInterval   0.5;/' "$c/system/controlDict"
    sed -i "s/^velocityUpdate .*/velocityUpdate  $update;/" "$c/constant/mpmProperties"
    grep -q "^velocityUpdate  $update;" "$c/constant/mpmProperties" || fail "could not set velocityUpdate $update"
    run "$c" particleGen
    run "$c" mpmFsi
    cp "$c/1.7/particles.vtp" "$WORK/through.vtp"
    # restart from the last write before the end (t = 1.5)
    rm -rf "$c/1.7"
    sed -i 's/^startFrom .*/startFrom       latestTime;/' "$c/system/controlDict"
    run "$c" mpmFsi
    grep -q "Restarting from time 1.5" "$c/log.mpmFsi" || fail "$update: the run did not restart from 1.5: $(grep -i start "$c/log.mpmFsi")"
    cmp "$c/1.7/particles.vtp" "$WORK/through.vtp" || fail "$update: the restarted run differs from the run through"
    echo "$update: restart from 1.5 byte-identical at 1.7"
done
echo "PASS: restart"
