#!/usr/bin/python3
"""Tate's (1967) one-dimensional eroding-rod model for the six rods of Table 1, with the
paper's materials (Table 2): the final penetration depth it gives for a target
resistance R_t, and the R_t that would give the experiment's depth (Table 3).

  rod:  rho_p dv/dt = -Y_p / l          (the rigid rear of the rod decelerates)
        dl/dt = -(v - u)               (the rod erodes at its head)
  head: 1/2 rho_p (v - u)^2 + Y_p = 1/2 rho_t u^2 + R_t
integrated (steps of 10 ns) until the rod is used up or stopped; where the balance gives
u >= v (Y_p > R_t at low speed) the rod moves on as a rigid body, rho_p l dv/dt = -R_t.
The depth the experiment reached needs the R_t printed (bisection); "-" where even R_t =
0.1 GPa falls short (the experiment is past Tate's hydrodynamic limit, its afterflow and
the rod's fragments going deeper than the balance allows).
R_t = 1.59 GPa is Hill's cylindrical cavity pressure k (1 + ln(G/k)), k = Y/sqrt(3),
for Table 2's steel (Y = 0.39 GPa, G = 95 GPa); Tate's own choice was of order 3.5-5.5 Y.
The last two columns: hvsph's depth at the paper's counts and the R_t that gives it.
Session 26, docs/validation.md (the rods).
"""
import math

RHO_P, RHO_T, YP = 17780.0, 7810.0, 0.983e9
# hvsph's depths at the paper's counts (docs/validation.md, at a glance; rod-1929 added in session 27)
HVSPH = {'1929': 0.1226, '5835': 0.1997, '5839': 0.2113, '5841': 0.1480, '5842': 0.1679,
         '5844': 0.1684}
RODS = {  # test: v (m/s), l (m), experiment L (m), KERNEL L (m)
    '1929': (1290.0, 0.15575, 0.080, 0.080),
    '5835': (2650.0, 0.15575, 0.2285, 0.221),
    '5839': (3450.0, 0.15575, 0.2415, 0.241),
    '5841': (2370.0, 0.1218, 0.1652, 0.161),
    '5842': (3580.0, 0.1218, 0.1886, 0.181),
    '5844': (4460.0, 0.1218, 0.1937, 0.191),
}


def head_speed(v, rt):
    """u from the modified Bernoulli balance; 0 if the rod cannot penetrate."""
    a = 0.5 * (RHO_P - RHO_T)
    b = -RHO_P * v
    c = 0.5 * RHO_P * v * v + YP - rt
    if abs(a) < 1e-12:
        u = -c / b
    else:
        disc = b * b - 4 * a * c
        u = (-b - math.sqrt(disc)) / (2 * a)
    return max(0.0, min(u, v))


def depth(v, l, rt, dt=1e-8, delta=0.0):
    """Final depth; delta > 0 takes the eroding head's speed short by that fraction of
    the balance's (session 41, docs/runs/s41/tate-deficit)."""
    x = 0.0
    while l > 1e-6 and v > 0:
        u = head_speed(v, rt)
        if u >= v - 1e-9:           # rigid body: no erosion
            x += v * dt
            v -= rt / (RHO_P * l) * dt
            continue
        u *= 1.0 - delta
        x += u * dt
        l -= (v - u) * dt
        v -= YP / (RHO_P * l) * dt if l > 1e-6 else 0.0
        if u <= 0:
            break
    return x


def solve_rt(v, l, target):
    lo, hi = 0.1e9, 20e9
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        if depth(v, l, mid, dt=2e-8) > target:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


if __name__ == "__main__":
    print("test | v km/s | u0 (R_t 1.59) km/s | L Tate (R_t 1.59) mm | L exp mm | L KERNEL mm |"
          " R_t for L exp GPa | L hvsph mm | R_t for L hvsph GPa")
    for k, (v, l, lexp, lk) in RODS.items():
        rt = 1.59e9
        need = solve_rt(v, l, lexp)
        print(f"{k} | {v/1e3:.2f} | {head_speed(v, rt)/1e3:.3f} | {depth(v, l, rt)*1e3:.1f} |"
              f" {lexp*1e3:.1f} | {lk*1e3:.1f} | " + (f"{need/1e9:.2f}" if need > 0.11e9 else "-")
              + (f" | {HVSPH[k]*1e3:.1f} | {solve_rt(v, l, HVSPH[k])/1e9:.2f}" if HVSPH[k] else " | - | -"))
