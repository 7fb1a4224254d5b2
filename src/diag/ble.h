/* ble.h — ballistic-limit equations (BLEs) of spacecraft shielding, from their published
 * forms: the critical projectile diameter d_c that a shield just stops, against impact
 * speed and obliquity.
 *
 * Sources (docs/ballistic-limit.md lists them with the equation numbers):
 *  - Christiansen E.L. (1993), "Design and performance equations for advanced meteoroid
 *    and debris shields", Int. J. Impact Eng. 14:145-156, eqs. 9-12 (C93);
 *  - Christiansen E.L. et al. (2009), Handbook for Designing MMOD Protection,
 *    NASA/TM-2009-214785, eqs. 4-23 to 4-26 (Whipple) and 4-1, 4-2, 4-6 (single wall,
 *    Cour-Palais) (HB09).
 *
 * The published forms are in the NASA units: d, t, S in cm, densities in g/cm3, speed
 * in km/s, rear-wall yield in ksi (1 ksi = 6.894757 MPa). These functions take and
 * return SI (m, kg/m3, m/s, Pa, radians) and convert inside, so a caller never meets
 * the mixed units. Obliquity θ is measured from the target's normal (θ = 0: normal
 * impact), as the equations measure it; Vn = V cos θ.
 *
 * Failure, as the equations define it: perforation or detached spall of the rear wall
 * (C93 p.147). d_c is the diameter at which that begins: larger spheres fail the shield.
 * The functions are pure; they return NAN for parameters outside their domain
 * (non-positive thicknesses, densities, speed; obliquity outside [0, 90°)). */
#ifndef HV_BLE_H
#define HV_BLE_H

/* The Whipple shield: bumper, stand-off, rear wall (C93 §3). */
struct ble_whipple {
  double bumper_thickness;   /* [m] t_b */
  double bumper_density;     /* [kg/m3] ρ_b */
  double standoff;           /* [m] S: back of the bumper to the front of the rear wall */
  double wall_thickness;     /* [m] t_w */
  double wall_yield;         /* [Pa] σ, the rear wall's yield stress (BLE input, ksi inside) */
  double projectile_density; /* [kg/m3] ρ_p */
};

/* The regime bounds in the normal component Vn: 3 and 7 km/s (C93 eqs. 9-11), so
 * 3/cos θ and 7/cos θ in V. */
#define BLE_WHIPPLE_VN_LOW  3.0e3 /* [m/s] */
#define BLE_WHIPPLE_VN_HIGH 7.0e3 /* [m/s] */
/* Above this obliquity the equations take d_c(65°) (C93 eq. 12, HB09 eq. 4-26). */
#define BLE_WHIPPLE_MAX_OBLIQUITY_DEG 65.0

enum ble_regime { BLE_BALLISTIC = 0, BLE_SHATTER = 1, BLE_HYPERVELOCITY = 2 };

/* The regime of an impact at speed v [m/s] and obliquity theta [rad] (capped at 65°):
 * ballistic for Vn <= 3 km/s, shatter for 3 < Vn < 7, hypervelocity for Vn >= 7. */
enum ble_regime ble_whipple_regime(double v, double theta);

/* Christiansen's Whipple-shield critical diameter [m] at speed v [m/s], obliquity theta
 * [rad]. Obliquities above 65° give d_c(65°). NAN for invalid parameters. */
double ble_whipple_dc(const struct ble_whipple *s, double v, double theta);

/* The speed [m/s] of the regime boundaries at obliquity theta (capped at 65°):
 * 3 km/s / cos θ and 7 km/s / cos θ. */
double ble_whipple_v_low(double theta);
double ble_whipple_v_high(double theta);

/* Single wall, Cour-Palais (modified; HB09 eqs. 4-1, 4-2, 4-6): */
struct ble_wall {
  double thickness;          /* [m] t */
  double density;            /* [kg/m3] ρ_t */
  double brinell;            /* Brinell hardness BHN of the wall */
  double sound_speed;        /* [m/s] C_t, the wall's sound speed */
  double projectile_density; /* [kg/m3] ρ_p */
};
/* The thickness factor k of t = k P∞: perforation 1.8, detached spall 2.2, incipient
 * (attached) spall 3.0 (C93 eqs. 4-6; HB09 eqs. 4-3 to 4-5). */
#define BLE_WALL_K_PERFORATION    1.8
#define BLE_WALL_K_DETACHED_SPALL 2.2
#define BLE_WALL_K_ATTACHED_SPALL 3.0

/* Semi-infinite penetration depth P∞ [m] of a sphere of diameter d [m]; the density ratio
 * exponent is 1/2 for ρp/ρt < 1.5 and 2/3 above (HB09 eqs. 4-1, 4-2). */
double ble_wall_pinf(const struct ble_wall *w, double d, double v, double theta);
/* Critical diameter [m] of the single wall for the factor k (HB09 eq. 4-6). */
double ble_wall_dc(const struct ble_wall *w, double v, double theta, double k);

#endif
