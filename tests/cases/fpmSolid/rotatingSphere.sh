#!/usr/bin/env bash
# The coupled rotating sphere (R11's setup, doc/methods/fpm.md §4.8) on the coarse sphere (spacing
# 1.25, h = 3 spacings = 3.75 as the tutorial's h / spacing: 280 particles), to t = 1.5 with the
# tutorial's settings. Asserted: the in-plane radius (bodyExtents mode radius about x3) has its first
# maximum at 1.1 +- 0.2 (R11's first extremum and bound), and the energy (kinetic + sum m e) falls
# between every two written times (0.01 s): a rise is an instability (it rose on the tutorial's
# sphere as a particle left, from about 4.3 s, before the entropy wave was kept at the surface; it
# falls to 5 s since). L_z is printed: the thesis gives no figure.
# R11 as written on the tutorial's sphere is the validation test rotatingSphereR11.
source "$(dirname "$0")/common.sh"
rotatingSphereStart rotatingSphere
exit 0
