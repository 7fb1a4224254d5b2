# Cavity radius per 10 mm slice: smallest distance of a non-rod particle from the x axis.
# Usage: python3 wallr.py RUNDIR SNAPSHOT_NUMBERS...  (uses tools/rod_floor.py read_vtu)
import sys, numpy as np
sys.path.insert(0, __import__('os').path.join(__import__('os').path.dirname(__import__('os').path.abspath(__file__)), '../../../../tools'))
from rod_floor import read_vtu
d = sys.argv[1]; snaps = [int(a) for a in sys.argv[2:]]
slices = [(0.01,0.02),(0.02,0.03),(0.03,0.04),(0.04,0.05),(0.05,0.06),(0.06,0.07),(0.08,0.09),(0.10,0.11)]
print("slice(mm)  " + "  ".join(f"{a*1e3:.0f}-{b*1e3:.0f}" for a,b in slices))
for s in snaps:
    v = read_vtu(f"{d}/particles_{s:05d}.vtu")
    x = v['x'].reshape(-1,3); body = v['body']
    r = np.hypot(x[:,1], x[:,2]); tg = body != 0
    row = []
    for a,b in slices:
        m = tg & (x[:,0]>a) & (x[:,0]<b)
        rr = np.sort(r[m])
        row.append(f"{rr[0]*1e3:5.1f}" if len(rr) else "  -  ")
    print(f"t={v['TIME']*1e6:5.1f}  " + "  ".join(row))
