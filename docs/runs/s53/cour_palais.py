#!/usr/bin/python3
"""Hand estimate (not a measurement): the depth of the crater a solid steel sphere of
diameter d makes in a semi-infinite Al 2024-T3 target at speed V, by Cour-Palais's
semi-infinite cratering equation as used in Whipple-shield design (Christiansen, 1993):
    P = 5.24 d^(19/18) HB^(-1/4) (rho_p / rho_t)^(1/2) (V / C)^(2/3)   [cm, km/s]
HB the target's Brinell hardness (2024-T3: 120), C its sound speed (Table 5's c0).
usage: cour_palais.py [V_km_s] d_mm..."""
import sys

RHO_P, RHO_T, HB, C = 7.85, 2.78, 120.0, 5.612
v = float(sys.argv[1]) if len(sys.argv) > 1 else 5.5
for a in (sys.argv[2:] or ['0.3', '0.6', '1.0', '1.57']):
    d = float(a) / 10
    p = 5.24 * d ** (19 / 18) * HB ** -0.25 * (RHO_P / RHO_T) ** 0.5 * (v / C) ** (2 / 3)
    m = 7.85e3 * 3.14159265 / 6 * d ** 3        # mg: g/cm3 * cm3 * 1e3
    print('d %.2f mm (%.2f mg) at %.2f km/s: crater depth %.2f mm' % (d * 10, m, v, p * 10))
