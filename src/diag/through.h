/* through.h — what went through a wall: the material behind the wall's original far
 * face that moves away from it, and is not the wall still attached (docs/measurements.md,
 * "Wall: what went through"). With the line-of-sight `perforated` of measure_plate, the
 * failure of a shield's rear wall as the ballistic-limit equations define it:
 * perforation or detached spall (Christiansen 1993, p. 147).
 *
 * Conventions of measure.h (SI; flight along +x; the wall filled x0 <= x <= x0 + t;
 * axis y = yc, z = 0; half models mirrored: masses doubled).
 * Counted: a particle i (of `solid` when given, with a finite position) with
 *   x_i > x0 + t + margin            behind the far face by more than the margin,
 *   v_x,i > 0                        moving away from it,
 *   ρ_i = |(y_i − yc, z_i)| <= r_max within the wall's shadow (what flew round a finite
 *                                    wall's edge did not go through it),
 * and not a particle of the wall's largest connected piece (friends-of-friends at 1.5 Δ,
 * meas_keep_largest_piece): a bulge, however far it bows out, is attached wall, while
 * spall that has broken loose, and the projectile's and bumper's debris, are not.
 * Reported: the count n, the mass M (full picture) and the mass-mean axial velocity
 * v = Σ m v_x / Σ m (0 when nothing went through), the part of M that is wall material,
 * and `through` = (n > 0).
 * Resolution: the margin (default Δ, the wall's spacing) keeps the rear face's own
 * particles, which sit Δ/2 inside it, and a rear-face ripple of less than Δ out; a wall
 * of fewer than 4 particle layers cannot tell a bulge from a breach (issue 71; the run
 * reports `wall_layers`). */
#ifndef HV_THROUGH_H
#define HV_THROUGH_H

#include <stddef.h>

#include "diag/measure.h"

struct meas_through_params {
  double margin;              /* [m] (default g->spacing) */
  double r_max;               /* [m] (default INFINITY) */
  const unsigned char *solid; /* optional [p->n]: the particles that may count (no gas) */
  const unsigned char *wall;  /* optional [p->n]: the wall's particles (default: body
                                  g->body) */
  const double *scale;        /* optional [p->n]: Δ_i/Δ (a wall of several bodies) */
};

struct meas_through {
  int through;      /* n > 0 */
  size_t n;         /* particles counted (simulated, not mirrored) */
  double mass;      /* [kg] full picture */
  double velocity;  /* [m/s] mass-mean v_x */
  double wall_mass; /* [kg] of mass, the wall's own (detached spall, plug) */
};

void meas_through_defaults(struct meas_through_params *par, const struct meas_geom *g);
int measure_through(const struct particles *p, const struct meas_geom *g,
                    const struct meas_through_params *par, struct meas_through *out,
                    struct hv_error *err);

#endif
