/* check.c — `hvsph check CASE`: the case read and set up as `hvsph run` would (the same
 * checks, --set and --material), then described instead of run; nothing is written.
 *
 * Printed (standard output): per body its material, particle count and spacing; for a
 * plate (a body far thinner along one axis than across it) the planes of particles
 * through its thickness; for the projectile (the fastest body) its particles per
 * radius; the measured plates' layers at the impact point; the first time step, the
 * steps to time.end (time.end / the first stable step: an estimate, since an impact
 * shortens the step), the memory the solver's arrays take and the wall time on this
 * machine, from a few steps of this very case timed here. Warnings (standard error):
 * a plate whose perforation is measured with fewer than CHECK_LAYERS_MIN layers at the
 * impact point.
 *
 * check_plausible_end() is shared with `hvsph run`: a bare time.end that promises more
 * steps than any case of this code takes is bad input (docs/units.md).
 */
#include "run/check.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "integrate/step.h"
#include "run/measure_run.h"
#include "run/run.h"
#include "run/sim.h"

/* Perforation with fewer layers than this through a plate is a lattice effect: with two
 * layers of 1.26 mm a 2 mm backwall was "perforated" by a 2 mm sphere, "not perforated"
 * by 3 mm and perforated again by 4 mm (issue 71); the paper's cases give their plates
 * 4-5 layers at the impact point (examples/paper/wp1.yaml). */

/* Steps timed for the wall-time estimate (after one untimed warm-up step, which builds
 * the grid and caches), and the wall time after which timing stops early: a case of
 * 1e7 particles takes seconds a step on 2 cores. */
#define CHECK_CALIB_STEPS 3
#define CHECK_CALIB_WALL 10.0   /* [s] */

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
    return hv_error_set(err, HV_EXIT_INPUT, "%s: time.dt_min: %g s is not below the first "
                        "stable step, %.3g s: the run would stop as failed at its first "
                        "step%s", cfg_where(c, "time.dt_min", where, sizeof where),
                        s->tp.dt_min, dt, cfg_is_bare(c, "time.dt_min")
                        ? " (a number without a unit is SI: seconds)" : "");
  /* a warning: a deliberately unstable first step is how a failing run is made on
     purpose (tests/unit/test_cli.c) */
  if (s->tp.dt_init > 10.0 * particle_step(s))
    hv_warn("%s: time.dt_init = %g s is %.2g times the first stable step, %.3g s: the first "
            "step is unstable%s", cfg_where(c, "time.dt_init", where, sizeof where),
            s->tp.dt_init, s->tp.dt_init / particle_step(s), particle_step(s),
            cfg_is_bare(c, "time.dt_init") ? " (a number without a unit is SI: seconds)" : "");
  return 0;
}

/* HV_CHECK_STEPS_MAX, argued: the longest case of examples/ takes about 3e4 steps at
 * its first stable step (wp2: 250 us, 34 201; the rods 1.1e4-1.8e4; `hvsph check` on
 * each, 2026-12-07), a run at four times the resolution some 1e5; 1e8 steps of even a
 * thousand particles are 1e11 particle-steps, more than a day at this code's 1e6
 * particle-steps per second on two cores (docs/performance.md).
 * Beyond it a bare time.end is a unit left out: `end: 20` (20 s) for 20 us. */
