/* validate.c — `hvsph validate [--rz] [--scale S] [--only NAME...] [-o DIR] [--threads N]
 * [--cases DIR] [--no-run] [--list]`.
 *
 * Runs each case of examples/paper/ (or --cases DIR) with its particle counts times S
 * (resolution = S), into DIR/<case>/, then puts the final value of each measured
 * quantity named in data/paper_results.yaml beside the experiment and the paper's own
 * simulation: DIR/validation.csv (a "# hvsph <version>" comment line, then
 * case,quantity,simulated,experiment,paper_simulation,unit,rel_error) and DIR/validation.md (tables, mean errors, runtimes, radiographs of
 * the final states of the impact cases). --no-run only re-reads earlier runs' outputs.
 * --resume continues each case that has a checkpoint in DIR/<case>/ (hvsph restart:
 * a stopped run goes on, a finished one is only re-read) and runs the others.
 * --set KEY=VALUE and --material OLD=NEW go to every case's run as to hvsph run's (a
 * material swap that no selected case takes is bad input) and are written at the head
 * of validation.md: one material set for the whole table, as the paper's aims ask.
 * A case's folder is validate's own: a new run of a case replaces the earlier one there
 * (hvsph run --overwrite). DIR is locked for the whole validation and each case's folder
 * while it runs (run/runfolder.h), so that two validations do not write one DIR.
 * --rz takes the axisymmetric cases of examples/paper/rz/ (the paper's normal impacts;
 * issue 74) instead, into out/validation-rz by default: the cases are the reference's
 * that have a file there, compared with the same rows; their resolution 1 is ten
 * particles per projectile radius, S scaling the ring counts (the spacing as S^-1/2).
 * --list prints the cases that would run (name, case file, the quantities compared)
 * and runs nothing, writes nothing; its --material swaps are checked on the case files
 * as before a run (a dry check of a material set).
 */
#include "cli/cli.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/options.h"
#include "config/config.h"
#include "diag/measure_table.h"
#include "run/restart.h"
#include "io/atomic_file.h"
#include "io/snapshot.h"
#include "material/material_read.h"
#include "render/render.h"
#include "run/run.h"
#include "run/runfolder.h"
#include "version.h"

#define VAL_MAX_CASES     64
#define VAL_MAX_ROWS      512
#define VAL_MAX_OVERRIDES 32

struct val_row {
  char cas[64], quantity[64], object[64], unit[16], note[256];
  double sim, exp, paper, paper_lo, paper_hi; /* NaN: none */
  int approx;
  int in_mean; /* counted in the mean error (0: another reading of a value already counted) */
};

struct val_case {
  char name[64];
  double runtime; /* [s] wall clock, NaN if not run now */
  int segments;   /* rows of its run_segments.csv (runs and restarts); 0: none */
  long particles;
  int status; /* exit status of the run (0 ok, -1 not run) */
};

/* The row (quantity, object) at time `time` (bitwise), or NULL. */
static const struct meas_row *row_at(const struct meas_table *t, const char *quantity,
                                     const char *object, double time)
{
  for (size_t k = 0; k < t->n; k++) {
    const struct meas_row *r = &t->rows[k];
    if (r->time == time && !strcmp(r->quantity, quantity) && !strcmp(r->object, object)) return r;
  }
  return NULL;
}

/* The value of (quantity, object) in a run's measurements: the last one, or for a debris
 * cloud's quantities the one at the output time when the cloud in free flight held the
 * most mass: its leading edge still short of the next plate by 5 % of the gap
 * (cloud_lead_distance < 0.95 cloud_gap; debris that has reached the plate piles up
 * there at rest and is still inside the cloud's region); NaN if absent. */
static double pick_measurement(const struct meas_table *t, const char *quantity, const char *object,
                               char *unit, size_t ulen)
{
  double v = NAN, best_time = NAN;
  if (!strncmp(quantity, "cloud_", 6)) {
    double best_mass = -1.0;
    for (size_t k = 0; k < t->n; k++) {
      const struct meas_row *r = &t->rows[k];
      if (strcmp(r->object, object) || strcmp(r->quantity, "cloud_mass") || !(r->value > best_mass))
        continue;
      const struct meas_row *lead = row_at(t, "cloud_lead_distance", object, r->time);
      const struct meas_row *gap = row_at(t, "cloud_gap", object, r->time);
      if (lead && gap && !(lead->value < 0.95 * gap->value)) continue; /* arrived */
      best_mass = r->value;
      best_time = r->time;
    }
  }
  for (size_t k = 0; k < t->n; k++) {
    const struct meas_row *r = &t->rows[k];
    if (strcmp(r->object, object) || strcmp(r->quantity, quantity)) continue;
    if (!isnan(best_time) && r->time != best_time) continue;
    v = r->value;
    snprintf(unit, ulen, "%s", r->unit);
  }
  return v;
}

