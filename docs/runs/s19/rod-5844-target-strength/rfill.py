# Usage: python3 rfill.py RUNDIR SNAPSHOT_NUMBERS...
# Cavity radius per slice from the filled fraction: the smallest r where the target's
# mass in 0.5 mm annuli reaches half of rho0 * annulus volume (and the next annulus too).
import sys, numpy as np
sys.path.insert(0, __import__('os').path.join(__import__('os').path.dirname(__import__('os').path.abspath(__file__)), '../../../../tools'))
from rod_floor import read_vtu
d = sys.argv[1]; snaps = [int(a) for a in sys.argv[2:]]
rho0 = 7810.0; dr = 0.5e-3
slices = [(0.01,0.02),(0.02,0.03),(0.03,0.04),(0.04,0.05),(0.05,0.06),(0.06,0.07)]
print("slice(mm)  " + "  ".join(f"{a*1e3:.0f}-{b*1e3:.0f}" for a,b in slices))
for s in snaps:
    v = read_vtu(f"{d}/particles_{s:05d}.vtu")
    x = v['x'].reshape(-1,3); body = v['body']; m = v['m']
    r = np.hypot(x[:,1], x[:,2]); tg = body != 0
    row = []
    for a,b in slices:
        sel = tg & (x[:,0]>a) & (x[:,0]<b) & (r < 0.03)
        h, e = np.histogram(r[sel], bins=np.arange(0, 0.03+dr, dr), weights=m[sel])
        vol = 0.5*np.pi*(e[1:]**2 - e[:-1]**2)*(b-a)   # half model: z > 0
        f = h/(rho0*vol)
        k = next((i for i in range(len(f)-1) if f[i] > 0.5 and f[i+1] > 0.5), None)
        row.append(f"{e[k]*1e3:5.1f}" if k is not None else "  -  ")
    print(f"t={v['TIME']*1e6:5.1f}  " + "  ".join(row))
