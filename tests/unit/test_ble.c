/* test_ble.c — the ballistic-limit equations of src/diag/ble.c against numbers computed
 * by hand from the published forms (C93 eqs. 9-12, HB09 eqs. 4-1, 4-2, 4-6, 4-23 to
 * 4-26), their continuity at the regime boundaries, the 65° cap, and shots of the
 * NASA/pyBLOSSUM database (shared/reference/shielding.md §3).
 *
 * Hand computations (NASA units: cm, g/cm3, km/s, ksi), the HB09 Fig. 4-4 shield:
 * t_b = 0.12 cm, ρ_b = 2.7, S = 10 cm, t_w = 0.32 cm, σ = 40 ksi, ρ_p = 2.8:
 *  V = 7, θ = 0 (eq. 11): d = 3.918 · 0.32^(2/3) · 2.8^(-1/3) · 2.7^(-1/9) · 7^(-2/3)
 *      · 10^(1/3) · (40/70)^(1/3) = 3.918 · 0.46784 · 0.70949 · 0.89551 · 0.27328
 *      · 2.15443 · 0.82983 = 0.56899 cm.
 *  V = 2, θ = 0 (eq. 9): (0.32 · (40/40)^0.5 + 0.12) / (0.6 · 1 · 2.8^0.5 · 2^(2/3))
 *      = 0.44 / (0.6 · 1.67332 · 1.58740) = 0.44 / 1.59374 = 0.27608;
 *      d = 0.27608^(18/19) = 0.29543 cm.
 *  V = 5, θ = 0 (eq. 10): low = (0.44 / (1.248 · 1.67332))^(18/19) = 0.21070^(18/19)
 *      = 0.22869; high = 1.071 · 0.46784 · 0.70949 · 0.89551 · 2.15443 · 0.82983
 *      = 0.56915; d = 0.22869 · (1.75 − 1.25) + 0.56915 · (1.25 − 0.75) = 0.39892 cm.
 *  V = 5, θ = 45° (Vn = 3.5355, eq. 10 with cos θ = 0.70711): low = (0.44 / (1.248 ·
 *      1.67332 · 0.70711))^(18/19) = 0.31758; d = 0.31758 · (1.75 − 0.88388) + 0.56915 ·
 *      (0.88388 − 0.75) = 0.35126 cm.
 * Single wall (HB09 eq. 4-6), Al 6061-T6: t = 0.3 cm, ρ_t = 2.713, BHN 95, C_t = 5.1 km/s,
 * ρ_p = 2.796, V = 6, θ = 0, k = 1.8: d = [0.3 · 95^0.25 · (2.713/2.796)^0.5 / (1.8 · 5.24
 *      · (6/5.1)^(2/3))]^(18/19) = [0.3 · 3.12199 · 0.98505 / (9.432 · 1.11443)]^(18/19)
 *      = 0.087771^(18/19) = 0.099762 cm; P∞ of that sphere = t / k = 0.16667 cm.
 * The hand values carry 5 digits: tolerance 2e-4 relative.
 * Continuity: the published constants 1.248 (= 0.6 · 3^(2/3) = 1.24805) and 1.071
 * (= 3.918 / 7^(2/3) = 1.07069) are rounded, so the regimes meet to 3e-4 relative, not
 * exactly: tolerance 5e-4.
 */
#include <math.h>
#include <stdio.h>

#include "diag/ble.h"
#include "testlib.h"

#define DEG (3.14159265358979323846 / 180.0)

static double rel(double a, double b) { return fabs(a - b) / fabs(b); }

static struct ble_whipple fig44(void)
{
  return (struct ble_whipple){.bumper_thickness = 1.2e-3,
                              .bumper_density = 2700,
                              .standoff = 0.1,
                              .wall_thickness = 3.2e-3,
                              .wall_yield = 40 * 6.894757293168e6,
                              .projectile_density = 2800};
}

