import sys, numpy as np
import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '../../../../tools'))
from rod_floor import read_vtu
for f in sys.argv[1:]:
    v = read_vtu(f)
    x = v['x'].reshape(-1,3); body = v['body']; p = v['p']; S = v['S'].reshape(-1,6); vel = v['v'].reshape(-1,3)
    rod = body == 0; r = np.hypot(x[:,1], x[:,2]); core = rod & (r < 2.4e-3)
    tip = np.percentile(x[rod,0], 99.9)
    print(f, "t", round(v['TIME']*1e6,1), "tip", round(tip*1e3,1))
    # S order: assume xx yy zz xy yz xz
    for a in range(0, 130, 10):
        m = np.where(core & (x[:,0] < tip - a*1e-3) & (x[:,0] >= tip - (a+10)*1e-3))[0]
        if len(m) == 0: continue
        s1 = []
        sxx = []
        for i in m:
            s = S[i]
            T = np.array([[s[0]-p[i], s[3], s[5]], [s[3], s[1]-p[i], s[4]], [s[5], s[4], s[2]-p[i]]])
            s1.append(np.linalg.eigvalsh(T)[-1]); sxx.append(T[0,0])
        s1 = np.array(s1)/1e9; sxx=np.array(sxx)/1e9
        print(f"  {a:3d}-{a+10:3d} mm: n {len(m):4d} sigma1 max {s1.max():6.2f} p95 {np.percentile(s1,95):6.2f} med {np.median(s1):6.2f} GPa; sxx med {np.median(sxx):6.2f}; vx med {np.median(vel[m,0]):6.0f}")