static double get_opt(struct cfg *c, const char *path, enum unit_dim dim, struct hv_error *err)
{
  double v;
  if (!cfg_has(c, path)) return NAN;
  if (cfg_get_quantity(c, path, dim, NULL, -HUGE_VAL, HUGE_VAL, &v, err)) return NAN;
  return v;
}

static enum unit_dim dim_of(const char *quantity)
{
  if (strstr(quantity, "velocity")) return UNIT_VELOCITY;
  if (strstr(quantity, "angle")) return UNIT_ANGLE;
  if (strstr(quantity, "pressure")) return UNIT_PRESSURE;
  if (strstr(quantity, "count") || !strcmp(quantity, "perforated")) return UNIT_NONE;
  return UNIT_LENGTH;
}

/* Particles in the run's first summary row (-1 without a summary). */
static long particles_of(const char *outdir)
{
  char path[4400];
  struct hv_error e;
  double *n = NULL;
  snprintf(path, sizeof path, "%s/summary.csv", outdir);
  const int rows = io_read_table_column(path, "n", &n, &e);
  const long v = rows > 0 ? (long)n[0] : -1;
  free(n);
  return v;
}

/* The last snapshot of a run folder (CSV, or VTU when it wrote none), or "" */
static void last_snapshot(const char *dir, char *out, size_t len)
{
  int *nums = NULL, n;
  const char *ext = io_list_readable_snapshots(dir, &nums, &n);
  out[0] = 0;
  if (n > 0) snprintf(out, len, "%s/particles_%05d.%s", dir, nums[n - 1], ext);
  free(nums);
}

/* Radiograph (side view along z, mirrored) of the final state. */
static int render_final(const char *dir, const char *png, struct hv_error *err)
{
  char snap[4400];
  last_snapshot(dir, snap, sizeof snap);
  if (!snap[0]) return 0;
  struct particles p;
  particles_init(&p);
  double t = NAN;
  int rc = io_read_particles(snap, &p, &t, err);
  if (!rc) {
    struct render_options o;
    render_options_default(&o);
    o.mode = RENDER_RADIOGRAPH;
    o.axis = 2;
    o.width = 900;
    struct render_info info = {.time = t, .source = snap};
    rc = render_png(png, &p, &o, &info, err);
  }
  particles_free(&p);
  return rc;
}

/* The user's --set and --material, given to every case's run. */
struct val_overrides {
  const char *sets[VAL_MAX_OVERRIDES], *swaps[VAL_MAX_OVERRIDES];
  int nsets, nswaps;
};

static int run_case(const char *cases, const char *name, const char *outdir, double scale,
                    int threads, int resume, struct val_overrides *ov, struct val_case *vc)
{
  char casefile[8400], set1[64];
  snprintf(casefile, sizeof casefile, "%s/%s.yaml", cases, name);
  snprintf(set1, sizeof set1, "resolution=%.17g", scale);
  const char *sets[VAL_MAX_OVERRIDES + 2] = {set1, "output.csv=true"};
  for (int k = 0; k < ov->nsets; k++) sets[2 + k] = ov->sets[k];
  struct run_options ro = {.case_path = casefile,
                           .outdir = outdir,
                           .sets = sets,
                           .nsets = 2 + ov->nsets,
                           .threads = threads,
                           .swaps = ov->swaps,
                           .nswaps = ov->nswaps,
                           .swaps_lenient = 1,
                           .overwrite = 1};
  char ckpt[8400];
  restart_path(outdir, ckpt, sizeof ckpt);
  if (resume && access(ckpt, R_OK) == 0) { /* continue it (its own resolution) */
    ro.restart_dir = outdir;               /* its used_parameters.yaml holds the overrides */
    ro.nsets = 0;
    ro.nswaps = 0;
    fprintf(stderr, "hvsph validate: %s: continuing the run in %s from its checkpoint\n", name,
            outdir);
  } else {
    fprintf(stderr, "hvsph validate: %s (resolution %g) -> %s\n", name, scale, outdir);
  }
  double t0 = omp_get_wtime();
  vc->status = run_main(&ro);
  vc->runtime = omp_get_wtime() - t0;
  return vc->status;
}

