/* params.c — reading the solver parameters of a case file (sph, time, output,
 * materials, domain). Every key has a documented default (docs/case-files.md). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "material/material_read.h"
#include "sph/rz.h"
#include "sim/sim.h"

static int read_sph(struct sph_params *sp, struct cfg *c, struct hv_error *err)
{
  static const char *const kernels[] = {"cubic-spline", "wendland-c2", "quadratic", NULL};
  static const char *const densities[] = {"continuity", "summation", NULL};
  static const char *const forms[] = {"volume", "mass", NULL};
  static const char *const switches[] = {"none", "cullen-dehnen", NULL};
  int k, dens, form, sw, no = 0, yes = 1;
  double eta = 1.2, alpha = 1.0, beta = 2.0, eps = 0.01, zero = 0.0, decay = 0.05;
  static const char *const geometries[] = {"3d", "axisymmetric", NULL};
  double as_eps = 0.3, as_n = 4.0, rest_tol = 1e-14, stretch = RZ_STRETCH_MAX;
  int geometry = 0;
  /* an axisymmetric case runs without the artificial stress (setup/rz.c) */
  if (cfg_get_choice(c, "domain.geometry", geometries[0], geometries, &geometry, err)) return -1;
  if (geometry == 1) as_eps = 0.0;
  if (cfg_get_choice(c, "sph.kernel", "cubic-spline", kernels, &k, err) ||
      cfg_get_choice(c, "sph.density", "continuity", densities, &dens, err) ||
      cfg_get_choice(c, "sph.continuity", "volume", forms, &form, err) ||
      cfg_get_quantity(c, "sph.eta", UNIT_NONE, &eta, 0.8, 3.0, &sp->eta, err) ||
      cfg_get_quantity(c, "sph.h_min", UNIT_LENGTH, &zero, 0.0, HUGE_VAL, &sp->h_min, err) ||
      cfg_get_quantity(c, "sph.h_max", UNIT_LENGTH, &zero, 0.0, HUGE_VAL, &sp->h_max, err) ||
      cfg_get_quantity(c, "sph.viscosity.alpha", UNIT_NONE, &alpha, 0.0, 10.0, &sp->alpha, err) ||
      cfg_get_quantity(c, "sph.viscosity.beta", UNIT_NONE, &beta, 0.0, 20.0, &sp->beta, err) ||
      cfg_get_quantity(c, "sph.viscosity.epsilon", UNIT_NONE, &eps, 1e-6, 1.0, &sp->eps, err) ||
      cfg_get_quantity(c, "sph.artificial_stress.epsilon", UNIT_NONE, &as_eps, 0.0, 2.0,
                       &sp->as_eps, err) ||
      cfg_get_quantity(c, "sph.artificial_stress.n", UNIT_NONE, &as_n, 1.0, 10.0, &sp->as_n, err) ||
      cfg_get_bool(c, "sph.gradient_correction", &no, &sp->grad_correction, err) ||
      cfg_get_bool(c, "sph.viscosity.reconstruct", &no, &sp->reconstruct, err) ||
      cfg_get_bool(c, "sph.viscosity.reconstruct_contact", &no, &sp->reconstruct_contact, err) ||
      cfg_get_quantity(c, "sph.density_diffusion", UNIT_NONE, &zero, 0.0, 1.0,
                       &sp->density_diffusion, err) ||
      cfg_get_bool(c, "sph.skip_resting", &yes, &sp->skip_resting, err) ||
      cfg_get_quantity(c, "sph.rest_tolerance", UNIT_NONE, &rest_tol, 0.0, 1e-6, &sp->rest_tol,
                       err) ||
      cfg_get_choice(c, "sph.viscosity.switch", "none", switches, &sw, err) ||
      cfg_get_quantity(c, "sph.viscosity.alpha_min", UNIT_NONE, &zero, 0.0, 10.0, &sp->av_min,
                       err) ||
      cfg_get_quantity(c, "sph.viscosity.decay", UNIT_NONE, &decay, 1e-3, 1.0, &sp->av_decay, err))
    return -1;
  /* read in RZ only: a 3D run's used_parameters.yaml does not list it */
  if (geometry == 1 && cfg_get_quantity(c, "sph.rz_stretch_max", UNIT_NONE, &stretch, 0.0, 1e6,
                                        &sp->rz_stretch_max, err))
    return -1;
  sp->av_switch = sw;
  sp->kernel = (enum kernel_kind)k;
  sp->summation = dens;
  sp->continuity_mass = form;
  char where[256];
  if (geometry != 1 && cfg_has(c, "sph.rz_stretch_max"))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: sph.rz_stretch_max: the hoop stretch of a ring is for "
                        "axisymmetric runs (domain.geometry: axisymmetric); remove it here",
                        cfg_where(c, "sph.rz_stretch_max", where, sizeof where));
  if (sp->rz_stretch_max > 0.0 && sp->rz_stretch_max < 1.0)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: sph.rz_stretch_max: %g is below 1: it caps the stretch r/r0 that "
                        "a ring's h follows (0: no cap)",
                        cfg_where(c, "sph.rz_stretch_max", where, sizeof where),
                        sp->rz_stretch_max);
  if (sp->av_switch && !(sp->alpha > 0.0))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: sph.viscosity.switch: cullen-dehnen varies "
                        "each particle's alpha up to sph.viscosity.alpha, which is 0 here",
                        cfg_where(c, "sph.viscosity.switch", where, sizeof where));
  if (sp->av_switch && sp->av_min > sp->alpha)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: sph.viscosity.alpha_min (%g) exceeds "
                        "sph.viscosity.alpha (%g), the switch's largest alpha",
                        cfg_where(c, "sph.viscosity.alpha_min", where, sizeof where), sp->av_min,
                        sp->alpha);
  if (sp->reconstruct_contact && !sp->reconstruct)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: sph.viscosity.reconstruct_contact: it extends "
                        "the reconstruction to pairs of different bodies, and needs "
                        "sph.viscosity.reconstruct: true",
                        cfg_where(c, "sph.viscosity.reconstruct_contact", where, sizeof where));
  /* the switch's own settings, given a value of their own without it, do nothing: said
     once (not refused: used_parameters.yaml lists them with their defaults, and a case
     may keep them while the switch is tried on and off) */
  if (!sp->av_switch && ((cfg_has(c, "sph.viscosity.alpha_min") && sp->av_min != zero) ||
                         (cfg_has(c, "sph.viscosity.decay") && sp->av_decay != decay)))
    hv_warn("%s: sph.viscosity.%s has no effect without sph.viscosity.switch: cullen-dehnen "
            "(the viscosity's alpha is sph.viscosity.alpha = %g everywhere)",
            cfg_where(c, sp->av_min != zero ? "sph.viscosity.alpha_min" : "sph.viscosity.decay",
                      where, sizeof where),
            sp->av_min != zero ? "alpha_min" : "decay", sp->alpha);
  if (sp->h_max > 0 && sp->h_min > sp->h_max)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: sph.h_min (%g m) exceeds sph.h_max (%g m)",
                        cfg_where(c, "sph.h_min", where, sizeof where), sp->h_min, sp->h_max);
  return 0;
}

