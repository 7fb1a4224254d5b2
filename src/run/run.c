/* run.c — the top-level run: case → setup → step loop with outputs → finish.
 *
 * Outputs go to OUTDIR: used_parameters.yaml, summary.csv (one row per output
 * time), particles_NNNNN.vtu + run.pvd, and particles_NNNNN.csv when asked. Every
 * file is written to a temporary name and renamed. Ctrl-C ends the run after the
 * current step and writes that state; a second Ctrl-C stops at once. SIGTERM, SIGHUP,
 * SIGUSR1, SIGUSR2 and SIGXCPU do the same (batch systems send one of them before a
 * time limit's SIGKILL).
 *
 * One process at a time writes a run folder (its lock, run/runfolder.h); a new run
 * refuses a folder that holds an earlier run unless told to replace it (--overwrite).
 */
#include "run/run.h"

#include <errno.h>
#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "config/config.h"
#include "core/infile.h"
#include "diag/conservation.h"
#include "integrate/step.h"
#include "io/atomic_file.h"
#include "io/snapshot.h"
#include "material/material_read.h"
#include "run/plausible.h"
#include "run/measure_run.h"
#include "run/restart.h"
#include "run/runfolder.h"
#include "sim/sim.h"
#include "setup/setup.h"
#include "version.h"

static volatile sig_atomic_t interrupted = 0; /* the signal that ended the run, or 0 */

/* The signals that end a run with its state written: Ctrl-C, kill, a closed terminal,
 * and what batch systems send ahead of a time limit (Slurm's --signal, PBS, LSF: USR1,
 * USR2 or TERM; SIGXCPU at a CPU-time limit's soft value). */
static const struct {
  int sig;
  const char *name;
} stop_signals[] = {{SIGINT, "SIGINT"},   {SIGTERM, "SIGTERM"}, {SIGHUP, "SIGHUP"},
                    {SIGUSR1, "SIGUSR1"}, {SIGUSR2, "SIGUSR2"}, {SIGXCPU, "SIGXCPU"}};
#define NSTOP ((int)(sizeof stop_signals / sizeof stop_signals[0]))

static void on_stop_signal(int sig)
{
  interrupted = sig;
  /* a second signal of the same kind stops at once (its default action), but SIGXCPU,
     which the kernel repeats every second past the soft limit until the hard limit's
     SIGKILL: its repeats are ignored, so that the state gets written meanwhile */
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = sig == SIGXCPU ? SIG_IGN : SIG_DFL;
  sigemptyset(&sa.sa_mask);
  sigaction(sig, &sa, NULL);
}

/* Installs the handler for the stop signals, keeping their earlier actions in old. A
 * SIGHUP that is ignored (nohup) stays ignored. */
static void stop_signals_catch(struct sigaction *old)
{
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART; /* a write under way is not cut short by the signal */
  for (int k = 0; k < NSTOP; k++) {
    sigaction(stop_signals[k].sig, NULL, &old[k]);
    if (stop_signals[k].sig == SIGHUP && old[k].sa_handler == SIG_IGN) continue;
    sigaction(stop_signals[k].sig, &sa, NULL);
  }
}

/* The earlier actions back, but SIGXCPU's after a run it stopped: its repeats would end
 * the process (validate writing its tables) with a core dump. */
static void stop_signals_restore(const struct sigaction *old)
{
  for (int k = 0; k < NSTOP; k++)
    if (!(stop_signals[k].sig == SIGXCPU && interrupted == SIGXCPU))
      sigaction(stop_signals[k].sig, &old[k], NULL);
}

static const char *signal_name(int sig)
{
  for (int k = 0; k < NSTOP; k++)
    if (stop_signals[k].sig == sig) return stop_signals[k].name;
  return "a signal";
}

int run_interrupted(void) { return interrupted != 0; }

static double wall_time(void) { return omp_get_wtime(); }

/* totals over the particles; absorbed_*: what absorbing faces removed so far, so that
   mass + absorbed_mass etc. are conserved */
static const char *const summary_cols[RUN_SUMMARY_COLS] = {"step",
                                                           "time",
                                                           "dt",
                                                           "n",
                                                           "mass",
                                                           "px",
                                                           "py",
                                                           "pz",
                                                           "e_kin",
                                                           "e_int",
                                                           "e_total",
                                                           "absorbed_n",
                                                           "absorbed_mass",
                                                           "absorbed_px",
                                                           "absorbed_py",
                                                           "absorbed_pz",
                                                           "absorbed_e_kin",
                                                           "absorbed_e_int"};

