/* test_interrupt.c — Ctrl-C (SIGINT) ends a run cleanly, with its state written.
 *
 * examples/verification/tiny.yaml is started with time.end = 1000 s (hours of
 * work) and snapshots every 2 ms of simulated time. Once the run has written its
 * first output (so it is past set-up and stepping), the test waits 1 s and sends
 * SIGINT. Then:
 *   - the exit status is 130, within a few seconds of the signal, and the log says
 *     "interrupted at t = ...";
 *   - summary.csv is complete and its last row is the interrupted state (t < end);
 *   - run.pvd lists exactly the .vtu files present, the last of them at that time;
 *   - the last .vtu is complete: its appended blocks (an 8-byte count, then the
 *     data) add up exactly to the closing tags, its TIME and STEP match the row;
 *   - the last particle .csv reads back with every particle, at that time;
 *   - there are as many .vtu and .csv snapshots as summary rows, and no temporary
 *     file (".tmp.") is left in the folder.
 * While it runs, a second process is refused the folder (its lock): `hvsph restart` and
 * `hvsph run --overwrite` into it end with exit status 2 naming the running pid, and
 * touch nothing; after the run's end no lock file is left.
 * Then SIGTERM, SIGHUP, SIGUSR1, SIGUSR2 and SIGXCPU (what batch systems send before a
 * time limit), each to a run of its own: exit status 130, the log names the signal, and
 * the checkpoint continues (`hvsph restart` for 3 more steps, exit 0).
 * Then the same on a terminal 80 columns wide (a pseudo-terminal): the status line,
 * rewritten in place after a carriage return, must never be wider than 79 columns
 * (a wider one wraps, and each rewrite then leaves a row behind: it was padded to 160
 * columns), it still shows the time remaining, and the message after Ctrl-C begins a
 * line of its own.
 */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "io/snapshot.h"
#include "particles/particles.h"
#include "testlib.h"

#define NPART 3024 /* tiny.yaml */

static char dir[4200];

static const char *in_dir(const char *name)
{
  static char buf[4][4400];
  static int k = 0;
  char *b = buf[k++ % 4];
  if ((size_t)snprintf(b, sizeof buf[0], "%s/%s", dir, name) >= sizeof buf[0]) exit(1);
  return b;
}

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void sleep_s(double s)
{
  struct timespec ts = {(time_t)s, (long)((s - floor(s)) * 1e9)};
  while (nanosleep(&ts, &ts) && errno == EINTR) {}
}

/* Last data row of summary.csv: step and time; returns the number of rows or -1. */
static int summary_last(long *step, double *t, double *first_t)
{
  char *s = test_slurp(in_dir("summary.csv"), NULL);
  if (!s || !*s || s[strlen(s) - 1] != '\n') {
    free(s);
    return -1;
  }
  int rows = 0, header = 0, bad = 0;
  for (char *line = strtok(s, "\n"); line; line = strtok(NULL, "\n")) {
    if (line[0] == '#') continue;
    if (!header) {
      header = !strncmp(line, "step,time,dt,", 13);
      if (!header) bad = 1;
      continue;
    }
    int fields = 1;
    for (char *c = line; *c; c++) fields += *c == ',';
    char *end;
    *step = strtol(line, &end, 10);
    if (*end != ',') bad = 1;
    *t = strtod(end + 1, &end);
    if (*end != ',' || fields < 11) bad = 1;
    if (rows == 0) *first_t = *t;
    rows++;
  }
  free(s);
  return bad || !header ? -1 : rows;
}

