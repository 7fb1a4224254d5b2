/* test_cli.c — the command line and bad input, through the hvsph binary.
 *
 * Each bad case file is a one-line variant of the small case below (so the line
 * numbers in the expected messages are exact). For every failure the test checks:
 *   - the exit status (1 bad command line, 2 bad input, 3 failed run);
 *   - stderr holds exactly one error line ("hvsph: error: ..."), and that line
 *     names the file and line and the key (or the particle, time and field) — the
 *     expected pieces are written out below;
 *   - nothing half-written is left: no temporary file (".tmp.") in the output
 *     folder; for input errors the folder, prepared with a summary.csv of an earlier
 *     run, holds exactly that file afterwards, byte for byte; for a failed run,
 *     summary.csv is the new run's and complete (header, then rows of 18 fields).
 *
 * A run that fails (exit 3), reliably:
 *   - negative density: time.end = time.dt_init = 10 s with output.every = 0, so
 *     the first step is 10 s, about 25000 times the CFL step; the body expands
 *     (radial_velocity 0.2 m/s) and its particles cross, so the continuity equation
 *     (ρⁿ exp(Δt Dρ/ρⁿ)) sends ρ to infinity or 0 in that step: "particle N ...: field
 *     rho: inf kg/m3 is not a positive finite density".
 *   - non-finite values: pressure 1e306 Pa (finite, and so accepted); the pressure
 *     forces overflow to infinity, the time step to zero, and 0 × inf gives NaN:
 *     "particle N ...: rho = -nan".
 */
#include <dirent.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "run/runfolder.h"
#include "testlib.h"
#include "version.h"

static const char *base_lines[] = {
    "name: cli",                                                      /* 1 */
    "materials:",                                                     /* 2 */
    "  gas: {eos: ideal-gas, gamma: 1.4}",                            /* 3 */
    "domain:",                                                        /* 4 */
    "  min: [0, 0, 0]",                                               /* 5 */
    "  max: [0.1, 0.05, 0.05]",                                       /* 6 */
    "  boundary: {x: wall, y: periodic, z: periodic}",                /* 7 */
    "bodies:",                                                        /* 8 */
    "  - name: slab",                                                 /* 9 */
    "    material: gas",                                              /* 10 */
    "    shape: {type: box, min: [0, 0, 0], max: [0.1, 0.05, 0.05]}", /* 11 */
    "    spacing: 6.25 mm",                                           /* 12 */
    "    density: 1.0",                                               /* 13 */
    "    pressure: 1.0",                                              /* 14 */
    "    velocity: [0.3, 0.1, -0.05]",                                /* 15 */
    "    radial_velocity: 0.2",                                       /* 16 */
    "time:",                                                          /* 17 */
    "  end: 0.01",                                                    /* 18 */
    "output:",                                                        /* 19 */
    "  every: 0.005",                                                 /* 20 */
    "  csv: true",                                                    /* 21 */
};
#define NBASE          ((int)(sizeof base_lines / sizeof base_lines[0]))
#define SUMMARY_FIELDS 18 /* step ... e_total, then the absorbed_* tallies */
#define PREVIOUS       "# an earlier run\nstep,time\n0,0\n"

static char text[16384];

/* The base case with line `line` (1-based) replaced by `repl` ("" deletes it;
 * `repl` may hold several lines). line 0: the base case unchanged. */
static const char *variant(int line, const char *repl)
{
  size_t k = 0;
  for (int i = 1; i <= NBASE; i++) {
    const char *s = i == line ? repl : base_lines[i - 1];
    if (i == line && !*repl) continue;
    k += (size_t)snprintf(text + k, sizeof text - k, "%s\n", s);
  }
  return text;
}

static const char *path_of(const char *name)
{
  static char buf[8][4200];
  static int k = 0;
  char *b = buf[k++ % 8];
  if ((size_t)snprintf(b, sizeof buf[0], "%s/%s", test_tmpdir(), name) >= sizeof buf[0]) {
    fprintf(stderr, "path too long\n");
    exit(1);
  }
  return b;
}

/* Entries of a folder other than . and ..; counts those with ".tmp." in *ntmp. */
static int count_entries(const char *dir, int *ntmp, char *names, size_t len)
{
  DIR *d = opendir(dir);
  int n = 0;
  *ntmp = 0;
  if (names && len) names[0] = '\0';
  if (!d) return -1;
  struct dirent *e;
  while ((e = readdir(d))) {
    if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
    n++;
    if (strstr(e->d_name, ".tmp.")) (*ntmp)++;
    if (names && strlen(names) + strlen(e->d_name) + 2 < len) {
      strcat(names, " ");
      strcat(names, e->d_name);
    }
  }
  closedir(d);
  return n;
}

/* A fresh output folder holding only a summary.csv from "an earlier run". */
static const char *prepare_outdir(const char *name)
{
  const char *dir = path_of(name);
  char cmd[4400];
  snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", dir, dir);
  if (test_run(cmd, NULL, 0) != 0) {
    fprintf(stderr, "cannot prepare %s\n", dir);
    exit(1);
  }
  char sp[4400];
  snprintf(sp, sizeof sp, "%s/summary.csv", dir);
  FILE *f = fopen(sp, "w");
  if (!f || fputs(PREVIOUS, f) < 0 || fclose(f)) exit(1);
  return dir;
}

/* Runs hvsph with stdout discarded; *err gets stderr. Returns the exit status. */
static int hvsph(const char *args, char *err, size_t len)
{
  char cmd[13400]; /* the binary's path (4 kB) and args (9 kB) */
  snprintf(cmd, sizeof cmd, "{ '%s' %s 2>&1 >/dev/null; }", test_bin(), args);
  return test_run(cmd, err, len);
}

/* A child process of this test that takes dir's lock (through the library, as hvsph run
 * does) and waits to be killed; its pid, once it holds the lock. */
static pid_t hold_lock(const char *dir)
{
  int fds[2];
  if (pipe(fds)) exit(1);
  const pid_t child = fork();
  if (child == 0) {
    close(fds[0]);
    struct runfolder_lock l;
    struct hv_error err;
    const char ok = runfolder_lock(&l, dir, "run", 1, &err) == 0 ? 'y' : 'n';
    if (write(fds[1], &ok, 1) != 1) _exit(1);
    for (;;) pause(); /* killed by the test, the lock file left behind */
  }
  close(fds[1]);
  char ok = 0;
  CHECK(child > 0 && read(fds[0], &ok, 1) == 1 && ok == 'y',
        "a child process (%ld) took the "
        "lock of %s",
        (long)child, dir);
  close(fds[0]);
  return child;
}

/* The one "hvsph: error:" line of the output (NULL unless there is exactly one). */
static const char *error_line(const char *out, int *count)
{
  static char line[4096];
  const char *p = out, *found = NULL;
  *count = 0;
  while ((p = strstr(p, "hvsph: error: ")) != NULL) {
    if (p == out || p[-1] == '\n') {
      (*count)++;
      found = p;
    }
    p++;
  }
  if (*count != 1) return NULL;
  size_t n = strcspn(found, "\n");
  if (n >= sizeof line) n = sizeof line - 1;
  memcpy(line, found, n);
  line[n] = '\0';
  return line;
}

/* Checks one error line against up to 4 expected pieces (NULL-terminated). */
static void check_message(const char *what, const char *out, const char *const *want)
{
  int count;
  const char *line = error_line(out, &count);
  CHECK(line != NULL, "%s: exactly one error line (found %d)%s%s", what, count,
        line ? "" : "; output:\n", line ? "" : out);
  if (!line) return;
  for (int i = 0; want[i]; i++)
    CHECK(strstr(line, want[i]) != NULL, "%s: message has \"%s\"\n          %s", what, want[i],
          line);
}

/* An input error: exit 2, the message, and the output folder untouched. */
static void bad_input(const char *name, const char *yaml, const char *extra,
                      const char *const *want)
{
  char file[64], out[16384], args[9000], names[512];
  snprintf(file, sizeof file, "%s.yaml", name);
  const char *casefile = test_write_file(file, yaml);
  const char *dir = prepare_outdir(name);
  snprintf(args, sizeof args, "run '%s' -o '%s' --quiet %s", casefile, dir, extra ? extra : "");
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2, "%s: exit status %d (want 2)", name, rc);
  check_message(name, out, want);
  int ntmp, n = count_entries(dir, &ntmp, names, sizeof names);
  char sp[4400];
  snprintf(sp, sizeof sp, "%s/summary.csv", dir);
  char *prev = test_slurp(sp, NULL);
  CHECK(n == 1 && ntmp == 0 && prev && !strcmp(prev, PREVIOUS),
        "%s: output folder untouched: only the earlier summary.csv, intact (has:%s)", name, names);
  free(prev);
}

/* summary.csv complete: comment lines, the header, then rows of SUMMARY_FIELDS
 * numbers, each ending in a newline. Returns the number of rows (-1 if malformed). */
static int summary_rows(const char *dir)
{
  char sp[4400];
  snprintf(sp, sizeof sp, "%s/summary.csv", dir);
  size_t len;
  char *s = test_slurp(sp, &len);
  if (!s || !len || s[len - 1] != '\n') {
    free(s);
    return -1;
  }
  int rows = 0, header = 0, ok = 1;
  for (char *line = strtok(s, "\n"); line && ok; line = strtok(NULL, "\n")) {
    if (line[0] == '#') continue;
    int fields = 1;
    for (char *c = line; *c; c++) fields += *c == ',';
    if (!header) {
      static const char cols[] = "step,time,dt,n,mass,px,py,pz,e_kin,e_int,e_total";
      ok = !strncmp(line, cols, sizeof cols - 1) && fields == SUMMARY_FIELDS;
      header = 1;
      continue;
    }
    char *end = line;
    for (int f = 0; f < fields && ok; f++) {
      strtod(end, &end);
      ok = *end == (f + 1 < fields ? ',' : '\0');
      end++;
    }
    ok = ok && fields == SUMMARY_FIELDS;
    rows++;
  }
  free(s);
  return ok && header ? rows : -1;
}

/* A run that fails: exit 3, the message, no temporary files, a complete summary.csv
 * (the folder's earlier summary.csv replaced: --overwrite). */
static void failed_run(const char *name, const char *extra, const char *const *want)
{
  char out[16384], args[9000], names[512];
  const char *casefile = test_write_file("base.yaml", variant(0, ""));
  const char *dir = prepare_outdir(name);
  snprintf(args, sizeof args, "run '%s' -o '%s' --quiet --overwrite %s", casefile, dir, extra);
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 3, "%s: exit status %d (want 3)", name, rc);
  check_message(name, out, want);
  int ntmp;
  count_entries(dir, &ntmp, names, sizeof names);
  CHECK(ntmp == 0, "%s: no temporary files left (folder has:%s)", name, names);
  int rows = summary_rows(dir);
  CHECK(rows == 1,
        "%s: summary.csv is the new run's, complete, with its %d row(s) (want 1: "
        "the initial state)",
        name, rows);
}

