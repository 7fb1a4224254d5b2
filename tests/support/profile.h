/* profile.h — shared plumbing of the verification tests (tests/verification/).
 *
 * verif_run() runs `$HVSPH_BIN run $HVSPH_SOURCE_DIR/examples/verification/<name>.yaml
 * -o $HVSPH_TMP/<name> --overwrite --quiet --threads N` (the folder is the test's:
 * its last run replaced) plus any extra arguments (the test
 * program's own command-line arguments, e.g. `--set bodies[0].spacing=0.0025` for a
 * finer run, then $HVSPH_CASE_ARGS as in tests/support/solidcase.h), times it, and
 * returns the exit status. N is $HVSPH_TEST_THREADS, default 1 (`make check` runs
 * two tests at a time on two cores). verif_read_last() reads the
 * last particles_NNNNN.csv of that output folder. Profiles are CSV files under
 * $HVSPH_TMP for tools/figures/plot_verification.py: a comment line naming the problem,
 * time and measured numbers, then a header whose first column is the coordinate
 * (x or r [m]) followed by pairs `q,q_exact` (one row per particle) — see
 * docs/verification.md.
 */
#ifndef HV_PROFILE_H
#define HV_PROFILE_H

#include <stddef.h>
#include <stdio.h>

#include "particles/particles.h"

/* Runs the example; *wall [s] gets the run's wall-clock time. argv/argc: extra
 * arguments passed through to `hvsph run` (each shell-quoted). Returns the exit status. */
int verif_run(const char *name, int argc, char **argv, double *wall);
/* The same with the output folder $HVSPH_TMP/<dirname> (several runs of one example);
 * read it back with verif_read_last(dirname, ...). */
int verif_run_as(const char *name, const char *dirname, int argc, char **argv, double *wall);
/* Reads the highest-numbered particles_NNNNN.csv of $HVSPH_TMP/<name> into p (which
 * must be initialised); *t gets its time [s]. Returns 0, or -1 with a message. */
int verif_read_last(const char *name, struct particles *p, double *t);
/* Threads for the run: $HVSPH_TEST_THREADS, default 1. */
int verif_threads(void);

/* Opens $HVSPH_TMP/<file> for writing, with a first comment line `# <comment>` and
 * the header line `header` (e.g. "r,rho,rho_exact"); exits on failure. */
FILE *profile_open(const char *file, const char *comment, const char *header);
void profile_close(FILE *f);

/* Radii of the particles from the origin (r[i], i < p->n); caller frees. */
double *profile_radii(const struct particles *p);
/* Mass-weighted mean of q over particles in nb bins of width dr from 0: mean[b],
 * count[b] (0 where empty, mean[b] = NAN there). */
void profile_bin(const double *r, const double *m, const double *q, size_t n, double dr, int nb,
                 double *mean, long *count);

#endif
