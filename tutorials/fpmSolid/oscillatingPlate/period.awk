# The plate's mean period [s] from postProcessing/tip/0/probes.csv (the y velocity at the tip): the
# zero crossings, linearly interpolated, come every half period; the first (a quarter period in,
# from the mode's initial velocity) to the last. Usage: awk -F, -f period.awk probes.csv
# Prints "period crossings firstCrossing" (period nan with fewer than two crossings).
NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "p0_velocity_y") k = i; next }
{
    t = $1; v = $k
    if (NR > 2 && (v < 0) != (pv < 0)) { c = pt + (t - pt) * (-pv) / (v - pv); if (!n) first = c; last = c; ++n }
    pt = t; pv = v
}
END { printf "%s %d %s\n", (n >= 2 ? sprintf("%.6g", 2 * (last - first) / (n - 1)) : "nan"), n, (n ? sprintf("%.6g", first) : "none") }