static void outputs_free(struct run_outputs *o)
{
  measure_run_free(&o->mr);
  for (int i = 0; i < o->count; i++) free(o->files[i]);
  free(o->files);
  free(o->times);
  free(o->rows);
}

static int write_outputs(struct sim *s, struct run_outputs *o, struct hv_error *err)
{
  char path[4200], name[64];
  struct totals t;
  diag_totals(&s->p, &t);
  o->rows =
      hv_realloc(o->rows, (size_t)(o->nrows + 1) * RUN_SUMMARY_COLS * sizeof(double), "summary");
  const struct absorbed *ab = &s->bnd.absorbed;
  double row[RUN_SUMMARY_COLS] = {
      (double)s->step, s->t,       s->dt,      (double)s->p.n, t.mass,    t.mom[0],
      t.mom[1],        t.mom[2],   t.e_kin,    t.e_int,        t.e_total, (double)ab->n,
      ab->mass,        ab->mom[0], ab->mom[1], ab->mom[2],     ab->e_kin, ab->e_int};
  memcpy(o->rows + (size_t)o->nrows * RUN_SUMMARY_COLS, row, sizeof row);
  o->nrows++;
  struct snapshot_meta meta = {.time = s->t,
                               .step = s->step,
                               .version = HVSPH_VERSION,
                               .case_name = s->case_name,
                               .material_names = o->matnames,
                               .nmat = s->nmat,
                               .body_names = o->bodynames,
                               .nbody = s->nbody,
                               .vtu_zlib = s->out.compress};
  if (s->out.vtu) {
    snprintf(name, sizeof name, "particles_%05d.vtu", o->count);
    snprintf(path, sizeof path, "%s/%s", o->dir, name);
    if (io_write_vtu(path, &s->p, &meta, err)) return -1;
    o->times = hv_realloc(o->times, (size_t)(o->count + 1) * sizeof *o->times, "pvd");
    o->files = hv_realloc(o->files, (size_t)(o->count + 1) * sizeof *o->files, "pvd");
    o->times[o->count] = s->t;
    o->files[o->count] = strdup(name);
    snprintf(path, sizeof path, "%s/run.pvd", o->dir);
    if (io_write_pvd(path, o->times, (const char *const *)o->files, o->count + 1, &meta, err))
      return -1;
  }
  if (s->out.csv) {
    snprintf(path, sizeof path, "%s/particles_%05d.csv", o->dir, o->count);
    if (io_write_particles_csv(path, &s->p, &meta, err)) return -1;
  }
  if (measure_run_output(&o->mr, s, o->count, o->dir, o->matnames, err)) return -1;
  if (!s->out.vtu) { /* keep the count and the snapshot numbers in step */
    o->files = hv_realloc(o->files, (size_t)(o->count + 1) * sizeof *o->files, "pvd");
    o->files[o->count] = NULL;
  }
  o->count++;
  char comment[512];
  snprintf(comment, sizeof comment,
           "hvsph %s case %s: totals over the particles at each "
           "output time (SI units)",
           HVSPH_VERSION, s->case_name);
  snprintf(path, sizeof path, "%s/summary.csv", o->dir);
  return io_write_table_csv(path, summary_cols, RUN_SUMMARY_COLS, o->rows, o->nrows, comment, err);
}

void run_format_duration(char *buf, size_t len, double sec)
{
  if (!(sec < 59.95)) {  /* what "%.1f" would write as 60.0 is a minute */
    if (!(sec < 1e12)) { /* inf, or beyond any clock */
      snprintf(buf, len, "%.3g s", sec);
      return;
    }
    const long long t = (long long)(sec + 0.5);
    const int n = snprintf(buf, len, "%lld:%02lld:%02lld", t / 3600, t / 60 % 60, t % 60);
    if (sec >= 2 * 86400.0 && n > 0 && (size_t)n < len)
      snprintf(buf + n, len - (size_t)n, " (%.0f days)", sec / 86400.0);
  } else {
    snprintf(buf, len, "%.1f s", sec);
  }
}

