"""First contact of the debris with the backwall: per snapshot, the closest approach of a
debris particle (bodies 0-2) to a backwall particle (bodies 3-4), in units of the pair's
mean h and of the backwall's lattice spacing, and the debris' approach speed there."""
import glob, sys
import numpy as np
from scipy.spatial import cKDTree

def load(path):
    with open(path) as f:
        t = float(f.readline().split(' time ')[1].split()[0])
        f.readline()
        names = f.readline().strip().split(',')
    d = np.loadtxt(path, delimiter=',', skiprows=3)
    return t, {n: d[:, k] for k, n in enumerate(names)}

rows = []
for path in sorted(glob.glob(sys.argv[1] + '/particles_*.csv')):
    t, c = load(path)
    deb = c['body'] <= 2
    bw = c['body'] >= 3
    near = deb & (c['x'] > 0.185)
    if near.sum() == 0:
        print('%.2f us: no debris beyond 185 mm' % (t * 1e6)); continue
    X = np.stack([c['x'], c['y'], c['z']], 1)
    tree = cKDTree(X[bw])
    di, jj = tree.query(X[near])
    hb = c['h'][bw][jj]; hd = c['h'][near]
    ratio = di / (0.5 * (hb + hd))
    k = np.argmin(ratio)
    vx = c['vx'][near]
    lead = c['x'][near].max()
    # how many debris particles lie within 0.5 mean-h of a backwall particle
    close = (ratio < 0.5).sum()
    print('%.2f us: lead x %.2f mm, closest r/h %.3f (r %.3f mm, h_d %.3f h_bw %.3f mm, vx %.0f m/s), %d debris within 0.5 h, debris beyond 185 mm %d'
          % (t * 1e6, lead * 1e3, ratio[k], di[k] * 1e3, hd[k] * 1e3, hb[k] * 1e3, vx[k], close, near.sum()))
