# prescribedTraction in tlSph: a free unit cube (rho0 1100) pulled by 1e5 Pa on its face X = 1
# (area 1 m^2) until 5 ms, then released. The internal forces sum to zero (momentum projection),
# so the linear momentum grows as F t exactly: 250 N s at 2.5 ms, 500 N s at 5 ms and after;
# relative error below 1e-10 (round-off), momentum_y and _z stay at round-off.
source "$(dirname "$0")/common.sh"
c="$WORK/tractionCube"
cp -r "$SOURCE/tests/cases/tlSph/tractionCube" "$c"
particleGen -case "$c" > "$c/log.particleGen" 2>&1 || fail "particleGen: $(tail "$c/log.particleGen")"
run "$c" tlSph
csv="$c/postProcessing/conserved/0/conservedQuantities.csv"
awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    { t = $1; px = $c["momentum_x"]; expected = 1e5 * (t < 0.005 ? t : 0.005)
      e = px - expected; if (e < 0) e = -e
      if (t > 0 && e > 1e-10 * 500) { printf "momentum_x %.12g at t = %g, expected %.12g\n", px, t, expected; bad = 1 }
      for (k in a) {} py = $c["momentum_y"]; pz = $c["momentum_z"]; if (py * py + pz * pz > 1e-18) { print "transverse momentum", py, pz; bad = 1 }
      n++ }
    END { if (n < 4) { print "only", n, "rows"; bad = 1 } exit bad }' "$csv" || fail "momentum does not follow the applied force (see above)"
echo "PASS: prescribedTraction: momentum_x = F t to 1e-10 ($(tail -n 1 "$csv" | cut -d, -f3) N s at the end)"
