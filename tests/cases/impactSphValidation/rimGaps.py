#!/usr/bin/env python3
"""Hoop cracks in a Taylor bar's footprint (tests/cases/impactSphValidation/taylorBarStudy.sh).

Usage: rimGaps.py <particles.vtp> <lattice spacing s> [quarter]

Reads the particles written by impactSph (raw appended VTK, UInt64 headers) and prints, for the
layer of particles on the wall (z below the lowest centre + s/2) in the outer quarter of its
radius (r >= 0.75 of the largest), the number of particles there and the largest arc length
between neighbours round the rim, r dtheta, in units of s. With `quarter` (the model x, y >= 0 of
tutorials/impactSph/taylorBar/quarter3D) the particles are first mirrored across x = 0 and y = 0,
so that the gaps across the symmetry planes count too. A continuous rim has gaps of about one
spacing; a gap wider than the kernel's support (2h = 2.6 s with eta 1.3) is a crack: no particle
on one side interacts with one on the other, so no hoop stress is carried across it.
Standard library only."""
import math
import re
import struct
import sys


def positions(path):
    data = open(path, "rb").read()
    start = data.index(b"<AppendedData")
    base = data.index(b"_", start) + 1
    header = data[:start].decode()
    if 'header_type="UInt64"' not in header or 'encoding="raw"' not in data[start:base].decode():
        sys.exit(f"{path}: expected raw appended data with UInt64 headers")
    m = re.search(r'<DataArray type="Float64" Name="position" NumberOfComponents="3" format="appended" offset="(\d+)"', header)
    if not m:
        sys.exit(f"{path}: no Float64 position array")
    offset = base + int(m.group(1))
    n = struct.unpack_from("<Q", data, offset)[0] // 24
    v = struct.unpack_from("<%dd" % (3 * n), data, offset + 8)
    return [v[3 * i:3 * i + 3] for i in range(n)]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    x = positions(sys.argv[1])
    s = float(sys.argv[2])
    if len(sys.argv) > 3 and sys.argv[3] == "quarter":
        x = [(sx * p[0], sy * p[1], p[2]) for p in x for sx in (1, -1) for sy in (1, -1)
             if not (sx < 0 and p[0] == 0) and not (sy < 0 and p[1] == 0)]
    zmin = min(p[2] for p in x)
    layer = [p for p in x if p[2] < zmin + 0.5 * s]
    radius = max(math.hypot(p[0], p[1]) for p in layer)
    ring = sorted((math.atan2(p[1], p[0]), math.hypot(p[0], p[1])) for p in layer
                  if math.hypot(p[0], p[1]) >= 0.75 * radius)
    if len(ring) < 2:
        sys.exit(f"{sys.argv[1]}: fewer than 2 particles in the outer quarter of the wall layer")
    gaps = [(b[0] - a[0]) * 0.5 * (a[1] + b[1]) / s for a, b in zip(ring, ring[1:])]
    first, last = ring[0], ring[-1]
    gaps.append((first[0] + 2 * math.pi - last[0]) * 0.5 * (first[1] + last[1]) / s)
    print("%d %.3f %.4g" % (len(ring), max(gaps), radius))


main()