static void fmt_val(char *buf, size_t len, double v, double scale)
{
  if (isnan(v))
    snprintf(buf, len, "–");
  else
    snprintf(buf, len, "%.4g", v * scale);
}

/* Display unit for a quantity: mm, km/s, deg, kbar or none, with the factor from SI. */
static const char *display_unit(enum unit_dim d, double *f)
{
  switch (d) {
  case UNIT_LENGTH: *f = 1e3; return "mm";
  case UNIT_VELOCITY: *f = 1e-3; return "km/s";
  case UNIT_ANGLE: *f = 180.0 / 3.14159265358979323846; return "deg";
  case UNIT_PRESSURE: *f = 1e-8; return "kbar";
  default: *f = 1.0; return "";
  }
}

/* DIR/validation.csv: one line per row, the simulated, experimental and the paper's
 * values in display units and the relative error against the experiment. */
static int write_csv(const char *dir, const struct val_row *rows, int nrows, int norun,
                     struct hv_error *err)
{
  char path[4200];
  struct atomic_file af;
  snprintf(path, sizeof path, "%s/validation.csv", dir);
  if (atomic_file_open(&af, path, err)) return -1;
  /* a comment line first, as every CSV table of hvsph has (pandas' comment="#" and the
     numpy recipe of docs/output-files.md skip it) */
  atomic_file_printf(&af, err,
                     "# hvsph %s: validation against the seed paper%s (validation.md)\n"
                     "case,quantity,simulated,experiment,paper_simulation,unit,rel_error\n",
                     HVSPH_VERSION, norun ? ", re-read from earlier runs" : "");
  for (int k = 0; k < nrows; k++) {
    const struct val_row *r = &rows[k];
    double f;
    const char *u = display_unit(dim_of(r->quantity), &f);
    double paper = r->paper;
    if (isnan(paper)) paper = 0.5 * (r->paper_lo + r->paper_hi);
    double rel = NAN;
    if (!isnan(r->exp) && r->exp != 0) rel = (r->sim - r->exp) / r->exp;
    atomic_file_printf(&af, err, "%s,%s%s%s,%.6g,%.6g,%.6g,%s,%.4g\n", r->cas, r->quantity,
                       strchr(r->object, ':') || strcmp(r->object, "") ? ":" : "", r->object,
                       r->sim * f, r->exp * f, paper * f, u, rel);
  }
  return atomic_file_commit(&af, err);
}

