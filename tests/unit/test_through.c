/* test_through.c — what went through a wall (src/diag/through.c) on constructed particle
 * sets with known answers.
 *
 * A wall of 4 layers (spacing Δ = 1 mm, 4 mm thick, 30 × 30 mm, half model z >= 0)
 * and, behind it:
 *  - nothing: nothing went through;
 *  - a bulge: the wall's rear layer within 6 mm of the axis bowed back by up to 2.5 Δ
 *    (a paraboloid), moving away: its centre lies 1.96 Δ behind the rear face, beyond
 *    the margin Δ, yet each particle stays within the linking length 1.5 Δ of its
 *    neighbours in the layer (the steepest step, at r = 6 mm, is 0.83 Δ across 1 Δ:
 *    1.30 Δ apart): attached, not through ("anything behind the face" would call it
 *    a breach);
 *  - detached spall: a 3 × 3 × 1 block of wall particles 5Δ behind the rear face at
 *    300 m/s: through, with its mass (doubled: half model) and velocity exactly, and all
 *    of it wall mass;
 *  - projectile debris (another body) behind at 2 km/s beside the spall: the mass-mean
 *    velocity of both;
 *  - material moving back towards the wall (v_x < 0), and material that flew past the
 *    wall's edge (outside r_max): not counted;
 *  - within the margin (a particle Δ/2 behind the face): not counted.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "diag/through.h"
#include "particles/particles.h"
#include "testlib.h"
#include "testparticles.h"

static const double D = 1e-3;   /* [m] spacing */
static const double M = 2.7e-6; /* [kg] particle mass */

static struct meas_geom geom(void)
{
  return (struct meas_geom){
      .body = 1, .x0 = 0.0, .thickness = 4 * D, .yc = 0.0, .spacing = D, .half_model = 1};
}

/* The wall: 4 layers x 30 x 15 (z >= 0), particle centres at cell centres. bulge > 0
 * bows the rear layer within 6 mm of the axis back by up to bulge (moving at 100 m/s). */
static void wall(struct particles *p, double bulge)
{
  for (int i = 0; i < 4; i++)
    for (int j = -15; j < 15; j++)
      for (int k = 0; k < 15; k++) {
        const double y = (j + 0.5) * D, z = (k + 0.5) * D;
        double x = (i + 0.5) * D;
        int moved = 0;
        if (bulge > 0 && i == 3 && y * y + z * z < 36 * D * D) {
          x += bulge * (1 - (y * y + z * z) / (36 * D * D));
          moved = 1;
        }
        const size_t s = tp_add(p, x, y, z, M, 1.2 * D, 2700, 1);
        if (moved) p->v[0][s] = 100.0;
      }
}

static struct meas_through run(struct particles *p, double r_max)
{
  const struct meas_geom g = geom();
  struct meas_through_params par;
  struct meas_through out;
  struct hv_error err = {0};
  meas_through_defaults(&par, &g);
  if (r_max > 0) par.r_max = r_max;
  CHECK(measure_through(p, &g, &par, &out, &err) == 0, "measure_through: %s", err.msg);
  return out;
}

int main(void)
{
  struct particles p;

  particles_init(&p);
  wall(&p, 0.0);
  struct meas_through r = run(&p, 0);
  CHECK(!r.through && r.n == 0 && r.mass == 0 && r.velocity == 0,
        "intact wall: nothing through "
        "(n %zu)",
        r.n);
  particles_free(&p);

  /* a bulge, joined to the wall */
  particles_init(&p);
  wall(&p, 2.5 * D);
  double xmax = 0;
  for (size_t i = 0; i < p.n; i++) xmax = fmax(xmax, p.x[0][i]);
  CHECK(xmax > 5.9 * D, "the bulge reaches %.3g mm, beyond face + margin (5 mm)", xmax * 1e3);
  r = run(&p, 0);
  CHECK(!r.through, "attached bulge: not through (n %zu)", r.n);
  particles_free(&p);

  /* detached spall: 3 x 3 x 1 wall particles 5 Δ behind, at 300 m/s */
  particles_init(&p);
  wall(&p, 0.0);
  for (int j = -1; j <= 1; j++)
    for (int k = 0; k < 3; k++) {
      const size_t s = tp_add(&p, 9.5 * D, (j + 0.5) * D, (k + 0.5) * D, M, 1.2 * D, 2700, 1);
      p.v[0][s] = 300.0;
    }
  r = run(&p, 0);
  CHECK(r.through && r.n == 9, "detached spall: through, 9 particles (n %zu)", r.n);
  CHECK_CLOSE(r.mass, 2 * 9 * M, 1e-18, "spall mass (half model: doubled)");
  CHECK_CLOSE(r.velocity, 300.0, 1e-9, "spall velocity");
  CHECK_CLOSE(r.wall_mass, r.mass, 1e-18, "all of it wall");

  /* projectile debris (body 0): 3 particles of mass M at 2 km/s */
  for (int k = 0; k < 3; k++) {
    const size_t s = tp_add(&p, 12.0 * D, 5 * D, (k + 0.5) * D, M, 1.2 * D, 2700, 0);
    p.v[0][s] = 2000.0;
  }
  /* moving back towards the wall, and past the wall's edge: not counted */
  size_t s = tp_add(&p, 12.0 * D, -5 * D, 0.5 * D, M, 1.2 * D, 2700, 0);
  p.v[0][s] = -500.0;
  s = tp_add(&p, 12.0 * D, 40 * D, 0.5 * D, M, 1.2 * D, 2700, 0);
  p.v[0][s] = 3000.0;
  /* within the margin: Δ/2 behind the rear face */
  s = tp_add(&p, 4.5 * D, 8 * D, 0.5 * D, M, 1.2 * D, 2700, 0);
  p.v[0][s] = 3000.0;
  r = run(&p, 13 * D);
  CHECK(r.n == 12, "spall and debris: 12 particles (n %zu)", r.n);
  CHECK_CLOSE(r.velocity, (9 * 300.0 + 3 * 2000.0) / 12, 1e-9, "mass-mean velocity");
  CHECK_CLOSE(r.wall_mass, 2 * 9 * M, 1e-18, "wall part");
  particles_free(&p);

  /* invalid parameters: an error, no answer */
  particles_init(&p);
  struct meas_geom g = geom();
  g.thickness = 0;
  struct meas_through_params par;
  struct meas_through out;
  struct hv_error err = {0};
  meas_through_defaults(&par, &g);
  CHECK(measure_through(&p, &g, &par, &out, &err) == -1 && err.code == HV_EXIT_INPUT,
        "zero thickness refused");
  particles_free(&p);
  return test_finish();
}
