/* measure.c — `hvsph measure RUNDIR [--case FILE]`: the measurements of a finished
 * (or interrupted) run taken again from its particle snapshots.
 *
 * A run writes measurements.csv as it goes; when the definitions of the measurements
 * change (docs/measurements.md), or a run was made without them, this command
 * re-reads the run's own used_parameters.yaml (every value it ran with), rebuilds the
 * bodies' geometry from it (original faces, thicknesses, spacings), loads every
 * particles_NNNNN.csv (or, when it has none, particles_NNNNN.vtu) of the folder in
 * turn and writes measurements.csv and the fragments_NNNNN.csv files anew (each to a temporary name, then renamed).
 *
 * The backwall's peak pressure at the centre is a running maximum over every time
 * step, which snapshots cannot give; the value of the run's earlier measurements.csv
 * at the same time is kept when it is larger than the maximum over the snapshots.
 *
 * It takes the run folder's lock (run/runfolder.h) as a run does: a run still going
 * rewrites measurements.csv at each output, so measuring it then is refused (exit 2).
 */
#include "cli/cli.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/options.h"
#include "config/config.h"
#include "diag/measure_table.h"
#include "io/snapshot.h"
#include "run/measure_run.h"
#include "run/run.h"
#include "run/runfolder.h"
#include "sim/sim.h"

static void usage(FILE *f)
{
  fprintf(f, "usage: hvsph measure RUNDIR [--case FILE] [--skip-missing] [--quiet]\n"
             "  takes the measurements of a run again from its particle snapshots\n"
             "  (RUNDIR/particles_NNNNN.csv, or its .vtu files when it has no CSV) and rewrites\n"
             "  RUNDIR/measurements.csv and fragments_NNNNN.csv; the case is\n"
             "  RUNDIR/used_parameters.yaml unless --case names another (docs/measurements.md).\n"
             "  An output without its snapshot is an error (nothing rewritten) unless\n"
             "  --skip-missing: then the others are measured and each missing one is named\n");
}

/* The files of folder `stage` moved into `dir` (each by a rename, so each whole), or
 * with move = 0 deleted; then the folder itself. */
static int unstage(const char *stage, const char *dir, int move, struct hv_error *err)
{
  DIR *d = opendir(stage);
  int rc = 0;
  if (d) {
    struct dirent *e;
    char from[4600], to[4600];
    while ((e = readdir(d))) {
      if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
      snprintf(from, sizeof from, "%s/%s", stage, e->d_name);
      snprintf(to, sizeof to, "%s/%s", dir, e->d_name);
      if (!move || rc) {
        remove(from);
      } else if (rename(from, to)) {
        rc = hv_error_set(err, HV_EXIT_RUN, "cannot move '%s' to '%s': %s", from, to,
                          strerror(errno));
        remove(from);
      }
    }
    closedir(d);
  }
  rmdir(stage);
  return rc;
}

/* The outputs of the run (0 to nt - 1 by summary.csv; without it, 0 to the last
 * snapshot found) that have no snapshot among snaps[0..ns-1] (sorted). Their rows would
 * vanish from measurements.csv, which would look complete: an error naming the first
 * (and how many), unless skip (--skip-missing), where each is a warning. */
static int report_missing(const char *dir, const char *ext, const int *snaps, int ns, int nt,
                          int skip, struct hv_error *err)
{
  const int nout = nt >= 0 ? nt : snaps[ns - 1] + 1;
  int nmiss = 0, first = -1;
  for (int k = 0, j = 0; k < nout; k++) {
    while (j < ns && snaps[j] < k) j++;
    if (j < ns && snaps[j] == k) continue;
    if (!nmiss++) first = k;
    if (skip)
      hv_warn("%s/particles_%05d.%s is missing: output %d is not measured (its rows "
              "are not in measurements.csv)",
              dir, k, ext, k);
  }
  if (!nmiss || skip) return 0;
  return hv_error_set(err, HV_EXIT_INPUT,
                      "%s/particles_%05d.%s is missing%s%d of the run's %d "
                      "outputs %s no snapshot): measurements.csv would lack their rows, so "
                      "nothing is rewritten; restore the snapshot%s, or give --skip-missing "
                      "to measure the others",
                      dir, first, ext, nt >= 0 ? " (summary.csv lists it; " : " (", nmiss, nout,
                      nmiss == 1 ? "has" : "have", nmiss == 1 ? "" : "s");
}

/* The particles of snapshot spath (number k) belong to the case's bodies and
 * materials, and snapshot 0 has each body's count of the set-up: its spacings feed the
 * measurements. Returns 0 or -1 with err set (bad input). */