static int read_time(struct time_params *tp, struct cfg *c, struct hv_error *err)
{
  double cfl = 0.3, cfla = 0.25, zero = 0.0, dtmin = 1e-30, growth = 1.2;
  long maxs = 0;
  return cfg_get_quantity(c, "time.end", UNIT_TIME, NULL, 0.0, HUGE_VAL, &tp->end, err) ||
                 cfg_get_quantity(c, "time.cfl", UNIT_NONE, &cfl, 1e-3, 1.0, &tp->cfl, err) ||
                 cfg_get_quantity(c, "time.cfl_acceleration", UNIT_NONE, &cfla, 1e-3, 1.0,
                                  &tp->cfl_acc, err) ||
                 cfg_get_quantity(c, "time.dt_init", UNIT_TIME, &zero, 0.0, HUGE_VAL, &tp->dt_init,
                                  err) ||
                 cfg_get_quantity(c, "time.dt_max", UNIT_TIME, &zero, 0.0, HUGE_VAL, &tp->dt_max,
                                  err) ||
                 cfg_get_quantity(c, "time.dt_min", UNIT_TIME, &dtmin, 0.0, HUGE_VAL, &tp->dt_min,
                                  err) ||
                 cfg_get_quantity(c, "time.growth", UNIT_NONE, &growth, 1.0, 10.0, &tp->growth,
                                  err) ||
                 cfg_get_int(c, "time.max_steps", &maxs, 0, 1000000000L, &tp->max_steps, err)
             ? -1
             : 0;
}

static int read_output(struct output_params *op, struct cfg *c, struct hv_error *err)
{
  double zero = 0.0;
  int yes = 1, no = 0;
  long every = 100;
  double ten_min = 600.0;
  return cfg_get_quantity(c, "output.every", UNIT_TIME, &zero, 0.0, HUGE_VAL, &op->every, err) ||
                 cfg_get_bool(c, "output.checkpoint", &yes, &op->checkpoint, err) ||
                 cfg_get_quantity(c, "output.checkpoint_wall", UNIT_TIME, &ten_min, 0.0, HUGE_VAL,
                                  &op->checkpoint_wall, err) ||
                 cfg_get_bool(c, "output.vtu", &yes, &op->vtu, err) ||
                 cfg_get_bool(c, "output.csv", &no, &op->csv, err) ||
                 cfg_get_bool(c, "output.compress", &no, &op->compress, err) ||
                 cfg_get_int(c, "output.log_every", &every, 1, 1000000000L, &op->log_every, err)
             ? -1
             : 0;
}

