#!/usr/bin/python3
"""Grady's (1982, J. Appl. Phys. 53:322) energy-balance fragment size for a body expanding
at strain rate edot, s = (sqrt(20) K_IC / (rho c edot))^(2/3): an estimate, since K_IC is
not in the paper's tables (ranges assumed below). edot: the debris' expansion rates
measured by cloud_rate.py (tr(A)/3 of the fitted velocity gradient): §2.4's projectile
1.76e5 1/s at 5 us and 9.4e4 at 10 us (session 52's paper-count run, cloud_rate.out),
W.P.2's 1.11e5 at 5 us, 7.85e4 at 10 us and 4.0e4 at 20 us (session 51's,
cloud_rate_wp2.out); §2.4's projectile breaks within 1-5 us, when its rate is higher, so
3e5 is shown too.
§2.4: Table 5's projectile steel (rho0 7700 kg/m3, c0 4760 m/s), K_IC 50-100 MPa m^0.5;
W.P.2: Table 5's al-alloy (2780, 5612), K_IC 25-35 MPa m^0.5 (2024-T3's range)."""
import math
cases = [("§2.4 steel", 7700.0, 4760.0, (50e6, 100e6), (3e5, 1.76e5, 9.4e4)),
         ("W.P.2 aluminium", 2780.0, 5612.0, (25e6, 35e6), (1.11e5, 7.85e4, 4.0e4))]
print('case | K_IC MPa m^0.5 | edot 1/s | s mm')
for name, rho, c, ks, rates in cases:
    for K in ks:
        for edot in rates:
            s = (math.sqrt(20) * K / (rho * c * edot)) ** (2 / 3)
            print('%s | %.0f | %.3g | %.2f' % (name, K / 1e6, edot, s * 1e3))