static void progress(const struct sim *s, double t0, double wall0, int tty, int final)
{
  double el = wall_time() - wall0, frac = (s->t - t0) / (s->tp.end - t0 > 0 ? s->tp.end - t0 : 1);
  double eta = frac > 0 ? el * (1 - frac) / frac : 0.0;
  char line[480], head[96], mid[96], tail[128];
  char lim[160] = "";
  if (s->step > 0 && (s->dt_limit == DT_CFL || s->dt_limit == DT_ACCELERATION)) {
    const char *body = s->dt_limit_body >= 0 ? s->body[s->dt_limit_body].name : "?";
    snprintf(lim, sizeof lim, "  [dt: %s, particle %lld in '%s']", step_limit_name(s->dt_limit),
             (long long)s->dt_limit_id, body);
  } else if (s->step > 0) {
    snprintf(lim, sizeof lim, "  [dt: %s]", step_limit_name(s->dt_limit));
  }
  snprintf(head, sizeof head, "step %ld  t = %.4e / %.4e s", s->step, s->t, s->tp.end);
  snprintf(mid, sizeof mid, "  dt = %.3e s  n = %zu", s->dt, s->p.n);
  char els[48], rem[48];
  run_format_duration(els, sizeof els, el);
  run_format_duration(rem, sizeof rem, eta);
  snprintf(tail, sizeof tail, "  elapsed %s  remaining %s", els, rem);
  snprintf(line, sizeof line, "%s%s%s%s", head, mid, tail, lim);
  if (tty) {
    /* one line rewritten in place: it must not wrap (a carriage return goes back to the
       start of the last row only), so on a narrower terminal the limiter goes first,
       then dt and n, then what does not fit */
    struct winsize ws;
    const size_t cols = ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 1
                            ? (size_t)ws.ws_col - 1
                            : sizeof line - 1;
    if (strlen(line) > cols) snprintf(line, sizeof line, "%s%s%s", head, mid, tail);
    if (strlen(line) > cols) snprintf(line, sizeof line, "%s%s", head, tail);
    if (strlen(line) > cols) line[cols] = '\0';
    const size_t len = strlen(line);
    /* blanks over the rest of the previous line (within the terminal's width) */
    const size_t was = hv_status_len();
    const int pad = was > len ? (int)((was < cols ? was : cols) - len) : 0;
    fprintf(stderr, "\r%s%*s%s", line, pad, "", final ? "\n" : "");
    hv_status_line(final ? 0 : len > 0 ? len : 1);
  } else {
    fprintf(stderr, "hvsph: %s\n", line);
  }
  fflush(stderr);
}

int run_setup(struct sim *s, struct cfg *c, struct hv_error *err)
{
  memset(s, 0, sizeof *s);
  particles_init(&s->p);
  nbr_grid_init(&s->grid);
  boundary_init(&s->bnd);
  s->cfg = c;
  /* the case's own sweep (hvsph sweep reads it; a run takes the case as it stands) */
  cfg_mark_used(c, "sweep");
  if (sim_read_params(s, c, err) || setup_bodies(s, c, err)) return -1;
  /* bounds on h: by default 1/10 to 10 times the initial range */
  double hmin = HUGE_VAL, hmax = 0.0;
  for (size_t i = 0; i < s->p.n; i++) {
    if (s->p.h[i] < hmin) hmin = s->p.h[i];
    if (s->p.h[i] > hmax) hmax = s->p.h[i];
  }
  if (s->sph.h_max == 0.0) s->sph.h_max = 10.0 * hmax;
  if (s->sph.h_min == 0.0) s->sph.h_min = 0.1 * hmin;
  /* a periodic dimension must hold two interaction radii (ghost layers of 2 h_max) */
  for (int d = 0; d < 3; d++) {
    const double L = s->bnd.hi[d] - s->bnd.lo[d];
    if (s->bnd.kind[d][0] == BND_PERIODIC && L < 4.0 * hmax) {
      char where[256];
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: domain: the periodic length in %c (%g m) is "
                          "shorter than two interaction radii (4 h = %g m); make the domain "
                          "longer or the spacing finer",
                          cfg_where(c, "domain.boundary", where, sizeof where), "xyz"[d], L,
                          4.0 * hmax);
    }
  }
  return 0;
}

static const char *default_name(const char *path, char *buf, size_t len)
{
  const char *b = strrchr(path, '/');
  snprintf(buf, len, "%s", b ? b + 1 : path);
  char *dot = strrchr(buf, '.');
  if (dot) *dot = 0;
  return buf;
}

