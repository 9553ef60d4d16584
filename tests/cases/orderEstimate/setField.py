# setField.py <particles.vtp> <field> <component> <expression>: overwrites, in place, component
# <component> (0-based) of the Float64 point array <field> of a particles.vtp that mfdyn wrote
# (raw appended data, UInt64 byte counts; tests/cases/mpmFsi/vtp.py reads the same layout) with
# <expression>, a numpy expression in the particles' coordinates x, y, z. The file keeps its size
# and layout: only the array's values change.
import re
import sys

import numpy as np

path, name, component, expression = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
data = bytearray(open(path, 'rb').read())
head = data[:data.index(b'<AppendedData')].decode()
start = data.index(b'_', data.index(b'<AppendedData')) + 1


def array(array_name):
    """(values as an (n, components) view into data, components) of a Float64 array."""
    m = re.search(r'<DataArray type="(\w+)" Name="%s" NumberOfComponents="(\d+)" format="appended" offset="(\d+)"'
                  % re.escape(array_name), head)
    if not m:
        sys.exit('setField.py: no array %s in %s' % (array_name, path))
    if m.group(1) != 'Float64':
        sys.exit('setField.py: array %s in %s is %s, not Float64' % (array_name, path, m.group(1)))
    components, offset = int(m.group(2)), start + int(m.group(3))
    nbytes = int(np.frombuffer(data, dtype='<u8', count=1, offset=offset)[0])
    values = np.frombuffer(data, dtype='<f8', count=nbytes // 8, offset=offset + 8).reshape(-1, components)
    return values, offset + 8


position, _ = array('position')
x, y, z = position[:, 0], position[:, 1], position[:, 2]
values, begin = array(name)
if component >= values.shape[1]:
    sys.exit('setField.py: %s has %d components' % (name, values.shape[1]))
new = values.copy()
new[:, component] = np.broadcast_to(eval(expression, {'np': np, 'x': x, 'y': y, 'z': z}), x.shape)
data[begin:begin + new.nbytes] = new.astype('<f8').tobytes()
open(path, 'wb').write(data)
