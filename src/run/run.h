/* run.h — `hvsph run`: read a case, set it up, step it to the end with outputs. */
#ifndef HV_RUN_H
#define HV_RUN_H

#include "config/config.h"
#include "core/error.h"

struct run_options {
  const char *case_path;
  const char *outdir;      /* NULL: out/<case name> */
  const char *const *sets; /* --set assignments */
  int nsets;
  int threads; /* 0: OpenMP default */
  int quiet;
  const char *restart_dir;  /* continue the run in this folder from its checkpoint
                                   (case_path and outdir unused) */
  const char *const *swaps; /* --material OLD=NEW: bodies of material OLD get NEW */
  int nswaps;
  int swaps_lenient; /* 0: a swap that no body takes is bad input; 1: it is
                                   ignored (validate, which checks over all its cases) */
  int overwrite;     /* a new run replaces an earlier run in its folder (0: it
                                   refuses the folder, exit 2) */
  int force;         /* more than RUN_MAX_OUTPUTS outputs (0: refused, exit 2) */
};

/* The most outputs (snapshots, summary rows, checkpoints) a run writes without --force.
 * A snapshot of a paper case at its resolution holds 10^5 to 10^6 particles, 20 to 200
 * MB: 10 000 of them fill 0.2 to 2 TB, and one folder of 10 000 files is where listings
 * and ParaView's series loading turn slow. The example cases write 2 to 52 outputs, and a
 * movie of 10 000 frames runs 5.5 min at 30 frames/s: more is a unit slip (`every: 1e-9`
 * meant in us), which --force lets through when meant. */
#define RUN_MAX_OUTPUTS 10000

/* Returns an exit status (enum hv_exit); prints its own messages. */
int run_main(const struct run_options *o);
/* Whether the last run_main was stopped by a signal (SIGINT, SIGTERM, SIGHUP, SIGUSR1,
 * SIGUSR2, SIGXCPU), whatever its exit status
 * (a failure to write the state after the signal returns that failure's status). */
int run_interrupted(void);

/* --material OLD=NEW on a loaded case: every body whose `material` is OLD is given NEW
 * instead, as --set bodies[i].material=NEW would; NEW is looked up as the body's material
 * would be (material_find_or_load: the case's materials, then the library), an unknown
 * one bad input named as the swap. strict: a swap that no body takes is bad input (a
 * misspelt name would otherwise run the case unchanged). hits (or NULL): the bodies that
 * took swap k are added to hits[k]. */
int run_apply_swaps(struct cfg *c, const char *const *swaps, int nswaps, int strict, int *hits,
                    struct hv_error *err);

/* A wall-clock duration as the progress line and hvsph check write it: "7.6 s" under a
 * minute, else h:mm:ss ("27:46:40": a run that promises days shows it at a glance, where
 * "100000.0 s" did not), with the days added from two on ("52:00:00 (2 days)"). */
void run_format_duration(char *buf, size_t len, double sec);

/* Reads a case file (with overrides) into a ready simulation; used by run and bench. */
struct sim;
int run_setup(struct sim *s, struct cfg *c, struct hv_error *err);

/* Bad input (HV_EXIT_INPUT, naming the file, line and key output.every and the count)
 * when a run from t_from with `written` outputs already on disk (0 for a new run) would
 * write more than RUN_MAX_OUTPUTS in all; with force a warning only. */
int run_check_output_count(const struct sim *s, struct cfg *c, double t_from, int written,
                           int force, struct hv_error *err);

#endif
