/* testlib.c — see testlib.h. */
#include "testlib.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

int test_passed = 0, test_failed = 0;

static void check_v(int ok, const char *file, int line, const char *fmt, va_list ap)
{
  if (ok) {
    test_passed++;
    printf("  ok    ");
  } else {
    test_failed++;
    printf("  FAIL  %s:%d: ", file, line);
  }
  vprintf(fmt, ap);
  printf("\n");
  fflush(stdout);
}

void test_check(int ok, const char *file, int line, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  check_v(ok, file, line, fmt, ap);
  va_end(ap);
}

static int pending_ok;

int test_pending(int ok)
{
  pending_ok = ok;
  return ok;
}

void test_check_pending(const char *file, int line, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  check_v(pending_ok, file, line, fmt, ap);
  va_end(ap);
}

int test_finish(void)
{
  printf("%d passed, %d failed\n", test_passed, test_failed);
  return test_failed ? 1 : 0;
}

const char *test_bin(void)
{
  const char *b = getenv("HVSPH_BIN");
  return b ? b : "build/hvsph";
}

const char *test_source_dir(void)
{
  const char *s = getenv("HVSPH_SOURCE_DIR");
  return s ? s : ".";
}

static int mkdir_p(const char *dir)
{
  char buf[4096];
  snprintf(buf, sizeof buf, "%s", dir);
  for (char *q = buf + 1; *q; q++) {
    if (*q == '/') {
      *q = 0;
      if (mkdir(buf, 0755) && errno != EEXIST) return -1;
      *q = '/';
    }
  }
  if (mkdir(buf, 0755) && errno != EEXIST) return -1;
  return 0;
}

const char *test_tmpdir(void)
{
  static char dir[4096];
  if (!dir[0]) {
    const char *t = getenv("HVSPH_TMP");
    snprintf(dir, sizeof dir, "%s", t ? t : "/tmp/hvsph-test");
    if (mkdir_p(dir)) {
      fprintf(stderr, "cannot create %s: %s\n", dir, strerror(errno));
      exit(1);
    }
  }
  return dir;
}

const char *test_write_file(const char *name, const char *text)
{
  static char paths[8][4096];
  static int k = 0;
  char *path = paths[k++ % 8];
  if (snprintf(path, 4096, "%s/%s", test_tmpdir(), name) >= 4096) {
    fprintf(stderr, "path too long: %s/%s\n", test_tmpdir(), name);
    exit(1);
  }
  FILE *f = fopen(path, "w");
  if (!f || fputs(text, f) < 0 || fclose(f)) {
    fprintf(stderr, "cannot write %s\n", path);
    exit(1);
  }
  return path;
}

int test_run(const char *cmdline, char *output, size_t len)
{
  size_t cl = strlen(cmdline);
  char *cmd = malloc(cl + 8);
  if (!cmd) return -1;
  memcpy(cmd, cmdline, cl);
  memcpy(cmd + cl, " 2>&1", 6);
  FILE *f = popen(cmd, "r");
  free(cmd);
  if (!f) return -1;
  size_t k = 0;
  char buf[4096];
  size_t r;
  while ((r = fread(buf, 1, sizeof buf, f)) > 0) {
    if (output && k + 1 < len) {
      size_t c = r < len - 1 - k ? r : len - 1 - k;
      memcpy(output + k, buf, c);
      k += c;
    }
  }
  if (output && len) output[k] = 0;
  int st = pclose(f);
  if (st == -1) return -1;
  return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}

char *test_slurp(const char *path, size_t *len)
{
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  size_t cap = 1 << 16, n = 0, r;
  char *b = malloc(cap + 1);
  while (b && (r = fread(b + n, 1, cap - n, f)) > 0) {
    n += r;
    if (n == cap) {
      char *nb = realloc(b, (cap *= 2) + 1);
      if (!nb) free(b);
      b = nb;
    }
  }
  fclose(f);
  if (b) b[n] = '\0';
  if (len) *len = n;
  return b;
}

int test_summary_energy_span(const char *rundir, double *e0, double *e1)
{
  char path[4300], line[4096];
  snprintf(path, sizeof path, "%s/summary.csv", rundir);
  FILE *f = fopen(path, "r");
  if (!f) return -1;
  int rows = 0;
  while (fgets(line, sizeof line, f)) {
    if (line[0] < '0' || line[0] > '9') continue; /* the header and comment lines */
    char *q = line;
    for (int k = 0; k < 10 && q; k++) {
      q = strchr(q, ',');
      if (q) q++;
    }
    if (!q) continue;
    const double e = strtod(q, NULL);
    if (rows++ == 0) *e0 = e;
    *e1 = e;
  }
  fclose(f);
  return rows >= 2 ? 0 : -1;
}

void test_refused_case(const char *what, const char *text, int line, const char *key,
                       const char *word)
{
  static int k = 0;
  char name[64], out[8192], cmd[16384], dir[4200], where[300];
  snprintf(name, sizeof name, "bad%02d.yaml", k++);
  const char *file = test_write_file(name, text);
  snprintf(dir, sizeof dir, "%s/out_%s", test_tmpdir(), name);
  snprintf(cmd, sizeof cmd, "'%s' run '%s' -o '%s' --quiet", test_bin(), file, dir);
  const int rc = test_run(cmd, out, sizeof out);
  snprintf(where, sizeof where, "%s:%d", name, line);
  struct stat st;
  const int written = stat(dir, &st) == 0;
  const int has_where = strstr(out, where) != NULL, has_key = strstr(out, key) != NULL;
  const int has_word = !word || strstr(out, word) != NULL;
  const int lines = (int)(strchr(out, '\n') && strchr(out, '\n')[1] == '\0');
  CHECK(rc == 2 && has_where && has_key && has_word && lines && !written,
        "%s: exit %d (2), names %s (%s), the key %s (%s)%s%s%s, one line (%s), nothing "
        "written (%s)\n    message: %s",
        what, rc, where, has_where ? "yes" : "NO", key, has_key ? "yes" : "NO",
        word ? ", says '" : "", word ? word : "", word ? (has_word ? "' (yes)" : "' (NO)") : "",
        lines ? "yes" : "NO", written ? "NO" : "yes", out);
}
