# The isentropic shock-bar (doc/methods/sph-impact.md 8.5, Zisis 2017 §5.3: cubic equations of state, energy
# equation), run by the tutorial's Allrun. No exact solution, so a regression of what the method
# promises: mass exact, momentum to round-off (< 1e-12), total energy drift below 1e-4 (the run:
# 3.8e-7), and a flat pressure across the shocked hard|soft interface (the mass flux's purpose):
# within 0.015 (~5h) of the largest density drop on 0.8 < x < 1, the pressure sampled along the
# bar stays within 15% of the median over +-0.05 (the run: ~7%, the blip of unequal masses).
. "$(dirname "$0")/common.sh"
d=$(runTutorial isentropicShockBar)
csv="$d/postProcessing/conserved/0/conservedQuantities.csv"
first=$(sed -n 2p "$csv"); last=$(tail -n 1 "$csv")
[ "$(echo "$last" | cut -d, -f1)" = 0.25 ] || fail "last conserved row at t = $(echo "$last" | cut -d, -f1)"
[ "$(echo "$first" | cut -d, -f2)" = "$(echo "$last" | cut -d, -f2)" ] || fail "mass changed: $first -> $last"
# The CSV holds 10 digits of momentum 0.6; the log's summary gives the change itself.
dp=$(awk '/momentum_x change/ { v = $4; sub(/^-/, "", v); print v }' "$d/log.impactSph")
[ -n "$dp" ] || fail "the log's Diagnostics lack the momentum change"
less "$dp" 1e-12 || fail "momentum changed by $dp"
dE=$(relErr "$(echo "$last" | cut -d, -f6)" "$(echo "$first" | cut -d, -f6)")
less "$dE" 1e-4 || fail "energy drift $dE"
bar="$d/postProcessing/sample/0.25/bar.csv"
[ -f "$bar" ] || fail "sample wrote no bar.csv"
flat=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    $(c["density"]) != "nan" { n++; x[n] = $(c["x"]); r[n] = $(c["density"]); p[n] = $(c["pressure"]) }
    END {
        for (k = 2; k <= n; ++k) if (x[k] > 0.8 && x[k] < 1 && r[k-1] - r[k] > drop) { drop = r[k-1] - r[k]; xi = x[k] }
        m = 0; for (k = 1; k <= n; ++k) if (x[k] > xi - 0.05 && x[k] < xi + 0.05) v[++m] = p[k]
        for (i = 2; i <= m; ++i) { t = v[i]; for (j = i - 1; j >= 1 && v[j] > t; --j) v[j + 1] = v[j]; v[j + 1] = t }
        ref = v[int((m + 1) / 2)]
        for (k = 1; k <= n; ++k) if (x[k] > xi - 0.015 && x[k] < xi + 0.015) { e = (p[k] - ref) / ref; if (e < 0) e = -e; if (e > w) w = e }
        printf "%.4g %.4g %.4g\n", w, xi, ref }' "$bar")
read -r dev xi pref <<< "$flat"
less "$dev" 0.15 || fail "pressure across the interface at x = $xi off its median $pref by $dev"
wall=$(awk '/^ *wall time/ { print $3; exit }' "$d/log.impactSph")
pass "isentropic shock-bar: momentum change $dp, energy drift $dE, interface at x = $xi: P within $dev of $pref, wall time $wall s"
