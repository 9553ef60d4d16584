# The particle-to-grid sums are deterministic for any thread count (libraries/mpm/ParticleColouring.hpp:
# cell colouring, no atomics): two fine disks (3016 particles each, stiff enough to collide
# within the run) give byte-identical particles.vtp on 1 and 2 threads, with linear hats and
# with quadratic B-splines (whose colours are 4 x 4 cells wide). 6032 particles keep every
# particle and node loop above the parallel threshold (4096 items), so 2 threads do split them.
source "$(dirname "$0")/common.sh"
for shape in linear quadraticBSpline; do
    base="$WORK/$shape"
    copyTutorial twoDisks "$base"
    sed -i 's/cells (10 10)/cells (31 31)/g; s/centre (0.2 0.2)/centre (0.3 0.3)/; s/centre (0.8 0.8)/centre (0.7 0.7)/' "$base/system/particleGenDict"
    sed -i 's/youngsModulus   1000;/youngsModulus   1e4;/' "$base/constant/materialProperties"
    sed -i "s/^shapeFunction .*/shapeFunction   $shape;/" "$base/constant/mpmProperties"
    sed -i 's/^endTime .*/endTime         0.45;/; s/^writeInterval .*/writeInterval   0.45;/' "$base/system/controlDict"
    grep -q "centre (0.7 0.7)" "$base/system/particleGenDict" || fail "could not move the disks"
    run "$base" particleGen
    cp -r "$base" "$base-2"
    OMP_NUM_THREADS=1 run "$base" mpmFsi
    OMP_NUM_THREADS=2 run "$base-2" mpmFsi
    grep -q "threads: 2" "$base-2/log.mpmFsi" || fail "the second run did not use 2 threads"
    cmp "$base/0.45/particles.vtp" "$base-2/0.45/particles.vtp" || fail "$shape: 1 and 2 threads differ"
    echo "$shape: particles.vtp at t = 0.45 byte-identical on 1 and 2 threads"
done
echo "PASS: determinism"
