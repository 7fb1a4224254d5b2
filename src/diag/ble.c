/* ble.c — the ballistic-limit equations of ble.h, in their published forms (NASA units
 * inside: cm, g/cm3, km/s, ksi). Sources and definitions in ble.h. */
#include "diag/ble.h"

#include <math.h>

#define BLE_PI 3.14159265358979323846
#define CM     1e-2             /* [m] */
#define G_CM3  1e3              /* [kg/m3] */
#define KM_S   1e3              /* [m/s] */
#define KSI    6.894757293168e6 /* [Pa]: 1000 lbf/in2 */

static double cap_theta(double theta)
{
  const double cap = BLE_WHIPPLE_MAX_OBLIQUITY_DEG * BLE_PI / 180.0;
  return theta > cap ? cap : theta;
}

static int angle_ok(double theta) { return isfinite(theta) && theta >= 0 && theta < 0.5 * BLE_PI; }

double ble_whipple_v_low(double theta) { return BLE_WHIPPLE_VN_LOW / cos(cap_theta(theta)); }

double ble_whipple_v_high(double theta) { return BLE_WHIPPLE_VN_HIGH / cos(cap_theta(theta)); }

enum ble_regime ble_whipple_regime(double v, double theta)
{
  const double vn = v * cos(cap_theta(theta));
  if (vn <= BLE_WHIPPLE_VN_LOW) return BLE_BALLISTIC;
  if (vn < BLE_WHIPPLE_VN_HIGH) return BLE_SHATTER;
  return BLE_HYPERVELOCITY;
}

double ble_whipple_dc(const struct ble_whipple *s, double v, double theta)
{
  if (!(s->bumper_thickness > 0 && s->bumper_density > 0 && s->standoff > 0 &&
        s->wall_thickness > 0 && s->wall_yield > 0 && s->projectile_density > 0 && v > 0 &&
        isfinite(v) && angle_ok(theta)))
    return NAN;
  theta = cap_theta(theta);
  /* NASA units */
  const double tb = s->bumper_thickness / CM, tw = s->wall_thickness / CM;
  const double S = s->standoff / CM, sig = s->wall_yield / KSI;
  const double rp = s->projectile_density / G_CM3, rb = s->bumper_density / G_CM3;
  const double V = v / KM_S, c = cos(theta), vn = V * c;
  const double front = tw * sqrt(sig / 40.0) + tb;
  double d;
  if (vn <= 3.0) {
    /* C93 eq. 9, HB09 eq. 4-24 */
    d = pow(front / (0.6 * pow(c, 5.0 / 3.0) * sqrt(rp) * pow(V, 2.0 / 3.0)), 18.0 / 19.0);
  } else if (vn < 7.0) {
    /* C93 eq. 10, HB09 eq. 4-25: linear in Vn between the two end equations */
    const double low = pow(front / (1.248 * sqrt(rp) * c), 18.0 / 19.0);
    const double high = 1.071 * pow(tw, 2.0 / 3.0) * pow(rp, -1.0 / 3.0) * pow(rb, -1.0 / 9.0) *
                        cbrt(S) * cbrt(sig / 70.0);
    d = low * (1.75 - vn / 4.0) + high * (vn / 4.0 - 0.75);
  } else {
    /* C93 eq. 11, HB09 eq. 4-23 */
    d = 3.918 * pow(tw, 2.0 / 3.0) * pow(rp, -1.0 / 3.0) * pow(rb, -1.0 / 9.0) *
        pow(vn, -2.0 / 3.0) * cbrt(S) * cbrt(sig / 70.0);
  }
  return d * CM;
}

static int wall_ok(const struct ble_wall *w, double v, double theta)
{
  return w->thickness > 0 && w->density > 0 && w->brinell > 0 && w->sound_speed > 0 &&
         w->projectile_density > 0 && v > 0 && isfinite(v) && angle_ok(theta);
}

/* the density-ratio exponent of HB09 eqs. 4-1 and 4-2 */
static double density_exponent(const struct ble_wall *w)
{
  return w->projectile_density / w->density < 1.5 ? 0.5 : 2.0 / 3.0;
}

double ble_wall_pinf(const struct ble_wall *w, double d, double v, double theta)
{
  if (!wall_ok(w, v, theta) || !(d > 0)) return NAN;
  const double vn = v * cos(theta) / KM_S, ct = w->sound_speed / KM_S;
  const double p = 5.24 * pow(d / CM, 19.0 / 18.0) * pow(w->brinell, -0.25) *
                   pow(w->projectile_density / w->density, density_exponent(w)) *
                   pow(vn / ct, 2.0 / 3.0);
  return p * CM;
}

double ble_wall_dc(const struct ble_wall *w, double v, double theta, double k)
{
  if (!wall_ok(w, v, theta) || !(k > 0)) return NAN;
  const double vn = v * cos(theta) / KM_S, ct = w->sound_speed / KM_S;
  /* HB09 eq. 4-6, solved from t = k P∞ */
  const double d = pow(w->thickness / CM * pow(w->brinell, 0.25) *
                           pow(w->density / w->projectile_density, density_exponent(w)) /
                           (k * 5.24 * pow(vn / ct, 2.0 / 3.0)),
                       18.0 / 19.0);
  return d * CM;
}