static void test_commands(void)
{
  char out[16384], args0[9000];
  int rc = hvsph("--help", out, sizeof out); /* stderr only: must be empty */
  CHECK(rc == 0 && out[0] == '\0', "--help exits 0 (%d) and writes nothing to stderr", rc);
  char cmd[4400];
  snprintf(cmd, sizeof cmd, "'%s' --help 2>/dev/null", test_bin());
  rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0 && strstr(out, "hvsph run CASE.yaml") && strstr(out, "hvsph bench") &&
            strstr(out, "--set") && strstr(out, "--threads") && strstr(out, "exit status"),
        "--help on stdout mentions run, bench, --set, --threads and the exit statuses");
  /* each command's --help: exit 0, its own synopsis on stdout, not the others' */
  static const char *const cmds[] = {"run", "restart", "bench", "validate", "render", "measure"};
  for (int k = 0; k < 6; k++) {
    snprintf(cmd, sizeof cmd, "'%s' %s --help 2>&1", test_bin(), cmds[k]);
    rc = test_run(cmd, out, sizeof out);
    char own[64];
    snprintf(own, sizeof own, "hvsph %s ", cmds[k]);
    int others = 0;
    for (int j = 0; j < 6; j++) {
      char other[64];
      snprintf(other, sizeof other, "hvsph %s ", cmds[j]);
      others += j != k && strstr(out, other) != NULL;
    }
    CHECK(rc == 0 && strstr(out, own) && !others && !strstr(out, "hvsph: "),
          "hvsph %s --help: exit %d (want 0), its synopsis and no other's, no message: %.200s",
          cmds[k], rc, out);
  }
  snprintf(cmd, sizeof cmd, "'%s' --version 2>/dev/null", test_bin());
  rc = test_run(cmd, out, sizeof out);
  /* "hvsph <release> (commit <hash>[-dirty])": the release of project() in
   * CMakeLists.txt, MAJOR.MINOR.PATCH, and the commit from git */
  char version[256] = "";
  snprintf(version, sizeof version, "%s", HVSPH_VERSION);
  char want_line[300];
  snprintf(want_line, sizeof want_line, "hvsph %s\n", HVSPH_VERSION);
  CHECK(rc == 0 && !strcmp(out, want_line),
        "--version exits 0 (%d) and prints one line '%.*s': "
        "'%s'",
        rc, (int)strlen(want_line) - 1, want_line, out);
  unsigned major, minor, patch;
  char after[8] = "";
  CHECK(sscanf(HVSPH_RELEASE, "%u.%u.%u%1s", &major, &minor, &patch, after) == 3 &&
            !strcmp(HVSPH_VERSION, HVSPH_RELEASE " (commit " HVSPH_COMMIT ")"),
        "the version is MAJOR.MINOR.PATCH (commit ...): '%s'", HVSPH_VERSION);
  /* "unknown" only where the build had nothing to take the commit from: a copy of the
   * tree without its history, not a `git archive` tarball, no -DHVSPH_COMMIT; from git
   * it is an abbreviated hash (7 or more hex digits), "-dirty" when the tree was edited */
  size_t hexlen = strspn(HVSPH_COMMIT, "0123456789abcdef");
  CHECK(strcmp(HVSPH_VERSION_SOURCE, "git") ||
            (hexlen >= 7 && (!HVSPH_COMMIT[hexlen] || !strcmp(HVSPH_COMMIT + hexlen, "-dirty"))),
        "from git the commit is a hash: '%s'", HVSPH_COMMIT);
  CHECK(strcmp(HVSPH_COMMIT, "unknown") || !strcmp(HVSPH_VERSION_SOURCE, "none"),
        "the commit is known (from %s): '%s'", HVSPH_VERSION_SOURCE, HVSPH_COMMIT);

  /* render's errors read as every command's: one "hvsph: error: " line (they read
   * "hvsph render: " before 48553fe, 2026-12-07) */
  snprintf(args0, sizeof args0, "render '%s' -o '%s'", path_of("missing.vtu"),
           path_of("missing.png"));
  rc = hvsph(args0, out, sizeof out);
  CHECK(rc == 2 && !strncmp(out, "hvsph: error: cannot open '", 27) &&
            strchr(out, '\n') == out + strlen(out) - 1,
        "render of a missing snapshot: exit %d (want 2), one line 'hvsph: error: cannot open "
        "...': %.200s",
        rc, out);

  /* the version is the one written into the outputs */
  const char *casefile = test_write_file("base.yaml", variant(0, ""));
  const char *dir = path_of("ok");
  char args[9000];
  snprintf(args, sizeof args, "run '%s' -o '%s' --overwrite", casefile, dir);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "the base case runs (exit %d)", rc);
  CHECK(strstr(out, "hvsph: step ") && !strchr(out, '\r') && strstr(out, "hvsph: done:"),
        "not on a terminal: plain log lines 'hvsph: step ...' (no carriage returns) and 'done'");
  char up[4400];
  snprintf(up, sizeof up, "%s/used_parameters.yaml", dir);
  char *u = test_slurp(up, NULL), want[300];
  snprintf(want, sizeof want, "# Parameters used by hvsph %s\n", version);
  CHECK(u && !strncmp(u, want, strlen(want)), "used_parameters.yaml starts with '%.*s'",
        (int)strlen(want) - 1, want);
  free(u);
  /* every file of the run carries the version near its start: a "#" comment of the CSV
   * tables, the XML comment of the VTU and PVD, the checkpoint's version record */
  {
    static const char *const with_version[] = {
        "summary.csv",          "particles_00000.vtu", "run.pvd",       "particles_00000.csv",
        "used_parameters.yaml", "run_segments.csv",    "checkpoint.hvc"};
    for (size_t k = 0; k < sizeof with_version / sizeof *with_version; k++) {
      char fp[4400];
      snprintf(fp, sizeof fp, "%s/%s", dir, with_version[k]);
      size_t flen = 0;
      char *ftext = test_slurp(fp, &flen);
      size_t head = flen < 4096 ? flen : 4096, vl = strlen(HVSPH_VERSION);
      int found = 0;
      for (size_t i = 0; ftext && i + vl <= head && !found; i++)
        found = !memcmp(ftext + i, HVSPH_VERSION, vl);
      CHECK(found, "%s carries the version '%s' in its first 4 kB", with_version[k], HVSPH_VERSION);
      free(ftext);
    }
  }
  CHECK(summary_rows(dir) == 3, "summary.csv has 3 rows (t = 0, 0.005, 0.01)");
  /* each log line says what set the step: a stability limit at a particle of 'slab' */
  const char *lim = strstr(out, "[dt: CFL h/v_sig, particle ");
  if (!lim) lim = strstr(out, "[dt: acceleration sqrt(h/|a|), particle ");
  CHECK(lim && strstr(lim, " in 'slab']"), "log lines name the step's limit and particle: %.*s",
        lim ? (int)strcspn(lim, "\n") : 4, lim ? lim : "none");
  snprintf(args, sizeof args,
           "run '%s' -o '%s' --overwrite "
           "--set time.dt_max=1e-5 --set output.log_every=1",
           casefile, path_of("dtmax"));
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0 && strstr(out, "[dt: time.dt_max]"),
        "with a small time.dt_max the lines say "
        "'[dt: time.dt_max]' (exit %d)",
        rc);

  /* bodies of very different particle masses are warned about, once per heavy body, with
     the remedy; the threshold is 30 (docs/case-files.md): 64- and 34-fold warn, 16-fold
     does not */
  {
    char two[16384];
    snprintf(two, sizeof two, "%s",
             variant(11, "    shape: {type: box, min: [0, 0, 0], "
                         "max: [0.05, 0.05, 0.05]}"));
    char *t = strstr(two, "time:\n");
    static const char *const spacing[] = {"1.5625 mm", "1.9 mm", "2.5 mm"};
    static const char *const fold[] = {"'fine' (64.0-fold", "'fine' (34.3-fold", NULL};
    for (int k = 0; k < 3 && t; k++) {
      char body[512], whole[16384], name[32];
      snprintf(body, sizeof body,
               "  - name: fine\n    material: gas\n    shape: {type: box, "
               "min: [0.05, 0, 0], max: [0.1, 0.05, 0.05]}\n    spacing: %s\n    density: "
               "1.0\n    pressure: 1.0\n",
               spacing[k]);
      snprintf(whole, sizeof whole, "%.*s%s%s", (int)(t - two), two, body, t);
      snprintf(name, sizeof name, "two_%d", k);
      char file[40];
      snprintf(file, sizeof file, "%s.yaml", name);
      const char *f = test_write_file(file, whole);
      snprintf(args, sizeof args,
               "run '%s' -o '%s' --overwrite "
               "--set time.end=0",
               f, path_of(name));
      rc = hvsph(args, out, sizeof out);
      const char *w = strstr(out, "warning: body 'slab' (particles of ");
      /* the remedy: (30/64)^(1/3) = 0.7768, (30/34.3)^(1/3) = 0.9563 of the slab's
         spacing, rounded down so that it does bring the ratio below 30 */
      static const char *const remedy[] = {"A spacing for 'slab' at most 0.77 times",
                                           "A spacing for 'slab' at most 0.95 times", NULL};
      if (fold[k])
        CHECK(rc == 0 && w && strstr(w, fold[k]) && strstr(w, remedy[k]) &&
                  !strstr(w + 1, "warning: body"),
              "spacing 6.25 against %s: one warning naming "
              "both bodies, %s) (exit %d): %.*s",
              spacing[k], fold[k], rc, w ? (int)strcspn(w, "\n") : 4, w ? w : "none");
      else
        CHECK(rc == 0 && !strstr(out, "warning: body"),
              "spacing 6.25 against %s (16-fold): no "
              "warning (exit %d)",
              spacing[k], rc);
    }
  }

  /* the viscosity switch's own keys without the switch: one warning naming the key and
     where it was given; their defaults (as used_parameters.yaml lists them) say nothing */
  {
    const char *f = test_write_file("base.yaml", variant(0, ""));
    static const char *const sets[] = {"sph.viscosity.alpha_min=0.1", "sph.viscosity.decay=0.2",
                                       "sph.viscosity.alpha_min=0", "sph.viscosity.decay=0.05"};
    for (int k = 0; k < 4; k++) {
      char name[16];
      snprintf(name, sizeof name, "inert_%d", k);
      char rm[4200]; /* a fresh folder: an earlier test run's snapshots warn too */
      snprintf(rm, sizeof rm, "rm -rf '%s'", path_of(name));
      test_run(rm, NULL, 0);
      snprintf(args, sizeof args, "run '%s' -o '%s' --set time.end=0 --set %s", f, path_of(name),
               sets[k]);
      rc = hvsph(args, out, sizeof out);
      char msg[160];
      snprintf(msg, sizeof msg,
               "warning: --set: %.*s has no effect without "
               "sph.viscosity.switch: cullen-dehnen",
               (int)strcspn(sets[k], "="), sets[k]);
      const char *w = strstr(out, "warning: ");
      CHECK(rc == 0 && (k < 2 ? w && strstr(out, msg) && !strstr(w + 1, "warning: ") : !w),
            "--set %s without the switch: %s (exit %d): %.*s", sets[k],
            k < 2 ? "one warning" : "no warning", rc, w ? (int)strcspn(w, "\n") : 4,
            w ? w : "none");
    }
  }

  /* bench --set: its case changed like a run's, a bad key is bad input (exit 2) */
  rc = hvsph("bench --particles 512 --steps 1 --threads 1 --solid --set "
             "sph.viscosity.reconstruct=true",
             out, sizeof out);
  CHECK(rc == 0 && strstr(out, "override: sph.viscosity.reconstruct = true"),
        "bench --solid --set sph.viscosity.reconstruct=true runs (exit %d)", rc);
  rc = hvsph("bench --particles 512 --steps 1 --set sph.viscosity.alpa=1", out, sizeof out);
  CHECK(rc == 2 && strstr(out, "unknown key 'sph.viscosity.alpa' (did you mean 'alpha'?)"),
        "bench --set with an unknown key: exit %d (want 2), %.*s", rc, (int)strcspn(out, "\n"),
        out);

  /* --material OLD=NEW: the bodies of material OLD run with NEW (here the library's
     nitrogen for the case's own gas), as used_parameters.yaml records; a name no body has
     is bad input naming the case file and the bodies' materials (a typo would otherwise
     run the case unchanged); so is a NEW that neither the case nor the library has; no '='
     is a usage error */
  snprintf(args, sizeof args,
           "run '%s' -o '%s' --overwrite "
           "--set time.end=0 --material gas=nitrogen",
           casefile, path_of("swap"));
  rc = hvsph(args, out, sizeof out);
  snprintf(up, sizeof up, "%s/used_parameters.yaml", path_of("swap"));
  u = test_slurp(up, NULL);
  CHECK(rc == 0 && u && strstr(u, "material: \"nitrogen\"") && !strstr(u, "material: \"gas\""),
        "run --material gas=nitrogen runs the slab as nitrogen (exit %d)", rc);
  free(u);
  snprintf(args, sizeof args, "run '%s' -o '%s' --set time.end=0 --material gsa=nitrogen", casefile,
           path_of("swap2"));
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2 && strstr(out, "base.yaml: --material gsa=nitrogen: no body of the case has "
                               "the material 'gsa' (its bodies have: gas)"),
        "--material with a name no body has: "
        "exit %d (want 2): %.*s",
        rc, (int)strcspn(out, "\n"), out);
  snprintf(args, sizeof args, "run '%s' -o '%s' --set time.end=0 --material gas=nitrogne", casefile,
           path_of("swap3"));
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2 && strstr(out, "error: --material gas=nitrogne: ") &&
            strstr(out, "base.yaml:10: bodies[0].material: unknown material 'nitrogne' (the "
                        "case defines: gas; the library ") &&
            !strstr(out, "override: bodies[0]"),
        "--material to an unknown material: exit %d (want 2), named as the swap and the "
        "body's key, nothing applied: %s",
        rc, out);
  { /* the swaps act at once: a=b and b=a exchange the two bodies' materials */
    char two[16384];
    snprintf(two, sizeof two, "%s",
             variant(11, "    shape: {type: box, min: [0, 0, 0], "
                         "max: [0.05, 0.05, 0.05]}"));
    char *t = strstr(two, "time:\n"), *g = strstr(two, "  gas: {");
    char whole[16400];
    snprintf(whole, sizeof whole,
             "%.*s  gas2: {eos: ideal-gas, gamma: 1.6667}\n%.*s  - name: "
             "right\n    material: gas2\n    shape: {type: box, min: [0.05, 0, 0], max: [0.1, "
             "0.05, 0.05]}\n    spacing: 6.25 mm\n    density: 1.0\n    pressure: 1.0\n%s",
             g ? (int)(g - two) : 0, two, g && t ? (int)(t - g) : 0, g ? g : "", t ? t : "");
    const char *f = test_write_file("swap2.yaml", whole);
    snprintf(args, sizeof args,
             "run '%s' -o '%s' --overwrite --set time.end=0 --material gas=gas2 "
             "--material gas2=gas",
             f, path_of("swapx"));
    rc = hvsph(args, out, sizeof out);
    CHECK(rc == 0 && strstr(out, "override: bodies[0].material = gas2") &&
              strstr(out, "override: bodies[1].material = gas") &&
              !strstr(out, "bodies[0].material = gas\n"),
          "--material gas=gas2 --material gas2=gas "
          "exchanges the two bodies' materials (exit %d): %s",
          rc, out);
  }
  snprintf(args, sizeof args, "run '%s' -o '%s' --material gas", casefile, path_of("swap4"));
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 1 && strstr(out, "--material 'gas': write OLD=NEW"),
        "--material without '=': "
        "exit %d (want 1): %s",
        rc, out);

  static const struct {
    const char *args, *what;
  } usage[] = {
      {"", "no command"},
      {"run", "run without a case file"},
      {"frobnicate", "an unknown command"},
      {"run a.yaml --threads 0", "--threads 0"},
      {"run a.yaml --threads two", "--threads two"},
      {"run a.yaml b.yaml", "two case files"},
      {"run a.yaml --bogus", "an unknown option"},
      {"bench --particles", "bench --particles without a value"},
      {"restart somewhere --material a=b", "restart with --material"},
  };
  for (size_t k = 0; k < sizeof usage / sizeof usage[0]; k++) {
    rc = hvsph(usage[k].args, out, sizeof out);
    CHECK(rc == 1 && out[0], "%s ('hvsph %s'): exit status %d (want 1) with a message: %.*s",
          usage[k].what, usage[k].args, rc, (int)strcspn(out, "\n"), out);
  }
}

