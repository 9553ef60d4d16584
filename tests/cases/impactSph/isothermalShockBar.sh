# The isothermal shock-bar (doc/methods/sph-impact.md 8.2, Zisis 2017 Fig. 5.1), run by the tutorial's Allrun,
# against its exact solution (isothermalShockBarError): every plateau's median rho, v and P within
# 3% of the exact values at t = 0.3 and 0.4 (once the plateaus behind the reflected and transmitted
# waves are wide enough to have a middle), and the shocks, where P crosses the mean of the states
# either side, within 2h of the exact fronts at every write time. The tutorial's run: plateaus
# within 0.55%, shocks within 0.9h.
. "$(dirname "$0")/common.sh"
d=$(runTutorial isothermalShockBar)
out="$d/postProcessing/bar/0"
[ -f "$out/plateaus.csv" ] && [ -f "$out/fronts.csv" ] || fail "no plateaus.csv or fronts.csv"
[ "$(tail -n 1 "$out/plateaus.csv" | cut -d, -f1)" = 0.4 ] || fail "last plateau row not at t = 0.4"
[ "$(awk -F, 'NR > 1 && $1 >= 0.3' "$out/plateaus.csv" | wc -l)" = 6 ] || fail "expected 3 plateaus at t = 0.3 and 0.4: $(cat "$out/plateaus.csv")"
worst=$(awk -F, 'function rel(a, b) { d = (a - b) / b; return d < 0 ? -d : d }
    NR > 1 && $1 >= 0.3 { for (k = 3; k <= 7; k += 2) { e = rel($k, $(k + 1)); if (e > w) { w = e; at = $1 " " $2 } } }
    END { printf "%.4g %s\n", w, at }' "$out/plateaus.csv")
less "${worst%% *}" 0.03 || fail "plateau off by ${worst} (relative): $(cat "$out/plateaus.csv")"
fronts=$(awk -F, 'NR > 1 { d = ($3 - $4) / $5; if (d < 0) d = -d; if (d > w || $3 == "nan") { w = d; at = $1 " " $2 } }
    END { printf "%.3g %s\n", w, at }' "$out/fronts.csv")
less "${fronts%% *}" 2 || fail "shock front off by ${fronts} h: $(cat "$out/fronts.csv")"
wall=$(awk '/^ *wall time/ { print $3; exit }' "$d/log.impactSph")
pass "isothermal shock-bar: plateaus within ${worst%% *} relative (worst at t = ${worst#* }), shocks within ${fronts%% *} h, wall time $wall s"
