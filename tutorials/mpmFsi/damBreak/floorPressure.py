# floorPressure.py <case> <time> [dx]: x and p of the particles within 1.5 dx of the floor at one
# write, p = -(sxx + syy + szz)/3 of the written (smoothed) stress, for the README's plot.
import os, re, struct, sys
def read(path):
    raw = open(path, 'rb').read()
    end = raw.index(b'<AppendedData')
    start = raw.index(b'_', end) + 1
    head = raw[:end].decode('latin1')
    out = {}
    for m in re.finditer(r'<DataArray type="Float64" Name="(\w+)" NumberOfComponents="(\d+)" format="appended" offset="(\d+)"', head):
        name, nc, off = m.group(1), int(m.group(2)), int(m.group(3))
        nbytes = struct.unpack_from('<Q', raw, start + off)[0]
        v = struct.unpack_from('<%dd' % (nbytes // 8), raw, start + off + 8)
        out[name] = [v[i * nc:(i + 1) * nc] for i in range(nbytes // 8 // nc)]
    return out
d = read(os.path.join(sys.argv[1], sys.argv[2], 'particles.vtp'))
dx = float(sys.argv[3]) if len(sys.argv) > 3 else 0.0028575
rows = []
for q, s, zz in zip(d['position'], d['cauchyStress'], d['cauchyStressZZ']):
    if q[1] < 1.5 * dx: rows.append((q[0], -(s[0] + s[1] + zz[0]) / 3))
for x, p in sorted(rows): print("%.6g %.6g" % (x / 0.05715, p / (1000 * 9.81 * 2 * 0.05715)))
