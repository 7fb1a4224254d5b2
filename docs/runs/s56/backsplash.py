#!/usr/bin/python3
"""Back-splash coming back from the face in front of the bumper: for each particles_*.csv of a
run folder, the mass at x < -2 mm moving +x faster than 100 m/s (half model: x2), its mean
v_x and nearest x. usage: backsplash.py RUNDIR"""
import sys, glob, numpy as np
for f in sorted(glob.glob(sys.argv[1] + '/particles_*.csv'))[1:]:
    lines = open(f).read().splitlines()
    t = float(lines[0].split('time ')[1].split(' s')[0])
    hdr = [l for l in lines if not l.startswith('#')][0].split(',')
    c = {k: i for i, k in enumerate(hdr)}
    d = np.array([list(map(float, l.split(','))) for l in lines if l and not l.startswith('#') and not l.startswith('id')])
    x = d[:, c['x']]; vx = d[:, c['vx']]; m = d[:, c['m']]; mat = d[:, c['mat']]
    ret = (x < -0.002) & (vx > 100)
    print('t=%6.2f us  back-splash returning (x<-2mm, vx>100 m/s): %.4g g, mean vx %.0f m/s, nearest x %.1f mm; mass within 2 mm in front of bumper moving +x: %.4g g' % (
        t*1e6, 2*m[ret].sum()*1e3, (m[ret]*vx[ret]).sum()/max(m[ret].sum(),1e-30), x[ret].max()*1e3 if ret.any() else float('nan'),
        2*m[(x > -0.002) & (x < 0) & (vx > 100)].sum()*1e3))