/* run_segments.csv: one row per run or restart of this folder — which hvsph, how many
 * threads, when, from which step and time to which, how long, how it ended — rewritten
 * (through atomic_file) at every checkpoint and at the end. A restart keeps the rows before
 * it. Provenance only: nothing reads it back but `validate` (the total wall time). */
struct segment {
  char *prev; /* the rows of the earlier segments (with the header), or NULL */
  int index;
  char started[32]; /* UTC */
  long step0;
  double t0, wall0;
};

static const char SEG_HEADER[] =
    "# hvsph run segments: one row per run or restart of this folder (docs/output-files.md)\n"
    "segment,version,threads,started_utc,step_from,time_from,step_to,time_to,wall_s,end\n";

static void segment_begin(struct segment *g, const char *dir, int restart, const struct sim *s)
{
  memset(g, 0, sizeof *g);
  char path[4200];
  snprintf(path, sizeof path, "%s/run_segments.csv", dir);
  /* a regular file only (a FIFO would block the restart): anything else starts afresh */
  struct hv_error open_err = {0};
  FILE *f = restart ? hv_open_input(path, "run segments", 64LL << 20, NULL, &open_err) : NULL;
  if (f) {
    size_t len = 0, cap = 4096;
    g->prev = hv_malloc(cap, "run segments");
    for (size_t k; (k = fread(g->prev + len, 1, cap - len - 1, f)) > 0;) {
      len += k;
      if (len + 1 == cap) g->prev = hv_realloc(g->prev, cap *= 2, "run segments");
    }
    fclose(f);
    g->prev[len] = 0;
    if (len == 0 || g->prev[len - 1] != '\n' ||
        strncmp(g->prev, SEG_HEADER, sizeof SEG_HEADER - 1)) {
      free(g->prev); /* not ours or torn: start afresh */
      g->prev = NULL;
    } else {
      for (const char *q = g->prev + sizeof SEG_HEADER - 1; *q; q++) g->index += *q == '\n';
    }
  }
  time_t now = time(NULL);
  struct tm tm;
  gmtime_r(&now, &tm);
  strftime(g->started, sizeof g->started, "%Y-%m-%dT%H:%M:%SZ", &tm);
  g->step0 = s->step;
  g->t0 = s->t;
  g->wall0 = wall_time();
}

static int segment_write(const struct segment *g, const char *dir, const struct sim *s,
                         const char *end, struct hv_error *err)
{
  char path[4200];
  snprintf(path, sizeof path, "%s/run_segments.csv", dir);
  struct atomic_file af;
  if (atomic_file_open(&af, path, err)) return -1;
  if (atomic_file_printf(&af, err, "%s", g->prev ? g->prev : SEG_HEADER) ||
      atomic_file_printf(&af, err, "%d,%s,%d,%s,%ld,%.17g,%ld,%.17g,%.1f,%s\n", g->index,
                         HVSPH_VERSION, omp_get_max_threads(), g->started, g->step0, g->t0, s->step,
                         s->t, wall_time() - g->wall0, end)) {
    atomic_file_abort(&af);
    return -1;
  }
  return atomic_file_commit(&af, err);
}

/* Checkpoints: at every output time, every output.checkpoint_wall seconds of wall-clock
 * time, and when the run stops between output times. */
struct ckpt_clock {
  double wall; /* when the last one was written */
  long step;   /* its step */
};

static int checkpoint(struct sim *s, struct run_outputs *o, struct ckpt_clock *cc,
                      const struct segment *g, struct hv_error *err)
{
  if (!s->out.checkpoint || cc->step == s->step) return 0;
  if (restart_write(s, o, err) || segment_write(g, o->dir, s, "running", err)) return -1;
  cc->wall = wall_time();
  cc->step = s->step;
  return 0;
}

