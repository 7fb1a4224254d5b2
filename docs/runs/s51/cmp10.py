# cmp10.py SNAPSHOT...: per body, W.P.3 at a snapshot: momentum, mass behind the second bumper (x > 61.3 mm),
# mass moving back between the bumpers; the second bumper's particles above 1.2 rho0 and 10 GPa (session 51)
import sys, numpy as np
sys.path.insert(0, __import__("os").path.dirname(__import__("os").path.abspath(__file__))); import vtu
RHO0 = 2785.0
for f in sys.argv[1:]:
    d = vtu.load(f); b = d["body"].astype(int); m = d["m"]; vx = d["vx"]; x = d["x"]; r = np.hypot(d["y"], d["z"])
    print("== %s t=%.2f us" % (f.split("/")[-2], d["t"]*1e6))
    beh = x > 0.0613
    for bb in (0, 1, 2, 3):
        s = b == bb
        if bb == 3:
            hi = s & (d["rho"] > 1.2*RHO0)
            print("  bumper2: P %.1f; behind 61.3 mm %.1f mg; vx>1 km/s %.2f mg (P %.2f); rho>1.2rho0: %d particles, max %.2f rho0; p>10 GPa: %d" % ((m[s]*vx[s]).sum()*1e3, m[s&beh].sum()*1e6, m[s&(vx>1000)].sum()*1e6, (m[s&(vx>1000)]*vx[s&(vx>1000)]).sum()*1e3, hi.sum(), d["rho"][s].max()/RHO0, (s & (d["p"]>1e10)).sum()))
        else:
            fw = s & (x > 0.01)
            print("  body %d: P %.1f; behind bumper2 %.2f mg (P %.2f); between, moving back %.2f mg (P %.2f); rho>1.2rho0: %d" % (bb, (m[s]*vx[s]).sum()*1e3, m[s&beh].sum()*1e6, (m[s&beh]*vx[s&beh]).sum()*1e3, m[fw & ~beh & (vx<0)].sum()*1e6, (m[fw&~beh&(vx<0)]*vx[fw&~beh&(vx<0)]).sum()*1e3, (s & (d["rho"]>1.2*RHO0)).sum()))
