/* test_used_parameters.c — used_parameters.yaml is a case file that reproduces its run.
 *
 * Its header says "This file can be run as a case file". examples/verification/
 * tiny.yaml is run, then the used_parameters.yaml it wrote is run as a case; the
 * second run must succeed and write bitwise the same particle files, run.pvd and
 * summary.csv (same version, same case name). Its own used_parameters.yaml must hold
 * the same keys with the same values (only the header lines and the "default"
 * markers may differ, since every value is now given explicitly).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testlib.h"

static const char *join(char *buf, size_t len, const char *a, const char *b)
{
  if ((size_t)snprintf(buf, len, "%s/%s", a, b) >= len) {
    fprintf(stderr, "path too long: %s/%s\n", a, b);
    exit(1);
  }
  return buf;
}

/* used_parameters.yaml without comment lines and without the "default" markers. */
static char *normalised(const char *path)
{
  char *s = test_slurp(path, NULL);
  if (!s) return NULL;
  char *out = malloc(strlen(s) + 1), *o = out;
  for (char *line = strtok(s, "\n"); line; line = strtok(NULL, "\n")) {
    if (line[0] == '#') continue;
    char *mark = strstr(line, "  # ");
    size_t n = strlen(line);
    if (mark) {
      char *d = strstr(mark, "default");
      if (d && d[7] == '\0') {   /* "  # m, default" -> "  # m", "  # default" -> "" */
        n = (size_t)(d - line);
        while (n > 0 && (line[n - 1] == ' ' || line[n - 1] == ',' || line[n - 1] == '#')) n--;
      }
    }
    memcpy(o, line, n);
    o += n;
    *o++ = '\n';
  }
  *o = '\0';
  free(s);
  return out;
}

static int run(const char *casefile, const char *dir, char *out, size_t len)
{
  char cmd[9000];
  if ((size_t)snprintf(cmd, sizeof cmd, "rm -rf '%s' && '%s' run '%s' -o '%s' --quiet", dir,
                       test_bin(), casefile, dir) >= sizeof cmd)
    return -1;
  return test_run(cmd, out, len);
}

int main(void)
{
  char casefile[4200], d1[4200], d2[4200], used1[4400], used2[4400], out[8192];
  join(casefile, sizeof casefile, test_source_dir(), "examples/verification/tiny.yaml");
  join(d1, sizeof d1, test_tmpdir(), "first");
  join(d2, sizeof d2, test_tmpdir(), "again");
  join(used1, sizeof used1, d1, "used_parameters.yaml");
  join(used2, sizeof used2, d2, "used_parameters.yaml");

  int rc = run(casefile, d1, out, sizeof out);
  CHECK(rc == 0, "tiny.yaml runs (exit %d)%s%s", rc, rc ? ": " : "", rc ? out : "");
  if (rc) return test_finish();
  rc = run(used1, d2, out, sizeof out);
  CHECK(rc == 0, "its used_parameters.yaml runs as a case file (exit %d)%s%s", rc,
        rc ? ": " : "", rc ? out : "");
  if (rc) return test_finish();

  static const char *const files[] = {"summary.csv", "run.pvd", "particles_00000.vtu",
                                      "particles_00000.csv", "particles_00004.vtu",
                                      "particles_00004.csv"};
  for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
    char p1[4400], p2[4400];
    size_t n1 = 0, n2 = 0;
    char *a = test_slurp(join(p1, sizeof p1, d1, files[k]), &n1);
    char *b = test_slurp(join(p2, sizeof p2, d2, files[k]), &n2);
    CHECK(a && b && n1 == n2 && !memcmp(a, b, n1), "%s: the rerun wrote the same %zu bytes "
          "(%zu)", files[k], n1, n2);
    free(a);
    free(b);
  }
  char *u1 = normalised(used1), *u2 = normalised(used2);
  int same = u1 && u2 && !strcmp(u1, u2);
  CHECK(same, "the rerun's used_parameters.yaml holds the same keys and values");
  if (!same && u1 && u2) {
    char *l1 = u1, *l2 = u2;
    while (*l1 && *l1 == *l2) l1++, l2++;
    while (l1 > u1 && l1[-1] != '\n') l1--;
    while (l2 > u2 && l2[-1] != '\n') l2--;
    printf("  first difference:\n    %.*s\n    %.*s\n", (int)strcspn(l1, "\n"), l1,
           (int)strcspn(l2, "\n"), l2);
  }
  free(u1);
  free(u2);
  return test_finish();
}