static int read_materials(struct sim *s, struct cfg *c, struct hv_error *err)
{
  const char *const *names;
  char where[256], path[256];
  s->nmat = 0;
  if (!cfg_has(c, "materials")) return 0; /* bodies may name library materials only */
  int n = cfg_keys(c, "materials", &names);
  if (n < 0)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: 'materials' must map material names to "
                        "their parameters",
                        cfg_where(c, "materials", where, sizeof where));
  if (n > HV_MAX_MATERIALS)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: at most %d materials",
                        cfg_where(c, "materials", where, sizeof where), HV_MAX_MATERIALS);
  for (int i = 0; i < n; i++) {
    snprintf(path, sizeof path, "materials.%s", names[i]);
    if (material_read(c, path, names[i], &s->mat[i], err)) return -1;
  }
  s->nmat = n;
  return 0;
}

/* The case's name names its output folder (out/<name>) and is written into every output
 * file: a plain file name of ASCII letters, digits and . _ - +, starting with a letter,
 * digit or _ (so no '/' that leaves out/, no "." or "..", no leading '-' that a shell
 * command would take for an option, no blanks or control characters), at most 100
 * characters. */
#define CASE_NAME_MAX 100
static int check_name(struct cfg *c, const char *name, struct hv_error *err)
{
  const size_t n = strlen(name);
  size_t bad = n;
  for (size_t k = 0; k < n && bad == n; k++) {
    const unsigned char ch = (unsigned char)name[k];
    const int alnum =
        (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9');
    if (!(alnum || ch == '_' || (k > 0 && (ch == '.' || ch == '-' || ch == '+')))) bad = k;
  }
  if (n > 0 && n <= CASE_NAME_MAX && bad == n) return 0;
  char where[256], what[64];
  const unsigned char ch = bad < n ? (unsigned char)name[bad] : 0;
  if (n == 0)
    snprintf(what, sizeof what, "it is empty");
  else if (n > CASE_NAME_MAX)
    snprintf(what, sizeof what, "%zu characters", n);
  else if (ch >= ' ' && ch < 0x7f)
    snprintf(what, sizeof what, "'%c' at character %zu", ch, bad + 1);
  else
    snprintf(what, sizeof what, "byte 0x%02x at character %zu", ch, bad + 1);
  char shown[64]; /* control characters as '?': the message stays one line */
  snprintf(shown, sizeof shown, "%.60s%s", name, n > 60 ? "..." : "");
  for (char *q = shown; *q; q++)
    if ((unsigned char)*q < ' ' || *q == 0x7f) *q = '?';
  return hv_error_set(err, HV_EXIT_INPUT,
                      "%s: name: '%s' is not a plain file name (%s): "
                      "the name is the output folder's (out/<name>); write it with ASCII "
                      "letters, digits and . _ - +, starting with a letter, digit or _, at "
                      "most %d characters (e.g. \"whipple-shield_2\")",
                      cfg_where(c, "name", where, sizeof where), shown, what, CASE_NAME_MAX);
}

int sim_read_params(struct sim *s, struct cfg *c, struct hv_error *err)
{
  long reorder_def = 10, reorder = 10;
  const char *name;
  if (cfg_get_string(c, "name", "case", &name, err) || check_name(c, name, err)) return -1;
  snprintf(s->case_name, sizeof s->case_name, "%s", name);
  if (read_sph(&s->sph, c, err) || read_time(&s->tp, c, err) || read_output(&s->out, c, err) ||
      read_materials(s, c, err) || boundary_read(&s->bnd, c, err) ||
      cfg_get_int(c, "sph.reorder_every", &reorder_def, 1, 1000000, &reorder, err) ||
      sim_axisym_params(s, c, err))
    return -1;
  s->reorder_every = (int)reorder;
  /* a bare interval longer than the run: a number meant in us (`every: 5`); not one
     written with its unit (a --set time.end shorter than it, for a quick look) */
  if (s->out.every > s->tp.end && s->tp.end > 0.0 && cfg_is_bare(c, "output.every")) {
    char where[256];
    hv_warn("%s: output.every = %g s is longer than time.end = %g s: outputs at the start and "
            "the end only (a number without a unit is seconds; 0 says 'start and end' outright)",
            cfg_where(c, "output.every", where, sizeof where), s->out.every, s->tp.end);
  }
  return 0;
}

void sim_free(struct sim *s)
{
  particles_free(&s->p);
  for (int m = 0; m < s->nmat; m++) material_free(&s->mat[m]);
  boundary_free(&s->bnd);
  nbr_grid_free(&s->grid);
  sph_cache_free(&s->cache);
}
