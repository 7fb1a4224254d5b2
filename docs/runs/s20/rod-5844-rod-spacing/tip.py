# Usage: python3 tip.py SNAPSHOT.vtu...
# Profiles behind the tip: per 2 mm slice behind the deepest tungsten: wall radius by
# filled volume (particle volume m/rho, 0.25 mm annuli), tungsten r95 and r_max,
# target radial speed in the 1.5 mm inside the wall.
import sys, numpy as np
import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '../../../../tools'))
from rod_floor import read_vtu
for f in sys.argv[1:]:
    v = read_vtu(f)
    x = v['x'].reshape(-1,3); body = v['body']; m = v['m']; rho = v['rho']; vel = v['v'].reshape(-1,3)
    r = np.hypot(x[:,1], x[:,2]); w = body == 0; tg = ~w
    tip = np.percentile(x[w,0], 99.9)
    print(f"{f}: t = {v['TIME']*1e6:.1f} us, tip {tip*1e3:.1f} mm")
    print("  behind(mm)  wall_r  W_r95  W_rmax  vr_wall(m/s)")
    dr = 0.25e-3
    for a in np.arange(0, 0.024, 0.002):
        x1 = tip - a; x0 = x1 - 0.002
        sel = tg & (x[:,0] > x0) & (x[:,0] < x1) & (r < 0.03)
        h, e = np.histogram(r[sel], bins=np.arange(0, 0.03 + dr, dr), weights=m[sel]/rho[sel])
        vol = 0.5*np.pi*(e[1:]**2 - e[:-1]**2)*0.002
        fr = h/vol
        # smooth over 4 bins (1 mm) against lattice noise
        fr = np.convolve(fr, np.ones(4)/4, mode='same')
        k = next((i for i in range(len(fr)-1) if fr[i] > 0.5 and fr[i+1] > 0.5), None)
        wr = e[k]*1e3 if k is not None else float('nan')
        ws = w & (x[:,0] > x0) & (x[:,0] < x1)
        r95 = np.percentile(r[ws], 95)*1e3 if ws.sum() > 3 else float('nan')
        rmx = r[ws].max()*1e3 if ws.any() else float('nan')
        ring = sel & (np.abs(r*1e3 - wr - 0.75) < 0.75)
        vr = ((vel[ring,1]*x[ring,1] + vel[ring,2]*x[ring,2])/r[ring]).mean() if ring.any() else float('nan')
        print(f"  {a*1e3:4.0f}-{a*1e3+2:2.0f}   {wr:6.2f}  {r95:6.2f}  {rmx:6.2f}  {vr:7.0f}")
