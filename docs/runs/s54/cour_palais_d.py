#!/usr/bin/python3
"""Hand estimate (not a measurement), the inverse of docs/runs/s53/cour_palais.py: the
diameter d of a solid sphere that digs a crater of depth P into a semi-infinite Al 2024-T3
target at speed V, by Cour-Palais's semi-infinite cratering equation as used in
Whipple-shield design (Christiansen, 1993):
    P = 5.24 d^(19/18) HB^(-1/4) (rho_p / rho_t)^(1/2) (V / C)^(2/3)   [cm, km/s]
HB = 120 (2024-T3), C = 5.612 km/s and rho_t = 2.78 g/cm3 (Table 5's al-alloy).
usage: cour_palais_d.py RHO_P_g_cm3 V_km_s P_mm..."""
import sys

RHO_T, HB, C = 2.78, 120.0, 5.612
rho_p, v = float(sys.argv[1]), float(sys.argv[2])
for a in sys.argv[3:]:
    p = float(a) / 10
    d = (p / (5.24 * HB ** -0.25 * (rho_p / RHO_T) ** 0.5 * (v / C) ** (2 / 3))) ** (18 / 19)
    m = rho_p * 3.14159265 / 6 * d ** 3 * 1e3     # mg
    print('crater %.1f mm at %.2f km/s: sphere of %.2f mm (%.1f mg) of %.2f g/cm3'
          % (p * 10, v, d * 10, m, rho_p))