static int run_loop(struct sim *s, struct run_outputs *o, const struct segment *g, int quiet,
                    struct hv_error *err)
{
  const int tty = isatty(STDERR_FILENO);
  const double t0 = s->t, wall0 = wall_time(), tend = s->tp.end, every = s->out.every;
  struct ckpt_clock cc = {wall0, s->step}; /* the state at the start is on disk already */
  double last_print = wall0;
  long printed_step = -1;
  /* output k falls at t_start + k × every (the last one at the end time) */
  double next_out = every > 0 ? o->t_start + (double)o->next_k * every : tend;
  while (every > 0 && next_out <= s->t) { /* a restart with a shorter output.every */
    o->next_k++;
    next_out = o->t_start + (double)o->next_k * every;
  }
  /* a restart with a longer output.every: the checkpoint's next_k counts the old
     interval, so the multiples of the new one between the checkpoint's time and
     next_k × every would be skipped; step back to the first one after the checkpoint.
     The test is the negation of the one that counts an output time as reached (below),
     so with an unchanged interval next_k is never moved. */
  while (every > 0 && o->next_k > 1 &&
         s->t < o->t_start + (double)(o->next_k - 1) * every - 1e-9 * every) {
    o->next_k--;
    next_out = o->t_start + (double)o->next_k * every;
  }
  if (next_out > tend || tend - next_out < 1e-9 * every) next_out = tend;
  /* measurement times between outputs (measure.every): t_start + k × mevery; one within
     1e-9 mevery of an output time is that output's */
  const double mevery = o->mr.any ? o->mr.every : 0.0, mtol = 1e-9 * mevery;
  double next_meas = INFINITY;
  if (mevery > 0) {
    next_meas = o->t_start + (double)o->next_mk * mevery;
    while (next_meas <= s->t + mtol) next_meas = o->t_start + (double)++o->next_mk * mevery;
    /* a restart with a longer measure.every: as for the outputs above */
    while (o->next_mk > 1 && o->t_start + (double)(o->next_mk - 1) * mevery > s->t + mtol)
      next_meas = o->t_start + (double)--o->next_mk * mevery;
  }
  while (s->t < tend && !interrupted) {
    if (s->tp.max_steps && s->step >= s->tp.max_steps) break;
    int hit = 0, mhit = 0;
    if (next_meas < next_out - mtol && s->t + s->dt >= next_meas) {
      s->dt = next_meas - s->t;
      mhit = 1;
    } else if (s->t + s->dt >= next_out) {
      s->dt = next_out - s->t;
      hit = 1;
    }
    if (step_advance(s, err)) return -1;
    measure_run_step(&o->mr, s);
    if (mhit) {
      s->t = next_meas;
      next_meas = o->t_start + (double)++o->next_mk * mevery;
      if (measure_run_output(&o->mr, s, -1, o->dir, o->matnames, err)) return -1;
    }
    if (hit) {
      s->t = next_out;
      /* the k-th output time reached (not an end time between two of them, which a
         run carried further with a later end would otherwise skip the next one for) */
      if (every > 0 && next_out >= o->t_start + (double)o->next_k * every - 1e-9 * every)
        o->next_k++;
      next_out = every > 0 ? o->t_start + (double)o->next_k * every : tend;
      if (next_out > tend || tend - next_out < 1e-9 * every) next_out = tend;
      while (next_meas <= s->t + mtol) next_meas = o->t_start + (double)++o->next_mk * mevery;
      if (write_outputs(s, o, err) || checkpoint(s, o, &cc, g, err)) return -1;
    } else if (s->out.checkpoint_wall > 0 && wall_time() - cc.wall >= s->out.checkpoint_wall) {
      if (checkpoint(s, o, &cc, g, err)) return -1;
    }
    if (!quiet) {
      double now = wall_time();
      if ((tty && now - last_print > 0.25) || (!tty && s->step % s->out.log_every == 0)) {
        progress(s, t0, wall0, tty, 0);
        last_print = now;
        printed_step = s->step;
      }
    }
  }
  if (!quiet && (tty || printed_step != s->step)) progress(s, t0, wall0, tty, 1);
  int wrote_last =
      o->nrows > 0 && o->rows[(size_t)(o->nrows - 1) * RUN_SUMMARY_COLS] == (double)s->step;
  /* stopped between output times (interrupted, max_steps): the checkpoint first, with
     the outputs so far, so that a restart numbers its snapshots as an uninterrupted run */
  if (!wrote_last && (checkpoint(s, o, &cc, g, err) || write_outputs(s, o, err))) return -1;
  return 0;
}