static int check_particles(const struct sim *s, const char *spath, int k, const char *casefile,
                           struct hv_error *err)
{
  for (size_t i = 0; i < s->p.n; i++)
    if (s->p.body[i] < 0 || s->p.body[i] >= s->nbody || s->p.mat[i] < 0 || s->p.mat[i] >= s->nmat)
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: particle id %lld: body %d or material %d is "
                          "not one of the case's (%s)",
                          spath, (long long)s->p.id[i], (int)s->p.body[i], (int)s->p.mat[i],
                          casefile);
  if (k != 0) return 0;
  size_t cnt[sizeof s->body / sizeof s->body[0]] = {0};
  for (size_t i = 0; i < s->p.n; i++) cnt[s->p.body[i]]++;
  for (int b = 0; b < s->nbody; b++)
    if (cnt[b] != s->body[b].count)
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: %zu particles of body '%s', where %s set up "
                          "by this hvsph gives %zu: the run was set up differently (by another "
                          "version's particle counts, docs/case-files.md 'particles'); measure "
                          "it with the hvsph that ran it",
                          spath, cnt[b], s->body[b].name, casefile, s->body[b].count);
  return 0;
}

/* The peak pressure of the earlier measurements.csv at time t, where higher, carried
 * into mr: the snapshots hold the pressure at output times only, the run saw every step. */
static void carry_peak(const struct meas_table *old, struct measure_run *mr, double t)
{
  for (size_t q = 0; q < old->n; q++) {
    const struct meas_row *r = &old->rows[q];
    if (!strcmp(r->quantity, "peak_pressure_center") && isfinite(r->value) &&
        fabs(r->time - t) <= 1e-9 * fmax(fabs(t), 1e-12) && r->value > mr->peak_pressure)
      mr->peak_pressure = r->value;
  }
}

/* Snapshot k of the run in dir measured, its files written into stage. Returns 1
 * measured, 0 skipped (not one of the run's outputs), -1 failed with err set. */
static int measure_snapshot(struct sim *s, struct measure_run *mr, const struct meas_table *old,
                            const char *dir, const char *ext, int k, const double *times, int nt,
                            const char *stage, const char *const *matnames, const char *casefile,
                            int quiet, struct hv_error *err)
{
  char spath[4400];
  snprintf(spath, sizeof spath, "%s/particles_%05d.%s", dir, k, ext);
  s->p.n = 0;
  double t = NAN;
  const int axisym = s->p.axisym; /* the case's geometry: the snapshot must have it */
  if ((nt < 0 || k < nt) && io_read_particles(spath, &s->p, &t, err)) return -1;
  if (s->p.axisym != axisym) {
    s->p.axisym = axisym;
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s is %s, the case %s is %s (domain.geometry): measured with the "
                        "wrong geometry its numbers would mean nothing",
                        spath, axisym ? "3D" : "axisymmetric", casefile,
                        axisym ? "axisymmetric" : "3D");
  }
  if (!io_snapshot_in_run(k, t, times, nt)) {
    hv_warn("%s is not one of the outputs in summary.csv (an earlier run's, left in the "
            "folder): skipped",
            spath);
    return 0;
  }
  if (check_particles(s, spath, k, casefile, err)) return -1;
  s->t = isfinite(t) ? t : 0.0;
  if (k > 0) measure_run_step(mr, s); /* as a run: no step before snapshot 0 */
  carry_peak(old, mr, s->t);
  const int mrc = measure_run_output(mr, s, k, stage, matnames, err);
  if (mrc == MEASURE_FAILED_DATA) { /* the snapshot's particles, not the run: bad input */
    err->code = HV_EXIT_INPUT;
    hv_error_prefix(err, "%s: ", spath);
  }
  if (mrc) return -1;
  if (!quiet) hv_info("measured %s (t = %g s, %zu particles)", spath, s->t, s->p.n);
  return 1;
}

/* The run's case c (read from casefile) set up as the run was, with its measurements.
 * Returns 0 or -1 with err set. */
static int set_up(const char *casefile, struct cfg *c, struct sim *s, struct measure_run *mr,
                  struct hv_error *err)
{
  /* the set-up's notes and warnings (spacings fitted to a plate, a lattice that overfills
     its shape) are the run's, which said them: not again (errors come back in err) */
  const int level = hv_log_level;
  hv_log_level = 0;
  const int bad = run_setup(s, c, err);
  hv_log_level = level;
  if (bad || measure_run_read(mr, s, c, err) || cfg_check_unused(c, err)) return -1;
  if (!mr->any)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: the case has no 'measure' section: nothing "
                        "to measure (docs/case-files.md)",
                        casefile);
  return 0;
}

/* The run's snapshots in dir (*snaps, *ns; their extension returned) and its output
 * times from summary.csv (*times, *nt; nt < 0 when it cannot be read). Returns NULL with
 * err set when the folder has none, or misses some (report_missing). */
static const char *list_snapshots(const char *dir, int skip_missing, int **snaps, int *ns,
                                  double **times, int *nt, struct hv_error *err)
{
  const char *ext = io_list_readable_snapshots(dir, snaps, ns);
  if (*ns < 0) {
    hv_error_set(err, HV_EXIT_INPUT, "%s: cannot open the run folder", dir);
    return NULL;
  }
  if (*ns == 0) {
    hv_error_set(err, HV_EXIT_INPUT, "%s: no particles_NNNNN.csv or .vtu snapshots", dir);
    return NULL;
  }
  /* a folder reused by a shorter run keeps the earlier run's later snapshots: only
     those that match this run's summary.csv (number and time) are its own */
  char spath[4400];
  snprintf(spath, sizeof spath, "%s/summary.csv", dir);
  struct hv_error ignored;
  *nt = io_read_table_column(spath, "time", times, &ignored);
  if (*nt < 0) hv_warn("%s: every snapshot is taken as the run's", ignored.msg);
  if (report_missing(dir, ext, *snaps, *ns, *nt, skip_missing, err)) return NULL;
  return ext;
}