static int write_reports(const char *dir, const struct val_row *rows, int nrows,
                         const struct val_case *cs, int ncase, double scale, int norun, int rz,
                         const struct val_overrides *ov, struct hv_error *err)
{
  char path[4200];
  struct atomic_file af;
  if (write_csv(dir, rows, nrows, norun, err)) return -1;
  snprintf(path, sizeof path, "%s/validation.md", dir);
  if (atomic_file_open(&af, path, err)) return -1;
  if (norun)
    atomic_file_printf(&af, err,
                       "# Validation against the seed paper\n\nTables%s re-read by hvsph %s "
                       "(`--no-run`) from earlier runs; the version, resolution and thread count "
                       "of each run are in its `used_parameters.yaml` and log.\n\n",
                       rz ? " of the axisymmetric (RZ) cases" : "", HVSPH_VERSION);
  else if (rz)
    atomic_file_printf(&af, err,
                       "# Validation against the seed paper\n\nhvsph %s, the axisymmetric (RZ) "
                       "cases of examples/paper/rz/ at resolution %g (%.3g particles per "
                       "projectile radius), %d thread%s.\n\n",
                       HVSPH_VERSION, scale, 10.0 * sqrt(scale), omp_get_max_threads(),
                       omp_get_max_threads() == 1 ? "" : "s");
  else
    atomic_file_printf(&af, err,
                       "# Validation against the seed paper\n\nhvsph %s, particle counts × %g "
                       "of the paper's (resolution %g), %d thread%s.\n\n",
                       HVSPH_VERSION, scale, scale, omp_get_max_threads(),
                       omp_get_max_threads() == 1 ? "" : "s");
  if (ov->nsets + ov->nswaps) {
    atomic_file_printf(&af, err, "Every case run with");
    for (int k = 0; k < ov->nswaps; k++)
      atomic_file_printf(&af, err, " `--material %s`", ov->swaps[k]);
    for (int k = 0; k < ov->nsets; k++) atomic_file_printf(&af, err, " `--set %s`", ov->sets[k]);
    atomic_file_printf(&af, err, " (the case files otherwise as committed).\n\n");
  }
  atomic_file_printf(
      &af, err,
      "| case | quantity | hvsph | experiment | paper (KERNEL) | unit | hvsph vs exp. | paper vs exp. |\n"
      "|---|---|---|---|---|---|---|---|\n");
  double sum_us = 0, sum_paper = 0;
  int n_both = 0;
  for (int k = 0; k < nrows; k++) {
    const struct val_row *r = &rows[k];
    double f;
    const char *u = display_unit(dim_of(r->quantity), &f);
    char s[32], e[32], pp[64], eu[32] = "–", ep[32] = "–";
    fmt_val(s, sizeof s, r->sim, f);
    fmt_val(e, sizeof e, r->exp, f);
    if (!isnan(r->paper))
      fmt_val(pp, sizeof pp, r->paper, f);
    else if (!isnan(r->paper_lo))
      snprintf(pp, sizeof pp, "%.3g–%.3g", r->paper_lo * f, r->paper_hi * f);
    else
      snprintf(pp, sizeof pp, "–");
    if (!isnan(r->exp) && r->exp != 0 && !isnan(r->sim)) {
      double a = (r->sim - r->exp) / r->exp;
      snprintf(eu, sizeof eu, "%+.1f %%", 100 * a);
      if (!isnan(r->paper)) {
        const double b = (r->paper - r->exp) / r->exp;
        snprintf(ep, sizeof ep, "%+.1f %%", 100 * b);
        if (r->in_mean) {
          sum_us += fabs(a);
          sum_paper += fabs(b);
          n_both++;
        }
      }
    }
    atomic_file_printf(&af, err, "| %s | %s (%s)%s%s | %s | %s%s | %s%s | %s | %s | %s |\n", r->cas,
                       r->quantity, r->object, r->note[0] ? " ¹" : "", r->in_mean ? "" : " ²", s,
                       r->approx ? "~" : "", e, r->approx ? "~" : "", pp, u, eu, ep);
  }
  if (n_both)
    atomic_file_printf(
        &af, err,
        "\nMean |relative error| against the experiments, over the %d "
        "quantities where both simulations give a number: hvsph %.1f %%, the paper's "
        "KERNEL code %.1f %%. Rows marked ² are a second reading of an experimental "
        "value already counted and are left out of the mean.\n",
        n_both, 100 * sum_us / n_both, 100 * sum_paper / n_both);
  int noted = 0; /* the notes' heading only where a row has one */
  for (int k = 0; k < nrows; k++)
    if (rows[k].note[0])
      atomic_file_printf(&af, err, "%s- %s, %s (%s): %s\n", noted++ ? "" : "\n¹ notes:\n\n",
                         rows[k].cas, rows[k].quantity, rows[k].object, rows[k].note);
  atomic_file_printf(
      &af, err,
      "\n## Runs\n\n| case | particles | runtime [s] | status | radiograph |\n|---|---|---|---|---|\n");
  for (int k = 0; k < ncase; k++) {
    char rt[64];
    if (isnan(cs[k].runtime))
      snprintf(rt, sizeof rt, "(earlier run)");
    else if (cs[k].segments > 1)
      snprintf(rt, sizeof rt, "%.0f (%d segments)", cs[k].runtime, cs[k].segments);
    else
      snprintf(rt, sizeof rt, "%.0f", cs[k].runtime);
    atomic_file_printf(&af, err, "| %s | %ld | %s | %s | ![%s](%s/final.png) |\n", cs[k].name,
                       cs[k].particles, rt,
                       cs[k].status == 0                     ? "ok"
                       : cs[k].status < 0                    ? "not run"
                       : cs[k].status == HV_EXIT_INTERRUPTED ? "interrupted"
                                                             : "failed",
                       cs[k].name, cs[k].name);
  }
  return atomic_file_commit(&af, err);
}

static int usage(void)
{
  fprintf(stderr, "usage: hvsph validate [--rz] [--scale S] [--only NAME...] [-o DIR] "
                  "[--threads N] [--cases DIR] [--no-run] [--resume] [--list] "
                  "[--set KEY=VALUE]... [--material OLD=NEW]...\n");
  return HV_EXIT_USAGE;
}

