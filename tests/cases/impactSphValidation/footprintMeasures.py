#!/usr/bin/env python3
"""Footprint measures of a Taylor bar quarter beside the extent (tests/cases/impactSphValidation/taylorBarStudy.sh).

Usage: footprintMeasures.py <initial particles.vtp> <final particles.vtp> <lattice spacing s> <rod radius R0>

Prints four numbers:
  areaRatio  the rod's cross-section on the lattice against the circle's: (particles in the lowest layer
             at t = 0) s^2 / (pi R0^2 / 4). A cell-centred cubic lattice cut by a circle has a staircase
             edge, so the rod it makes is not the rod of radius R0: +3.5%, +0.6%, -1.0%, +1.0% at
             R0/8, R0/10, R0/12, R0/16 (taylorBar README). The error does not fall monotonically with s.
  rMax       the radial distance of the outermost particle of the wall layer (centres below the lowest
             centre + s/2) plus s/2, in m: the footprint as a radius, at any angle.
  r90        the radius (+ s/2) inside which 90% of that layer's particles lie, in m: a measure that one
             petal's tip does not set.
  n          the number of particles in the wall layer.
  below, stretched  of the particles stretched round the hoop by ln(r/r0) = 0.8 to 1.2 (r0 >= 0.5 mm),
             how many carry a plastic strain below ln(r/r0) - 0.01, the least an intact axisymmetric
             flow gives (the README's hoop bound): a torn foot has many.
The extent max(x, y) + s/2 that ../Allrun prints reads a particle near a symmetry plane, so it depends on
where round the rim the widest particles sit; rMax does not. Neither is the finite-element footprint
exactly (a continuum edge); they are measurements of the particle rim, stated as such.
Standard library only (as rimGaps.py)."""
import math
import re
import struct
import sys


def arrays(path, wanted):
    """{name: list of tuples} of the named (type, components) arrays of a raw appended VTP file."""
    data = open(path, "rb").read()
    start = data.index(b"<AppendedData")
    base = data.index(b"_", start) + 1
    header = data[:start].decode()
    if 'header_type="UInt64"' not in header or 'encoding="raw"' not in data[start:base].decode():
        sys.exit(f"{path}: expected raw appended data with UInt64 headers")
    out = {}
    for name, (kind, nc) in wanted.items():
        m = re.search(r'<DataArray type="%s" Name="%s" NumberOfComponents="%d" format="appended" offset="(\d+)"'
                      % (kind, name, nc), header)
        if not m:
            sys.exit(f"{path}: no {kind} {name} array")
        offset = base + int(m.group(1))
        n = struct.unpack_from("<Q", data, offset)[0] // (8 * nc)
        v = struct.unpack_from("<%d%s" % (n * nc, "d" if kind == "Float64" else "q"), data, offset + 8)
        out[name] = [v[nc * i:nc * i + nc] for i in range(n)]
    return out


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    a0 = arrays(sys.argv[1], {"position": ("Float64", 3), "globalId": ("Int64", 1)})
    a = arrays(sys.argv[2], {"position": ("Float64", 3), "globalId": ("Int64", 1), "plasticStrain": ("Float64", 1)})
    s, R0 = float(sys.argv[3]), float(sys.argv[4])
    if not (s > 0 and R0 > 0):
        sys.exit("spacing and radius must be positive")
    x0, x = a0["position"], a["position"]
    # The hoop bound (README, "Why the footprint does not converge"): a point that has moved from
    # radius r0 to r in an axisymmetric isochoric flow carries an equivalent plastic strain of at
    # least ln(r/r0) less its elastic strain (taken as 0.01). Particles far below it have moved
    # apart without the continuum stretching between them: the foot has torn there.
    start = {g[0]: math.hypot(p[0], p[1]) for g, p in zip(a0["globalId"], x0)}
    stretched = below = 0
    for g, p, e in zip(a["globalId"], x, a["plasticStrain"]):
        rStart = start.get(g[0], 0.0)
        if rStart < 0.5e-3:
            continue  # near the axis the hoop strain is ill-defined
        hoop = math.log(max(math.hypot(p[0], p[1]), 1e-12) / rStart)
        if 0.8 <= hoop < 1.2:
            stretched += 1
            below += e[0] < hoop - 0.01
    z0 = min(p[2] for p in x0)
    # The lowest layer of a lattice: centres within a thousandth of a spacing of the lowest.
    bottom = sum(1 for p in x0 if p[2] < z0 + 1e-3 * s)
    areaRatio = bottom * s * s / (math.pi * R0 * R0 / 4)
    zmin = min(p[2] for p in x)
    r = sorted(math.hypot(p[0], p[1]) for p in x if p[2] < zmin + 0.5 * s)
    r90 = r[int(0.9 * (len(r) - 1))]
    print("%.4f %.6g %.6g %d %d %d" % (areaRatio, r[-1] + 0.5 * s, r90 + 0.5 * s, len(r), below, stretched))


main()