int run_apply_swaps(struct cfg *c, const char *const *swaps, int nswaps, int strict, int *hits_out,
                    struct hv_error *err)
{
  const int nb = cfg_len(c, "bodies");
  /* the swaps act at once: with a=b and b=a the two exchange, not a to b and back */
  unsigned char *done = calloc(nb > 0 ? (size_t)nb : 1, 1);
  struct material *scratch = calloc(1, sizeof *scratch);
  int rc = 0;
  if (!done || !scratch) rc = hv_error_set(err, HV_EXIT_RUN, "out of memory");
  for (int k = 0; k < nswaps && !rc; k++) {
    const char *sw = swaps[k], *eq = strchr(sw, '=');
    char old[128], key[64], bodies[1024] = "";
    if (!eq || eq == sw || !eq[1] || (size_t)(eq - sw) >= sizeof old || strchr(eq + 1, '=')) {
      rc = hv_error_set(err, HV_EXIT_USAGE,
                        "--material '%s': write OLD=NEW, two material "
                        "names",
                        sw);
      break;
    }
    snprintf(old, sizeof old, "%.*s", (int)(eq - sw), sw);
    int hits = 0;
    for (int b = 0; b < nb && !rc; b++) {
      const char *m;
      snprintf(key, sizeof key, "bodies[%d].material", b);
      if (done[b] || !cfg_has(c, key) || cfg_get_string(c, key, NULL, &m, err)) {
        hv_error_clear(err); /* a body without a usable material: its own error later */
        continue;
      }
      if (strcmp(m, old)) {
        const size_t u = strlen(bodies);
        snprintf(bodies + u, sizeof bodies - u, "%s%s", u ? ", " : "", m);
        continue;
      }
      /* NEW looked up as the body will look it up, named as the swap if unknown */
      int nscratch = 0;
      if (!hits) {
        if (material_find_or_load(c, key, eq + 1, scratch, &nscratch, 1, err) < 0) {
          rc = hv_error_prefix(err, "--material %s: ", sw);
          break;
        }
        material_free(scratch);
      }
      char set[512];
      snprintf(set, sizeof set, "%s=%s", key, eq + 1);
      if (cfg_apply_set(c, set, err)) {
        rc = -1;
        break;
      }
      done[b] = 1;
      hits++;
    }
    if (rc) break;
    if (hits_out) hits_out[k] += hits;
    if (strict && !hits)
      rc = hv_error_set(err, HV_EXIT_INPUT,
                        "%s: --material %s: no body of the case has the "
                        "material '%s' (its bodies have: %s)",
                        cfg_file(c), sw, old, bodies[0] ? bodies : "none");
  }
  free(scratch);
  free(done);
  return rc;
}

int run_check_output_count(const struct sim *s, struct cfg *c, double t_from, int written,
                           int force, struct hv_error *err)
{
  const double every = s->out.every, span = s->tp.end - t_from;
  if (!(every > 0.0) || !(span > 0.0)) return 0;
  /* the outputs still to come (each multiple of every up to the end, and the end) and,
     for a new run, the initial state; as a double: 1e300 outputs is a count too */
  const double n = (double)written + (written ? 1.0 : 2.0) + floor(span / every);
  if (n <= RUN_MAX_OUTPUTS) return 0;
  char where[256];
  cfg_where(c, "output.every", where, sizeof where);
  if (force) {
    hv_warn("%s: output.every = %g s writes %.0f outputs by time.end = %g s (--force)", where,
            every, n, s->tp.end);
    return 0;
  }
  return hv_error_set(err, HV_EXIT_INPUT,
                      "%s: output.every = %g s with time.end = %g s writes "
                      "%.0f outputs (snapshots, summary rows, checkpoints), more than "
                      "%d: was the interval meant in another unit (a bare number is seconds: "
                      "\"every: 1 us\")? Give --force to write them all",
                      where, every, s->tp.end, n, RUN_MAX_OUTPUTS);
}

/* A restart's folder locked and its checkpoint there, before anything is read: a run
 * still going rewrites these files (and may not have written its first checkpoint yet).
 * Returns 0 or -1 with err set. */
static int restart_lock(const char *dir, const char *ckpt, int quiet, struct runfolder_lock *lock,
                        struct hv_error *err)
{
  struct stat st;
  if (stat(dir, &st) == 0 && S_ISDIR(st.st_mode) &&
      runfolder_lock(lock, dir, "restart", quiet, err))
    return -1;
  if (access(ckpt, R_OK))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: no checkpoint to restart from (%s); runs "
                        "write one at every output time unless output.checkpoint is false",
                        ckpt, strerror(errno));
  return 0;
}

/* A restart's outputs so far read back with its state from the checkpoint, and the
 * temporary files of the stopped run removed. Returns 0 or -1 with err set. */
