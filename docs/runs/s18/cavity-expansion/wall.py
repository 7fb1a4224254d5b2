"""The cavity wall of docs/runs/s18/cavity-expansion/case.yaml over time:
    python3 wall.py RUNDIR
For each particles_NNNNN.vtu: the steel's innermost particle in each of 36 angular
bins, its mean radius less Δ/2 (0.2 mm; min and max over the bins), its mean radial
velocity, and the gas's mean pressure. Needs python3-numpy."""
import glob, os, sys
import numpy as np
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '../../../../tools'))
from rod_floor import read_vtu
for f in sorted(glob.glob(sys.argv[1]+'/particles_*.vtu')):
    d=read_vtu(f); X=d['x'].reshape(-1,3); V=d['v'].reshape(-1,3)
    s=d['body']==1
    x,y=X[s,0],X[s,1]; r=np.hypot(x,y); th=np.arctan2(y,x)
    vr=(V[s,0]*x+V[s,1]*y)/np.maximum(r,1e-12)
    bins=np.linspace(-np.pi,np.pi,37)
    idx=np.digitize(th,bins)
    rin=[]; vin=[]
    for k in range(1,37):
        m=idx==k
        if m.sum():
            j=np.argmin(np.where(m,r,np.inf)); rin.append(r[j]); vin.append(vr[j])
    g=d['body']==0
    pg=d['p'][g].mean()
    print("t=%5.1f us  wall r=%.3f mm (min %.3f max %.3f)  v_wall=%.1f m/s  gas p=%.2f GPa"%(d['TIME']*1e6,(np.mean(rin)-0.2e-3)*1e3,(np.min(rin)-0.2e-3)*1e3,(np.max(rin)-0.2e-3)*1e3,np.mean(vin),pg/1e9))