static void test_bad_input(void)
{
  /* the case's name is the output folder's: a plain file name only */
  bad_input("name_path", variant(1, "name: ../../x"), NULL,
            (const char *const[]){"name_path.yaml:1: name: '../../x' is not a plain file name",
                                  "letters, digits and . _ - +", NULL});
  bad_input("name_dash", variant(1, "name: -rf"), NULL,
            (const char *const[]){"name_dash.yaml:1: name: '-rf'", "'-' at character 1", NULL});
  bad_input(
      "name_blank", variant(1, "name: \"my case\""), NULL,
      (const char *const[]){"name_blank.yaml:1: name: 'my case'", "' ' at character 3", NULL});
  bad_input("name_dot", variant(1, "name: \"..\""), NULL,
            (const char *const[]){"name_dot.yaml:1: name: '..'", NULL});
  bad_input(
      "name_control", variant(1, "name: \"a\\tb\""), NULL,
      (const char *const[]){"name_control.yaml:1: name: 'a?b'", "byte 0x09 at character 2", NULL});
  bad_input("name_set", variant(0, ""), "--set name=a/b",
            (const char *const[]){"--set: name: 'a/b'", "'/' at character 2", NULL});
  /* no bound on the outputs: 0.01 s every 1 ns is 10^7 snapshots (without --force) */
  bad_input("many_outputs", variant(20, "  every: 1e-9"), NULL,
            (const char *const[]){"many_outputs.yaml:20: output.every = 1e-09 s",
                                  "outputs (snapshots, summary rows, checkpoints), more than "
                                  "10000",
                                  "--force", NULL});

  /* a quarter model of a body that is not symmetric about its planes y = 0 and z = 0 */
  bad_input("quarter_body", variant(7, "  boundary: {x: wall}\n  symmetry: quarter"), NULL,
            (const char *const[]){"quarter_body.yaml:12: bodies[0].shape: body 'slab' is not "
                                  "mirror-symmetric about the plane y = 0",
                                  "use symmetry: half or none", NULL});
  bad_input("quarter_axis",
            "name: qa\n"
            "materials: {gas: {eos: ideal-gas, gamma: 1.4}}\n"
            "domain: {min: [0, 0, 0], max: [0.1, 0.05, 0.05], symmetry: quarter}\n"
            "bodies:\n"
            "  - {name: slab, material: gas, density: 1.0, pressure: 1.0, spacing: 12.5 mm,\n"
            "     shape: {type: box, min: [0, -0.05, -0.05], max: [0.1, 0.05, 0.05]}}\n"
            "time: {end: 0.01}\n"
            "measure: {axis_y: 1 mm}\n",
            NULL,
            (const char *const[]){"quarter_axis.yaml:8: measure.axis_y: a quarter model's impact "
                                  "axis is its planes' line y = 0, z = 0",
                                  NULL});

  /* malformed YAML: line and column of the fault */
  bad_input("malformed", variant(7, "  boundary: {x: wall, y: periodic, z: periodic}}"), NULL,
            (const char *const[]){"malformed.yaml:7:", "YAML syntax error", NULL});
  bad_input("indent", variant(18, "  end: 0.01\n cfl: 0.3"), NULL,
            (const char *const[]){"indent.yaml:19:", "YAML syntax error", "indentation", NULL});
  /* values */
  bad_input("neg_density", variant(13, "    density: -5"), NULL,
            (const char *const[]){"neg_density.yaml:13: bodies[0].density: ", "-5", "out of range",
                                  NULL});
  /* wrong units: a condensed body's density in g/cm3 written bare (SI, so 2.7 kg/m3) */
  bad_input("bare_density", variant(13, "    density: 2.7"), "--set bodies[0].material=al-alloy",
            (const char *const[]){"bare_density.yaml:13: bodies[0].density: ",
                                  "the bare number 2.7 is read as 2.7 kg/m3", "was it 2.7 g/cm3?",
                                  NULL});
  bad_input("kg_velocity", variant(15, "    velocity: [5 kg, 0, 0]"), NULL,
            (const char *const[]){"kg_velocity.yaml:15: bodies[0].velocity[0]: ",
                                  "unit 'kg' is a mass, expected a velocity", NULL});
  bad_input("kg_radial", variant(16, "    radial_velocity: 5 kg"), NULL,
            (const char *const[]){"kg_radial.yaml:16: bodies[0].radial_velocity: ",
                                  "unit 'kg' is a mass, expected a velocity", NULL});
  bad_input("bad_number", variant(18, "  end: fast"), NULL,
            (const char *const[]){"bad_number.yaml:18: time.end: ", NULL});
  /* keys */
  bad_input("unknown_key", variant(18, "  end: 0.01\n  clf: 0.3"), NULL,
            (const char *const[]){"unknown_key.yaml:19: ", "unknown key 'time.clf'",
                                  "did you mean 'cfl'?", NULL});
  bad_input(
      "unknown_body_key", variant(16, "    radial_velocty: 0.2"), NULL,
      (const char *const[]){"unknown_body_key.yaml:16: ", "unknown key 'bodies[0].radial_velocty'",
                            "did you mean 'radial_velocity'?", NULL});
  bad_input(
      "missing_key", variant(18, ""), NULL,
      (const char *const[]){"missing_key.yaml:17: ", "missing required key 'time.end'", NULL});
  /* materials */
  bad_input("unknown_material", variant(10, "    material: air"), NULL,
            (const char *const[]){"unknown_material.yaml:10: bodies[0].material: ",
                                  "unknown material 'air'", "the case defines: gas", NULL});
  bad_input("unknown_eos", variant(3, "  gas: {eos: ideal-gass, gamma: 1.4}"), NULL,
            (const char *const[]){
                "unknown_eos.yaml:3: materials.gas.eos: ", "'ideal-gass' is not one of", NULL});
  bad_input("unknown_library", variant(3, "  gas: {library: unobtainium}"), NULL,
            (const char *const[]){"unknown_library.yaml:3: ", "materials.gas.library",
                                  "unobtainium", NULL});
  /* summation density with strength: refused, naming the key */
  bad_input("summation_solid", variant(3, "  gas: {library: al-alloy}\nsph: {density: summation}"),
            "--set bodies[0].density=2780",
            (const char *const[]){"summation_solid.yaml:4: sph.density: ",
                                  "summation is for cases without strength", NULL});
  bad_input("reconstruct_gas",
            variant(3, "  gas: {eos: ideal-gas, gamma: 1.4}\nsph: {viscosity: "
                       "{reconstruct: true}}"),
            NULL,
            (const char *const[]){"reconstruct_gas.yaml:4: sph.viscosity.reconstruct: ",
                                  "acts on pairs of particles with strength", NULL});
  /* the viscosity switch: a maximum alpha of 0, a floor above it, an unknown switch */
  bad_input("switch_alpha0",
            variant(3, "  gas: {eos: ideal-gas, gamma: 1.4}\nsph: {viscosity: "
                       "{switch: cullen-dehnen, alpha: 0}}"),
            NULL,
            (const char *const[]){"switch_alpha0.yaml:4: sph.viscosity.switch: ", "which is 0 here",
                                  NULL});
  bad_input("switch_floor",
            variant(3, "  gas: {eos: ideal-gas, gamma: 1.4}\nsph: {viscosity: "
                       "{switch: cullen-dehnen, alpha_min: 1.5}}"),
            NULL,
            (const char *const[]){"switch_floor.yaml:4: sph.viscosity.alpha_min (1.5) ",
                                  "exceeds sph.viscosity.alpha (1)", NULL});
  bad_input("switch_name",
            variant(3, "  gas: {eos: ideal-gas, gamma: 1.4}\nsph: {viscosity: "
                       "{switch: balsara}}"),
            NULL,
            (const char *const[]){
                "switch_name.yaml:4: sph.viscosity.switch: ", "'balsara' is not one of", NULL});
  bad_input("mass_form_solid", variant(3, "  gas: {library: al-alloy}\nsph: {continuity: mass}"),
            "--set bodies[0].density=2780",
            (const char *const[]){"mass_form_solid.yaml:4: sph.continuity: ",
                                  "mass is for cases without strength", NULL});
  bad_input("recon_contact_alone",
            variant(3, "  gas: {library: al-alloy}\nsph: {viscosity: {reconstruct_contact: true}}"),
            NULL,
            (const char *const[]){"recon_contact_alone.yaml:4: "
                                  "sph.viscosity.reconstruct_contact: ",
                                  "needs sph.viscosity.reconstruct: true", NULL});
  /* a periodic domain far longer than the neighbour grid can hold (1e308 m: its ghosts
     span it), found when the first grid is built: bad input naming the domain */
  bad_input("periodic_huge", variant(5, "  min: [0, 0, -1e308]"), NULL,
            (const char *const[]){"periodic_huge.yaml:4: domain: ",
                                  "do not fit the neighbour "
                                  "grid",
                                  "span 1e+308 m in direction z", NULL});
  /* --set */
  const char *base = variant(0, "");
  bad_input("set_syntax", base, "--set 'time..end=1'",
            (const char *const[]){"--set", "time..end", "bad key path", NULL});
  bad_input("set_no_value", base, "--set time.end",
            (const char *const[]){"--set 'time.end': expected key=value", NULL});
  bad_input("set_index", base, "--set 'bodies[3].spacing=1 mm'",
            (const char *const[]){"--set bodies[3].spacing: ", "fewer entries", NULL});
  bad_input("set_not_map", base, "--set time.end.x=1",
            (const char *const[]){"--set time.end.x: 'time.end' is not a mapping", NULL});
  bad_input("set_unit", base, "--set 'time.end=5 kg'",
            (const char *const[]){"--set: time.end: ", "unit 'kg' is a mass", NULL});
  bad_input("set_unknown", base, "--set time.ennd=1",
            (const char *const[]){"--set: unknown key 'time.ennd'", "did you mean 'end'?", NULL});
}

