# orderEstimate on manufactured runs (common.sh): the known orders come back at every time, in
# both norms. Tolerance 1e-6: the grid values are exact to round-off (~1e-15 relative, first-order
# MLS reproduces the linear f and g), the differences lose about 3 digits (dx^p ~ 1e-3 of f), and
# the CSV holds 10 significant digits; so the orders are good to ~1e-9, and 1e-6 still fails for
# any wrong ingredient (a wrong d or a swapped run moves p by O(1), a Shepard-smeared value by
# ~1e-2).
. "$(dirname "$0")/common.sh"

study="$WORK/study"
makeStudy "$study"
csv="$study/postProcessing/orderEstimate/orderEstimate.csv"

check() {  # <norm>
    local log="$study/log.orderEstimate.$1" t points
    orderEstimate -case "$study" > "$log" 2>&1 || fail "$1: orderEstimate failed: $(cat "$log")"
    grep -q "1 time is not written by all three runs and skipped: 0.25 (coarse)" "$log" ||
        fail "$1: no warning about time 0.25: $(cat "$log")"
    [ "$(head -n 1 "$csv")" = "time,points,pressure_d21,pressure_d32,pressure_ratio,pressure_order,temperature_d21,temperature_d32,temperature_ratio,temperature_order,velocity_x_d21,velocity_x_d32,velocity_x_ratio,velocity_x_order,velocity_y_d21,velocity_y_d32,velocity_y_ratio,velocity_y_order" ] ||
        fail "$1: header $(head -n 1 "$csv")"
    [ "$(wc -l < "$csv")" -eq 3 ] || fail "$1: expected 2 rows (times 0 and 0.5): $(cat "$csv")"
    for t in 0 0.5; do
        # The coarse run's particles span (0.05..1.95) x (0.05..0.95): 19 x 9 = 171 grid points in
        # the common box, of which those within about a smoothing length of the coarse surface
        # (kernel sum < 0.9) are left out; the interior ones are kept.
        points=$(cell "$csv" "$t" points)
        [ "$points" -gt 50 ] && [ "$points" -lt 171 ] || fail "$1: time $t: $points grid points, expected 50..170"
        near "$(cell "$csv" "$t" pressure_order)" 2 1e-6 || fail "$1: time $t: pressure order $(cell "$csv" "$t" pressure_order), expected 2"
        near "$(cell "$csv" "$t" temperature_order)" 1.5 1e-6 ||
            fail "$1: time $t: temperature order $(cell "$csv" "$t" temperature_order), expected 1.5"
        near "$(cell "$csv" "$t" velocity_x_order)" 1 1e-6 || fail "$1: time $t: velocity_x order $(cell "$csv" "$t" velocity_x_order), expected 1"
        # Geometric refinement in 2D (N ratio 4): ratio = 2^-p.
        near "$(cell "$csv" "$t" pressure_ratio)" 0.25 1e-8 || fail "$1: time $t: pressure ratio $(cell "$csv" "$t" pressure_ratio)"
        # velocity_y is the same 0.25 in every run: differences of round-off only, no order.
        near "$(cell "$csv" "$t" velocity_y_d21)" 0 1e-14 || fail "$1: time $t: velocity_y_d21 $(cell "$csv" "$t" velocity_y_d21), expected 0"
        [ "$(cell "$csv" "$t" velocity_y_order)" = nan ] || fail "$1: time $t: velocity_y order not NaN"
    done
    summary="$study/postProcessing/orderEstimate/summary.txt"
    [ -f "$summary" ] || fail "$1: no summary.txt"
    grep -q "N1 N2 N3 = 200 800 3200 (2D, at time 0)" "$summary" || fail "$1: summary lacks N: $(cat "$summary")"
    grep -q "dx1 dx2 dx3 = 0.1 0.05 0.025" "$summary" || fail "$1: summary lacks dx: $(cat "$summary")"
    grep -qE "^pressure +2\.0000 +2/2 +2\.0000 +2\.0000$" "$summary" || fail "$1: summary's pressure line: $(cat "$summary")"
    grep -qE "^temperature +1\.5000 +2/2 " "$summary" || fail "$1: summary's temperature line: $(cat "$summary")"
    grep -qE "^velocity_y +none +0/2 " "$summary" || fail "$1: summary's velocity_y line: $(cat "$summary")"
    grep -q "velocity_y: 2 times left out of the mean: no ratio (||phi2 - phi1|| is zero, below 1e-10 of the values" "$summary" || fail "$1: no note on velocity_y: $(cat "$summary")"
    grep -q "Order estimate" "$log" || fail "$1: the summary is not printed"
    pass "$1 norm: orders 2, 1.5, 1 at times 0 and 0.5 ($points points)"
}