/* Checks the appended blocks of a .vtu add up; gets TIME, STEP and NumberOfPoints. */
static int vtu_complete(const char *path, double *t, long *step, long *np)
{
  size_t len;
  char *b = test_slurp(path, &len);
  if (!b) return 0;
  static const char tail[] = "\n  </AppendedData>\n</VTKFile>\n";
  const char *start = strstr(b, "<AppendedData encoding=\"raw\">\n   _");
  const char *tm = strstr(b, "Name=\"TIME\""), *st = strstr(b, "Name=\"STEP\"");
  const char *npts = strstr(b, "NumberOfPoints=\"");
  int ok = start && tm && st && npts && len > sizeof tail &&
           !memcmp(b + len - (sizeof tail - 1), tail, sizeof tail - 1);
  if (ok) {
    *t = strtod(strchr(tm, '>') + 1, NULL);
    *step = strtol(strchr(st, '>') + 1, NULL, 10);
    *np = strtol(npts + 16, NULL, 10);
    int narrays = 0;
    for (const char *p = strstr(b, "format=\"appended\""); p && p < start;
         p = strstr(p + 1, "format=\"appended\""))
      narrays++;
    size_t pos = (size_t)(strchr(start, '_') - b) + 1, end = len - (sizeof tail - 1);
    int blocks = 0;
    while (pos + 8 <= end) {
      uint64_t nb;
      memcpy(&nb, b + pos, 8);
      if (nb > end - pos - 8) break;
      pos += 8 + nb;
      blocks++;
    }
    ok = pos == end && blocks == narrays && narrays > 0;
    printf("  %s: %zu bytes, %d appended blocks for %d arrays, %s\n", path, len, blocks, narrays,
           ok ? "complete" : "INCOMPLETE");
  }
  free(b);
  return ok;
}

/* While the run (pid) goes on in dir: a restart and a new run with --overwrite are refused
   (exit 2, the message naming the pid), and summary.csv is not rewritten by them. */
static void locked_out(const char *casefile, pid_t pid)
{
  char cmd[9000], out[8192], want[64];
  snprintf(want, sizeof want, "process %ld on ", (long)pid);
  for (int k = 0; k < 2; k++) {
    char args[8800];
    if (k == 0)
      snprintf(args, sizeof args, "restart '%s' --quiet", dir);
    else
      snprintf(args, sizeof args, "run '%s' -o '%s' --overwrite --quiet", casefile, dir);
    snprintf(cmd, sizeof cmd, "'%s' %s", test_bin(), args);
    const int rc = test_run(cmd, out, sizeof out);
    CHECK(rc == 2 && strstr(out, "is in use by another hvsph") && strstr(out, want),
          "while the run goes on, hvsph %s is refused: exit %d (want 2), naming pid %ld: %.300s",
          k ? "run --overwrite" : "restart", rc, (long)pid, out);
  }
  CHECK(kill(pid, 0) == 0, "... and the run goes on");
}

/* A run stopped by signal sig: exit 130, the log names the signal, and its checkpoint
   continues for 3 more steps. */
