import sys, numpy as np
sys.path.insert(0, "/work/main/tools")
from rod_floor import read_vtu
mats = {1: (7810.0, 4900.0, 4.5), 0: (17780.0, 4612.0, 3.54)}
def Ec(rho, rho0, c0, n):
    x = rho / rho0
    return c0**2 / n * ((x**(n - 1) - 1) / (n - 1) - 1 + 1 / x)
for f in sys.argv[1:]:
    d = read_vtu(f)
    print(f"# {f} t={d['TIME']*1e6:.1f} us")
    for b in (0, 1):
        s = d["body"] == b
        m = d["m"][s]; e = d["e"][s]; rho = d["rho"][s]
        eth = e - Ec(rho, *mats[b])
        ke = 0.5 * m * (d["v"][s]**2).sum(1)
        tot_e = (m * e).sum(); tot_th = (m * eth).sum()
        hot = eth > 300e3
        print(f" body {b}: KE {ke.sum():9.1f} J  IE {tot_e:9.1f} J  Eth {tot_th:9.1f} J  "
              f"Eth in eth>300kJ/kg: {(m*eth)[hot].sum():8.1f} J ({hot.sum()} particles, mass {m[hot].sum()*1e3:.2f} g)  "
              f"plastic-work est Y*eps_p*m/rho0: {(m*d['eps_p'][s]).sum()*(0.39e9 if b==1 else 0.983e9)/mats[b][0]:8.1f} J")