/* Every mistake on measure's command line is "bad argument", with the usage. */
static int measure_fail(const struct cli_cmd *c, enum cli_error e, const char *arg)
{
  (void)c;
  (void)e;
  fprintf(stderr, "hvsph measure: bad argument '%s'\n", arg);
  usage(stderr);
  return HV_EXIT_USAGE;
}

int cli_measure(int argc, char **argv)
{
  const char *dir = NULL, *casefile = NULL;
  int quiet = 0, skip_missing = 0;
  const struct cli_opt opts[] = {
      {"--help", "-h", CLI_HELP, .dest = NULL},
      {"--case", NULL, CLI_VALUE, .dest = &casefile},
      {"--quiet", "-q", CLI_FLAG, .dest = &quiet, .flag = 1},
      {"--skip-missing", NULL, CLI_FLAG, .dest = &skip_missing, .flag = 1},
  };
  const struct cli_cmd cmd = {.name = "measure",
                              .opts = opts,
                              .nopts = (int)(sizeof opts / sizeof opts[0]),
                              .positional = &dir,
                              .fail = measure_fail,
                              .help = usage};
  const int st = cli_parse(&cmd, argc, argv);
  if (st != CLI_GO_ON) return st;
  if (!dir) {
    usage(stderr);
    return HV_EXIT_USAGE;
  }
  struct hv_error err;
  hv_error_clear(&err);
  struct sim s;
  struct measure_run mr;
  memset(&s, 0, sizeof s);
  memset(&mr, 0, sizeof mr);
  meas_table_init(&mr.table);
  int *snaps = NULL;
  double *times = NULL;
  struct meas_table old; /* the earlier measurements.csv: its peak pressures */
  meas_table_init(&old);
  struct cfg *c = NULL;
  int status = HV_EXIT_OK;
  char path[4400], stage[4400] = "";
  struct runfolder_lock lock;
  runfolder_lock_init(&lock);
  if (!casefile) {
    snprintf(path, sizeof path, "%s/used_parameters.yaml", dir);
    casefile = path;
  }
  c = cfg_load(casefile, &err);
  if (!c || set_up(casefile, c, &s, &mr, &err)) goto fail;
  /* one writer at a time: a run still going rewrites measurements.csv itself */
  if (runfolder_lock(&lock, dir, "measure", quiet, &err)) goto fail;
  int ns, nt;
  const char *ext = list_snapshots(dir, skip_missing, &snaps, &ns, &times, &nt, &err);
  if (!ext) goto fail;
  struct hv_error ignored;
  char mpath[4400];
  snprintf(mpath, sizeof mpath, "%s/measurements.csv", dir);
  meas_table_read(&old, mpath, &ignored); /* none: no earlier peak pressures */
  /* the new files go to a hidden folder of their own and replace the run's only when
     every snapshot has been measured: a snapshot that fails leaves the earlier
     measurements.csv (and its peak pressures) and fragment files as they were */
  snprintf(stage, sizeof stage, "%s/.measure.tmp.%ld", dir, (long)getpid());
  if (mkdir(stage, 0777)) {
    hv_error_set(&err, HV_EXIT_RUN, "cannot create folder '%s': %s", stage, strerror(errno));
    stage[0] = 0;
    goto fail;
  }
  const char *matnames[HV_MAX_MATERIALS];
  for (int i = 0; i < s.nmat; i++) matnames[i] = s.mat[i].name;
  int measured = 0;
  for (int j = 0; j < ns; j++) {
    const int rc = measure_snapshot(&s, &mr, &old, dir, ext, snaps[j], times, nt, stage, matnames,
                                    casefile, quiet, &err);
    if (rc < 0) goto fail;
    measured += rc;
  }
  if (!measured) {
    hv_error_set(&err, HV_EXIT_INPUT, "%s: none of the snapshots matches the run's summary.csv",
                 dir);
    goto fail;
  }
  const int moved = unstage(stage, dir, 1, &err);
  stage[0] = 0;
  if (moved) goto fail;
  if (!quiet)
    hv_info("measurements of %d snapshot%s written to %s", measured, measured == 1 ? "" : "s",
            mpath);
  goto done;
fail:
  hv_log(0, "%s", err.msg);
  status = err.code ? err.code : HV_EXIT_RUN;
done:
  if (stage[0]) unstage(stage, dir, 0, NULL);
  runfolder_unlock(&lock);
  free(snaps);
  free(times);
  meas_table_free(&old);
  measure_run_free(&mr);
  sim_free(&s);
  if (c) cfg_free(c);
  return status;
}
