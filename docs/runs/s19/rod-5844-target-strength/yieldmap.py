# Radial bins (2 mm) of target particles between depths XA and XB [m]: sqrt(3 J2)/Y, p,
# S_rr - S_tt, radial speed, eps_p.  Usage: python3 yieldmap.py RUNDIR SNAP Y[Pa] XA XB
import sys, numpy as np
sys.path.insert(0, __import__('os').path.join(__import__('os').path.dirname(__import__('os').path.abspath(__file__)), '../../../../tools'))
from rod_floor import read_vtu
d, s, Y = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
xa, xb = float(sys.argv[4]), float(sys.argv[5])
v = read_vtu(f"{d}/particles_{s:05d}.vtu")
x = v['x'].reshape(-1,3); S = v['S'].reshape(-1,6); p = v['p']; body = v['body']; vel = v['v'].reshape(-1,3)
print("t =", v['TIME']*1e6, "us")
r = np.hypot(x[:,1], x[:,2])
J2 = 0.5*(S[:,0]**2+S[:,1]**2+S[:,2]**2) + S[:,3]**2+S[:,4]**2+S[:,5]**2
seq = np.sqrt(3*J2)
# radial and hoop components of S
c = x[:,1]/np.maximum(r,1e-12); sn = x[:,2]/np.maximum(r,1e-12)
Srr = S[:,1]*c*c + S[:,2]*sn*sn + 2*S[:,5]*c*sn
Stt = S[:,1]*sn*sn + S[:,2]*c*c - 2*S[:,5]*c*sn
vr = vel[:,1]*c + vel[:,2]*sn
tg = body == 1
for ra in np.arange(0, 0.04, 0.002):
    m = tg & (x[:,0] > xa) & (x[:,0] < xb) & (r >= ra) & (r < ra+0.002)
    if m.sum() == 0: continue
    print(f"r {ra*1e3:4.0f}-{(ra+0.002)*1e3:4.0f} n {m.sum():4d} seq/Y {np.mean(seq[m])/Y:5.2f} p {np.mean(p[m])/1e9:6.2f} GPa  Srr-Stt {np.mean(Srr[m]-Stt[m])/1e9:6.3f}  vr {np.mean(vr[m]):7.1f}  eps_p {np.mean(v['eps_p'][m]):.3f}")
