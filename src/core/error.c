/* error.c — see error.h. */
#include "core/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int hv_log_level = 2;

static size_t status_len = 0; /* see hv_status_line() */

void hv_status_line(size_t len) { status_len = len; }

size_t hv_status_len(void) { return status_len; }

void hv_status_end(void)
{
  if (status_len) fputc('\n', stderr);
  status_len = 0;
}

void hv_error_clear(struct hv_error *err)
{
  if (!err) return;
  err->code = 0;
  err->msg[0] = '\0';
}

void hv_error_set_(struct hv_error *err, int code, const char *fmt, ...)
{
  if (!err) return;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(err->msg, sizeof err->msg, fmt, ap);
  va_end(ap);
  err->code = code;
}

void hv_error_prefix_(struct hv_error *err, const char *fmt, ...)
{
  if (!err) return;
  char head[1024], old[sizeof err->msg];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(head, sizeof head, fmt, ap);
  va_end(ap);
  memcpy(old, err->msg, sizeof old);
  size_t hl = strlen(head), ol = strlen(old);
  if (hl > sizeof err->msg - 1) hl = sizeof err->msg - 1;
  if (ol > sizeof err->msg - 1 - hl) ol = sizeof err->msg - 1 - hl;
  memcpy(err->msg, head, hl);
  memcpy(err->msg + hl, old, ol);
  err->msg[hl + ol] = '\0';
  if (!err->code) err->code = HV_EXIT_RUN;
}

void hv_log(int level, const char *fmt, ...)
{
  if (level > hv_log_level) return;
  hv_status_end();
  static const char *tag[] = {"error: ", "warning: ", "", ""};
  fputs("hvsph: ", stderr);
  fputs(tag[level < 0 ? 0 : (level > 3 ? 3 : level)], stderr);
  va_list ap;
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fputc('\n', stderr);
}

void hv_fatal(const char *file, int line, const char *func, const char *fmt, ...)
{
  hv_status_end();
  fprintf(stderr, "hvsph: internal error at %s:%d %s(): ", file, line, func);
  va_list ap;
  va_start(ap, fmt);
  vfprintf(stderr, fmt, ap);
  va_end(ap);
  fputc('\n', stderr);
  exit(HV_EXIT_RUN);
}

void *hv_malloc(size_t bytes, const char *what)
{
  void *p = malloc(bytes ? bytes : 1);
  if (!p) {
    hv_status_end();
    fprintf(stderr, "hvsph: out of memory allocating %zu bytes for %s\n", bytes, what);
    exit(HV_EXIT_RUN);
  }
  return p;
}

void *hv_calloc(size_t n, size_t size, const char *what)
{
  void *p = calloc(n ? n : 1, size ? size : 1);
  if (!p) {
    hv_status_end();
    fprintf(stderr, "hvsph: out of memory allocating %zu x %zu bytes for %s\n", n, size, what);
    exit(HV_EXIT_RUN);
  }
  return p;
}

void *hv_realloc(void *p, size_t bytes, const char *what)
{
  void *q = realloc(p, bytes ? bytes : 1);
  if (!q) {
    hv_status_end();
    fprintf(stderr, "hvsph: out of memory growing %s to %zu bytes\n", what, bytes);
    exit(HV_EXIT_RUN);
  }
  return q;
}
