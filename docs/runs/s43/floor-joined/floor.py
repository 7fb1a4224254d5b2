#!/usr/bin/python3
"""Session 43: session 41's wide free test at 1.29 km/s (free129.yaml: tungsten into
tungsten without strength, where a steady floor moves at v/2 = 0.645 km/s), alpha = 1,
with the rod joined to the core, and with the viscosity's reconstruction for the pairs
of the two bodies (study.patch's HV_RECON_ALL, what sph.viscosity.reconstruct_contact
does since c090c53), beside session 41's runs with alpha = 1 and alpha = 0.2 (its
folders free-a1, free-a02). Penetration depth L from measurements.csv; speeds as
session 41's free.py (end points, then least-squares slopes).

Usage: /usr/bin/python3 floor.py   (in this folder; writes floor.txt). docs/validation.md,
"The floor at 1.29 km/s: the viscosity between the bodies (session 43)".
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
S41 = os.path.join(HERE, '..', '..', 's41', 'floor-free')
sys.path.insert(0, os.path.join(HERE, '..', '..', '..', '..', 'tools'))
sys.path.insert(0, S41)
import free  # noqa: E402
import meas_csv  # noqa: E402

RUNS = [  # folder, v (km/s), what
    (os.path.join(S41, 'free-a1'), 1.29, 'alpha = 1, beta = 2 (the cases; session 41)'),
    (os.path.join(S41, 'free-a02'), 1.29, 'alpha = 0.2, beta = 0.4 (session 41)'),
    (os.path.join(HERE, 'free-a1-joined'), 1.29, 'alpha = 1, the rod joined to the core (part_of)'),
    (os.path.join(HERE, 'free-a1-reconall'), 1.29,
     'alpha = 1, the reconstruction for the pairs of the two bodies too (reconstruct_contact)'),
    (os.path.join(HERE, 'free-a1-recongrad'), 1.29,
     '... and each gradient over both bodies (HV_GRAD_ALL), to 30 us'),
    (os.path.join(HERE, 'free-a1-densall'), 1.29,
     'alpha = 1, bodies apart, the contact density rule off (HV_DENS_ALL), to 30 us'),
]
SPANS = [(10, 30), (20, 30), (30, 50), (30, 45), (10, 50)]


def main():
    lines, fits = free.speed_tables(RUNS, SPANS, (10, 20, 30, 50))
    meas_csv.emit(os.path.join(HERE, 'floor.txt'), lines + [''] + fits)


if __name__ == '__main__':
    main()
