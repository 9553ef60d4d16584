"""Checks a grid written in pieces (grid.pvti and grid_<r>.vti, mpmFsi's writeGrid on several
ranks) against the serial run's grid.vti: the index names one piece per rank (at most one per
cell layer) with the slab extents of libraries/grid/VtiWriter.hpp, and each piece's arrays are
the serial arrays' bytes over the piece's node layers, bit for bit.
Usage: gridPieces.py <serial grid.vti> <directory with grid.pvti> <ranks>"""
import re
import struct
import sys
from pathlib import Path


def image(path):
    """(WholeExtent, [(name, components, bytes)]) of the point arrays of a .vti mfdyn wrote."""
    data = path.read_bytes()
    head_end = data.index(b'<AppendedData encoding="raw">')
    head = data[:head_end].decode()
    start = data.index(b"_", head_end) + 1
    extent = [int(x) for x in re.search(r'<ImageData WholeExtent="([^"]*)"', head).group(1).split()]
    point_data = head[head.index("<PointData>"):head.index("</PointData>")]
    arrays = []
    for name, components, offset in re.findall(
            r'Name="([^"]*)" NumberOfComponents="(\d+)" format="appended" offset="(\d+)"', point_data):
        at = start + int(offset)
        (size,) = struct.unpack_from("<Q", data, at)
        arrays.append((name, int(components), data[at + 8:at + 8 + size]))
    return extent, arrays


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


serial_extent, serial_arrays = image(Path(sys.argv[1]))
directory, ranks = Path(sys.argv[2]), int(sys.argv[3])
index = (directory / "grid.pvti").read_text()
whole = [int(x) for x in re.search(r'<PImageData WholeExtent="([^"]*)"', index).group(1).split()]
if whole != serial_extent:
    fail(f"grid.pvti's WholeExtent {whole}, the serial {serial_extent}")
pieces = re.findall(r'<Piece Extent="([^"]*)" Source="([^"]*)"/>', index)
axis = max(d for d in range(3) if serial_extent[2 * d + 1] > 0)
cells = serial_extent[2 * axis + 1]
expected = min(ranks, cells)
if len(pieces) != expected:
    fail(f"grid.pvti lists {len(pieces)} pieces, not {expected}")
layer = 1
for d in range(axis):
    layer *= serial_extent[2 * d + 1] + 1
for r, (extent_text, source) in enumerate(pieces):
    extent = [int(x) for x in extent_text.split()]
    first, last = cells * r // expected, cells * (r + 1) // expected
    slab = list(serial_extent)
    slab[2 * axis], slab[2 * axis + 1] = first, last
    if source != f"grid_{r}.vti" or extent != slab:
        fail(f"piece {r}: {source} with extent {extent}, not grid_{r}.vti with {slab}")
    piece_extent, piece_arrays = image(directory / source)
    if piece_extent != slab:
        fail(f"{source}: WholeExtent {piece_extent}, its index says {slab}")
    if [a[:2] for a in piece_arrays] != [a[:2] for a in serial_arrays]:
        fail(f"{source}: arrays {[a[:2] for a in piece_arrays]}, the serial {[a[:2] for a in serial_arrays]}")
    for (name, width, values), (_, _, serial_values) in zip(piece_arrays, serial_arrays):
        begin, end = first * layer * width * 8, (last + 1) * layer * width * 8
        if values != serial_values[begin:end]:
            fail(f"{source}: {name} differs from the serial grid.vti over node layers {first}..{last}")
print(f"{len(pieces)} grid pieces equal to the serial grid.vti, bit for bit")
