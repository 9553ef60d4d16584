# frontShift.awk: the surge front of frontPosition.csv against Martin & Moyce (1952) Fig. 3
# (n^2 = 2, a = 2.25 in; the points of frontError.awk) with the run's clock started late by dT
# (in T = t sqrt(2g/a) units): Z_run(T - dT) against Z_MM(T), for dT = 0 .. 0.5; -v a -v g.
# A release that is not instantaneous shifts the experiment's time origin (README).
BEGIN { FS = ","; n = split("0.832 1.219 1.997 2.547 3.345", T, " "); split("1.217 1.474 2.292 2.995 4.134", Z, " "); s = sqrt(2 * g / a) }
NR > 1 { k++; t[k] = $1 * s; z[k] = $3 / a }
END {
    for (d = 0; d <= 0.501; d += 0.05) {
        worst = 0; line = ""
        for (i = 1; i <= n; ++i) {
            tt = T[i] - d
            for (j = 2; j <= k; ++j) if (t[j] >= tt) break
            zi = z[j-1] + (z[j] - z[j-1]) * (tt - t[j-1]) / (t[j] - t[j-1])
            e = (zi - Z[i]) / Z[i]; line = line sprintf(" %+.1f", 100 * e)
            if (e < 0) e = -e; if (e > worst) worst = e
        }
        printf "dT %.2f (dt %.1f ms) worst %.1f%% :%s\n", d, 1000 * d / s, 100 * worst, line
    }
}