/* validate's command line */
struct val_args {
  double scale;                    /* on the particle counts */
  const char *outdir, *cases;      /* DIR; the case files' folder (NULL: the paper's) */
  const char *only[VAL_MAX_CASES]; /* --only: the cases run (none: all) */
  int nonly;
  int threads, norun, resume;
  int rz;   /* the axisymmetric cases (examples/paper/rz/) */
  int list; /* print the cases, run nothing */
  struct val_overrides ov;
};

/* Every mistake on validate's command line prints the usage. */
static int val_fail(const struct cli_cmd *c, enum cli_error e, const char *arg)
{
  (void)c;
  (void)e;
  (void)arg;
  return usage();
}

/* --scale: a positive finite factor on the particle counts */
static int val_scale(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                     const char *val)
{
  (void)c;
  (void)opt;
  char *end;
  const double v = strtod(val, &end);
  if (*end || !(v > 0) || !isfinite(v)) return usage();
  *(double *)o->dest = v;
  return CLI_GO_ON;
}

/* --threads: as hvsph check's, 1 to 4096, the whole argument a decimal number */
static int val_threads(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                       const char *val)
{
  (void)c;
  (void)opt;
  long v;
  if (cli_decimal(val, o->lo, o->hi, &v)) return usage();
  *(int *)o->dest = (int)v;
  return CLI_GO_ON;
}

/* Reads the command line into a; returns CLI_GO_ON or the exit status. */
static int parse_args(int argc, char **argv, struct val_args *a)
{
  struct cli_list sets = {a->ov.sets, 0, VAL_MAX_OVERRIDES};
  struct cli_list swaps = {a->ov.swaps, 0, VAL_MAX_OVERRIDES};
  struct cli_list only = {a->only, 0, VAL_MAX_CASES};
  const struct cli_opt opts[] = {
      {"--scale", NULL, CLI_VALUE, .dest = &a->scale, .convert = val_scale},
      {"--output", "-o", CLI_VALUE, .dest = &a->outdir},
      {"--threads", NULL, CLI_VALUE, .dest = &a->threads, .convert = val_threads, .lo = 1,
       .hi = 4096},
      {"--cases", NULL, CLI_VALUE, .dest = &a->cases},
      {"--no-run", NULL, CLI_FLAG, .dest = &a->norun, .flag = 1},
      {"--resume", NULL, CLI_FLAG, .dest = &a->resume, .flag = 1},
      {"--rz", NULL, CLI_FLAG, .dest = &a->rz, .flag = 1},
      {"--list", NULL, CLI_FLAG, .dest = &a->list, .flag = 1},
      {"--set", NULL, CLI_LIST, .dest = &sets},
      {"--material", NULL, CLI_LIST, .dest = &swaps},
      {"--only", NULL, CLI_WORDS, .dest = &only}, /* no name: not every case */
  };
  const struct cli_cmd cmd = {.name = "validate",
                              .opts = opts,
                              .nopts = (int)(sizeof opts / sizeof opts[0]),
                              .fail = val_fail};
  const int st = cli_parse(&cmd, argc, argv);
  a->ov.nsets = sets.n;
  a->ov.nswaps = swaps.n;
  a->nonly = only.n;
  if (st != CLI_GO_ON) return st;
  if (a->norun && a->ov.nsets + a->ov.nswaps) {
    fprintf(stderr, "hvsph validate: --set and --material change the runs; with --no-run "
                    "nothing is run (each run's used_parameters.yaml holds what it ran with)\n");
    return HV_EXIT_USAGE;
  }
  return CLI_GO_ON;
}

/* Whether the case `name` is one this validation takes (--only, or all). */
static int wanted(const struct val_args *a, const char *name)
{
  int want = a->nonly == 0;
  for (int k = 0; k < a->nonly; k++) want |= !strcmp(name, a->only[k]);
  return want;
}

/* Every --only name is a case of refpath's (with --rz: one that has a file in casedir). */
static int check_only(const struct val_args *a, const char *const *names, int nnames,
                      const char *refpath, const char *casedir, struct hv_error *err)
{
  for (int k = 0; k < a->nonly; k++) {
    int found = 0;
    for (int j = 0; j < nnames; j++) found |= !strcmp(names[j], a->only[k]);
    if (found) continue;
    if (a->rz)
      return hv_error_set(err, HV_EXIT_INPUT,
                          "validate --rz: no case '%s' in %s (the axisymmetric cases are the "
                          "paper's normal impacts of %s that have a file there)",
                          a->only[k], casedir, refpath);
    return hv_error_set(err, HV_EXIT_INPUT, "validate: no case '%s' in %s", a->only[k], refpath);
  }
  return 0;
}

