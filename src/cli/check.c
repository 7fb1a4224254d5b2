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
 * The plausibility checks it shares with `hvsph run` are the driver's (run/plausible.c).
 */
#include "cli/cli.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/options.h"
#include "integrate/step.h"
#include "run/measure_run.h"
#include "run/plausible.h"
#include "run/run.h"
#include "sim/sim.h"

/* Perforation with fewer layers than this through a plate is a lattice effect: with two
 * layers the answer did not even grow with the sphere's size (issue 71; docs/cli.md,
 * "hvsph check", and docs/measurements.md, "Wall: what went through"); the paper's
 * cases give their plates 4-5 layers at the impact point (examples/paper/wp1.yaml). */

/* Steps timed for the wall-time estimate (after one untimed warm-up step, which builds
 * the grid and caches), and the wall time after which timing stops early: a case of
 * 1e7 particles takes seconds a step on 2 cores. */
#define CHECK_CALIB_STEPS 3
#define CHECK_CALIB_WALL  10.0 /* [s] */

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

/* The bodies' rows, the projectile and the plates. */
static void report_bodies(const struct sim *s, const size_t *first)
{
  double speed, v[3];
  const int pj = projectile(s, first, &speed, v);
  if (s->p.axisym)
    printf("\naxisymmetric: each particle is a ring about the x axis (its mass the ring's); "
           "radii and\nthicknesses are of the body revolved\n");
  printf("\n%-16s %-16s %10s %11s\n", "body", "material", s->p.axisym ? "rings" : "particles",
         "spacing");
  for (int b = 0; b < s->nbody; b++) {
    const struct body_info *bi = &s->body[b];
    char note[256] = "", sp[32];
    snprintf(sp, sizeof sp, "%.4g mm", 1e3 * bi->spacing);
    double thick;
    const int ax = check_plate_axis(s, b, &thick);
    if (b == pj) {
      /* the radius across the flight: half the widest extent across its main axis */
      int fa = 0;
      for (int d = 1; d < 3; d++)
        if (fabs(v[d]) > fabs(v[fa])) fa = d;
      double r = 0.0, ext[3];
      check_body_extent(s, b, ext);
      for (int d = 0; d < 3; d++)
        if (d != fa) r = fmax(r, 0.5 * ext[d]);
      snprintf(note, sizeof note,
               "projectile: %.3g km/s, radius %.4g mm, %.1f particles per "
               "radius",
               1e-3 * speed, 1e3 * r, r / bi->spacing);
    } else if (ax >= 0) {
      const int one = b;
      double t;
      const int planes = plate_body_planes(s, &one, 1, ax, 0.0, 0.0, &t);
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
  if (pj >= 0) {
    double ext[3];
    check_body_extent(s, pj, ext);
    for (int d = 1; d < 3; d++) rp = fmax(rp, 0.5 * ext[d]);
  }
  const int ngroups = mr->nplate + (mr->nbackwall > 0);
  for (int k = 0; k < ngroups; k++) {
    const int *bodies = k < mr->nplate ? mr->plate[k] : mr->backwall;
    const int nb = k < mr->nplate ? mr->nplate_body[k] : mr->nbackwall;
    const char *what = k < mr->nplate ? "measure.plates" : "measure.backwall";
    double sp = HUGE_VAL, thick;
    for (int j = 0; j < nb; j++) sp = fmin(sp, s->body[bodies[j]].spacing);
    /* the column the projectile punches: its radius, at least two spacings */
    const double r = fmax(rp, 2.0 * sp);
    int planes = plate_body_planes(s, bodies, nb, 0, r, mr->axis_y, &thick);
    if (planes == 0) planes = plate_body_planes(s, bodies, nb, 0, 0.0, mr->axis_y, &thick);
    printf("%-16s perforation measured (%s): %d particle layer%s through %.4g mm at the "
           "impact point\n",
           s->body[bodies[0]].name, what, planes, planes == 1 ? "" : "s", 1e3 * thick);
    if (planes < CHECK_LAYERS_MIN)
      hv_warn("plate '%s' (%s): only %d particle layer%s through its %.4g mm at the impact "
              "point; its perforation is measured, and with fewer than %d layers the answer "
              "follows the lattice more than the physics (two layers of 1.26 mm gave "
              "perforated, not perforated, perforated for 2, 3 and 4 mm spheres): give it a "
              "spacing of at most %.4g mm there (a finer disc joined with part_of, as "
              "examples/paper/wp1.yaml does)",
              s->body[bodies[0]].name, what, planes, planes == 1 ? "" : "s", 1e3 * thick,
              CHECK_LAYERS_MIN, 1e3 * thick / CHECK_LAYERS_MIN);
  }
}

/* Times a few steps of the set-up case (it is not run afterwards): seconds per step,
 * or -1 with err set when a step fails. */
static double time_steps(struct sim *s, int *timed, struct hv_error *err)
{
  const double w0 = omp_get_wtime();
  if (step_advance(s, err)) return -1.0; /* warm-up: the grid, caches, first sums */
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

/* The first step and what limits it, the steps to time.end, the memory and the wall
 * time from a few steps of the case timed here. Returns 0, or -1 with err set when
 * those steps fail. */
static int report_cost(struct sim *s, struct hv_error *err)
{
  const int threads = omp_get_max_threads();
  const double dt0 = s->dt, dt = check_first_stable_step(s);
  const double steps = ceil((s->tp.end - s->t) / dt * (1.0 - 1e-12));
  const enum dt_limit lim = s->dt_limit;
  const int64_t lim_id = s->dt_limit_id;
  const int lim_body = s->dt_limit_body;
  printf("\nfirst time step  %.4g s (%s", dt0, step_limit_name(lim));
  if ((lim == DT_CFL || lim == DT_ACCELERATION) && lim_body >= 0)
    printf(", particle %lld in '%s'", (long long)lim_id, s->body[lim_body].name);
  printf(")\n");
  printf("steps            about %.*g to time.end = %g s (an estimate: time.end / the first "
         "stable step, %.4g s;\n                 an impact shortens the step, so expect more)\n",
         steps < 1e7 ? 7 : 3, steps, s->tp.end, dt);
  if (s->tp.max_steps > 0 && (double)s->tp.max_steps < steps)
    printf("                 time.max_steps = %ld stops it before\n", s->tp.max_steps);
  fflush(stdout);
  int timed = 0;
  const double per_step = time_steps(s, &timed, err);
  if (per_step < 0) {
    hv_error_prefix(err, "the case sets up, but its first steps fail: ");
    return -1;
  }
  const size_t arrays =
      s->p.touched * particles_bytes_per_particle(&s->p) + nbr_grid_bytes(&s->grid) +
      s->bnd.cap * (sizeof *s->bnd.src + sizeof *s->bnd.flip + sizeof *s->bnd.side) +
      sph_cache_bytes(&s->cache);
  const long rss = cli_peak_rss_kib();
  printf("memory           %.1f MiB in the solver's arrays (%.0f bytes per particle, ghosts and "
         "neighbour grid\n                 included, after %d step%s); peak resident %.1f MiB\n",
         (double)arrays / 1048576.0, (double)arrays / (double)(s->p.n ? s->p.n : 1), timed + 1,
         timed ? "s" : "", rss > 0 ? (double)rss / 1024.0 : -1.0);
  char wall[64];
  const double capped = s->tp.max_steps > 0 ? fmin(steps, (double)s->tp.max_steps) : steps;
  run_format_duration(wall, sizeof wall, per_step * capped);
  printf("wall time        about %s on this machine with %d thread%s (%d step%s of this case "
         "timed here:\n                 %.3g s a step x %.*g steps; outputs and the impact's "
         "shorter steps add to it)\n",
         wall, threads, threads == 1 ? "" : "s", timed, timed == 1 ? "" : "s", per_step,
         capped < 1e7 ? 7 : 3, capped);
  return 0;
}

/* Every mistake on check's command line is "unexpected argument". */
static int check_fail(const struct cli_cmd *c, enum cli_error e, const char *arg)
{
  (void)c;
  (void)e;
  return usage_error("unexpected argument", arg);
}

/* --threads: set at once, for the set-up and the steps timed */
static int check_threads(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                         const char *val)
{
  (void)c;
  (void)opt;
  long t;
  if (cli_decimal(val, o->lo, o->hi, &t))
    return usage_error("--threads needs a positive integer, not", val);
  omp_set_num_threads((int)t);
  return CLI_GO_ON;
}

int cli_check(int argc, char **argv)
{
  const char *case_path = NULL;
  struct cli_list sets = {hv_calloc((size_t)argc + 1, sizeof *sets.v, "check arguments"), 0, argc};
  struct cli_list swaps = {hv_calloc((size_t)argc + 1, sizeof *swaps.v, "check arguments"), 0,
                           argc};
  const struct cli_opt opts[] = {
      {"--set", NULL, CLI_LIST, .eq = 1, .dest = &sets},
      {"--material", NULL, CLI_LIST, .dest = &swaps},
      {"--threads", NULL, CLI_VALUE, .convert = check_threads, .lo = 1, .hi = 4096},
  };
  const struct cli_cmd cmd = {.name = "check",
                              .opts = opts,
                              .nopts = (int)(sizeof opts / sizeof opts[0]),
                              .positional = &case_path,
                              .fail = check_fail};
  int status = cli_parse(&cmd, argc, argv);
  if (status == CLI_GO_ON && !case_path) status = usage_error("missing case file", NULL);
  const char **const set = sets.v, **const swap = swaps.v;
  const int nsets = sets.n, nswaps = swaps.n;
  if (status != CLI_GO_ON) {
    free(set);
    free(swap);
    return status;
  }
  status = HV_EXIT_OK;
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
    if (cfg_apply_set(c, set[i], &err)) goto fail;
  if (run_apply_swaps(c, swap, nswaps, 1, NULL, &err) || run_setup(&s, c, &err) ||
      measure_run_read(&mr, &s, c, &err) || cfg_check_unused(c, &err) || step_init(&s, &err) ||
      check_plausible_end(&s, c, &err))
    goto fail;
  /* the bodies' particles are contiguous, in body order, until the first step */
  first = hv_calloc((size_t)s.nbody + 1, sizeof *first, "check bodies");
  for (int b = 1; b < s.nbody; b++) first[b] = first[b - 1] + s.body[b - 1].count;
  const int threads = omp_get_max_threads();
  printf("case %s (%s): %d bod%s, %zu particles%s, %d thread%s\n", case_path, s.case_name, s.nbody,
         s.nbody == 1 ? "y" : "ies", s.p.n,
         s.bnd.quarter_model ? ", quarter model"
         : s.bnd.half_model  ? ", half model"
                             : "",
         threads, threads == 1 ? "" : "s");
  report_bodies(&s, first);
  if (mr.nplate > 0 || mr.nbackwall > 0) {
    printf("\n");
    report_measured(&s, &mr, first);
  }
  if (report_cost(&s, &err)) goto fail;
  goto done;
fail:
  hv_log(0, "%s", err.msg);
  status = err.code ? err.code : HV_EXIT_RUN;
done:
  free(first);
  measure_run_free(&mr);
  sim_free(&s);
  if (c) cfg_free(c);
  free(set);
  free(swap);
  return status;
}
