# Twist angle of the top face about the Y axis from the probes of system/controlDict (the `top`
# function object: eight material points of the face Y = 6, p0 ... p7, followed through
# position). For a probe with reference position (X0, Z0) and current (x, z) the rotation about
# +Y is atan2(Z0 x - X0 z, X0 x + Z0 z); each probe's angle is unwrapped across +-pi from row to
# row (the probes are written every step) and the eight are averaged. Also the centroid of the
# eight points in x, z: zero for a perfect axial rotation.
#     awk -F, -f twistAngle.awk postProcessing/top/0/probes.csv > twist.csv
BEGIN {
    pi = atan2(0, -1)
    split("0.5 -0.5 -0.5 0.5 0.5 0 -0.5 0", X0, " ")
    split("0.5 0.5 -0.5 -0.5 0 0.5 0 -0.5", Z0, " ")
    print "time,twist,twistDegrees,centroidX,centroidZ"
}
NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
{
    sum = 0; cx = 0; cz = 0
    for (k = 0; k < 8; ++k) {
        x = $col["p" k "_position_x"]; z = $col["p" k "_position_z"]
        a = atan2(Z0[k + 1] * x - X0[k + 1] * z, X0[k + 1] * x + Z0[k + 1] * z)
        if (NR == 2) angle[k] = a
        else {
            d = a - previous[k]
            while (d > pi) d -= 2 * pi
            while (d < -pi) d += 2 * pi
            angle[k] += d
        }
        previous[k] = a
        sum += angle[k]; cx += x; cz += z
    }
    printf "%.10g,%.8g,%.6g,%.6g,%.6g\n", $1, sum / 8, sum / 8 * 180 / pi, cx / 8, cz / 8
}