static void test_outdir(void)
{
  char out[16384], args[9000], want[4400];
  const char *casefile = test_write_file("base.yaml", variant(0, ""));
  const char *missing = path_of("no_such_case.yaml");
  snprintf(args, sizeof args, "run '%s' -o '%s' --quiet", missing, path_of("nocase"));
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2, "a case file that does not exist: exit status %d (want 2)", rc);
  snprintf(want, sizeof want, "cannot open case file '%s': No such file or directory", missing);
  check_message("no case file", out, (const char *const[]){want, NULL});
  struct stat st;
  CHECK(stat(path_of("nocase"), &st) != 0, "... and no output folder is created");
  const char *file = test_write_file("regular_file", "not a folder\n");
  snprintf(args, sizeof args, "run '%s' -o '%s/sub' --quiet", casefile, file);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2, "output folder below a regular file: exit status %d (want 2)", rc);
  snprintf(want, sizeof want,
           "cannot create folder '%s/sub' (at '%s'): exists and is not a "
           "folder",
           file, file);
  check_message("outdir below a file", out, (const char *const[]){want, NULL});
  char *f = test_slurp(file, NULL);
  CHECK(f && !strcmp(f, "not a folder\n"), "the regular file is untouched");
  free(f);
  snprintf(args, sizeof args, "run '%s' -o '%s' --quiet", casefile, file);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2, "output folder that is a regular file: exit status %d (want 2)", rc);
  snprintf(want, sizeof want, "cannot create folder '%s': exists and is not a folder", file);
  check_message("outdir is a file", out, (const char *const[]){want, NULL});
}

/* An input error found only when the first step is prepared (the periodic box is
 * too short for the smoothing length): exit 2, no temporary file, the earlier
 * summary.csv intact. (used_parameters.yaml has already been written by then.) */
static void test_late_input_error(void)
{
  char out[16384], args[9000], names[512];
  const char *casefile = test_write_file("base.yaml", variant(0, ""));
  const char *dir = prepare_outdir("periodic_short");
  snprintf(args, sizeof args, "run '%s' -o '%s' --quiet --set sph.eta=3", casefile, dir);
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2, "periodic box shorter than two interaction radii: exit status %d (want 2)", rc);
  check_message(
      "periodic_short", out,
      (const char *const[]){"base.yaml:7: domain: the periodic length in y (0.05 m)", NULL});
  int ntmp;
  count_entries(dir, &ntmp, names, sizeof names);
  char sp[4400];
  snprintf(sp, sizeof sp, "%s/summary.csv", dir);
  char *prev = test_slurp(sp, NULL);
  CHECK(ntmp == 0 && prev && !strcmp(prev, PREVIOUS),
        "periodic_short: no temporary file, the earlier summary.csv intact (folder has:%s)", names);
  free(prev);
}

/* The mass-ratio warning names only bodies that can meet (bodies_can_meet, src/setup):
 * a light tungsten rod (0.2 mm lattice, 1/55 of the steel block's particle mass) aimed
 * at a block of 1 mm is named; aimed at a 0.5 mm core joined to that block through its
 * whole depth, the block 5 mm from the axis, it is not (the core is 7 times heavier than
 * the rod, the block 55 times but out of the rod's path); nor when it flies past the
 * block's face (along y, 4 mm in front of it: more than 1.5 times the 2 mm reach), nor
 * aimed 5 mm beside it; a light disc (0.25 mm) set in a heavy
 * ring (1 mm) at rest, a seam, is named. */
static void test_mass_ratio_warning(void)
{
  static const char *const fmt =
      "name: meet\n"
      "domain: {min: [-8 mm, -18 mm, 0], max: [11 mm, 18 mm, 12 mm], half_model: true}\n"
      "bodies:\n"
      "  - name: rod\n"
      "    material: tungsten-alloy\n"
      "    shape: {type: cylinder, center: [-5 mm, %s, 0], axis: [1, 0, 0], radius: 0.5 mm, length: 3 mm}\n"
      "    spacing: 0.2 mm\n"
      "    velocity: [%s]\n"
      "  - name: block\n"
      "    material: steel-target\n"
      "    shape: {type: box, min: [0, -10 mm, -10 mm], max: [10 mm, 10 mm, 10 mm]%s}\n"
      "    spacing: 1 mm\n"
      "%s"
      "time: {end: 0}\n";
  static const char *const core =
      "  - name: core\n"
      "    material: steel-target\n"
      "    part_of: block\n"
      "    shape: {type: box, min: [0, -5 mm, -5 mm], max: [10 mm, 5 mm, 5 mm]}\n"
      "    spacing: 0.5 mm\n";
  static const char *const hole =
      ",\n            minus: [{type: box, min: [0, -5 mm, -5 mm], max: [10 mm, 5 mm, 5 mm]}]";
  struct {
    const char *what, *y, *v, *minus, *extra;
    int warn;
  } v[] = {
      {"a rod aimed at the coarse block", "0", "2 km/s, 0, 0", "", "", 1},
      {"a rod aimed at a fine core through the coarse block", "0", "2 km/s, 0, 0", hole, core, 0},
      {"a rod flying past the block's face", "0", "0, 2 km/s, 0", "", "", 0},
      {"a rod aimed beside the block (at y = 15 mm, 5 mm outside it)", "15 mm", "2 km/s, 0, 0", "",
       "", 0},
  };
  char yaml[4096], name[64], args[4400], out[16384];
  for (size_t k = 0; k < sizeof v / sizeof v[0]; k++) {
    snprintf(yaml, sizeof yaml, fmt, v[k].y, v[k].v, v[k].minus, v[k].extra);
    snprintf(name, sizeof name, "meet_%zu.yaml", k);
    const char *file = test_write_file(name, yaml);
    snprintf(args, sizeof args, "run '%s' -o '%s/meet_%zu' --overwrite", file, test_tmpdir(), k);
    const int st = hvsph(args, out, sizeof out);
    const int warned = strstr(out, "much heavier than 'rod'") != NULL;
    CHECK(st == 0 && warned == v[k].warn,
          "%s: exit %d, the rod %s named in a mass-ratio warning "
          "(expected %s): %s",
          v[k].what, st, warned ? "is" : "is not", v[k].warn ? "named" : "not", out);
  }
  /* a 0.25 mm disc set in a 1 mm ring at rest: they touch at the seam */
  static const char *const seam =
      "name: seam\n"
      "domain: {min: [-2 mm, -12 mm, 0], max: [4 mm, 12 mm, 12 mm], half_model: true}\n"
      "bodies:\n"
      "  - name: ring\n"
      "    material: steel-target\n"
      "    shape: {type: box, min: [0, -10 mm, -10 mm], max: [2 mm, 10 mm, 10 mm],\n"
      "            minus: [{type: cylinder, center: [1 mm, 0, 0], axis: [1, 0, 0], radius: 4 mm, length: 2 mm}]}\n"
      "    spacing: 1 mm\n"
      "  - name: disc\n"
      "    material: steel-target\n"
      "    part_of: ring\n"
      "    shape: {type: cylinder, center: [1 mm, 0, 0], axis: [1, 0, 0], radius: 4 mm, length: 2 mm}\n"
      "    spacing: 0.25 mm\n"
      "time: {end: 0}\n";
  const char *file = test_write_file("meet_seam.yaml", seam);
  snprintf(args, sizeof args, "run '%s' -o '%s/meet_seam' --overwrite", file, test_tmpdir());
  const int st = hvsph(args, out, sizeof out);
  CHECK(st == 0 && strstr(out, "'ring'") && strstr(out, "much heavier than 'disc'"),
        "a light disc in a heavy ring at rest (a seam): the ring's warning names the disc "
        "(exit %d): %s",
        st, out);

  /* just above the threshold (a rod of 18.25 g/cm3 on a 0.242 mm lattice, 30.1 times
     lighter than the block's particles) the offered spacing factor, cbrt(30/30.1) =
     0.9989, is printed rounded down (0.99), so that it does bring the ratio below 30; it
     was printed as "1" */
  static const char *const near =
      "name: near\n"
      "domain: {min: [-8 mm, -18 mm, 0], max: [11 mm, 18 mm, 12 mm], half_model: true}\n"
      "materials:\n"
      "  heavy-w: {library: tungsten-alloy, rho0: 18.25 g/cm3}\n"
      "bodies:\n"
      "  - name: rod\n"
      "    material: heavy-w\n"
      "    shape: {type: cylinder, center: [-5 mm, 0, 0], axis: [1, 0, 0], radius: 2 mm, length: 4 mm}\n"
      "    spacing: 0.242 mm\n"
      "    velocity: [2 km/s, 0, 0]\n"
      "  - name: block\n"
      "    material: steel-target\n"
      "    shape: {type: box, min: [0, -10 mm, -10 mm], max: [10 mm, 10 mm, 10 mm]}\n"
      "    spacing: 1 mm\n"
      "time: {end: 0}\n";
  file = test_write_file("meet_near.yaml", near);
  snprintf(args, sizeof args, "run '%s' -o '%s/meet_near' --overwrite", file, test_tmpdir());
  const int st2 = hvsph(args, out, sizeof out);
  const char *r = strstr(out, "much heavier than 'rod' (");
  const char *f = strstr(out, "A spacing for 'block' at most ");
  double ratio = 0.0, factor = 0.0;
  CHECK(st2 == 0 && r && f && sscanf(r, "much heavier than 'rod' (%lf-fold", &ratio) == 1 &&
            sscanf(f, "A spacing for 'block' at most %lf times", &factor) == 1 && ratio > 30.0 &&
            ratio < 30.3 && factor < 1.0 && ratio * factor * factor * factor < 30.0,
        "a mass ratio just above 30 (read %.4g): the offered spacing factor %.4g brings it "
        "below 30 (exit %d): %s",
        ratio, factor, st2, out);
}

