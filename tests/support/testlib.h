/* testlib.h — a small test harness for hvsph's C tests.
 *
 * CHECK(cond, fmt, ...) records a pass or a failure with a message;
 * CHECK_CLOSE(a, b, tol, what) checks |a - b| <= tol. test_finish() prints
 * "N passed, N failed" and returns the exit status for main().
 * The environment gives HVSPH_BIN (the hvsph binary), HVSPH_SOURCE_DIR and
 * HVSPH_TMP (a scratch folder private to the test; created by test_tmpdir()).
 */
#ifndef HV_TESTLIB_H
#define HV_TESTLIB_H

#include <stddef.h>

extern int test_passed, test_failed;

void test_check(int ok, const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* CHECK evaluates cond first, then the message's arguments (the comma operator orders
 * them; as arguments of one call their order would be unspecified, and a check like
 * CHECK(measure(&r) == 0, "%g", r.x) printed the value from before the call). */
int test_pending(int ok);
void test_check_pending(const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
#define CHECK(cond, ...)                                                                           \
  (test_pending(!!(cond)), test_check_pending(__FILE__, __LINE__, __VA_ARGS__))
#define CHECK_CLOSE(a, b, tol, what)                                                               \
  do {                                                                                             \
    double a_ = (a), b_ = (b), t_ = (tol);                                                         \
    test_check(a_ - b_ <= t_ && b_ - a_ <= t_, __FILE__, __LINE__,                                 \
               "%s: %.10g vs %.10g (tolerance %.3g)", (what), a_, b_, t_);                         \
  } while (0)

int test_finish(void);

/* Paths from the environment (fall back to sensible defaults when run by hand). */
const char *test_bin(void);
const char *test_source_dir(void);
/* Creates (if needed) and returns the test's scratch folder. */
const char *test_tmpdir(void);
/* Writes text to a file under the scratch folder; returns its full path (static buffer rotates 8). */
const char *test_write_file(const char *name, const char *text);
/* Reads a whole file (NUL-terminated); NULL when it cannot. *len (may be NULL) gets
 * the size. The caller frees. */
char *test_slurp(const char *path, size_t *len);
/* Runs a shell command line; returns its exit status (or -1). If `output` is not NULL,
 * stdout+stderr are captured into it (up to len-1 bytes). */
int test_run(const char *cmdline, char *output, size_t len);
/* Writes the case `text` to bad<NN>.yaml in the test's folder and runs `hvsph run` on
 * it; CHECKs (labelled `what`) exit status 2, a one-line message naming "<file>:<line>",
 * `key` and `word` (may be NULL), and no output folder written. */
void test_refused_case(const char *what, const char *text, int line, const char *key,
                       const char *word);
/* The first and last total energy (e_total, column 11) of a run folder's summary.csv:
 * 0, or -1 when the file is missing or has fewer than two rows. */
int test_summary_energy_span(const char *rundir, double *e0, double *e1);

#endif