int check_plausible_end(const struct sim *s, struct cfg *c, struct hv_error *err)
{
  const double dt = check_first_stable_step(s), left = s->tp.end - s->t;
  if (!(dt > 0) || !(left > 0)) return 0;
  if (check_step_keys(s, c, dt, err)) return -1;
  const double steps = left / dt;
  if (!(steps > HV_CHECK_STEPS_MAX)) return 0;
  char where[256];
  if (dt < particle_step(s)) {   /* time.dt_max holds it down, not the time span */
    hv_warn("%s: time.dt_max = %g s, below the first stable step (%.3g s), makes time.end "
            "about %.2g steps: this run may take very long (hvsph check estimates its wall "
            "time)", cfg_where(c, "time.dt_max", where, sizeof where), s->tp.dt_max,
            particle_step(s), steps);
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
      return hv_error_set(err, HV_EXIT_INPUT, "%s: time.end: the bare number %g is read as %g "
                          "s (a number without a unit is SI), about %.2g steps of the first "
                          "stable step, %.3g s: more than %.0e, far beyond any case of this "
                          "code; was it %g %s? Write the value with its unit", where,
                          s->tp.end, s->tp.end, steps, dt, HV_CHECK_STEPS_MAX, s->tp.end,
                          units[k].unit);
  /* written with its unit it is meant: said, not refused */
  hv_warn("%s: time.end = %g s is about %.2g steps of the first stable step, %.3g s: this "
          "run may take very long (hvsph check estimates its wall time)", where, s->tp.end,
          steps, dt);
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

/* The axis a body is thin along (its plate normal), or -1: its extent along it at most
 * half its extent across (a half model's bodies cut at z = 0 counted whole). */
static int plate_axis(const struct sim *s, int b, double *thick)
{
  const struct body_info *bi = &s->body[b];
  double ext[3];
  for (int d = 0; d < 3; d++) ext[d] = bi->hi[d] - bi->lo[d];
  if (s->bnd.half_model && bi->lo[2] >= -0.5 * bi->spacing) ext[2] = 2.0 * bi->hi[2];
  int ax = 0;
  for (int d = 1; d < 3; d++)
    if (ext[d] < ext[ax]) ax = d;
  for (int d = 0; d < 3; d++)
    if (d != ax && !(ext[ax] <= 0.5 * ext[d])) return -1;
  *thick = ext[ax];
  return ax;
}

/* Planes through body b's thickness along ax: all its particles (r <= 0), or those
 * within r of the line y = axis_y, z = 0 along x (the measurements' impact axis). */
static int body_planes(const struct sim *s, const int *bodies, int nb, int ax, double r,
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
  int planes = body_planes(s, bodies, nb, 0, fmax(r, 2.0 * sp), axis_y, &thick);
  if (planes == 0) planes = body_planes(s, bodies, nb, 0, 0.0, axis_y, &thick);
  return planes;
}

/* The fastest body (its mean speed), or -1 when nothing moves or there is one body
 * (a projectile hits something). */
static int projectile(const struct sim *s, const size_t *first, double *speed, double v[3])
{
  int best = -1;
  *speed = 0.0;
  if (s->nbody < 2) return -1;
  for (int b = 0; b < s->nbody; b++) {
    double m[3] = {0, 0, 0};
    const size_t n = s->body[b].count;
    for (size_t i = first[b]; i < first[b] + n; i++)
      for (int d = 0; d < 3; d++) m[d] += s->p.v[d][i] / (double)n;
    const double sp = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    if (sp > *speed) {
      *speed = sp;
      best = b;
      memcpy(v, m, sizeof m);
    }
  }
  return best;
}

static long peak_rss_kib(void)
{
  FILE *f = fopen("/proc/self/status", "r");
  if (!f) return -1;
  char line[256];
  long kib = -1;
  while (fgets(line, sizeof line, f))
    if (!strncmp(line, "VmHWM:", 6)) kib = strtol(line + 6, NULL, 10);
  fclose(f);
  return kib;
}

/* The bodies' rows, the projectile and the plates. */
static void report_bodies(const struct sim *s, const size_t *first)
{
  double speed, v[3];
  const int pj = projectile(s, first, &speed, v);
  printf("\n%-16s %-16s %10s %11s\n", "body", "material", "particles", "spacing");
  for (int b = 0; b < s->nbody; b++) {
    const struct body_info *bi = &s->body[b];
    char note[256] = "", sp[32];
    snprintf(sp, sizeof sp, "%.4g mm", 1e3 * bi->spacing);
    double thick;
    const int ax = plate_axis(s, b, &thick);
    if (b == pj) {
      /* the radius across the flight: half the widest extent across its main axis */
      int fa = 0;
      for (int d = 1; d < 3; d++)
        if (fabs(v[d]) > fabs(v[fa])) fa = d;
      double r = 0.0;
      for (int d = 0; d < 3; d++)
        if (d != fa) r = fmax(r, 0.5 * (bi->hi[d] - bi->lo[d]));
      snprintf(note, sizeof note, "projectile: %.3g km/s, radius %.4g mm, %.1f particles per "
               "radius", 1e-3 * speed, 1e3 * r, r / bi->spacing);
    } else if (ax >= 0) {
      const int one = b;
      double t;
      const int planes = body_planes(s, &one, 1, ax, 0.0, 0.0, &t);
      snprintf(note, sizeof note, "plate %.4g mm thick along %c: %d particle layer%s", 1e3 * thick,
               "xyz"[ax], planes, planes == 1 ? "" : "s");
    }
    if (s->sph.piece && s->piece[b] != b) {
      const size_t u = strlen(note);
      snprintf(note + u, sizeof note - u, "%spart of '%s'", u ? "; " : "",
               s->body[s->piece[b]].name);
    }
    printf("%-16s %-16s %10zu %11s  %s\n", bi->name, s->mat[bi->mat].name, bi->count, sp, note);
  }
}

/* The measured plates' layers at the impact point, with a warning under CHECK_LAYERS_MIN. */
static void report_measured(const struct sim *s, const struct measure_run *mr, const size_t *first)
{
  double speed, v[3], rp = 0.0;
  const int pj = projectile(s, first, &speed, v);
  if (pj >= 0)
    for (int d = 1; d < 3; d++) rp = fmax(rp, 0.5 * (s->body[pj].hi[d] - s->body[pj].lo[d]));
  const int ngroups = mr->nplate + (mr->nbackwall > 0);
  for (int k = 0; k < ngroups; k++) {
    const int *bodies = k < mr->nplate ? mr->plate[k] : mr->backwall;
    const int nb = k < mr->nplate ? mr->nplate_body[k] : mr->nbackwall;
    const char *what = k < mr->nplate ? "measure.plates" : "measure.backwall";
    double sp = HUGE_VAL, thick;
    for (int j = 0; j < nb; j++) sp = fmin(sp, s->body[bodies[j]].spacing);
    /* the column the projectile punches: its radius, at least two spacings */
    const double r = fmax(rp, 2.0 * sp);
    int planes = body_planes(s, bodies, nb, 0, r, mr->axis_y, &thick);
    if (planes == 0) planes = body_planes(s, bodies, nb, 0, 0.0, mr->axis_y, &thick);
    printf("%-16s perforation measured (%s): %d particle layer%s through %.4g mm at the "
           "impact point\n", s->body[bodies[0]].name, what, planes, planes == 1 ? "" : "s",
           1e3 * thick);
    if (planes < CHECK_LAYERS_MIN)
      hv_warn("plate '%s' (%s): only %d particle layer%s through its %.4g mm at the impact "
              "point; its perforation is measured, and with fewer than %d layers the answer "
              "follows the lattice more than the physics (two layers of 1.26 mm gave "
              "perforated, not perforated, perforated for 2, 3 and 4 mm spheres): give it a "
              "spacing of at most %.4g mm there (a finer disc joined with part_of, as "
              "examples/paper/wp1.yaml does)", s->body[bodies[0]].name, what, planes,
              planes == 1 ? "" : "s", 1e3 * thick, CHECK_LAYERS_MIN,
              1e3 * thick / CHECK_LAYERS_MIN);
  }
}

/* Times a few steps of the set-up case (it is not run afterwards): seconds per step,
 * or -1 with err set when a step fails. */
static double time_steps(struct sim *s, int *timed, struct hv_error *err)
{
  const double w0 = omp_get_wtime();
  if (step_advance(s, err)) return -1.0;   /* warm-up: the grid, caches, first sums */
  const double w1 = omp_get_wtime();
  *timed = 0;
  while (*timed < CHECK_CALIB_STEPS && omp_get_wtime() - w0 < CHECK_CALIB_WALL &&
         s->t < s->tp.end) {
    if (step_advance(s, err)) return -1.0;
    ++*timed;
  }
  if (*timed == 0) {
    *timed = 1;
    return w1 - w0;
  }
  return (omp_get_wtime() - w1) / *timed;
}

/* "hvsph check: <what> '<arg>' (see hvsph check --help)": exit status 1 */
static int usage_error(const char *what, const char *arg)
{
  fprintf(stderr, "hvsph check: %s%s%s%s (see hvsph check --help)\n", what, arg ? " '" : "",
          arg ? arg : "", arg ? "'" : "");
  return HV_EXIT_USAGE;
}

int check_main(int argc, char **argv)
{
  const char *case_path = NULL;
  const char **sets = hv_calloc((size_t)argc + 1, sizeof *sets, "check arguments");
  const char **swaps = hv_calloc((size_t)argc + 1, sizeof *swaps, "check arguments");
  int nsets = 0, nswaps = 0, status = HV_EXIT_OK;
  for (int i = 0; i < argc && status == HV_EXIT_OK; i++) {
    const char *a = argv[i];
    if (!strcmp(a, "--set") && i + 1 < argc) sets[nsets++] = argv[++i];
    else if (!strncmp(a, "--set=", 6)) sets[nsets++] = a + 6;
    else if (!strcmp(a, "--material") && i + 1 < argc) swaps[nswaps++] = argv[++i];
    else if (!strcmp(a, "--threads") && i + 1 < argc) {
      char *end;
      const long t = strtol(argv[++i], &end, 10);
      if (*end || end == argv[i] || t < 1 || t > 4096)
        status = usage_error("--threads needs a positive integer, not", argv[i]);
      else omp_set_num_threads((int)t);
    } else if (a[0] == '-' || case_path) status = usage_error("unexpected argument", a);
    else case_path = a;
  }
  if (status == HV_EXIT_OK && !case_path) status = usage_error("missing case file", NULL);
  if (status != HV_EXIT_OK) {
    free(sets);
    free(swaps);
    return status;
  }
  struct hv_error err;
  hv_error_clear(&err);
  struct sim s;
  struct measure_run mr;
  memset(&s, 0, sizeof s);
  memset(&mr, 0, sizeof mr);
  size_t *first = NULL;
  struct cfg *c = cfg_load(case_path, &err);
  if (!c) goto fail;
  for (int i = 0; i < nsets; i++)
    if (cfg_apply_set(c, sets[i], &err)) goto fail;
  if (run_apply_swaps(c, swaps, nswaps, 1, NULL, &err) || run_setup(&s, c, &err) ||
      measure_run_read(&mr, &s, c, &err) || cfg_check_unused(c, &err) || step_init(&s, &err) ||
      check_plausible_end(&s, c, &err))
    goto fail;
  /* the bodies' particles are contiguous, in body order, until the first step */
  first = hv_calloc((size_t)s.nbody + 1, sizeof *first, "check bodies");
  for (int b = 1; b < s.nbody; b++) first[b] = first[b - 1] + s.body[b - 1].count;
  const int threads = omp_get_max_threads();
  printf("case %s (%s): %d bod%s, %zu particles%s, %d thread%s\n", case_path, s.case_name,
         s.nbody, s.nbody == 1 ? "y" : "ies", s.p.n, s.bnd.half_model ? ", half model" : "",
         threads, threads == 1 ? "" : "s");
  report_bodies(&s, first);
  if (mr.nplate > 0 || mr.nbackwall > 0) {
    printf("\n");
    report_measured(&s, &mr, first);
  }
  const double dt0 = s.dt, dt = check_first_stable_step(&s);
  const double steps = ceil((s.tp.end - s.t) / dt * (1.0 - 1e-12));
  const enum dt_limit lim = s.dt_limit;
  const int64_t lim_id = s.dt_limit_id;
  const int lim_body = s.dt_limit_body;
  printf("\nfirst time step  %.4g s (%s", dt0, step_limit_name(lim));
  if ((lim == DT_CFL || lim == DT_ACCELERATION) && lim_body >= 0)
    printf(", particle %lld in '%s'", (long long)lim_id, s.body[lim_body].name);
  printf(")\n");
  printf("steps            about %.*g to time.end = %g s (an estimate: time.end / the first "
         "stable step, %.4g s;\n                 an impact shortens the step, so expect more)\n",
         steps < 1e7 ? 7 : 3, steps, s.tp.end, dt);
  if (s.tp.max_steps > 0 && (double)s.tp.max_steps < steps)
    printf("                 time.max_steps = %ld stops it before\n", s.tp.max_steps);
  fflush(stdout);
  int timed = 0;
  const double per_step = time_steps(&s, &timed, &err);
  if (per_step < 0) {
    hv_error_prefix(&err, "the case sets up, but its first steps fail: ");
    goto fail;
  }
  const size_t arrays = s.p.touched * particles_bytes_per_particle(&s.p) +
                        nbr_grid_bytes(&s.grid) +
                        s.bnd.cap * (sizeof *s.bnd.src + sizeof *s.bnd.flip + sizeof *s.bnd.side) +
                        sph_cache_bytes(&s.cache);
  const long rss = peak_rss_kib();
  printf("memory           %.1f MiB in the solver's arrays (%.0f bytes per particle, ghosts and "
         "neighbour grid\n                 included, after %d step%s); peak resident %.1f MiB\n",
         (double)arrays / 1048576.0, (double)arrays / (double)(s.p.n ? s.p.n : 1), timed + 1,
         timed ? "s" : "", rss > 0 ? (double)rss / 1024.0 : -1.0);
  char wall[64];
  const double capped = s.tp.max_steps > 0 ? fmin(steps, (double)s.tp.max_steps) : steps;
  run_format_duration(wall, sizeof wall, per_step * capped);
  printf("wall time        about %s on this machine with %d thread%s (%d step%s of this case "
         "timed here:\n                 %.3g s a step x %.*g steps; outputs and the impact's "
         "shorter steps add to it)\n", wall, threads, threads == 1 ? "" : "s", timed,
         timed == 1 ? "" : "s", per_step, capped < 1e7 ? 7 : 3, capped);
  goto done;
fail:
  hv_log(0, "%s", err.msg);
  status = err.code ? err.code : HV_EXIT_RUN;
done:
  free(first);
  measure_run_free(&mr);
  sim_free(&s);
  if (c) cfg_free(c);
  free(sets);
  free(swaps);
  return status;
}