/* A body whose lattice cells fill more than 1.02 of its exact volume is named in a
 * warning that offers a fitting spacing: a half rod of 1 mm radius, 4 mm long, on a
 * 0.45 mm cubic lattice holds 72 points, whose cells fill 72 x 0.45^3 / (pi/2 x 4) =
 * 1.044 of it; 0.3 mm (208 points: 0.8939) does not warn, nor does the spacing the
 * warning offers. */
static void test_lattice_cover_warning(void)
{
  static const char *const fmt =
      "name: cover\n"
      "domain: {min: [-8 mm, -5 mm, 0], max: [1 mm, 5 mm, 5 mm], half_model: true}\n"
      "bodies:\n"
      "  - name: rod\n"
      "    material: tungsten-alloy\n"
      "    shape: {type: cylinder, center: [-5 mm, 0, 0], axis: [1, 0, 0], radius: 1 mm, length: 4 mm}\n"
      "    spacing: %s\n"
      "    velocity: [1 km/s, 0, 0]\n"
      "time: {end: 0}\n";
  char yaml[2048], args[4400], out[16384], fit[64] = "";
  const char *const spacing[] = {"0.45 mm", "0.3 mm", fit};
  for (int k = 0; k < 3; k++) {
    snprintf(yaml, sizeof yaml, fmt, spacing[k]);
    char name[64];
    snprintf(name, sizeof name, "cover_%d.yaml", k);
    const char *file = test_write_file(name, yaml);
    snprintf(args, sizeof args, "run '%s' -o '%s/cover_%d' --overwrite", file, test_tmpdir(), k);
    const int st = hvsph(args, out, sizeof out);
    const char *w = strstr(out, "body 'rod': its ");
    if (k == 0) {
      CHECK(st == 0 && w && strstr(w, "its 72 lattice cells of 0.45 mm fill 1.044 times") &&
                strstr(w, "4.2 % lighter"),
            "a 0.45 mm lattice filling 1.044 of the rod: warned with its numbers (exit %d): %s", st,
            out);
      const char *f = w ? strstr(w, "Nearest fit: spacing ") : NULL;
      double sp = 0.0;
      CHECK(f && sscanf(f, "Nearest fit: spacing %lf mm", &sp) == 1 && sp > 0.405 && sp < 0.495,
            "the warning offers a spacing within 10 %% of 0.45 mm: %s", out);
      snprintf(fit, sizeof fit, "%.5g mm", sp);
    } else {
      CHECK(st == 0 && !w, "spacing %s: no lattice-cover warning (exit %d): %s", spacing[k], st,
            out);
    }
  }
}

/* hvsph validate over tiny stand-ins for the paper's cases (--cases: the base case under
 * two of paper_results.yaml's names), with nothing slow: no run gets past its set-up, or
 * --no-run. An earlier validation's tables in the folder must survive bad input. */
#define PREVIOUS_TABLE "previous table\n"
static const char *prepare_valdir(const char *name)
{
  const char *dir = path_of(name);
  char cmd[4400], p[4400];
  snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", dir, dir);
  if (test_run(cmd, NULL, 0) != 0) exit(1);
  static const char *const files[] = {"validation.md", "validation.csv"};
  for (int k = 0; k < 2; k++) {
    snprintf(p, sizeof p, "%s/%s", dir, files[k]);
    FILE *f = fopen(p, "w");
    if (!f || fputs(PREVIOUS_TABLE, f) < 0 || fclose(f)) exit(1);
  }
  return dir;
}

static int tables_kept(const char *dir)
{
  char p[4400];
  int ok = 1;
  static const char *const files[] = {"validation.md", "validation.csv"};
  for (int k = 0; k < 2; k++) {
    snprintf(p, sizeof p, "%s/%s", dir, files[k]);
    char *s = test_slurp(p, NULL);
    ok = ok && s && !strcmp(s, PREVIOUS_TABLE);
    free(s);
  }
  return ok;
}

static void test_validate(void)
{
  char out[16384], args[9000], cases[4400];
  snprintf(cases, sizeof cases, "%s", path_of("vcases"));
  char cmd[9000];
  snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", cases, cases);
  test_run(cmd, NULL, 0);
  static const char *const names[] = {"bumper-1", "wp1"};
  for (int k = 0; k < 2; k++) {
    char f[4500];
    snprintf(f, sizeof f, "%s/%s.yaml", cases, names[k]);
    FILE *fp = fopen(f, "w");
    if (!fp || fputs(variant(0, ""), fp) < 0 || fclose(fp)) exit(1);
  }

  /* a --set that the cases do not take: bad input (exit 2), reported once by the first
     case's run; the later case is not run, the earlier tables are kept */
  const char *dir = prepare_valdir("val_badset");
  snprintf(args, sizeof args,
           "validate --only wp1 bumper-1 --cases '%s' --threads 1 --set "
           "time.ennd=1 -o '%s'",
           cases, dir);
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2, "validate --set with an unknown key: exit status %d (want 2)", rc);
  check_message("validate --set time.ennd", out,
                (const char *const[]){"unknown key 'time.ennd'", NULL});
  CHECK(tables_kept(dir), "validate with bad input: the earlier validation.md and "
                          "validation.csv are kept");
  int ntmp, n = count_entries(dir, &ntmp, NULL, 0);
  CHECK(ntmp == 0 && n == 2,
        "validate with bad input: nothing else in the folder (%d "
        "entries, %d temporary)",
        n, ntmp);

  /* a case file missing from --cases: bad input too */
  dir = prepare_valdir("val_nocase");
  snprintf(args, sizeof args, "validate --only wp1 --cases '%s/none' --threads 1 -o '%s'", cases,
           dir);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2 && tables_kept(dir),
        "validate with a missing case file: exit status %d "
        "(want 2), the earlier tables kept",
        rc);
  check_message("validate, missing case file", out,
                (const char *const[]){"cannot open case file", "none/wp1.yaml", NULL});
  /* ... also with --material, whose swaps are checked on the case files first: the
     missing file named, not a swap that no body took */
  snprintf(args, sizeof args,
           "validate --only wp1 --cases '%s/none' --threads 1 --material "
           "gas=nitrogen -o '%s'",
           cases, dir);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2 && tables_kept(dir),
        "validate --material with a missing case file: exit "
        "status %d (want 2), the earlier tables kept",
        rc);
  check_message("validate --material, missing case file", out,
                (const char *const[]){"cannot open case file", "none/wp1.yaml", NULL});

  /* an unknown --only name: exit 2 naming it, and no output folder made */
  const char *fresh = path_of("val_fresh");
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", fresh);
  test_run(cmd, NULL, 0);
  snprintf(args, sizeof args, "validate --no-run --only wp11 -o '%s'", fresh);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2, "validate --only wp11: exit status %d (want 2)", rc);
  check_message("validate --only wp11", out, (const char *const[]){"no case 'wp11'", NULL});
  struct stat st;
  CHECK(stat(fresh, &st) != 0, "validate --only wp11 creates no output folder");

  /* a DIR in use by another process (its lock): refused, the tables kept */
  dir = prepare_valdir("val_locked");
  const pid_t holder = hold_lock(dir);
  snprintf(args, sizeof args, "validate --no-run --only wp1 -o '%s'", dir);
  rc = hvsph(args, out, sizeof out);
  kill(holder, SIGKILL);
  waitpid(holder, NULL, 0);
  CHECK(rc == 2 && tables_kept(dir),
        "validate into a DIR in use: exit %d (want 2), the tables "
        "kept",
        rc);
  check_message("validate, DIR in use", out, (const char *const[]){"is in use by another", NULL});

  /* --only without a name, --scale inf: usage errors (not every case, not a scale no run
     takes); --no-run keeps a regression from running anything */
  static const char *const usage[] = {"--only",
                                      "--only --threads 1",
                                      "--scale inf --only wp1",
                                      "--scale 0 --only wp1",
                                      "--scale -2 --only wp1",
                                      "--threads 2x --only wp1",
                                      "--threads 5000 --only wp1"};
  for (int k = 0; k < 7; k++) {
    snprintf(args, sizeof args, "validate --no-run %s -o '%s'", usage[k], path_of("val_usage"));
    rc = hvsph(args, out, sizeof out);
    CHECK(rc == 1, "validate %s: exit status %d (want 1)", usage[k], rc);
  }

  /* --no-run over a run whose last snapshot cannot be read: the radiograph is a warning,
     the tables are written (exit 0); a case without any run is "not run", not "ok" */
  dir = prepare_valdir("val_norun");
  char p[4500];
  snprintf(cmd, sizeof cmd, "mkdir -p '%s/wp1'", dir);
  test_run(cmd, NULL, 0);
  snprintf(p, sizeof p, "%s/wp1/particles_00000.csv", dir);
  FILE *f = fopen(p, "w");
  if (!f || fputs("garbage\n", f) < 0 || fclose(f)) exit(1);
  snprintf(args, sizeof args, "validate --no-run --only wp1 bumper-1 -o '%s'", dir);
  rc = hvsph(args, out, sizeof out);
  snprintf(p, sizeof p, "%s/validation.csv", dir);
  char *vcsv = test_slurp(p, NULL);
  CHECK(vcsv &&
            !strncmp(vcsv, "# hvsph " HVSPH_VERSION ": ", strlen("# hvsph " HVSPH_VERSION ": ")),
        "validation.csv starts with a comment line giving the version: %.80s", vcsv ? vcsv : "");
  free(vcsv);
  snprintf(p, sizeof p, "%s/validation.md", dir);
  char *md = test_slurp(p, NULL);
  CHECK(md && strstr(md, "hvsph " HVSPH_VERSION), "validation.md names the version");
  int nerr;
  error_line(out, &nerr);
  CHECK(rc == 0 && nerr == 0 && strstr(out, "wp1: no radiograph") && md &&
            strstr(md, "| wp1 | hole_diameter (bumper) |"),
        "validate --no-run with an unreadable "
        "snapshot: a warning, the tables written (exit %d): %s",
        rc, out);
  CHECK(md && strstr(md, "| bumper-1 | -1 | (earlier run) | not run |"),
        "validate --no-run: a case with no run in the folder is 'not run'");
  free(md);
}

