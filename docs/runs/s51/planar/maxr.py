import sys, glob, numpy as np
sys.path.insert(0, __import__("os").path.join(__import__("os").path.dirname(__import__("os").path.abspath(__file__)), "..")); import vtu
for d in sys.argv[1:]:
    fs = sorted(glob.glob(d + "/particles_*.csv"))
    worst = 0; cnt = 0; last = None
    for f in fs[1:]:
        a = vtu.read_csv(f); s = a["body"] == 1
        r = a["rho"][s] / 2780.0
        worst = max(worst, r.max()); cnt = max(cnt, (r > 2).sum())
        last = a
    print("%s: %d snapshots, plate max rho %.2f rho0, at most %d plate particles above 2 rho0 in one snapshot" % (d, len(fs), worst, cnt))
