# Reads the arrays of a particles.vtp that mfdyn wrote (raw appended, UInt64 headers): read(path)
# returns {name: [tuple per particle]}; "position" holds the points.
import re, struct, sys
def read(path):
    data = open(path, 'rb').read()
    head = data[:data.index(b'<AppendedData')].decode()
    start = data.index(b'_', data.index(b'<AppendedData')) + 1
    out = {}
    for m in re.finditer(r'<DataArray type="(\w+)" Name="(\w+)"(?: NumberOfComponents="(\d+)")? format="appended" offset="(\d+)"', head):
        typ, name, nc, off = m.group(1), m.group(2), int(m.group(3) or 1), int(m.group(4))
        p = start + off
        nbytes = struct.unpack('<Q', data[p:p + 8])[0]
        fmt = 'd' if typ == 'Float64' else 'q'
        n = nbytes // 8
        v = struct.unpack('<%d%s' % (n, fmt), data[p + 8:p + 8 + nbytes])
        out[name] = [v[i * nc:(i + 1) * nc] for i in range(n // nc)]
    return out