static void stopped_by(const char *casefile, int sig, const char *name)
{
  char sdir[4400], log[4500], cmd[9000], out[8192];
  snprintf(sdir, sizeof sdir, "%s/sig_%s", test_tmpdir(), name);
  snprintf(log, sizeof log, "%s/sig_%s.log", test_tmpdir(), name);
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", sdir);
  test_run(cmd, NULL, 0);
  pid_t pid = fork();
  if (pid == 0) {
    if (!freopen(log, "w", stderr) || !freopen("/dev/null", "w", stdout)) _exit(99);
    signal(sig, SIG_DFL); /* hvsph keeps an ignored SIGHUP ignored (nohup) */
    execl(test_bin(), "hvsph", "run", casefile, "-o", sdir, "--set", "time.end=1000", "--set",
          "output.every=1000", "--set", "output.checkpoint_wall=0", (char *)NULL);
    _exit(98);
  }
  if (pid <= 0) {
    CHECK(0, "%s: started hvsph", name);
    return;
  }
  /* past set-up and its first output (summary.csv), then 0.3 s of steps */
  char sp[4500];
  snprintf(sp, sizeof sp, "%s/summary.csv", sdir);
  struct stat st;
  int status = 0, done = 0;
  for (double t0 = now(); now() - t0 < 60 && stat(sp, &st); sleep_s(0.02)) {}
  sleep_s(0.3);
  kill(pid, sig);
  for (double t0 = now(); !done && now() - t0 < 60; sleep_s(0.01))
    done = waitpid(pid, &status, WNOHANG) == pid;
  if (!done) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
  char *text = test_slurp(log, NULL), want[64];
  snprintf(want, sizeof want, ") by %s; the state", name);
  CHECK(done && WIFEXITED(status) && WEXITSTATUS(status) == 130 && text && strstr(text, want),
        "%s ends the run with exit status 130 (got %s %d) and the log says '%s': %.200s", name,
        WIFEXITED(status) ? "exit" : "signal",
        WIFEXITED(status)     ? WEXITSTATUS(status)
        : WIFSIGNALED(status) ? WTERMSIG(status)
                              : -1,
        want, text && strstr(text, "interrupted") ? strstr(text, "interrupted") : "");
  free(text);
  long step = -1;
  double t = -1, tfirst = -1;
  char keep[sizeof dir];
  memcpy(keep, dir, sizeof dir); /* summary_last reads dir's */
  snprintf(dir, sizeof dir, "%s/sig_%s", test_tmpdir(), name);
  const int rows = summary_last(&step, &t, &tfirst);
  memcpy(dir, keep, sizeof dir);
  snprintf(cmd, sizeof cmd, "'%s' restart '%s' --set time.max_steps=%ld", test_bin(), sdir,
           step + 3);
  const int rc = test_run(cmd, out, sizeof out);
  snprintf(want, sizeof want, "(step %ld,", step);
  CHECK(rows >= 2 && step > 0 && rc == 0 && strstr(out, "from its checkpoint at t = ") &&
            strstr(out, want),
        "%s: the checkpoint at step %ld continues (hvsph restart, 3 steps: exit %d): %.300s", name,
        step, rc, out);
}

/* hvsph on a pseudo-terminal 80 columns wide, interrupted after its first status
   line and 1 s more: checks its status lines and messages as a terminal shows them. */
static void on_terminal(const char *casefile)
{
  char tdir[4400];
  snprintf(tdir, sizeof tdir, "%s/tty", test_tmpdir());
  struct winsize ws = {.ws_row = 24, .ws_col = 80};
  int fd = -1;
  pid_t pid = forkpty(&fd, NULL, NULL, &ws);
  if (pid == 0) {
    execl(test_bin(), "hvsph", "run", casefile, "-o", tdir, "--overwrite", "--set", "time.end=1000",
          "--set", "output.every=1000", (char *)NULL);
    _exit(98);
  }
  CHECK(pid > 0, "started hvsph on a terminal (pid %ld)", (long)pid);
  if (pid <= 0) return;
  size_t len = 0, cap = 1 << 16;
  char *out = malloc(cap + 1);
  double t0 = now(), tsig = -1;
  int status = 0, done = 0;
  while (now() - t0 < 90) {
    struct pollfd pf = {.fd = fd, .events = POLLIN};
    if (poll(&pf, 1, 50) > 0) {
      const ssize_t k = read(fd, out + len, cap - len);
      if (k > 0)
        len += (size_t)k;
      else if (k == 0 || errno != EINTR)
        break; /* EIO: the terminal's other side closed */
      if (len == cap) out = realloc(out, (cap *= 2) + 1);
    }
    out[len] = 0;
    if (tsig < 0 && strstr(out, "step ") && strstr(out, "remaining")) tsig = now() + 1.0;
    if (tsig > 0 && now() > tsig) {
      kill(pid, SIGINT);
      tsig = 1e300;
    }
  }
  for (double tw = now(); !done && now() - tw < 20; sleep_s(0.01))
    done = waitpid(pid, &status, WNOHANG) == pid;
  if (!done) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
  close(fd);
  out[len] = 0;
  CHECK(done && WIFEXITED(status) && WEXITSTATUS(status) == 130,
        "on a terminal: exit status 130 after SIGINT (got %s %d)",
        WIFEXITED(status) ? "exit" : "signal",
        WIFEXITED(status)     ? WEXITSTATUS(status)
        : WIFSIGNALED(status) ? WTERMSIG(status)
                              : -1);
  /* the pieces between carriage returns and newlines, as the terminal's rows start */
  int nstatus = 0, widest = 0, remaining = 0, msg_at_start = 0;
  for (char *p = out; *p;) {
    const size_t n = strcspn(p, "\r\n");
    const char before = p > out ? p[-1] : '\n';
    if (!strncmp(p, "step ", 5)) {
      nstatus++;
      int w = (int)n;
      while (w > 0 && p[w - 1] == ' ') w--; /* blanks over a longer previous line count */
      if ((int)n > widest) widest = (int)n;
      const char save = p[w];
      p[w] = '\0';
      remaining += strstr(p, "remaining") != NULL;
      p[w] = save;
    }
    if (!strncmp(p, "hvsph: interrupted at t = ", 26) && before == '\n') msg_at_start = 1;
    p += n;
    if (*p) p++;
  }
  printf("  on a terminal 80 columns wide: %d status line writes, the widest %d columns, %d "
         "showing the time remaining\n",
         nstatus, widest, remaining);
  CHECK(nstatus > 0 && widest <= 79,
        "on a terminal 80 columns wide the status line fits (%d "
        "writes, widest %d columns <= 79)",
        nstatus, widest);
  CHECK(nstatus > 0 && remaining == nstatus, "and shows the time remaining (%d of %d)", remaining,
        nstatus);
  CHECK(msg_at_start, "'hvsph: interrupted at t = ...' begins a line of its own");
  free(out);
}

