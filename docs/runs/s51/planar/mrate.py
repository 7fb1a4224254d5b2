import sys, glob, numpy as np
sys.path.insert(0, __import__("os").path.join(__import__("os").path.dirname(__import__("os").path.abspath(__file__)), "..")); import vtu
import os
A = float(os.environ.get("AREA", "3.24e-6"))
for d, pex in zip(sys.argv[1::2], sys.argv[2::2]):
    T, P = [], []
    for f in sorted(glob.glob(d + "/particles_*.csv")):
        a = vtu.read_csv(f); s = a["body"] == 1
        T.append(a["t"]); P.append((a["m"][s]*a["vx"][s]).sum())
    T, P = np.array(T), np.array(P)
    k = T >= 0.1e-6 - 1e-12
    sl = np.polyfit(T[k], P[k], 1)[0]
    k2 = T >= 0.2e-6 - 1e-12
    sl2 = np.polyfit(T[k2], P[k2], 1)[0]
    print("%s: force %.4g N (from 0.1 us), %.4g (from 0.2 us), exact p A %.4g: %+.2f %% / %+.2f %%" % (d, sl, sl2, float(pex)*A, 100*(sl/(float(pex)*A)-1), 100*(sl2/(float(pex)*A)-1)))
