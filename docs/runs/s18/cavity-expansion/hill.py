"""Hill's quasi-static cylindrical cavity in elastic-perfectly-plastic, incompressible
material (plane strain): the pressure to hold a cavity expanded from a0 to a,
    p = k (1 - c^2/b^2 + ln(c^2/a^2)),  c^2 = (G/k)(a^2 - a0^2),  k = Y/sqrt(3)
(elastic while c < a, fully plastic 2k ln(b/a) once c > b), against a gas of
p0 (a0/a)^(2 gamma): the static equilibrium, and the radius where the gas's work equals
the work of expansion. The case: docs/runs/s18/cavity-expansion/case.yaml. Needs
python3-numpy and python3-scipy."""
import numpy as np
from scipy.integrate import quad
from scipy.optimize import brentq
G=95e9; Y=2e9; k=Y/np.sqrt(3); b=30e-3; a0=2e-3; gam=1.4
def p_hill(a):
    c2=(G/k)*(a*a-a0*a0)
    if c2<=a*a: # elastic: p = 2G (a^2-a0^2)/(2a^2)?  incompressible elastic: p = G (1 - a0^2/a^2)(1 - a^2/b^2)
        return G*(1-a0*a0/(a*a))
    if c2>=b*b: return 2*k*np.log(b/a)
    return k*(1-c2/(b*b)+np.log(c2/(a*a)))
def Wh(a): return quad(lambda x: p_hill(x)*2*np.pi*x, a0, a, limit=200)[0]
for p0 in [10e9,15e9,20e9,30e9]:
    Wg=lambda a: 2*np.pi*p0*a0**2*(1-(a0/a)**(2*gam-2))/(2*gam-2)
    f=lambda a: Wg(a)-Wh(a)
    try:
        am=brentq(f,a0*1.0001,b*0.9)
    except Exception as e:
        am=float('nan')
    # static equilibrium
    g=lambda a: p0*(a0/a)**(2*gam)-p_hill(a)
    try: ae=brentq(g,a0*1.0001,b*0.9)
    except Exception: ae=float('nan')
    print("p0 %.0f GPa: energy a_max %.3f mm, static equilibrium a %.3f mm, p_hill(a_max) %.2f GPa"%(p0/1e9,am*1e3,ae*1e3,p_hill(am)/1e9))
print("limit pressure (b inf) k(1+ln(G/k)) = %.2f GPa"%(k*(1+np.log(G/k))/1e9))
