import sys, numpy as np
import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '../../../../tools'))
from rod_floor import read_vtu
for f in sys.argv[1:]:
    v = read_vtu(f)
    x = v['x'].reshape(-1,3); dam = v['damage']; body = v['body']; vel=v['v'].reshape(-1,3); p=v['p']
    S = v['S'].reshape(-1,6) if 'S' in v else None
    rod = body == 0
    r = np.hypot(x[:,1], x[:,2])
    tip = np.percentile(x[rod,0], 99.9)
    core = rod & (r < 2.4e-3)
    print(f, "t", v['TIME']*1e6, "tip", round(tip*1e3,1), "rod core particles", core.sum(), "split", round(np.mean(dam[core]>=1),3))
    out = []
    for a in range(0, 130, 10):
        m = core & (x[:,0] < tip - a*1e-3) & (x[:,0] >= tip - (a+10)*1e-3)
        if m.sum(): out.append(f"{a}-{a+10}:{np.mean(dam[m]>=1):.2f}")
    print("   split fraction by mm behind tip:", " ".join(out))
