/* restart.h — checkpoints of a run (OUTDIR/checkpoint.hvc) and restarts from them.
 *
 * A checkpoint holds everything the step loop carries from one step to the next —
 * the particles' state fields (particles.h, PF_STATE), the clock (t, the next Δt
 * and the last proposed one, the step number), what absorbing faces removed, the
 * running peak pressure and table of the measurements, and the output bookkeeping
 * (summary rows, snapshot list, index of the next output time) — so that a run
 * continued from it writes, step for step, the same numbers as a run that was
 * never stopped (tests/consistency/test_restart.c checks the files bitwise).
 *
 * The bookkeeping is that of the last regular output: the extra snapshot an
 * interrupted run writes at the moment it stops is not in it, so the continued run
 * numbers its snapshots as the uninterrupted run would and replaces that extra one.
 * The file format is io/checkpoint.h's; the records are those restart_write puts
 * (docs/cli.md, "hvsph restart", lists what they hold).
 */
#ifndef HV_RESTART_H
#define HV_RESTART_H

#include "core/error.h"
#include "run/measure_run.h"
#include "sim/sim.h"

#define RUN_SUMMARY_COLS 18

/* What `hvsph run` has written so far and where the next output falls. */
struct run_outputs {
  struct measure_run mr;
  char dir[4000];
  int count;     /* outputs written (the next snapshot's number) */
  double *times; /* [count] time of each .vtu (when output.vtu) */
  char **files;  /* [count] its file name (NULL without .vtu) */
  double *rows;  /* [nrows × RUN_SUMMARY_COLS] summary.csv */
  int nrows;
  double t_start; /* [s] the run's start: output k falls at t_start + k × every */
  long next_k;    /* index of the next output time */
  long next_mk;   /* index of the next measurement time (measure.every) */
  const char *matnames[HV_MAX_MATERIALS];
  const char *bodynames[64]; /* sim's body[].name */
};

/* OUTDIR/checkpoint.hvc */
void restart_path(const char *dir, char *buf, size_t len);
/* Writes the checkpoint of s and o (atomically: the previous one stays intact until
 * this one is complete). */
int restart_write(const struct sim *s, const struct run_outputs *o, struct hv_error *err);
/* Replaces the state of s (set up from the same case) and the bookkeeping of o (its
 * dir and measurement set-up already filled) with those of the checkpoint at path.
 * Errors (HV_EXIT_INPUT) name the file and the record, or the mismatch between the
 * checkpoint and the case. */
int restart_read(struct sim *s, struct run_outputs *o, const char *path, struct hv_error *err);

#endif