static int reopen_folder(const struct run_options *ro, struct sim *s, struct cfg *c,
                         struct run_outputs *o, const char *ckpt, struct hv_error *err)
{
  if (restart_read(s, o, ckpt, err) || run_check_output_count(s, c, s->t, o->count, ro->force, err))
    return -1;
  const int stale = atomic_file_remove_stale(o->dir);
  if (stale > 0 && !ro->quiet)
    hv_info("removed %d unfinished temporary file%s of the stopped run", stale,
            stale == 1 ? "" : "s");
  return 0;
}

/* A new run's folder made and locked, an earlier run there refused or (--overwrite)
 * removed. Returns 0 or -1 with err set. */
static int open_folder(const struct run_options *ro, struct sim *s, struct cfg *c,
                       struct run_outputs *o, struct runfolder_lock *lock, struct hv_error *err)
{
  if (run_check_output_count(s, c, s->t, 0, ro->force, err) || io_mkdir_p(o->dir, err) ||
      runfolder_lock(lock, o->dir, "run", ro->quiet, err))
    return -1;
  /* an earlier run in the folder: its checkpoint, snapshots and tables would be
     replaced or, worse, mixed with this run's (a restart continuing the old state
     under the new used_parameters.yaml) */
  char what[1024];
  if (runfolder_earlier_run(o->dir, what, sizeof what) > 0) {
    if (!ro->overwrite)
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s holds an earlier run (%s): a new run does "
                          "not write over it. Continue it with 'hvsph restart %s', write "
                          "elsewhere with -o OUTDIR, or give --overwrite to replace it",
                          o->dir, what, o->dir);
    const int gone = runfolder_remove_run(o->dir, err);
    if (gone < 0) return -1;
    atomic_file_remove_stale(o->dir);
    if (!ro->quiet)
      hv_info("--overwrite: removed the earlier run's %d file%s from %s (%s)", gone,
              gone == 1 ? "" : "s", o->dir, what);
  }
  o->t_start = s->t;
  o->next_k = 1;
  o->next_mk = 1;
  return 0;
}

/* The run's last line: interrupted (the exit status says so) or done. */
static int say_end(const struct run_options *ro, const struct sim *s, const struct run_outputs *o)
{
  if (interrupted) {
    if (s->step == 0) /* before the first step: the initial outputs only, no checkpoint */
      hv_info("interrupted before the first step; %s holds the initial state's outputs, "
              "no checkpoint (run the case again, with --overwrite)",
              o->dir);
    else
      hv_info("interrupted at t = %g s (step %ld) by %s; the state at that time is written "
              "to %s%s",
              s->t, s->step, signal_name(interrupted), o->dir,
              s->out.checkpoint ? " (continue with hvsph restart)" : "");
    return HV_EXIT_INTERRUPTED;
  }
  if (!ro->quiet)
    hv_info("done: %ld steps to t = %g s; results in %s/ (summary.csv, run.pvd)", s->step, s->t,
            o->dir);
  if (!ro->quiet && s->p.indiv)
    hv_info("individual time steps: %lld particle rate evaluations at %ld ticks (%.4g per "
            "particle per block of %d levels)%s",
            s->evals, s->eval_ticks,
            s->p.n > 0 && s->step > 0 ? (double)s->evals / ((double)s->p.n * (double)s->step) : 0.0,
            s->tp.levels,
            s->over_steps > 0 ? "; some steps wanted less than the finest level" : "");
  return HV_EXIT_OK;
}

/* The run's first line: the case or the restart, its particles and threads. */
static void say_start(const struct run_options *ro, const struct sim *s,
                      const struct run_outputs *o)
{
  if (ro->restart_dir)
    hv_info("restart of %s from its checkpoint at t = %g s (step %ld, %d outputs written): "
            "%zu particles, %d thread%s, t_end = %g s",
            o->dir, s->t, s->step, o->count, s->p.n, omp_get_max_threads(),
            omp_get_max_threads() == 1 ? "" : "s", s->tp.end);
  else
    hv_info("case %s: %zu particles, %d bod%s, %d thread%s, t_end = %g s, output to %s",
            ro->case_path, s->p.n, s->nbody, s->nbody == 1 ? "y" : "ies", omp_get_max_threads(),
            omp_get_max_threads() == 1 ? "" : "s", s->tp.end, o->dir);
}