/* With --rz, the reference's cases that have a file in casedir (the oblique bumper tests
 * have none: an axisymmetric case is a normal impact), into rz[]; returns their number,
 * or -1 with err set when there is none (no RZ folder). Without --rz, all of them. */
static int select_cases(const struct val_args *a, const char *const *names, int nnames,
                        const char *casedir, const char **sel, struct hv_error *err)
{
  int n = 0;
  for (int j = 0; j < nnames && n < VAL_MAX_CASES; j++) {
    char cf[8400];
    snprintf(cf, sizeof cf, "%s/%s.yaml", casedir, names[j]);
    if (!a->rz || access(cf, R_OK) == 0) sel[n++] = names[j];
  }
  if (a->rz && n == 0)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "validate --rz: no case file of the paper's cases in %s "
                        "(examples/paper/rz/, written by tools/gen_paper_cases.py)",
                        casedir);
  return n;
}

/* --list: each case that would run, its case file and the rows compared; to stdout. */
static int list_cases(const struct val_args *a, struct cfg *ref, const char *const *names,
                      int nnames, const char *casedir, struct hv_error *err)
{
  for (int j = 0; j < nnames; j++) {
    if (!wanted(a, names[j])) continue;
    printf("%-14s %s/%s.yaml ", names[j], casedir, names[j]);
    const int nq = cfg_len(ref, names[j]);
    for (int q = 0; q < nq; q++) {
      char key[256];
      const char *qty, *obj;
      snprintf(key, sizeof key, "%s[%d].quantity", names[j], q);
      if (cfg_get_string(ref, key, NULL, &qty, err)) return -1;
      snprintf(key, sizeof key, "%s[%d].object", names[j], q);
      if (cfg_get_string(ref, key, "", &obj, err)) return -1;
      printf("%s%s(%s)", q ? " " : "", qty, obj);
    }
    printf("\n");
  }
  return fflush(stdout) ? hv_error_set(err, HV_EXIT_RUN, "validate --list: cannot write the list")
                        : 0;
}

/* Each --material swap is taken by a body of some selected case: checked on the case
 * files before anything runs (a misspelt name would run every case unchanged). */
static int check_swaps(const struct val_args *a, const char *const *names, int nnames,
                       const char *casedir, struct hv_error *err)
{
  int hits[VAL_MAX_OVERRIDES] = {0};
  for (int j = 0; j < nnames; j++) {
    if (!wanted(a, names[j])) continue;
    char cf[8400];
    snprintf(cf, sizeof cf, "%s/%s.yaml", casedir, names[j]);
    struct cfg *cc = cfg_load(cf, err);
    if (!cc) return -1; /* a case that cannot be read: said here, not as a swap that took nothing */
    struct hv_error serr;
    const int level = hv_log_level;
    hv_log_level = 1; /* the runs log their overrides */
    for (int k = 0; k < a->ov.nsets; k++) {
      hv_error_clear(&serr);
      cfg_apply_set(cc, a->ov.sets[k], &serr);
    }
    const int rc = run_apply_swaps(cc, a->ov.swaps, a->ov.nswaps, 0, hits, err);
    hv_log_level = level;
    cfg_free(cc);
    if (rc) return -1;
  }
  for (int k = 0; k < a->ov.nswaps; k++)
    if (!hits[k])
      return hv_error_set(err, HV_EXIT_INPUT,
                          "validate: --material %s: no body of the "
                          "selected case(s) in %s has that material",
                          a->ov.swaps[k], casedir);
  return 0;
}

/* The run's wall time over all its segments (runs and restarts), when recorded. */
static void case_runtime(const char *dir, struct val_case *vc)
{
  char spath[4300];
  snprintf(spath, sizeof spath, "%s/run_segments.csv", dir);
  double *wall = NULL;
  struct hv_error serr;
  const int nseg = access(spath, R_OK) ? 0 : io_read_table_column(spath, "wall_s", &wall, &serr);
  if (nseg > 0) {
    vc->runtime = 0.0;
    for (int k = 0; k < nseg; k++) vc->runtime += wall[k];
    vc->segments = nseg;
  }
  free(wall);
}

/* A validation under way: the reference, the rows and cases so far. */
struct val_run {
  struct val_args *a;
  struct cfg *ref; /* data/paper_results.yaml */
  char casedir[4200];
  struct val_row *rows;
  int nrows;
  struct val_case *cs;
  int ncase, failed, interrupted;
  struct meas_table mt; /* the measurements of the case at hand */
};

