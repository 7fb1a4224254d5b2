/* error.h — status codes, error messages that gather context, logging.
 *
 * Input and I/O layers return 0 or -1 and fill a struct hv_error; callers add
 * context on the way up with hv_error_prefix() ("case.yaml:14: body 'bumper': ...").
 * Internal invariants that must never fail use HV_FATAL, which prints
 * file:line function(): message and exits with HV_EXIT_RUN.
 */
#ifndef HV_ERROR_H
#define HV_ERROR_H

#include <stddef.h>

enum hv_exit {
  HV_EXIT_OK = 0,
  HV_EXIT_USAGE = 1, /* bad command line */
  HV_EXIT_INPUT = 2, /* bad case file, material, unit, unwritable output folder */
  HV_EXIT_RUN = 3,   /* a run that failed: NaN, negative density, full disk, internal error */
  HV_EXIT_INTERRUPTED = 130
};

struct hv_error {
  int code; /* one of enum hv_exit; 0 while no error */
  char msg[2048];
};

void hv_error_clear(struct hv_error *err);
/* Sets code and message (printf format). Evaluates to -1 so callers can
 * `return hv_error_set(...)`; the -1 is in the macro, where a static analyser that
 * reads one file at a time (scan-build, `make analyze`) sees it. The -1 comes from an
 * inline function, not a literal, so that a call whose value is dropped does not warn
 * (-Wunused-value). */
static inline int hv_error_minus_one_(void) { return -1; }
void hv_error_set_(struct hv_error *err, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
#define hv_error_set(...) (hv_error_set_(__VA_ARGS__), hv_error_minus_one_())
/* Prepends context to an existing message. Evaluates to -1. */
void hv_error_prefix_(struct hv_error *err, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
#define hv_error_prefix(...) (hv_error_prefix_(__VA_ARGS__), hv_error_minus_one_())

/* Logging to stderr. Levels: 0 error, 1 warning, 2 info, 3 debug. */
extern int hv_log_level;
void hv_log(int level, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
#define hv_info(...) hv_log(2, __VA_ARGS__)
#define hv_warn(...) hv_log(1, __VA_ARGS__)

/* A status line on a terminal (hvsph run's progress, rewritten in place with a carriage
 * return and no newline): hv_status_line(len) records that one of len characters is on
 * the screen (0: none). Every message of hv_log, hv_fatal and the allocators first ends
 * it with a newline, so that the message starts a line of its own. */
void hv_status_line(size_t len);
size_t hv_status_len(void);
void hv_status_end(void);

_Noreturn void hv_fatal(const char *file, int line, const char *func, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
#define HV_FATAL(...) hv_fatal(__FILE__, __LINE__, __func__, __VA_ARGS__)
/* Always-on check (not compiled out in release builds). */
#define HV_CHECK(cond, ...)                                                                        \
  do {                                                                                             \
    if (!(cond)) HV_FATAL(__VA_ARGS__);                                                            \
  } while (0)

/* Allocation that never returns NULL: reports the size and exits HV_EXIT_RUN. */
void *hv_malloc(size_t bytes, const char *what);
void *hv_calloc(size_t n, size_t size, const char *what);
void *hv_realloc(void *p, size_t bytes, const char *what);

#endif
