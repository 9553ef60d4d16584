# pressureNoise.py <case> [dx]: the particle-scale pressure noise of a damBreak run (README):
# p = -(sxx + syy + szz)/3 from cauchyStress (the smoothed stress), noise = RMS over particles of
# p - (mean p of the other particles within 1.5 dx), over rho g H (H = 2a), each write 0.04..0.18 s.
import struct, re, sys, math, os
def read(path):
    raw = open(path, 'rb').read()
    head_end = raw.index(b'<AppendedData')
    start = raw.index(b'_', head_end) + 1
    head = raw[:head_end].decode('latin1')
    out = {}
    n = int(re.search(r'NumberOfPoints="(\d+)"', head).group(1))
    for m in re.finditer(r'<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="(\d+)" format="appended" offset="(\d+)"', head):
        t, name, nc, off = m.group(1), m.group(2), int(m.group(3)), int(m.group(4))
        if t != 'Float64': continue
        o = start + off
        nbytes = struct.unpack_from('<Q', raw, o)[0]
        vals = struct.unpack_from('<%dd' % (nbytes // 8), raw, o + 8)
        out[name] = [vals[i*nc:(i+1)*nc] for i in range(n)]
    return out
case = sys.argv[1]; dx = float(sys.argv[2]) if len(sys.argv) > 2 else 0.0028575
scale = 1000 * 9.81 * 2 * 0.05715
res = []
for t in ['0.04', '0.06', '0.08', '0.1', '0.12', '0.14', '0.16', '0.18']:
    d = read(os.path.join(case, t, 'particles.vtp'))
    x = [q[0] for q in d['position']]; y = [q[1] for q in d['position']]
    s = d['cauchyStress']; zz = d['cauchyStressZZ']
    p = [-(s[i][0] + s[i][1] + zz[i][0]) / 3 for i in range(len(x))]
    if t == '0.04':
        pe = [q[0] for q in d['pressure']]
        chk = max(abs(p[i] - pe[i]) for i in range(len(x)))
    r = 1.5 * dx; h = {}
    for i in range(len(x)): h.setdefault((int(x[i] // r), int(y[i] // r)), []).append(i)
    sq = 0; cnt = 0
    for i in range(len(x)):
        cx, cy = int(x[i] // r), int(y[i] // r); sm = 0; k = 0
        for a in (-1, 0, 1):
            for b in (-1, 0, 1):
                for j in h.get((cx + a, cy + b), []):
                    if j != i and (x[j]-x[i])**2 + (y[j]-y[i])**2 < r*r: sm += p[j]; k += 1
        if k >= 4: sq += (p[i] - sm / k) ** 2; cnt += 1
    res.append(math.sqrt(sq / cnt) / scale)
print("%s noise/rho g H: at 0.1 s %.4f, mean 0.04-0.18 s %.4f, max %.4f (|p(sigma) - p field| at 0.04: %.3g Pa)" % (case, res[3], sum(res)/len(res), max(res), chk))
