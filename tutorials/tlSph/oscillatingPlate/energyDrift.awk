# The total energy's relative change, last row against the first, of
# postProcessing/conserved/0/conservedQuantities.csv. Usage: awk -F, -f energyDrift.awk <csv>
NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "totalEnergy") k = i; next }
NR == 2 { e0 = $k }
{ e = $k }
END { printf "%.6g\n", e / e0 - 1 }