/* The rows of case `name`: each quantity of the reference with its experiment's and the
 * paper's values, and the simulated one from v->mt. Returns 0 or -1 with err set. */
static int read_rows(struct val_run *v, const char *name, struct hv_error *err)
{
  char key[256];
  const int nq = cfg_len(v->ref, name);
  for (int q = 0; q < nq && v->nrows < VAL_MAX_ROWS; q++) {
    struct val_row *r = &v->rows[v->nrows++];
    const char *s;
    memset(r, 0, sizeof *r);
    snprintf(r->cas, sizeof r->cas, "%s", name);
    snprintf(key, sizeof key, "%s[%d].quantity", name, q);
    if (cfg_get_string(v->ref, key, NULL, &s, err)) return -1;
    snprintf(r->quantity, sizeof r->quantity, "%s", s);
    snprintf(key, sizeof key, "%s[%d].object", name, q);
    if (cfg_get_string(v->ref, key, "", &s, err)) return -1;
    snprintf(r->object, sizeof r->object, "%s", s);
    snprintf(key, sizeof key, "%s[%d].note", name, q);
    if (cfg_get_string(v->ref, key, "", &s, err)) return -1;
    snprintf(r->note, sizeof r->note, "%s", s);
    snprintf(key, sizeof key, "%s[%d].approx", name, q);
    int no = 0;
    if (cfg_get_bool(v->ref, key, &no, &r->approx, err)) return -1;
    snprintf(key, sizeof key, "%s[%d].in_mean", name, q);
    int yes = 1;
    if (cfg_get_bool(v->ref, key, &yes, &r->in_mean, err)) return -1;
    enum unit_dim d = dim_of(r->quantity);
    double one = 1.0, sc;
    snprintf(key, sizeof key, "%s[%d].scale", name, q);
    if (cfg_get_quantity(v->ref, key, UNIT_NONE, &one, -HUGE_VAL, HUGE_VAL, &sc, err)) return -1;
    snprintf(key, sizeof key, "%s[%d].experiment", name, q);
    r->exp = get_opt(v->ref, key, d, err);
    snprintf(key, sizeof key, "%s[%d].paper", name, q);
    r->paper = get_opt(v->ref, key, d, err);
    snprintf(key, sizeof key, "%s[%d].paper_low", name, q);
    r->paper_lo = get_opt(v->ref, key, d, err);
    snprintf(key, sizeof key, "%s[%d].paper_high", name, q);
    r->paper_hi = get_opt(v->ref, key, d, err);
    if (err->code) return -1;
    char unit[16];
    double val = pick_measurement(&v->mt, r->quantity, r->object, unit, sizeof unit);
    if (d == UNIT_ANGLE) val *= 3.14159265358979323846 / 180.0; /* the table writes degrees */
    r->sim = val * sc;
  }
  return 0;
}

/* One case: its run (unless --no-run), its radiograph and its rows. Returns 0, -1 with
 * err set, or HV_EXIT_INPUT once the case's bad input has been said. */
static int validate_case(struct val_run *v, const char *name, struct hv_error *err)
{
  struct val_args *a = v->a;
  struct val_case *vc = &v->cs[v->ncase++];
  snprintf(vc->name, sizeof vc->name, "%s", name);
  vc->runtime = NAN;
  vc->status = -1;
  char dir[4200], mpath[4300], png[4300];
  snprintf(dir, sizeof dir, "%s/%s", a->outdir, name);
  /* a case stopped by the user with its state written has not failed */
  if (!a->norun && run_case(v->casedir, name, dir, a->scale, a->threads, a->resume, &a->ov, vc) &&
      vc->status != HV_EXIT_INTERRUPTED)
    v->failed++;
  /* bad input (a --set the case does not take, a missing case file, a checkpoint of
     another case): its run has said what; the same would stop the later cases, and the
     tables of an earlier validation in DIR are kept */
  if (!a->norun && vc->status == HV_EXIT_INPUT) {
    fprintf(stderr,
            "hvsph validate: %s: bad input (above): the later cases are not run, "
            "%s/validation.md and validation.csv are left as they were\n",
            name, a->outdir);
    return HV_EXIT_INPUT;
  }
  /* Ctrl-C (or SIGTERM) ends the run with its state written and ends the validation
     too, also when writing that state failed: the tables are written for the cases
     so far */
  v->interrupted = !a->norun && (vc->status == HV_EXIT_INTERRUPTED || run_interrupted());
  vc->particles = particles_of(dir);
  if (a->norun) vc->status = vc->particles >= 0 ? 0 : -1; /* no summary.csv: no run */
  case_runtime(dir, vc);
  snprintf(png, sizeof png, "%s/final.png", dir);
  struct hv_error rerr; /* a warning only: not the validation's error */
  hv_error_clear(&rerr);
  if (render_final(dir, png, &rerr)) hv_warn("%s: no radiograph: %s", name, rerr.msg);
  snprintf(mpath, sizeof mpath, "%s/measurements.csv", dir);
  meas_table_free(&v->mt);
  struct hv_error merr;
  if (meas_table_read(&v->mt, mpath, &merr)) hv_warn("%s: %s", name, merr.msg);
  return read_rows(v, name, err);
}

