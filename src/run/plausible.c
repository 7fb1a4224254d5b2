/* plausible.c — the plausibility checks of a set-up case that `hvsph run` and
 * `hvsph check` both make: a bare time.end that promises more steps than any case of
 * this code takes is bad input (docs/units.md), and step keys that the first stable
 * step contradicts.
 */
#include "run/plausible.h"

#include <math.h>
#include <stdlib.h>

#include "core/error.h"
#include "sim/sim.h"

/* The particles' own smallest limit at the start (CFL and acceleration), before
 * time.dt_max. */
static double particle_step(const struct sim *s)
{
  double dt = HUGE_VAL;
  for (size_t i = 0; i < s->p.n; i++)
    if (s->p.dt[i] > 0 && s->p.dt[i] < dt) dt = s->p.dt[i];
  return dt < HUGE_VAL ? dt : s->dt;
}

double check_first_stable_step(const struct sim *s)
{
  const double dt = particle_step(s);
  return s->tp.dt_max > 0 && dt > s->tp.dt_max ? s->tp.dt_max : dt;
}

/* time.dt_min at or above the first stable step: the first step's successor falls
 * below it and the run stops as failed (exit 3, after its folder was prepared); and
 * time.dt_init far above it: a first step that the stability limits do not allow. */
static int check_step_keys(const struct sim *s, struct cfg *c, double dt, struct hv_error *err)
{
  char where[256];
  /* only a dt_min the case gives: the default (1e-30 s) is no real floor, and a step
     below it is made so by something else (a gas at 1e306 Pa), which the run shows */
  if (cfg_has(c, "time.dt_min") && s->tp.dt_min > 0 && s->tp.dt_min >= dt)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: time.dt_min: %g s is not below the first "
                        "stable step, %.3g s: the run would stop as failed at its first "
                        "step%s",
                        cfg_where(c, "time.dt_min", where, sizeof where), s->tp.dt_min, dt,
                        cfg_is_bare(c, "time.dt_min") ? " (a number without a unit is SI: seconds)"
                                                      : "");
  /* a warning: a deliberately unstable first step is how a failing run is made on
     purpose (tests/unit/test_cli.c) */
  if (s->tp.dt_init > 10.0 * particle_step(s))
    hv_warn("%s: time.dt_init = %g s is %.2g times the first stable step, %.3g s: the first "
            "step is unstable%s",
            cfg_where(c, "time.dt_init", where, sizeof where), s->tp.dt_init,
            s->tp.dt_init / particle_step(s), particle_step(s),
            cfg_is_bare(c, "time.dt_init") ? " (a number without a unit is SI: seconds)" : "");
  return 0;
}

/* HV_CHECK_STEPS_MAX, argued: the longest case of examples/ takes a few times 1e4 steps
 * at its first stable step (wp2; docs/units.md, "The rules"), a run at four times the
 * resolution some 1e5; 1e8 steps of even a thousand particles are 1e11 particle-steps,
 * more than a day at this code's speed on two cores (docs/performance.md, "The
 * benchmark").
 * Beyond it a bare time.end is a unit left out: `end: 20` (20 s) for 20 us. */
int check_plausible_end(const struct sim *s, struct cfg *c, struct hv_error *err)
{
  const double dt = check_first_stable_step(s), left = s->tp.end - s->t;
  if (!(dt > 0) || !(left > 0)) return 0;
  if (check_step_keys(s, c, dt, err)) return -1;
  const double steps = left / dt;
  if (!(steps > HV_CHECK_STEPS_MAX)) return 0;
  char where[256];
  if (dt < particle_step(s)) { /* time.dt_max holds it down, not the time span */
    hv_warn("%s: time.dt_max = %g s, below the first stable step (%.3g s), makes time.end "
            "about %.2g steps: this run may take very long (hvsph check estimates its wall "
            "time)",
            cfg_where(c, "time.dt_max", where, sizeof where), s->tp.dt_max, particle_step(s),
            steps);
    return 0;
  }
  cfg_where(c, "time.end", where, sizeof where);
  const int bare = cfg_is_bare(c, "time.end");
  static const struct {
    const char *unit;
    double f;
  } units[] = {{"us", 1e-6}, {"ns", 1e-9}, {"ms", 1e-3}};
  /* blamed on the missing unit only when a likely one brings it within: a step made
     tiny by something else (a pressure of 1e306 Pa in a gas) is that thing's fault, and
     the run shows it */
  for (size_t k = 0; bare && k < sizeof units / sizeof units[0]; k++)
    if ((s->tp.end * units[k].f - s->t) / dt <= HV_CHECK_STEPS_MAX)
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: time.end: the bare number %g is read as %g "
                          "s (a number without a unit is SI), about %.2g steps of the first "
                          "stable step, %.3g s: more than %.0e, far beyond any case of this "
                          "code; was it %g %s? Write the value with its unit",
                          where, s->tp.end, s->tp.end, steps, dt, HV_CHECK_STEPS_MAX, s->tp.end,
                          units[k].unit);
  /* written with its unit it is meant: said, not refused */
  hv_warn("%s: time.end = %g s is about %.2g steps of the first stable step, %.3g s: this "
          "run may take very long (hvsph check estimates its wall time)",
          where, s->tp.end, steps, dt);
  return 0;
}

