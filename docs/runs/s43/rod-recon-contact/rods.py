#!/usr/bin/python3
"""Session 43: rod-1929 and rod-5841 at resolution 0.3 with the 1.0 mm core (session
26's r29-case-c10.yaml and r41-case-c10.yaml: Table 2's materials, alpha = 1, the
reconstruction), with and without sph.viscosity.reconstruct_contact; L and D_wall at
every output.  rod-1929 without it: r29-base60 (run again here to 60 us; to 30 us it
repeats session 26's case-c10 to the digit); rod-5841 without it: session 26's
r41-case-c10.  Then the share of split particles (damage 1) among the rod's and the
target's particles within 2 mm (along x) of the rod's tip and 5 mm of the axis, in
r29-rc's snapshots at 30 and 60 us when they are at hand (out/s43/r29-rc).
Usage: /usr/bin/python3 rods.py > rods.txt (in this folder).  docs/validation.md,
"The floor at 1.29 km/s: the viscosity between the bodies (session 43)".
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', '..', '..', 'tools'))
import meas_csv  # noqa: E402

S26 = os.path.join(HERE, '..', '..', 's26', 'rod-1929-floor')
PAIRS = [('rod-1929, 1.29 km/s', os.path.join(HERE, 'r29-base60'), os.path.join(HERE, 'r29-rc')),
         ('rod-5841, 2.37 km/s', os.path.join(S26, 'r41-case-c10'), os.path.join(HERE, 'r41-rc'))]
Q = ['penetration_depth', 'cavity_diameter_wall']

for name, base, rc in PAIRS:
    b = meas_csv.read(os.path.join(base, 'measurements.csv'), Q)
    r = meas_csv.read(os.path.join(rc, 'measurements.csv'), Q)
    print(f'{name}: t us | L without / with (mm, ratio) | D_wall without / with (mm)')
    for t in sorted(set(b) & set(r)):
        if t == 0:
            continue
        Lb, Lr = b[t]['penetration_depth'], r[t]['penetration_depth']
        Db, Dr = (b[t].get('cavity_diameter_wall', 0), r[t].get('cavity_diameter_wall', 0))
        print(f'  {t:5.1f} | {Lb:6.2f} / {Lr:6.2f} ({Lr / Lb:.4f}) | {Db:6.2f} / {Dr:6.2f}')
    print()

RUN = os.path.join(HERE, '..', '..', '..', '..', 'out', 's43', 'r29-rc')
if os.path.isdir(RUN):
    import numpy as np
    import rod_floor
    for f in ('particles_00006.vtu', 'particles_00012.vtu'):
        d = rod_floor.read_vtu(os.path.join(RUN, f))
        x = d['x'].reshape(-1, 3)
        rod = d['body'] == 0
        tip = np.sort(x[rod, 0])[-5:].mean()
        near = (np.abs(x[:, 0] - tip) < 2e-3) & (np.hypot(x[:, 1], x[:, 2]) < 5e-3)
        out = [f'{f} (t = {float(d["TIME"]) * 1e6:.0f} us):']
        for who, sel in (('rod', near & rod), ('target', near & ~rod)):
            out.append(f'{who} {sel.sum()} particles, {100 * (d["damage"][sel] >= 1).mean():.0f} % split')
        print(' '.join(out))