static int validate(struct val_args *a, struct runfolder_lock *lock)
{
  if (a->threads > 0) omp_set_num_threads(a->threads);
  struct hv_error err;
  hv_error_clear(&err);
  static struct val_row rows[VAL_MAX_ROWS];
  static struct val_case cs[VAL_MAX_CASES];
  struct val_run v = {.a = a, .rows = rows, .cs = cs};
  char lib[4096], refpath[4200];
  if (material_library_path(lib, sizeof lib, &err)) goto fail;
  char *slash = strrchr(lib, '/');
  if (slash) *slash = 0;
  snprintf(refpath, sizeof refpath, "%s/paper_results.yaml", lib);
  const char *sub = a->rz ? "examples/paper/rz" : "examples/paper";
  snprintf(v.casedir, sizeof v.casedir, "%s", a->cases ? a->cases : sub);
  if (!a->cases && slash) snprintf(v.casedir, sizeof v.casedir, "%s/../%s", lib, sub);
  v.ref = cfg_load(refpath, &err);
  if (!v.ref) goto fail;
  const char *const *all;
  const int nall = cfg_keys(v.ref, NULL, &all);
  static const char *names[VAL_MAX_CASES];
  const int nnames = select_cases(a, all, nall, v.casedir, names, &err);
  if (nnames < 0 || check_only(a, names, nnames, refpath, v.casedir, &err)) {
    cfg_free(v.ref);
    goto fail;
  }
  if (a->list) { /* the swaps checked on the case files as for a run (a dry check of a set) */
    const int rc = (a->ov.nswaps && check_swaps(a, names, nnames, v.casedir, &err)) ||
                   list_cases(a, v.ref, names, nnames, v.casedir, &err);
    cfg_free(v.ref);
    if (rc) goto fail;
    return 0;
  }
  /* the folder only once the options are known to be good */
  if ((a->ov.nswaps && !a->norun && check_swaps(a, names, nnames, v.casedir, &err)) ||
      io_mkdir_p(a->outdir, &err) || runfolder_lock(lock, a->outdir, "validate", 0, &err)) {
    cfg_free(v.ref);
    goto fail;
  }
  meas_table_init(&v.mt);
  int st = 0;
  for (int j = 0; j < nnames && v.ncase < VAL_MAX_CASES && !v.interrupted && !st; j++)
    if (wanted(a, names[j])) st = validate_case(&v, names[j], &err);
  meas_table_free(&v.mt);
  cfg_free(v.ref);
  if (st == HV_EXIT_INPUT) return HV_EXIT_INPUT;
  if (st ||
      write_reports(a->outdir, rows, v.nrows, cs, v.ncase, a->scale, a->norun, a->rz, &a->ov, &err))
    goto fail;

  fprintf(stderr,
          "hvsph validate: %d case(s), %d failed%s; results in %s/validation.md and "
          "validation.csv\n",
          v.ncase, v.failed, v.interrupted ? ", interrupted (the later cases were not run)" : "",
          a->outdir);
  return v.interrupted ? HV_EXIT_INTERRUPTED : v.failed ? HV_EXIT_RUN : 0;
fail:
  hv_log(0, "%s", err.msg);
  return err.code ? err.code : HV_EXIT_RUN;
}

int cli_validate(int argc, char **argv)
{
  struct val_args a = {.scale = 1.0};
  const int st = parse_args(argc, argv, &a);
  if (st != CLI_GO_ON) return st;
  if (!a.outdir) a.outdir = a.rz ? "out/validation-rz" : "out/validation";
  struct runfolder_lock lock;
  runfolder_lock_init(&lock);
  const int status = validate(&a, &lock);
  runfolder_unlock(&lock);
  return status;
}