/* hvsph validate --rz (issue 74): the axisymmetric cases of examples/paper/rz/, the
 * paper's normal impacts. Nothing runs: --list prints the cases (name, case file, the
 * rows compared) and writes nothing; its --material swaps are checked on the case files
 * as before a run, so the sourced material set of the rods is checked here. */
static void test_validate_rz(void)
{
  char out[16384], cmd[9000];
  const char *fresh = path_of("valrz_fresh");
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", fresh);
  test_run(cmd, NULL, 0);
  snprintf(cmd, sizeof cmd, "'%s' validate --rz --list -o '%s' 2>&1", test_bin(), fresh);
  int rc = test_run(cmd, out, sizeof out);
  static const char *const normal[] = {
      "rod-1929", "rod-5835",      "rod-5839", "rod-5841", "rod-5842", "rod-5844", "bumper-1",
      "bumper-3", "whipple-steel", "wp1",      "wp2",      "wp3",      "vessel"};
  int lines = 0, listed = 0;
  for (const char *c = out; *c; c++) lines += *c == '\n';
  for (int k = 0; k < 13; k++) {
    char want[256];
    snprintf(want, sizeof want, "examples/paper/rz/%s.yaml ", normal[k]);
    const char *at = strstr(out, want);
    listed += at != NULL && (at == out || at[-1] != '-'); /* not rod-5841 inside x-rod-5841 */
  }
  struct stat st;
  CHECK(rc == 0 && lines == 13 && listed == 13 && !strstr(out, "bumper-17") &&
            strstr(out, "penetration_depth(target)") && stat(fresh, &st) != 0,
        "validate --rz --list: the 13 normal impacts of examples/paper/rz/ with their rows, "
        "no oblique case, nothing written (exit %d, %d lines): %.300s",
        rc, lines, out);
  /* the 3D list still has the oblique cases */
  snprintf(cmd, sizeof cmd, "'%s' validate --list --only bumper-17 2>&1", test_bin());
  rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0 && strstr(out, "examples/paper/bumper-17.yaml") && !strstr(out, "/rz/"),
        "validate --list --only bumper-17: the 3D case (exit %d): %.200s", rc, out);
  /* an oblique case asked for in RZ: bad input naming it and the folder */
  snprintf(cmd, sizeof cmd, "validate --rz --list --only bumper-17 -o '%s'", fresh);
  rc = hvsph(cmd, out, sizeof out);
  CHECK(rc == 2 && stat(fresh, &st) != 0, "validate --rz --only bumper-17: exit %d (want 2)", rc);
  check_message("validate --rz --only bumper-17", out,
                (const char *const[]){"no case 'bumper-17'", "examples/paper/rz", "normal", NULL});
  /* the sourced set of the rods: both swaps taken, both library names known */
  snprintf(cmd, sizeof cmd,
           "'%s' validate --rz --list --material steel-target=steel-4340 "
           "--material tungsten-alloy=tungsten-wha-rod 2>&1",
           test_bin());
  rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0 && strstr(out, "rz/rod-5841.yaml"),
        "validate --rz --list with the sourced set's two --material: taken (exit %d): %.200s", rc,
        out);
  /* a swap that no selected RZ case takes, a misspelt library name: bad input */
  snprintf(cmd, sizeof cmd, "validate --rz --list --only wp1 --material steel-target=steel-4340");
  rc = hvsph(cmd, out, sizeof out);
  CHECK(rc == 2, "validate --rz --list --only wp1 --material steel-target=...: exit %d (want 2)",
        rc);
  check_message("validate --rz, a swap no case takes", out,
                (const char *const[]){"steel-target=steel-4340", "no body", NULL});
  snprintf(cmd, sizeof cmd, "validate --rz --list --material tungsten-alloy=tungsten-wha-rd");
  rc = hvsph(cmd, out, sizeof out);
  CHECK(rc == 2, "validate --rz --list --material ...=tungsten-wha-rd: exit %d (want 2)", rc);
  check_message("validate --rz, an unknown material", out,
                (const char *const[]){"unknown material 'tungsten-wha-rd'", NULL});
  /* --rz over a folder without the cases: bad input, nothing made */
  const char *empty = path_of("valrz_empty");
  snprintf(cmd, sizeof cmd, "rm -rf '%s' && mkdir -p '%s'", empty, empty);
  test_run(cmd, NULL, 0);
  snprintf(cmd, sizeof cmd, "validate --rz --cases '%s' --only wp1 -o '%s'", empty, fresh);
  rc = hvsph(cmd, out, sizeof out);
  CHECK(rc == 2 && stat(fresh, &st) != 0, "validate --rz --cases EMPTY: exit %d (want 2)", rc);
  check_message("validate --rz --cases EMPTY", out,
                (const char *const[]){"no case file", "valrz_empty", NULL});
  /* --no-run over a folder without runs: the RZ tables say which cases they are */
  const char *dir = prepare_valdir("valrz_norun");
  snprintf(cmd, sizeof cmd, "validate --rz --no-run --only wp1 -o '%s'", dir);
  rc = hvsph(cmd, out, sizeof out);
  char p[4500];
  snprintf(p, sizeof p, "%s/validation.md", dir);
  char *md = test_slurp(p, NULL);
  CHECK(rc == 0 && md && strstr(md, "axisymmetric (RZ)") && strstr(md, "| wp1 | -1 |"),
        "validate --rz --no-run: RZ tables, wp1 not run (exit %d)", rc);
  free(md);
  /* flags take no value */
  rc = hvsph("validate --rz=1 --list", out, sizeof out);
  CHECK(rc == 1, "validate --rz=1: a usage error (exit %d, want 1)", rc);
}

/* hvsph measure over a tiny run with measurements: it rewrites measurements.csv (the same
 * rows, the definitions unchanged); a snapshot that cannot be read is bad input (exit 2)
 * and leaves the run's measurements.csv and fragment files as they were */
static void test_measure(void)
{
  char out[16384], args[9000], names[512];
  const char *casefile =
      test_write_file("measured.yaml", variant(21, "  csv: true\nmeasure: {plates: [slab], "
                                                   "fragments: true}"));
  const char *dir = path_of("measured");
  snprintf(args, sizeof args, "run '%s' -o '%s' --overwrite --quiet", casefile, dir);
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "the measured case runs (exit %d): %s", rc, out);
  char mp[4400], fp[4400], sp[4400];
  snprintf(mp, sizeof mp, "%s/measurements.csv", dir);
  snprintf(fp, sizeof fp, "%s/fragments_00002.csv", dir);
  snprintf(sp, sizeof sp, "%s/particles_00001.csv", dir);
  char *m0 = test_slurp(mp, NULL), *f0 = test_slurp(fp, NULL);
  const char *vline = "# hvsph " HVSPH_VERSION " case ";
  CHECK(m0 && f0 && !strncmp(m0, vline, strlen(vline)) && !strncmp(f0, vline, strlen(vline)),
        "measurements.csv and fragments_00002.csv start with '%s'", vline);
  snprintf(args, sizeof args, "measure '%s' --quiet", dir);
  rc = hvsph(args, out, sizeof out);
  char *m1 = test_slurp(mp, NULL);
  CHECK(rc == 0 && m0 && m1 && !strcmp(m0, m1),
        "hvsph measure rewrites measurements.csv with "
        "the run's own rows (exit %d): %s",
        rc, out);
  { /* measure takes the folder's lock, as a run that rewrites measurements.csv does */
    const pid_t holder = hold_lock(dir);
    rc = hvsph(args, out, sizeof out);
    kill(holder, SIGKILL);
    waitpid(holder, NULL, 0);
    char *m2 = test_slurp(mp, NULL), want[64];
    snprintf(want, sizeof want, "is in use by another hvsph process %ld ", (long)holder);
    CHECK(rc == 2 && strstr(out, want) && m2 && m0 && !strcmp(m0, m2),
          "measure of a folder in "
          "use: exit %d (want 2), naming the process, measurements.csv unchanged: %.200s",
          rc, out);
    free(m2);
  }
  free(m1);
  /* the run's measurements.csv and fragments_00002.csv marked, to see that they stay */
  FILE *f = fopen(mp, "a");
  if (!f || fputs("# kept\n", f) < 0 || fclose(f)) exit(1);
  f = fopen(fp, "a");
  if (!f || fputs("# kept\n", f) < 0 || fclose(f)) exit(1);
  f = fopen(sp, "w");
  if (!f || fputs("garbage\n", f) < 0 || fclose(f)) exit(1);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2, "hvsph measure with an unreadable snapshot: exit status %d (want 2)", rc);
  check_message("measure, unreadable snapshot", out,
                (const char *const[]){"particles_00001.csv", NULL});
  m1 = test_slurp(mp, NULL);
  char *f1 = test_slurp(fp, NULL);
  CHECK(m0 && f0 && m1 && f1 && strlen(m1) == strlen(m0) + 7 && !strncmp(m1, m0, strlen(m0)) &&
            strlen(f1) == strlen(f0) + 7 && !strncmp(f1, f0, strlen(f0)),
        "... and measurements.csv and fragments_00002.csv are left as they were");
  int ntmp, n = count_entries(dir, &ntmp, names, sizeof names);
  CHECK(ntmp == 0 && n > 0, "... and nothing temporary is left (has:%s)", names);
  free(m0);
  free(f0);
  free(m1);
  free(f1);
}

/* Inputs that are no regular file, or too large: a FIFO as case file or checkpoint
 * blocked the open for ever, `hvsph run /dev/zero` read until the kernel killed it
 * (23 GiB). Each is refused at once with exit 2 and one line naming the file and what
 * it is. Every command runs under `timeout -k 5 20`, so that a regression fails (exit
 * 124, or 137 when SIGTERM, which hvsph takes as "stop after this step", is not
 * enough) instead of hanging the suite; each takes well under a second when refused. */
/* path_of(name), removed (a run folder of an earlier `make check`). */
static const char *fresh_path(const char *name)
{
  const char *p = path_of(name);
  char cmd[4400];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", p);
  if (test_run(cmd, NULL, 0) != 0) {
    fprintf(stderr, "cannot remove %s\n", p);
    exit(1);
  }
  return p;
}