int run_main(const struct run_options *ro)
{
  struct hv_error err;
  hv_error_clear(&err);
  struct sim s;
  struct run_outputs o;
  memset(&o, 0, sizeof o);
  memset(&s, 0, sizeof s);
  int status = HV_EXIT_OK;
  interrupted = 0;
  hv_status_line(0);
  if (ro->threads > 0) omp_set_num_threads(ro->threads);
  const char *restart = ro->restart_dir;
  char path[4200], ckpt[4200];
  struct cfg *c = NULL;
  struct segment seg;
  int seg_open = 0, caught = 0;
  struct sigaction old_actions[NSTOP];
  struct runfolder_lock lock;
  runfolder_lock_init(&lock);
  if (restart) { /* the case is the run's used_parameters.yaml */
    snprintf(path, sizeof path, "%s/used_parameters.yaml", restart);
    restart_path(restart, ckpt, sizeof ckpt);
    if (restart_lock(restart, ckpt, ro->quiet, &lock, &err)) goto fail;
  }
  const char *case_path = restart ? path : ro->case_path;

  c = cfg_load(case_path, &err);
  if (!c) goto fail;
  for (int i = 0; i < ro->nsets; i++)
    if (cfg_apply_set(c, ro->sets[i], &err)) goto fail;
  if (!restart && run_apply_swaps(c, ro->swaps, ro->nswaps, !ro->swaps_lenient, NULL, &err))
    goto fail;
  if (run_setup(&s, c, &err) || measure_run_read(&o.mr, &s, c, &err) || cfg_check_unused(c, &err))
    goto fail;
  /* a new run's first rates and time step, before anything is written: a set-up that
     the neighbour grid cannot hold is bad input and leaves the output folder as it was */
  if (!restart && (step_init(&s, &err) || check_plausible_end(&s, c, &err))) goto fail;

  char nbuf[256];
  if (restart)
    snprintf(o.dir, sizeof o.dir, "%s", restart);
  else if (ro->outdir)
    snprintf(o.dir, sizeof o.dir, "%s", ro->outdir);
  else
    snprintf(o.dir, sizeof o.dir, "out/%s",
             cfg_has(c, "name") ? s.case_name : default_name(ro->case_path, nbuf, sizeof nbuf));
  for (int i = 0; i < s.nmat; i++) o.matnames[i] = s.mat[i].name;
  for (int i = 0; i < s.nbody; i++) o.bodynames[i] = s.body[i].name;
  if (restart ? reopen_folder(ro, &s, c, &o, ckpt, &err) : open_folder(ro, &s, c, &o, &lock, &err))
    goto fail;
  /* a restart records its overrides (the file is what the continued run used) */
  if (!restart || ro->nsets > 0) {
    snprintf(path, sizeof path, "%s/used_parameters.yaml", o.dir);
    if (cfg_write_used(c, path, HVSPH_VERSION, &err)) goto fail;
  }

  if (!ro->quiet) say_start(ro, &s, &o);
  if (restart && s.t >= s.tp.end) {
    if (!ro->quiet)
      hv_info("nothing to do: the run reached t_end = %g s (continue it with --set "
              "time.end=LATER)",
              s.tp.end);
    goto done;
  }
  stop_signals_catch(old_actions);
  caught = 1;
  segment_begin(&seg, o.dir, restart != NULL, &s);
  seg_open = 1;
  if ((!restart && write_outputs(&s, &o, &err)) || run_loop(&s, &o, &seg, ro->quiet, &err))
    goto fail;
  stop_signals_restore(old_actions);
  caught = 0;
  if (segment_write(&seg, o.dir, &s,
                    interrupted      ? "interrupted"
                    : s.t < s.tp.end ? "stopped (max_steps)"
                                     : "done",
                    &err))
    goto fail;
  status = say_end(ro, &s, &o);
  goto done;
fail:
  if (caught) stop_signals_restore(old_actions);
  hv_log(0, "%s", err.msg);
  status = err.code ? err.code : HV_EXIT_RUN;
  if (seg_open) { /* the row says how it ended; a second failure here is not reported */
    struct hv_error e2;
    hv_error_clear(&e2);
    segment_write(&seg, o.dir, &s, "failed", &e2);
  }
done:
  runfolder_unlock(&lock);
  if (seg_open) free(seg.prev);
  outputs_free(&o);
  sim_free(&s);
  if (c) cfg_free(c);
  return status;
}
