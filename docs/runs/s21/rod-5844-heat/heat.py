#!/usr/bin/env python3
"""Target state near the cavity wall: thermal energy above the cold curve, by depth and radius."""
import sys, numpy as np
sys.path.insert(0, "/work/main/tools")
from rod_floor import read_vtu
rho0, c0, n, G = 7810.0, 4900.0, 4.5, 1.8
def Ec(rho):
    x = rho / rho0
    return c0**2 / n * ((x**(n - 1) - 1) / (n - 1) - 1 + 1 / x)
def pc(rho):
    return rho0 * c0**2 / n * ((rho / rho0)**n - 1)
f = sys.argv[1]
slabs = [float(s) for s in sys.argv[2].split(",")] if len(sys.argv) > 2 else [10, 20, 30, 40]
body = int(sys.argv[3]) if len(sys.argv) > 3 else 1
d = read_vtu(f)
t = d["TIME"] * 1e6
x = d["x"] * 1e3
sel = d["body"] == body
rod = d["body"] == 0
print(f"# {f} t = {t:.1f} us, tip {np.sort(x[rod,0])[-5:].mean():.1f} mm")
r = np.hypot(x[:, 1], x[:, 2])
vr = (d["v"][:, 1] * x[:, 1] + d["v"][:, 2] * x[:, 2]) / np.maximum(r, 1e-9)
rho, e, p = d["rho"], d["e"], d["p"]
eth = e - Ec(rho)
for a, b in zip(slabs[:-1], slabs[1:]):
    print(f"## depth {a:.0f}-{b:.0f} mm")
    print("  r[mm]   N  rho/rho0  e[kJ/kg] eth[kJ/kg] p[GPa] pth[GPa] eps_p  dmg  vr[m/s]")
    for r0 in np.arange(0, 30, 1.5):
        m = sel & (x[:, 0] >= a) & (x[:, 0] < b) & (r >= r0) & (r < r0 + 1.5)
        if m.sum() == 0: continue
        md = lambda q: np.median(q[m])
        print(f"  {r0:4.1f} {m.sum():4d}  {md(rho)/rho0:6.3f}  {md(e)/1e3:8.1f}  {md(eth)/1e3:8.1f}  "
              f"{md(p)/1e9:6.2f}  {md(G*rho*eth)/1e9:6.2f}  {md(d['eps_p']):5.2f} {md(d['damage']):4.2f} {md(vr):7.0f}")
