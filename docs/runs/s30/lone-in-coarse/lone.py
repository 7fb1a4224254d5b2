#!/usr/bin/python3
"""The lone particle (body 0) of lone-in-coarse / lone-in-fine at each output: x, vx, rho/rho0, p.
Usage: lone.py OUTDIR"""
import glob, sys
import numpy as np
for f in sorted(glob.glob(sys.argv[1] + '/particles_*.csv')):
    t = float(open(f).readline().split(' time ')[1].split()[0])
    lines = open(f).readlines()
    hdr = lines[2].strip().split(',')
    c = {k: i for i, k in enumerate(hdr)}
    d = np.loadtxt(lines[3:], delimiter=',', ndmin=2)
    k = np.where(d[:, c['body']] == 0)[0][0]
    print('t %5.2f us  x %6.3f mm  vx %6.0f m/s  rho/rho0 %.3f  p %8.3g GPa' % (
        t * 1e6, d[k, c['x']] * 1e3, d[k, c['vx']], d[k, c['rho']] / 7850.0, d[k, c['p']] / 1e9))
