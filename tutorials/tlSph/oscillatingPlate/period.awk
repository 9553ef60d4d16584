# The tip's mean period [s] from postProcessing/tip/0/probes.csv (the y deflection of the probe at
# the tip's centre): the zero crossings after t = 0.01 s, linearly interpolated, come every half
# period; the mean over the first to the last crossing. Usage: awk -F, -f period.awk probes.csv
NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "p0_position_y") k = i; next }
{
    t = $1; y = $k
    if (NR > 2 && (y < 0) != (py < 0) && t > 0.01) { c = pt + (t - pt) * (-py) / (y - py); if (!n) first = c; last = c; ++n }
    pt = t; py = y
}
END { if (n >= 2) printf "%.6g\n", 2 * (last - first) / (n - 1); else print "nan" }
