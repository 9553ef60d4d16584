#!/usr/bin/env python3
"""Sets v = (-A0 x, A0 y) on the particles of a particleGen output (0/particles.vtp, raw appended
binary, UInt64 block headers), in place. Standard library only.
Usage: setStrainVelocity.py <particles.vtp> [A0 = 100]"""
import re
import struct
import sys

path = sys.argv[1]
A0 = float(sys.argv[2]) if len(sys.argv) > 2 else 100.0
data = bytearray(open(path, "rb").read())
start = data.index(b"<AppendedData")
base = data.index(b"_", start) + 1
header = data[:start].decode()
if 'header_type="UInt64"' not in header or 'encoding="raw"' not in data[start:base].decode():
    sys.exit(f"{path}: expected raw appended data with UInt64 headers")


def array(name):
    m = re.search(r'<DataArray type="Float64" Name="%s" NumberOfComponents="3" format="appended" offset="(\d+)"' % name, header)
    if not m:
        sys.exit(f"{path}: no Float64 3-component array '{name}'")
    offset = base + int(m.group(1))
    nbytes = struct.unpack_from("<Q", data, offset)[0]
    return offset + 8, nbytes // 24


px, n = array("position")
vx, nv = array("velocity")
if n != nv:
    sys.exit(f"{path}: {n} positions but {nv} velocities")
for i in range(n):
    x, y, _ = struct.unpack_from("<3d", data, px + 24 * i)
    struct.pack_into("<3d", data, vx + 24 * i, -A0 * x, A0 * y, 0.0)
open(path, "wb").write(data)
print(f"set v = (-{A0:g} x, {A0:g} y) on {n} particles of {path}")
