#!/usr/bin/python3
"""Floor speeds of the rod-1929 variants at resolution 0.3 (session 26), and of two rod-5841
ones: the mean speed
of the penetration depth L (measurements.csv, every 5 us) over 10-30 us, 20-30 us and,
where the run goes on, 30-60 us, against the one-dimensional balance for the variant's
strengths (Tate with Y_p = 0.983 GPa and R_t = 1.59 GPa; R_t = 0 for a target without
strength; Bernoulli, u = v / (1 + sqrt(rho_t / rho_p)), for neither).

Usage: floor.py   (in this folder)
docs/validation.md ("The crater floor at 1.29 km/s").
"""
import csv
import os

HERE = os.path.dirname(os.path.abspath(__file__))
RUNS = [  # folder, what, theory (km/s)
    ('case', "the case (Table 2's materials; block 2.5 mm, rod 1.24 mm)", 0.736),
    ('tfluid', 'target without strength or fracture', 0.842),
    ('fluid', 'rod and target without strength or fracture', 0.776),
    ('fluid-c10', '... with a 1.0 mm core joined to the block', 0.776),
    ('fluid-c07', '... with a 0.7 mm core', 0.776),
    ('fluid-c10-long', '... 1.0 mm core, run to 60 us', 0.776),
    ('fluid-c10-a02', '... 1.0 mm core, alpha = 0.2, beta = 0.4', 0.776),
    ('fluid-c10-a0', '... 1.0 mm core, no artificial viscosity', 0.776),
    ('fluid-c10-r064', '... 1.0 mm core, rod 0.64 mm', 0.776),
    ('fluid-c10-xv0', '... 1.0 mm core, no viscosity between rod and target (HV_XVISC=0) *', 0.776),
    ('fluid-c10-xrecon', '... 1.0 mm core, reconstruction between rod and target too (HV_XRECON=1) *',
     0.776),
    ('case-c10', "Table 2's materials, 1.0 mm core", 0.736),
    ('case-c10-a02', "Table 2's materials, 1.0 mm core, alpha = 0.2, beta = 0.4", 0.736),
    ('r41-case-c10', "rod-5841 (2.37 km/s), Table 2's materials, 1.0 mm core", 1.404),
    ('r41-case-c10-a02', "rod-5841, Table 2's materials, 1.0 mm core, alpha = 0.2, beta = 0.4",
     1.404),
]
# * experimental switches in src/sph/sph_solid.c's force pass, not committed (session 26):
#   HV_XVISC scaled the viscosity of pairs of different bodies, HV_XRECON applied the
#   reconstruction to them; run from r29-fluid-c10.yaml with that build.


def depths(folder, q='penetration_depth'):
    out = {}
    with open(os.path.join(HERE, folder, 'measurements.csv')) as f:
        for row in csv.reader(r for r in f if not r.startswith('#')):
            if len(row) > 2 and row[1] == q:
                out[round(float(row[0]) * 1e6)] = float(row[2]) * 1e3
    return out


CHANNEL_HEADER = ("L 10 / 20 / 30 us (mm) | floor 10-30 / 20-30 (km/s) | D_wall_mean 20 / 30 |"
                  " D_wall 20 / 30 | D_mean 20 / 30 (mm)")


def channel_row(folder):
    """Depth at 10 / 20 / 30 us, floor speed and the channel at 20 and 30 us of one run
    (the columns of CHANNEL_HEADER; sessions 31 and 32's eta.py and erode.py)."""
    L = depths(folder, 'penetration_depth')
    M = depths(folder, 'cavity_diameter_wall_mean')
    W = depths(folder, 'cavity_diameter_wall')
    A = depths(folder, 'cavity_diameter_mean')
    return (f"{L[10]:.2f} / {L[20]:.2f} / {L[30]:.2f} | {(L[30] - L[10]) / 20:.3f} /"
            f" {(L[30] - L[20]) / 10:.3f} | {M[20]:.2f} / {M[30]:.2f} | {W[20]:.2f} / {W[30]:.2f} |"
            f" {A[20]:.2f} / {A[30]:.2f}")


def main():
    print("variant | L at 10 / 20 / 30 us (mm) | u 10-30 | u 20-30 | u 30-60 us (km/s) | theory |"
          " u 10-30 / theory | steps to 30 us (60 for the long run)")
    for folder, what, th in RUNS:
        L = depths(folder)
        W = depths(folder, 'cavity_diameter_wall')
        M = depths(folder, 'cavity_diameter_wall_mean')
        u1 = (L[30] - L[10]) / 20
        u2 = (L[30] - L[20]) / 10
        u3 = f"{(L[60] - L[30]) / 30:.3f}" if 60 in L else "-"
        steps = open(os.path.join(HERE, folder, 'run_segments.csv')).read().strip().split('\n')[-1]
        steps = steps.split(',')[6]
        print(f"{what} | {L[10]:.2f} / {L[20]:.2f} / {L[30]:.2f} | {u1:.3f} | {u2:.3f} | {u3} |"
              f" {th:.3f} | {u1 / th - 1:+.1%} | {steps} steps" + (f" | D_wall 30 us {W[30]:.2f} mm, D_wall_mean {M[30]:.2f} mm"
                                               if 'case-' in folder else ""))


if __name__ == '__main__':
    main()
