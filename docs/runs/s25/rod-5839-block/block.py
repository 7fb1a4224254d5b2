"""rod-5839 at the paper's counts: where the target's kinetic energy and momentum go.

Reads the run's CSV snapshots (hvsph validate --scale 1 --only rod-5839, the run archived
in docs/runs/s23/rod-5839) and prints, for each: the target's volume-weighted mean
pressure, its momentum and mass-mean axial velocity, the kinetic energy of target and
rod, the target material in front of the block's original face (x < -2 mm: mass, KE,
mean axial velocity, farthest point) and the fraction of split target particles.

    /usr/bin/python3 block.py RUNDIR/particles_0000[0-7].csv > block.txt
"""
import sys
import numpy as np


def load(path):
    with open(path) as fh:
        head = [fh.readline() for _ in range(3)]
    data = np.loadtxt(path, delimiter=',', skiprows=3)
    cols = head[2].strip().split(',')
    return head[0].split()[-4], {c: data[:, i] for i, c in enumerate(cols)}


print("time_us  p_mean_GPa  px_target  px_rod  vx_target_mean  KE_target_kJ  KE_rod_kJ"
      "  front_mass_g  front_KE_kJ  front_vx_mean  front_min_x_mm  split_frac")
for path in sys.argv[1:]:
    t, p = load(path)
    tgt = p['mat'] == 1
    vol = p['m'] / p['rho']
    px = p['m'] * p['vx']
    ke = 0.5 * p['m'] * (p['vx']**2 + p['vy']**2 + p['vz']**2)
    front = tgt & (p['x'] < -2e-3)
    mf = p['m'][front].sum()
    print(f"{float(t)*1e6:7.1f}  {(p['p']*vol)[tgt].sum()/vol[tgt].sum()/1e9:10.3f}"
          f"  {px[tgt].sum():9.1f}  {px[~tgt].sum():6.1f}  {px[tgt].sum()/p['m'][tgt].sum():14.1f}"
          f"  {ke[tgt].sum()/1e3:12.1f}  {ke[~tgt].sum()/1e3:9.1f}  {mf*1e3:12.0f}"
          f"  {ke[front].sum()/1e3:11.2f}  {(px[front].sum()/mf if mf > 0 else 0):13.1f}"
          f"  {(p['x'][front].min()*1e3 if mf > 0 else 0):14.1f}  {(p['damage'][tgt] >= 1).mean():10.2f}")