check infinity
sed -i 's/^norm .*/norm l2;/' "$study/system/orderEstimateDict"
check l2

# -latestTime: one row, the latest common time (0.5, not the coarse run's own 0.25).
orderEstimate -case "$study" -latestTime > "$study/log.latest" 2>&1 || fail "-latestTime: $(cat "$study/log.latest")"
[ "$(wc -l < "$csv")" -eq 2 ] && [ "$(cut -d, -f1 "$csv" | tail -n 1)" = 0.5 ] || fail "-latestTime: $(cat "$csv")"
pass "-latestTime compares time 0.5 only"

# Shepard interpolation does not reproduce the linear fields near the edges of the stencils: the
# orders are then not exact, which shows the test can tell an exact estimate from a close one.
sed -i 's/^interpolation .*/interpolation shepard;/' "$study/system/orderEstimateDict"
orderEstimate -case "$study" -time 0 > "$study/log.shepard" 2>&1 || fail "shepard: $(cat "$study/log.shepard")"
near "$(cell "$csv" 0 pressure_order)" 2 1e-6 && fail "shepard: pressure order exactly 2 although Shepard smears the linear field"
pass "shepard interpolation gives an inexact order ($(cell "$csv" 0 pressure_order)), as it must"

# 3D, counts that are not a geometric sequence (N = 216, 512, 1728: dx = 0.2, 0.15, 0.1 on a
# 1.2 m cube, so dx is exactly proportional to N^(-1/3)), and no `h`: each run's smoothingLength
# field (1.3 dx). The order solves the general alpha(p) = ratio; p = 2.5 comes back to round-off.
cube="$WORK/cube"
for run in a:0.2:0.26 b:0.15:0.195 c:0.1:0.13; do
    IFS=: read -r name spacing h <<< "$run"
    mkdir -p "$cube/$name/system"
    cat > "$cube/$name/system/particleGenDict" <<DICT
dimension 3;
regions
{
    cube
    {
        shape   { type box; min (0 0 0); max (1.2 1.2 1.2); }
        lattice { type cubic; spacing $spacing; }
        density 1;
        fields  { pressure 0; smoothingLength $h; }
    }
}
DICT
    particleGen -case "$cube/$name" > "$cube/$name/log.particleGen" 2>&1 || fail "particleGen $name"
    setField "$cube/$name/0/particles.vtp" pressure 0 "x + 2*y - z + $spacing**2.5 * (1 + x + y + z)"
done
writeDict "$cube" 'runs (a b c);
fields (pressure);
grid { spacing 0.1; }'
orderEstimate -case "$cube" > "$cube/log.orderEstimate" 2>&1 || fail "3D: $(cat "$cube/log.orderEstimate")"
cubeCsv="$cube/postProcessing/orderEstimate/orderEstimate.csv"
near "$(cell "$cubeCsv" 0 pressure_order)" 2.5 1e-6 || fail "3D: pressure order $(cell "$cubeCsv" 0 pressure_order), expected 2.5"
grep -q "N1 N2 N3 = 216 512 1728 (3D, at time 0)" "$cube/postProcessing/orderEstimate/summary.txt" ||
    fail "3D: summary: $(cat "$cube/postProcessing/orderEstimate/summary.txt")"
pass "3D, non-geometric counts, smoothingLength fields: order 2.5 ($(cell "$cubeCsv" 0 points) points)"