static void test_not_regular(void)
{
  char out[16384], args[9000], want[4500];
  const char *fifo = fresh_path("fifo.yaml");
  CHECK(mkfifo(fifo, 0600) == 0, "made the FIFO %s", fifo);
  const char *dir = fresh_path("notreg");
  const struct {
    const char *path, *what;
  } cases[] = {{fifo, "is a FIFO"},
               {"/dev/zero", "is a character device"},
               {test_tmpdir(), "is a directory"}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    char full[13400];
    /* 4 GiB of address space: a regression that reads /dev/zero fails, not the machine */
    snprintf(full, sizeof full,
             "{ ulimit -v 4194304; timeout -k 5 20 '%s' run '%s' -o '%s' "
             "--quiet 2>&1 >/dev/null; }",
             test_bin(), cases[k].path, dir);
    const int rc = test_run(full, out, sizeof out);
    CHECK(rc == 2, "case file %s: exit status %d (want 2; 124 or 137: it hung)", cases[k].path, rc);
    snprintf(want, sizeof want, "case file '%s' %s", cases[k].path, cases[k].what);
    check_message(cases[k].path, out, (const char *const[]){want, "regular file", NULL});
  }
  struct stat st;
  CHECK(stat(dir, &st) != 0, "... and no output folder is created");

  /* 1 MiB (src/config/config.c argues the limit): the base case padded with comments to
     exactly the limit runs; one byte more is refused before it is read */
  static char big[(1 << 20) + 2];
  const char *base = variant(0, "");
  size_t n = (size_t)snprintf(big, sizeof big, "%s", base);
  while (n < (1u << 20)) {
    const size_t line = (1u << 20) - n < 100 ? (1u << 20) - n : 100;
    memset(big + n, '#', line - 1);
    big[n + line - 1] = '\n';
    n += line;
  }
  big[n] = '\0';
  const char *at = test_write_file("limit.yaml", big);
  snprintf(args, sizeof args, "run '%s' -o '%s' --quiet", at, fresh_path("limit"));
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "a case file of exactly 1 MiB runs (exit %d): %.300s", rc, out);
  big[n] = '\n';
  big[n + 1] = '\0';
  const char *over = test_write_file("over.yaml", big);
  snprintf(args, sizeof args, "run '%s' -o '%s' --quiet", over, fresh_path("over"));
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2, "a case file of 1 MiB + 1 byte: exit status %d (want 2)", rc);
  snprintf(want, sizeof want, "case file '%s' is 1048577 bytes, more than the 1048576", over);
  check_message("1 MiB + 1", out, (const char *const[]){want, NULL});

  /* a FIFO in place of the checkpoint: hvsph restart refuses it, naming it */
  const char *casefile = test_write_file("base.yaml", base);
  const char *rdir = fresh_path("fifo_ckpt");
  snprintf(args, sizeof args, "run '%s' -o '%s' --quiet", casefile, rdir);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "the run for the FIFO checkpoint (exit %d): %s", rc, out);
  char ck[4400], full[13400];
  snprintf(ck, sizeof ck, "%s/checkpoint.hvc", rdir);
  CHECK(remove(ck) == 0 && mkfifo(ck, 0600) == 0, "checkpoint.hvc replaced by a FIFO");
  snprintf(full, sizeof full,
           "{ timeout -k 5 20 '%s' restart '%s' --set time.end=0.02 --quiet "
           "2>&1 >/dev/null; }",
           test_bin(), rdir);
  rc = test_run(full, out, sizeof out);
  CHECK(rc == 2,
        "restart from a FIFO checkpoint: exit status %d (want 2; 124 or 137: it "
        "hung)",
        rc);
  snprintf(want, sizeof want, "checkpoint '%s' is a FIFO", ck);
  check_message("FIFO checkpoint", out, (const char *const[]){want, NULL});

  /* a FIFO in place of run_segments.csv (read on restart to append a row) blocked the
   * restart: it is taken as no earlier segments and replaced by a regular file */
  char seg[4400];
  snprintf(seg, sizeof seg, "%s/run_segments.csv", rdir);
  CHECK(remove(ck) == 0, "the FIFO checkpoint removed");
  snprintf(args, sizeof args, "run '%s' -o '%s' --quiet --overwrite", casefile, rdir);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "the run for the FIFO run_segments.csv (exit %d): %s", rc, out);
  CHECK(remove(seg) == 0 && mkfifo(seg, 0600) == 0, "run_segments.csv replaced by a FIFO");
  snprintf(full, sizeof full,
           "{ timeout -k 5 20 '%s' restart '%s' --set time.end=0.03 --quiet "
           "2>&1 >/dev/null; }",
           test_bin(), rdir);
  rc = test_run(full, out, sizeof out);
  struct stat sst;
  CHECK(rc == 0 && stat(seg, &sst) == 0 && S_ISREG(sst.st_mode),
        "restart with a FIFO run_segments.csv: exit status %d (want 0; 124 or 137: it hung), "
        "the file regular again",
        rc);

  /* a FIFO as the snapshot hvsph render reads */
  const char *sfifo = fresh_path("fifo.vtu");
  CHECK(mkfifo(sfifo, 0600) == 0, "made the FIFO %s", sfifo);
  snprintf(full, sizeof full, "{ timeout -k 5 20 '%s' render '%s' -o '%s' 2>&1 >/dev/null; }",
           test_bin(), sfifo, path_of("fifo.png"));
  rc = test_run(full, out, sizeof out);
  CHECK(rc == 2, "render of a FIFO: exit status %d (want 2; 124 or 137: it hung)", rc);
  snprintf(want, sizeof want, "'%s' is a FIFO", sfifo);
  check_message("FIFO snapshot", out, (const char *const[]){want, NULL});
}

/* Lines of a file that do not start with '#' (-1: no file). */
static int data_lines(const char *path)
{
  char *t = test_slurp(path, NULL);
  if (!t) return -1;
  int n = 0;
  for (char *q = t; *q; q = strchr(q, '\n') ? strchr(q, '\n') + 1 : q + strlen(q))
    if (*q != '#' && *q != '\n') n++;
  free(t);
  return n;
}

/* An output whose snapshot is missing: hvsph measure dropped its rows from
 * measurements.csv without a word and exited 0. Now it is an error naming the snapshot
 * (exit 2, measurements.csv as it was, nothing temporary left); with --skip-missing the
 * others are measured, a warning names the missing one, and its rows are absent. */
static void test_measure_missing(void)
{
  char out[16384], args[9000], names[512], want[4500];
  const char *casefile =
      test_write_file("measured_gap.yaml", variant(21, "  csv: true\nmeasure: {plates: [slab], "
                                                       "fragments: true}"));
  const char *dir = fresh_path("measured_gap");
  snprintf(args, sizeof args, "run '%s' -o '%s' --quiet", casefile, dir);
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "the measured case runs (exit %d): %s", rc, out);
  char mp[4400], sp[4400];
  snprintf(mp, sizeof mp, "%s/measurements.csv", dir);
  snprintf(sp, sizeof sp, "%s/particles_00001.csv", dir);
  char *m0 = test_slurp(mp, NULL);
  const int rows0 = data_lines(mp);
  CHECK(remove(sp) == 0, "removed %s", sp);
  snprintf(args, sizeof args, "measure '%s' --quiet", dir);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 2, "hvsph measure with particles_00001.csv missing: exit %d (want 2)", rc);
  snprintf(want, sizeof want, "%s is missing (summary.csv lists it; 1 of the run's 3 outputs", sp);
  check_message("measure, missing snapshot", out,
                (const char *const[]){want, "--skip-missing", NULL});
  char *m1 = test_slurp(mp, NULL);
  CHECK(m0 && m1 && !strcmp(m0, m1), "... and measurements.csv is left as it was");
  int ntmp, n = count_entries(dir, &ntmp, names, sizeof names);
  CHECK(ntmp == 0 && n > 0, "... and nothing temporary is left (has:%s)", names);
  free(m1);
  /* the others measured on request, the missing one named */
  snprintf(args, sizeof args, "'%s' measure '%s' --skip-missing --quiet 2>&1", test_bin(), dir);
  rc = test_run(args, out, sizeof out);
  snprintf(want, sizeof want, "hvsph: warning: %s is missing: output 1 is not measured", sp);
  const int rows1 = data_lines(mp);
  CHECK(rc == 0 && strstr(out, want) && rows0 > 3 && rows1 > 1 && rows1 < rows0 &&
            (rows0 - 1) % 3 == 0 && rows1 - 1 == (rows0 - 1) / 3 * 2,
        "--skip-missing: exit %d, the warning names it, 2 of 3 outputs' rows (%d rows of %d, "
        "headers included): %s",
        rc, rows1, rows0, out);
  free(m0);
  /* summary.csv a FIFO (it blocked the open): not read, with a warning naming it; the
     outputs are then the numbers up to the last snapshot, and the gap is found */
  snprintf(sp, sizeof sp, "%s/summary.csv", dir);
  CHECK(remove(sp) == 0 && mkfifo(sp, 0600) == 0, "summary.csv replaced by a FIFO");
  snprintf(args, sizeof args, "timeout -k 5 20 '%s' measure '%s' --quiet 2>&1", test_bin(), dir);
  rc = test_run(args, out, sizeof out);
  snprintf(want, sizeof want, "'%s' is a FIFO", sp);
  CHECK(rc == 2 && strstr(out, want) &&
            strstr(out, "particles_00001.csv is missing (1 of the "
                        "run's 3 outputs has no snapshot)"),
        "measure with summary.csv a FIFO: exit %d (want "
        "2; 124 or 137: it hung), the FIFO and the gap named: %s",
        rc, out);
}

/* A snapshot that reads but cannot be measured is bad input of that file: an aluminium
 * slab's run with fragments, one particle's x in particles_00001.csv damaged to 1e129 m
 * (beyond the fragment search's 2e6 linking lengths). It was exit status 3, a failed
 * run, with a message that did not name the file (found by fuzzing the snapshots). */
static void test_measure_damaged(void)
{
  char out[16384], args[9000];
  const char *casefile =
      test_write_file("measured_solid.yaml", variant(21, "  csv: true\nmeasure: {plates: [slab], "
                                                         "fragments: true}"));
  const char *dir = path_of("measured_solid");
  snprintf(args, sizeof args,
           "run '%s' -o '%s' --overwrite "
           "--quiet --set bodies[0].material=al-alloy "
           "--set bodies[0].density=2780 --set time.end=2e-6 --set output.every=1e-6",
           casefile, dir);
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "the aluminium slab runs (exit %d): %s", rc, out);
  char sp[4400];
  snprintf(sp, sizeof sp, "%s/particles_00001.csv", dir);
  char *s0 = test_slurp(sp, NULL);
  const char *row = s0 ? strstr(s0, "\nid,") : NULL;
  row = row ? strchr(row + 1, '\n') : NULL;
  const char *c1 = row ? strchr(row, ',') : NULL, *c2 = c1 ? strchr(c1 + 1, ',') : NULL;
  CHECK(c2 != NULL, "particles_00001.csv has a header and a first row");
  if (c2) {
    FILE *f = fopen(sp, "w");
    if (!f || fprintf(f, "%.*s1e129%s", (int)(c1 + 1 - s0), s0, c2) < 0 || fclose(f)) exit(1);
    snprintf(args, sizeof args, "measure '%s' --quiet", dir);
    rc = hvsph(args, out, sizeof out);
    CHECK(rc == 2, "hvsph measure with a particle at x = 1e129 m: exit status %d (want 2)", rc);
    check_message("measure, a particle far away", out,
                  (const char *const[]){"particles_00001.csv", "friends-of-friends", NULL});
  }
  free(s0);
}

/* A material in scaled units, written with its units (the library's rubber-ring: rho0
 * 1 kg/m3, c0 1 m/s), passes the wrong-units check; the run's used_parameters.yaml holds
 * those numbers bare (SI by construction), and `hvsph restart` and a run of that file as
 * a case take them (a first cut of the check refused both). */