static void hand_values(void)
{
  const struct ble_whipple s = fig44();
  CHECK(rel(ble_whipple_dc(&s, 7e3, 0), 0.56899e-2) < 2e-4, "7 km/s: %.6g m (hand 0.56899 cm)",
        ble_whipple_dc(&s, 7e3, 0));
  CHECK(rel(ble_whipple_dc(&s, 2e3, 0), 0.29543e-2) < 2e-4, "2 km/s: %.6g m (hand 0.29543 cm)",
        ble_whipple_dc(&s, 2e3, 0));
  CHECK(rel(ble_whipple_dc(&s, 5e3, 0), 0.39892e-2) < 2e-4, "5 km/s: %.6g m (hand 0.39892 cm)",
        ble_whipple_dc(&s, 5e3, 0));
  CHECK(rel(ble_whipple_dc(&s, 5e3, 45 * DEG), 0.35126e-2) < 2e-4,
        "5 km/s 45 deg: %.6g m (hand 0.35126 cm)", ble_whipple_dc(&s, 5e3, 45 * DEG));
  CHECK(ble_whipple_regime(2e3, 0) == BLE_BALLISTIC && ble_whipple_regime(5e3, 0) == BLE_SHATTER &&
            ble_whipple_regime(7e3, 0) == BLE_HYPERVELOCITY &&
            ble_whipple_regime(5e3, 60 * DEG) == BLE_BALLISTIC,
        "regimes");

  const struct ble_wall w = {.thickness = 3e-3,
                             .density = 2713,
                             .brinell = 95,
                             .sound_speed = 5.1e3,
                             .projectile_density = 2796};
  const double d = ble_wall_dc(&w, 6e3, 0, BLE_WALL_K_PERFORATION);
  CHECK(rel(d, 0.099762e-2) < 2e-4, "Cour-Palais d_c %.6g m (hand 0.099762 cm)", d);
  CHECK(rel(ble_wall_pinf(&w, d, 6e3, 0) * BLE_WALL_K_PERFORATION, 3e-3) < 1e-9,
        "t = 1.8 P_inf(d_c): %.9g m", ble_wall_pinf(&w, d, 6e3, 0) * 1.8);
  /* a tungsten sphere (ρp/ρt > 1.5) takes the 2/3 exponent: P∞ ∝ (ρp/ρt)^(2/3) */
  struct ble_wall wh = w;
  wh.projectile_density = 17000;
  struct ble_wall wh2 = w;
  wh2.projectile_density = 2 * 17000;
  CHECK(rel(ble_wall_pinf(&wh2, 1e-3, 6e3, 0) / ble_wall_pinf(&wh, 1e-3, 6e3, 0),
            pow(2.0, 2.0 / 3.0)) < 1e-12,
        "dense projectile: density exponent 2/3");
  /* obliquity enters through Vn: P∞(V, 60°) = P∞(V/2, 0) */
  CHECK(rel(ble_wall_pinf(&w, 1e-3, 6e3, 60 * DEG), ble_wall_pinf(&w, 1e-3, 3e3, 0)) < 1e-12,
        "single wall: Vn");
}