int main(void)
{
  snprintf(dir, sizeof dir, "%s/run", test_tmpdir());
  char casefile[4400], cmd[9000], logfile[4400];
  snprintf(casefile, sizeof casefile, "%s/examples/verification/tiny.yaml", test_source_dir());
  snprintf(logfile, sizeof logfile, "%s/log.txt", test_tmpdir());
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  test_run(cmd, NULL, 0);

  pid_t pid = fork();
  if (pid == 0) {
    if (!freopen(logfile, "w", stderr) || !freopen("/dev/null", "w", stdout)) _exit(99);
    /* 500 000 output times: --force (the run is stopped long before) */
    execl(test_bin(), "hvsph", "run", casefile, "-o", dir, "--force", "--set", "time.end=1000",
          "--set", "output.every=0.002", "--set", "output.log_every=1000000", (char *)NULL);
    _exit(98);
  }
  CHECK(pid > 0, "started hvsph (pid %ld)", (long)pid);
  if (pid <= 0) return test_finish();

  /* wait for the first output (the run is then stepping), then 1 s more */
  double t0 = now();
  struct stat st;
  int started = 0, status = 0;
  while (now() - t0 < 60) {
    if (stat(in_dir("summary.csv"), &st) == 0) {
      started = 1;
      break;
    }
    if (waitpid(pid, &status, WNOHANG) == pid) break;
    sleep_s(0.02);
  }
  CHECK(started, "the run wrote its first output after %.2f s", now() - t0);
  if (started) sleep_s(1.0);
  if (started) locked_out(casefile, pid);
  double tsig = now();
  kill(pid, SIGINT);
  int done = 0;
  while (now() - tsig < 60) {
    if (waitpid(pid, &status, WNOHANG) == pid) {
      done = 1;
      break;
    }
    sleep_s(0.01);
  }
  double lag = now() - tsig;
  if (!done) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
  CHECK(done && lag < 20, "hvsph ended %.2f s after SIGINT (< 20 s)", lag);
  CHECK(done && WIFEXITED(status) && WEXITSTATUS(status) == 130, "exit status 130 (got %s %d)",
        WIFEXITED(status) ? "exit" : "signal",
        WIFEXITED(status)     ? WEXITSTATUS(status)
        : WIFSIGNALED(status) ? WTERMSIG(status)
                              : -1);
  char *log = test_slurp(logfile, NULL);
  CHECK(log && strstr(log, "interrupted at t = "), "the log says 'interrupted at t = ...'");
  if (log)
    printf("  log: %.*s\n",
           (int)strcspn(strstr(log, "interrupted") ? strstr(log, "interrupted") : log, "\n"),
           strstr(log, "interrupted") ? strstr(log, "interrupted") : log);
  free(log);

  /* summary.csv */
  long step = -1;
  double t = -1, tfirst = -1;
  int rows = summary_last(&step, &t, &tfirst);
  printf("  summary.csv: %d rows, last at step %ld, t = %.17g s\n", rows, step, t);
  CHECK(rows >= 2, "summary.csv is complete with %d rows (>= 2)", rows);
  CHECK(t > 0 && t < 1000 && tfirst == 0.0,
        "its last row is the interrupted state: 0 < t = %g s "
        "< 1000 s",
        t);

  /* the folder: snapshots, no temporary files */
  DIR *d = opendir(dir);
  int nvtu = 0, ncsv = 0, ntmp = 0;
  struct dirent *e;
  while (d && (e = readdir(d))) {
    int k;
    char ext[8];
    if (strstr(e->d_name, ".tmp."))
      ntmp++;
    else if (sscanf(e->d_name, "particles_%5d.%3s", &k, ext) == 2)
      nvtu += !strcmp(ext, "vtu"), ncsv += !strcmp(ext, "csv");
  }
  if (d) closedir(d);
  CHECK(ntmp == 0, "no temporary files left (%d)", ntmp);
  CHECK(access(in_dir(".hvsph.lock"), F_OK) != 0, "no lock file left (.hvsph.lock)");
  CHECK(nvtu == rows && ncsv == rows, "%d .vtu and %d .csv snapshots, one per summary row (%d)",
        nvtu, ncsv, rows);

  /* run.pvd: lists the snapshots in order, the last at the final time */
  char *pvd = test_slurp(in_dir("run.pvd"), NULL);
  int nds = 0, order_ok = 1;
  double tlast = -1;
  for (const char *p = pvd ? strstr(pvd, "<DataSet ") : NULL; p; p = strstr(p + 1, "<DataSet ")) {
    char want[64];
    snprintf(want, sizeof want, "file=\"particles_%05d.vtu\"", nds);
    const char *eol = strchr(p, '\n');
    const char *f = strstr(p, want);
    if (!f || (eol && f > eol)) order_ok = 0;
    tlast = strtod(strstr(p, "timestep=\"") + 10, NULL);
    nds++;
  }
  CHECK(pvd && strstr(pvd, "</VTKFile>") && nds == rows && order_ok,
        "run.pvd is complete and lists particles_00000..%05d.vtu in order (%d entries)", rows - 1,
        nds);
  CHECK(tlast == t, "run.pvd's last timestep %.17g s is the last summary time", tlast);
  free(pvd);

  /* the last snapshot, both forms */
  char name[64];
  snprintf(name, sizeof name, "particles_%05d.vtu", rows - 1);
  double vt = -1;
  long vstep = -1, np = -1;
  int vok = vtu_complete(in_dir(name), &vt, &vstep, &np);
  CHECK(vok && vt == t && vstep == step && np == NPART,
        "last .vtu complete, TIME %.17g s, STEP %ld, %ld points (want %.17g, %ld, %d)", vt, vstep,
        np, t, step, NPART);
  snprintf(name, sizeof name, "particles_%05d.csv", rows - 1);
  struct particles p;
  particles_init(&p);
  struct hv_error err;
  double ct = -1;
  int cok = !io_read_particles_csv(in_dir(name), &p, &ct, &err);
  CHECK(cok && p.n == NPART && ct == t,
        "last .csv reads back: %zu particles at t = %.17g s "
        "(want %d at %.17g)%s%s",
        p.n, ct, NPART, t, cok ? "" : ": ", cok ? "" : err.msg);
  particles_free(&p);
  static const int sigs[] = {SIGTERM, SIGHUP, SIGUSR1, SIGUSR2, SIGXCPU};
  static const char *const names[] = {"SIGTERM", "SIGHUP", "SIGUSR1", "SIGUSR2", "SIGXCPU"};
  for (int k = 0; k < 5; k++) stopped_by(casefile, sigs[k], names[k]);
  on_terminal(casefile);
  return test_finish();
}
