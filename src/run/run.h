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
};

/* Returns an exit status (enum hv_exit); prints its own messages. */
int run_main(const struct run_options *o);
/* Whether the last run_main was stopped by SIGINT or SIGTERM, whatever its exit status
 * (a failure to write the state after the signal returns that failure's status). */
int run_interrupted(void);

/* Reads a case file (with overrides) into a ready simulation; used by run and bench. */
struct sim;
int run_setup(struct sim *s, struct cfg *c, struct hv_error *err);

#endif