static int cmp_double(const void *a, const void *b)
{
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* Planes of particles along axis ax among n coordinates u (sorted here): runs of values
 * closer than tol (a quarter spacing: a cubic lattice's layers are a spacing apart). */
static int count_planes(double *u, size_t n, double tol)
{
  if (n == 0) return 0;
  qsort(u, n, sizeof *u, cmp_double);
  int planes = 1;
  for (size_t i = 1; i < n; i++) planes += u[i] - u[i - 1] > tol;
  return planes;
}

/* Planes through body b's thickness along ax: all its particles (r <= 0), or those
 * within r of the line y = axis_y, z = 0 along x (the measurements' impact axis). */
int plate_body_planes(const struct sim *s, const int *bodies, int nb, int ax, double r,
                      double axis_y, double *thick)
{
  double *u = hv_malloc((s->p.n + 1) * sizeof *u, "check planes");
  size_t n = 0;
  double sp = HUGE_VAL;
  for (int k = 0; k < nb; k++) sp = fmin(sp, s->body[bodies[k]].spacing);
  for (size_t i = 0; i < s->p.n; i++) {
    int in = 0;
    for (int k = 0; k < nb && !in; k++) in = s->p.body[i] == bodies[k];
    if (!in) continue;
    const double dy = s->p.x[1][i] - axis_y, dz = s->p.x[2][i];
    if (r > 0 && dy * dy + dz * dz > r * r) continue;
    u[n++] = s->p.x[ax][i];
  }
  int planes = count_planes(u, n, 0.25 * sp);
  *thick = n ? u[n - 1] - u[0] + sp : 0.0;
  free(u);
  return planes;
}

int check_plate_layers(const struct sim *s, const int *bodies, int nb, double r, double axis_y)
{
  double sp = HUGE_VAL, thick;
  for (int j = 0; j < nb; j++) sp = fmin(sp, s->body[bodies[j]].spacing);
  int planes = plate_body_planes(s, bodies, nb, 0, fmax(r, 2.0 * sp), axis_y, &thick);
  if (planes == 0) planes = plate_body_planes(s, bodies, nb, 0, 0.0, axis_y, &thick);
  return planes;
}

void check_body_extent(const struct sim *s, int b, double ext[3])
{
  const struct body_info *bi = &s->body[b];
  for (int d = 0; d < 3; d++) ext[d] = bi->hi[d] - bi->lo[d];
  if (s->p.axisym) /* rings filling r <= hi[1]: the revolved body's diameter across x */
    ext[1] = ext[2] = 2.0 * bi->hi[1];
  else {
    if (s->bnd.half_model && bi->lo[2] >= -0.5 * bi->spacing)
      ext[2] = 2.0 * bi->hi[2]; /* a half model's body cut at z = 0, counted whole */
    if (s->bnd.quarter_model && bi->lo[1] >= -0.5 * bi->spacing)
      ext[1] = 2.0 * bi->hi[1]; /* a quarter model's, cut at y = 0 too */
  }
}

int check_plate_axis(const struct sim *s, int b, double *thick)
{
  double ext[3];
  check_body_extent(s, b, ext);
  int ax = 0;
  for (int d = 1; d < 3; d++)
    if (ext[d] < ext[ax]) ax = d;
  for (int d = 0; d < 3; d++)
    if (d != ax && !(ext[ax] <= 0.5 * ext[d])) return -1;
  *thick = ext[ax];
  return ax;
}
