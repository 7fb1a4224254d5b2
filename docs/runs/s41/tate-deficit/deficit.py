#!/usr/bin/python3
"""Tate's model (session 26's docs/runs/s26/tate/tate.py, imported; its depth() takes the
deficit as `delta` since session 41, its own output unchanged) with the
head's speed taken short by a fraction delta of the balance's: u = (1 - delta) u_Tate(v),
as the SPH stagnation flow without strength leaves it (the floor's deficit against
Bernoulli measured in the fluid runs of sessions 9, 26 and 41). Table 2's materials,
R_t = 1.59 GPa (Hill's cylindrical cavity pressure for its steel).

How a floor deficit reaches the depth: in steady penetration L/l = u/(v - u), so
dL/L = du/u (1 + u/(v - u)): 2.3-2.5 times the floor's deficit for tungsten into steel.

Usage: deficit.py   (writes deficit.txt beside it). Session 41, docs/validation.md.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', '..', 's26', 'tate'))
sys.path.insert(0, os.path.join(HERE, '..', '..', '..', '..', 'tools'))
import meas_csv  # noqa: E402
import tate  # noqa: E402


def main():
    rt = 1.59e9
    lines = ['test | v km/s | delta | L Tate mm | L Tate, head (1 - delta) mm | change |'
             ' L hvsph (paper counts) mm | L experiment mm']
    # delta: 0.033 at 4.46 km/s (session 9: rod-5844 without strength, res 0.3, 1.0 mm core);
    # 0.151 and 0.187 at 1.29 km/s (session 26: rod-1929 without strength, 1.0 mm core,
    # over 10-30 and 30-60 us)
    for test, delta in (('5844', 0.033), ('1929', 0.151), ('1929', 0.187)):
        v, l, lexp, _ = tate.RODS[test]
        l0 = tate.depth(v, l, rt) * 1e3
        l1 = tate.depth(v, l, rt, delta=delta) * 1e3
        lines.append(f'{test} | {v / 1e3:.2f} | {delta:.3f} | {l0:.1f} | {l1:.1f} |'
                     f' {100 * (l1 / l0 - 1):+.1f}% | {tate.HVSPH[test] * 1e3:.1f} | {lexp * 1e3:.1f}')
    meas_csv.emit(os.path.join(HERE, 'deficit.txt'), lines)


if __name__ == '__main__':
    main()
