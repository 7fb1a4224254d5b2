/* run.h — `hvsph run`: read a case, set it up, step it to the end with outputs. */
#ifndef HV_RUN_H
#define HV_RUN_H

#include "config/config.h"
#include "core/error.h"

struct run_options {
  const char *case_path;
  const char *outdir;           /* NULL: out/<case name> */
  const char *const *sets;      /* --set assignments */
  int nsets;
  int threads;                  /* 0: OpenMP default */
  int quiet;
  const char *restart_dir;      /* continue the run in this folder from its checkpoint
                                   (case_path and outdir unused) */
  const char *const *swaps;     /* --material OLD=NEW: bodies of material OLD get NEW */
  int nswaps;
  int swaps_lenient;            /* 0: a swap that no body takes is bad input; 1: it is
                                   ignored (validate, which checks over all its cases) */
};

/* Returns an exit status (enum hv_exit); prints its own messages. */
int run_main(const struct run_options *o);
/* Whether the last run_main was stopped by SIGINT or SIGTERM, whatever its exit status
 * (a failure to write the state after the signal returns that failure's status). */
int run_interrupted(void);

/* --material OLD=NEW on a loaded case: every body whose `material` is OLD is given NEW
 * instead, as --set bodies[i].material=NEW would; NEW is looked up as the body's material
 * would be (material_find_or_load: the case's materials, then the library), an unknown
 * one bad input named as the swap. strict: a swap that no body takes is bad input (a
 * misspelt name would otherwise run the case unchanged). hits (or NULL): the bodies that
 * took swap k are added to hits[k]. */
int run_apply_swaps(struct cfg *c, const char *const *swaps, int nswaps, int strict,
                    int *hits, struct hv_error *err);

/* A wall-clock duration as the progress line and hvsph check write it: "7.6 s" under a
 * minute, else h:mm:ss ("27:46:40": a run that promises days shows it at a glance, where
 * "100000.0 s" did not), with the days added from two on ("52:00:00 (2 days)"). */
void run_format_duration(char *buf, size_t len, double sec);

/* Reads a case file (with overrides) into a ready simulation; used by run and bench. */
struct sim;
int run_setup(struct sim *s, struct cfg *c, struct hv_error *err);

#endif
