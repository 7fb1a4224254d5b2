#!/usr/bin/python3
"""Session 44: session 41's wide free test at 1.29 km/s (free129.yaml: tungsten into
tungsten without strength, where a steady floor moves at v/2 = 0.645 km/s), alpha = 1,
the reconstruction across the contact (sph.viscosity.reconstruct_contact) and the pairs
of the two bodies exchanging their whole pressures, tension included (study.patch's
HV_CT=1) or their sum clipped at 0 (HV_CT=2); density diffusion (HV_DDIFF=0.1, what
sph.density_diffusion does since e823530); the standard viscosity everywhere, with and
without every body split from the start; beside session 43's runs: the rod joined to the core, and the reconstruction
across the contact alone (its folders free-a1-joined, free-a1-reconall), and session
41's alpha = 1 (free-a1). Speeds as session 41's free.py.

Usage: /usr/bin/python3 floor.py   (in this folder; writes floor.txt). docs/validation.md,
"The floor at 1.29 km/s: tension across the contact (session 44)".
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
S41 = os.path.join(HERE, '..', '..', 's41', 'floor-free')
S43 = os.path.join(HERE, '..', '..', 's43', 'floor-joined')
sys.path.insert(0, os.path.join(HERE, '..', '..', '..', '..', 'tools'))
sys.path.insert(0, S41)
import free  # noqa: E402
import meas_csv  # noqa: E402

RUNS = [  # folder, v (km/s), what
    (os.path.join(S41, 'free-a1'), 1.29, 'alpha = 1, beta = 2 (the cases; session 41)'),
    (os.path.join(S43, 'free-a1-joined'), 1.29, 'the rod joined to the core (session 43)'),
    (os.path.join(S43, 'free-a1-reconall'), 1.29,
     'bodies apart, reconstruct_contact (session 43)'),
    (os.path.join(HERE, 'free-a1-ct'), 1.29,
     'bodies apart, reconstruct_contact, tension across the contact (HV_CT=1), to 30 us'),
    (os.path.join(HERE, 'free-a1-ct2'), 1.29,
     'bodies apart, reconstruct_contact, the pair sum clipped at 0 (HV_CT=2), to 30 us'),
    (os.path.join(HERE, 'free-a1-dd01'), 1.29,
     'the cases\' rules, density diffusion delta = 0.1, to 30 us'),
    (os.path.join(HERE, 'free-a1-norecon'), 1.29,
     'the standard viscosity everywhere (reconstruct: false), to 30 us'),
    (os.path.join(HERE, 'free-a1-split'), 1.29,
     '... every body split from the start (free129-split.yaml), to 30 us'),
    (os.path.join(HERE, 'free-a1-split-dd01'), 1.29,
     '... split, density diffusion 0.1 (000984d, before the rho0/2 bound), to 30 us'),
    (os.path.join(HERE, 'free-a02-split'), 1.29,
     '... split, alpha = 0.2, beta = 0.4, to 30 us'),
]
SPANS = [(10, 20), (10, 30), (20, 30), (30, 50)]


def main():
    lines, fits = free.speed_tables(RUNS, SPANS, (10, 20, 30, 50))
    meas_csv.emit(os.path.join(HERE, 'floor.txt'), lines + [''] + fits)


if __name__ == '__main__':
    main()