static void test_scaled_units_restart(void)
{
  char out[16384], args[9000];
  const char *casefile = test_write_file("scaled.yaml", variant(13, "    density: 1 kg/m3"));
  const char *dir = path_of("scaled"), *dir2 = path_of("scaled_again");
  snprintf(args, sizeof args,
           "run '%s' -o '%s' --overwrite "
           "--quiet --set bodies[0].material=rubber-ring "
           "--set bodies[0].pressure=0 --set time.max_steps=3",
           casefile, dir);
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "scaled units: the run (exit %d): %s", rc, out);
  snprintf(args, sizeof args, "restart '%s' --quiet --set time.max_steps=6", dir);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "scaled units: hvsph restart takes used_parameters.yaml (exit %d): %s", rc, out);
  snprintf(args, sizeof args,
           "run '%s/used_parameters.yaml' -o '%s' --overwrite --quiet "
           "--set time.max_steps=2",
           dir, dir2);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "scaled units: used_parameters.yaml runs as a case (exit %d): %s", rc, out);
  snprintf(args, sizeof args,
           "restart '%s' --quiet --set time.max_steps=7 "
           "--set materials.rubber-ring.c0=2",
           dir);
  rc = hvsph(args, out, sizeof out);
  check_message("scaled units: a bare --set on restart", out,
                (const char *const[]){"--set: materials.rubber-ring.c0: the bare number 2", NULL});
  CHECK(rc == 2, "scaled units: ... is still checked (exit %d)", rc);
}

/* output.every written bare and longer than time.end (a 5 meant in us) is said: outputs
 * at the start and the end only; the run goes on */
/* A folder holding an earlier run is refused (exit 2, its files intact) unless
 * --overwrite, which removes that run's files and nothing else; a folder in use by
 * another process (its lock) is refused, naming the process; a lock left by a process
 * that was killed is taken over. */
static void test_run_folders(void)
{
  char out[16384], args[9000], cmd[9000];
  const char *casefile = test_write_file("base.yaml", variant(0, ""));
  const char *dir = path_of("earlier");
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  test_run(cmd, NULL, 0);
  snprintf(args, sizeof args, "run '%s' -o '%s' --quiet", casefile, dir);
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0, "a first run into a new folder (exit %d): %s", rc, out);
  char ck[4400], sp[4400], snap2[4400], notes[4400], lockf[4400];
  snprintf(ck, sizeof ck, "%s/checkpoint.hvc", dir);
  snprintf(sp, sizeof sp, "%s/summary.csv", dir);
  snprintf(snap2, sizeof snap2, "%s/particles_00002.vtu", dir);
  snprintf(notes, sizeof notes, "%s/notes.txt", dir);
  snprintf(lockf, sizeof lockf, "%s/" RUNFOLDER_LOCK, dir);
  FILE *f = fopen(notes, "w");
  if (!f || fputs("the user's own file\n", f) < 0 || fclose(f)) exit(1);
  size_t cklen = 0, splen = 0;
  char *ck0 = test_slurp(ck, &cklen), *sp0 = test_slurp(sp, &splen);
  int ntmp, n0 = count_entries(dir, &ntmp, NULL, 0);
  CHECK(ck0 && cklen > 0 && access(lockf, F_OK) != 0,
        "it wrote a checkpoint (%zu bytes) and "
        "left no lock file",
        cklen);

  /* again, as the issue's "quick check" (time.end = 0) and as a whole run: refused */
  static const char *const again[] = {"--set time.end=0", ""};
  for (int k = 0; k < 2; k++) {
    snprintf(args, sizeof args, "run '%s' -o '%s' --quiet %s", casefile, dir, again[k]);
    rc = hvsph(args, out, sizeof out);
    CHECK(rc == 2, "a new run%s into the folder of a finished run: exit %d (want 2)",
          k ? "" : " with time.end=0", rc);
    char w0[4500];
    snprintf(w0, sizeof w0, "%s holds an earlier run (checkpoint.hvc, summary.csv", dir);
    check_message("earlier run", out,
                  (const char *const[]){w0, "6 particle snapshot files", "hvsph restart",
                                        "--overwrite", NULL});
    size_t l1 = 0, l2 = 0;
    char *ck1 = test_slurp(ck, &l1), *sp1 = test_slurp(sp, &l2);
    CHECK(ck1 && l1 == cklen && !memcmp(ck0, ck1, cklen) && sp1 && l2 == splen &&
              !memcmp(sp0, sp1, splen) && count_entries(dir, &ntmp, NULL, 0) == n0,
          "... its checkpoint, summary.csv and files intact (%d entries)", n0);
    free(ck1);
    free(sp1);
  }
  snprintf(args, sizeof args, "restart '%s' --set time.end=0.015 --quiet", dir);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0 && summary_rows(dir) == 4,
        "... and the run continues from it (exit %d, %d "
        "summary rows)",
        rc, summary_rows(dir));

  /* --overwrite: the earlier run's files go (its later snapshot and checkpoint: this one
     writes neither), the user's notes stay */
  snprintf(args, sizeof args, "run '%s' -o '%s' --overwrite --set time.end=0", casefile, dir);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0 && strstr(out, "--overwrite: removed the earlier run's ") &&
            access(snap2, F_OK) != 0 && access(ck, F_OK) != 0 && access(notes, F_OK) == 0 &&
            summary_rows(dir) == 1,
        "--overwrite replaces it: exit %d, the earlier snapshots and checkpoint removed, "
        "notes.txt kept, summary.csv the new run's: %.300s",
        rc, out);

  /* a process holding the folder's lock */
  const pid_t child = hold_lock(dir);
  char pid[64];
  snprintf(pid, sizeof pid, "hvsph process %ld on ", (long)child);
  n0 = count_entries(dir, &ntmp, NULL, 0);
  for (int k = 0; k < 2; k++) {
    if (k == 0)
      snprintf(args, sizeof args, "run '%s' -o '%s' --overwrite --quiet", casefile, dir);
    else
      snprintf(args, sizeof args, "restart '%s'", dir);
    rc = hvsph(args, out, sizeof out);
    CHECK(rc == 2, "%s of a folder in use: exit %d (want 2)", k ? "restart" : "run --overwrite",
          rc);
    check_message(k ? "restart, folder in use" : "run, folder in use", out,
                  (const char *const[]){"is in use by another", pid, "(hvsph run, started ", NULL});
    CHECK(count_entries(dir, &ntmp, NULL, 0) == n0 && access(lockf, F_OK) == 0,
          "... nothing changed in the folder (%d entries, the lock file still there)", n0);
  }
  kill(child, SIGKILL);
  waitpid(child, NULL, 0);
  /* the killed process's lock file: stale, taken over with a note */
  char *lk = test_slurp(lockf, NULL), want[64];
  snprintf(want, sizeof want, "pid: %ld\n", (long)child);
  CHECK(lk && strstr(lk, want), "the killed process left its lock file naming it: %.80s",
        lk ? lk : "(none)");
  free(lk);
  snprintf(args, sizeof args, "run '%s' -o '%s' --overwrite --set time.end=0", casefile, dir);
  rc = hvsph(args, out, sizeof out);
  snprintf(want, sizeof want, "took over the lock left by hvsph process %ld ", (long)child);
  CHECK(rc == 0 && strstr(out, want) && access(lockf, F_OK) != 0,
        "a lock left by a killed process is taken over with a note (exit %d), and removed at "
        "the end: %.300s",
        rc, out);

  /* a lock file that is a symbolic link is not followed (the holder truncates it) */
  const char *victim = test_write_file("victim.txt", "not hvsph's\n");
  if (symlink(victim, lockf)) exit(1);
  snprintf(args, sizeof args, "run '%s' -o '%s' --overwrite --set time.end=0", casefile, dir);
  rc = hvsph(args, out, sizeof out);
  char *v = test_slurp(victim, NULL);
  CHECK(rc == 2 && v && !strcmp(v, "not hvsph's\n") && strstr(out, "cannot create the lock file"),
        "a lock file that is a symbolic link: exit %d (want 2), its target untouched: %.200s", rc,
        out);
  free(v);
  unlink(lockf);

  /* --force lets a case write more than 10000 outputs (here stopped after 2 steps) */
  snprintf(args, sizeof args,
           "run '%s' -o '%s' --overwrite --force --set output.every=1e-9 "
           "--set time.max_steps=2",
           casefile, dir);
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0 && strstr(out, "warning: --set: output.every = 1e-09 s writes ") &&
            strstr(out, "(--force)"),
        "--force: 10^7 output times are a warning only (exit %d): %.300s", rc, out);
  free(ck0);
  free(sp0);
}

static void test_every_warning(void)
{
  char out[16384], args[9000];
  const char *casefile = test_write_file("every.yaml", variant(20, "  every: 5"));
  snprintf(args, sizeof args, "run '%s' -o '%s' --overwrite --quiet", casefile, path_of("every"));
  int rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0 && strstr(out, "every.yaml:20: output.every = 5 s is longer than time.end = "
                               "0.01 s: outputs at the start and the end only"),
        "output.every past time.end: warned, run (exit %d): %s", rc, out);
  casefile = test_write_file("every0.yaml", variant(20, "  every: 0"));
  snprintf(args, sizeof args, "run '%s' -o '%s' --overwrite --quiet", casefile, path_of("every0"));
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0 && !strstr(out, "output.every"), "output.every 0: no warning (exit %d): %s", rc,
        out);
  /* with its unit it is meant (a --set time.end shorter than it, for a quick look) */
  casefile = test_write_file("every_unit.yaml", variant(20, "  every: 5 s"));
  snprintf(args, sizeof args,
           "run '%s' -o '%s' --overwrite "
           "--quiet",
           casefile, path_of("every_unit"));
  rc = hvsph(args, out, sizeof out);
  CHECK(rc == 0 && !strstr(out, "output.every"), "output.every 5 s: no warning (exit %d): %s", rc,
        out);
}

int main(void)
{
  /* the material library of this source tree, also for builds outside it (the binary
     looks for it in ../data next to itself unless HVSPH_DATA says otherwise) */
  char data[4200];
  snprintf(data, sizeof data, "%s/data", test_source_dir());
  setenv("HVSPH_DATA", data, 0);
  test_commands();
  test_bad_input();
  test_outdir();
  test_late_input_error();
  test_mass_ratio_warning();
  test_lattice_cover_warning();
  test_validate();
  test_validate_rz();
  test_measure();
  test_measure_damaged();
  test_not_regular();
  test_measure_missing();
  test_scaled_units_restart();
  test_every_warning();
  test_run_folders();
  failed_run("negative_density", "--set time.end=10 --set time.dt_init=10 --set output.every=0",
             (const char *const[]){"t = 0 s", "particle ", "body 'slab'",
                                   "field rho: ", "not a positive finite density", NULL});
  failed_run("not_finite", "--set bodies[0].pressure=1e306",
             (const char *const[]){"t = 0 s", "particle ", "body 'slab'", "nan", NULL});
  /* an energy the EOS takes but whose pressure overflows (Γρe > DBL_MAX): the message
     gives the state and the pressure; it said "is a valid state" */
  {
    char out[16384], args[9000];
    const char *casefile = test_write_file("eos_inf.yaml", variant(14, "    energy: 1e305"));
    const char *dir = prepare_outdir("eos_not_finite");
    snprintf(args, sizeof args,
             "run '%s' -o '%s' --overwrite --quiet --set bodies[0].density=2780 "
             "--set bodies[0].material=al-alloy",
             casefile, dir);
    const int rc = hvsph(args, out, sizeof out);
    CHECK(rc == 3, "eos_not_finite: exit status %d (want 3)", rc);
    check_message("eos_not_finite", out,
                  (const char *const[]){"t = 0 s", "particle 0", "material 'al-alloy'",
                                        "rho = 2780 kg/m3, e = 1e+305 J/kg gives no finite "
                                        "pressure or sound speed (p = inf Pa",
                                        NULL});
    CHECK(!strstr(out, "valid state"), "eos_not_finite: not called a valid state: %s", out);
  }
  return test_finish();
}
