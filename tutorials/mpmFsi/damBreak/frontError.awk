# frontError.awk: the surge front of frontPosition.csv (time, wall, front, height) against
# Martin & Moyce (1952) Fig. 3, n^2 = 2, a = 2.25 in, as digitised in PySPH examples/db_exp_data.py;
# -v a (column width, m) -v g. Prints each point's error and the largest, and the largest
# dZ/dT / 2 over a write interval (the Ritter bound dx/dt <= 2 sqrt(g H), H = 2a: dZ/dT <= 2).
BEGIN { FS = ","; n = split("0.832 1.219 1.997 2.547 3.345", T, " "); split("1.217 1.474 2.292 2.995 4.134", Z, " "); s = sqrt(2 * g / a) }
NR > 1 { k++; t[k] = $1 * s; z[k] = $3 / a; h[k] = $4 / (2 * a) }
END {
    worst = 0; rmax = 0
    for (i = 1; i <= n; ++i) {
        if (T[i] > t[k]) continue
        for (j = 2; j <= k; ++j) if (t[j] >= T[i]) break
        zi = z[j-1] + (z[j] - z[j-1]) * (T[i] - t[j-1]) / (t[j] - t[j-1])
        e = (zi - Z[i]) / Z[i]; printf "T %.3f  Z(MM) %.3f  Z(mpm) %.3f  error %+.1f%%\n", T[i], Z[i], zi, 100 * e
        if (e < 0) e = -e; if (e > worst) worst = e
    }
    # Ritter: dx/dt <= 2 sqrt(g H), H = 2a, i.e. dZ/dT <= 2 over each write interval
    for (j = 2; j <= k; ++j) { r = (z[j] - z[j-1]) / (t[j] - t[j-1]) / 2; if (r > rmax) { rmax = r; tr = t[j] } }
    printf "worst %.4f ritter %.4f at T %.2f\n", worst, rmax, tr
}