static void continuity(void)
{
  const struct ble_whipple s = fig44();
  const double eps = 1e-9;
  const double angles[] = {0, 30 * DEG, 45 * DEG, 60 * DEG};
  for (int k = 0; k < 4; k++) {
    const double th = angles[k];
    const double bounds[2] = {ble_whipple_v_low(th), ble_whipple_v_high(th)};
    CHECK(rel(bounds[0], 3e3 / cos(th)) < 1e-12 && rel(bounds[1], 7e3 / cos(th)) < 1e-12,
          "bounds at %g deg: %g %g m/s", th / DEG, bounds[0], bounds[1]);
    for (int b = 0; b < 2; b++) {
      const double below = ble_whipple_dc(&s, bounds[b] * (1 - eps), th);
      const double above = ble_whipple_dc(&s, bounds[b] * (1 + eps), th);
      CHECK(rel(below, above) < 5e-4, "continuity at %g m/s, %g deg: %.7g vs %.7g m", bounds[b],
            th / DEG, below, above);
    }
  }
  /* the 65° cap: any steeper obliquity gives d_c(65°) */
  CHECK(ble_whipple_dc(&s, 10e3, 70 * DEG) == ble_whipple_dc(&s, 10e3, 65 * DEG) &&
            ble_whipple_dc(&s, 4e3, 80 * DEG) == ble_whipple_dc(&s, 4e3, 65 * DEG),
        "65 deg cap");
  CHECK(ble_whipple_dc(&s, 10e3, 60 * DEG) != ble_whipple_dc(&s, 10e3, 65 * DEG), "below the cap");
  /* invalid input: NAN, never a number */
  struct ble_whipple bad = s;
  bad.standoff = 0;
  CHECK(isnan(ble_whipple_dc(&bad, 5e3, 0)) && isnan(ble_whipple_dc(&s, -1, 0)) &&
            isnan(ble_whipple_dc(&s, 5e3, 90 * DEG)),
        "invalid input gives NAN");
}

/* Shots of pyBLOSSUM's Whipple database (shielding.md §3: 6061-T6 bumper ρ_b = 2.713,
 * Al 2017-T4 spheres ρ_p = 2.796 g/cm3). The BLE is a design equation, conservative
 * by construction: a shot it calls failed may pass (NP with d > d_c: HD9920118, 8-3212,
 * 85-16) and near the shatter regime's top it is known to err the other way (Ryan,
 * Bjorkman & Christiansen 2011, IJIE 38: HD9920034 at 6.9 km/s, 4-2109). Checked
 * here: the shots the handbook equations classify as observed (hand-checked with the
 * same forms), so that a wrong exponent or unit moves at least one of them across. */
static void shots(void)
{
  static const struct {
    const char *name;
    double d, v, theta, tb, S, tw, sig; /* cm, km/s, deg, cm, cm, cm, ksi */
    int perforated;
  } shot[] = {
      {"HD9920028", 0.3175, 2.60, 0, 0.07874, 5.08, 0.3175, 40, 1},
      {"HD9920116", 0.3175, 6.90, 0, 0.07874, 5.08, 0.4572, 40, 0},
      {"HD0020053", 0.3175, 7.20, 45, 0.07874, 5.08, 0.318, 40, 0},
      {"HD0020153", 0.3175, 6.81, 45, 0.07874, 5.08, 0.254, 40, 1},
      {"4-2110", 0.4511, 7.00, 0, 0.12827, 10.16, 0.32004, 57, 0},
      {"8-3224", 0.2596, 8.97, 0, 0.0597, 4.669, 0.146304, 40, 1},
      {"86-2", 0.793, 6.98, 0, 0.159, 10.16, 0.318, 57, 1},
  };
  for (size_t k = 0; k < sizeof shot / sizeof shot[0]; k++) {
    const struct ble_whipple s = {.bumper_thickness = shot[k].tb * 1e-2,
                                  .bumper_density = 2713,
                                  .standoff = shot[k].S * 1e-2,
                                  .wall_thickness = shot[k].tw * 1e-2,
                                  .wall_yield = shot[k].sig * 6.894757293168e6,
                                  .projectile_density = 2796};
    const double dc = ble_whipple_dc(&s, shot[k].v * 1e3, shot[k].theta * DEG);
    CHECK((shot[k].d * 1e-2 > dc) == shot[k].perforated, "shot %s: d %.4g cm, d_c %.4g cm, %s",
          shot[k].name, shot[k].d, dc * 1e2, shot[k].perforated ? "P" : "NP");
  }
}

int main(void)
{
  hand_values();
  continuity();
  shots();
  return test_finish();
}
