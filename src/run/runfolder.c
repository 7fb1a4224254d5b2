/* runfolder.c — see runfolder.h. */
#include "run/runfolder.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <time.h>
#include <unistd.h>

#include "version.h"

void runfolder_lock_init(struct runfolder_lock *l)
{
  l->fd = -1;
  l->locked = 0;
  l->path[0] = '\0';
}

/* The holder as its lock file names it: "process 1234 on host (hvsph run, started
 * 2026-12-07T18:30:00Z)"; "" when the file says nothing (a holder that is starting). */
static void holder_of(int fd, char *out, size_t len)
{
  char buf[1024], pid[32] = "", host[256] = "", started[64] = "", cmd[128] = "";
  const ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
  out[0] = '\0';
  if (n <= 0) return;
  buf[n] = '\0';
  for (char *line = buf; line && *line;) {
    char *next = strchr(line, '\n');
    if (next) *next++ = '\0';
    sscanf(line, "pid: %31s", pid);
    sscanf(line, "host: %255s", host);
    sscanf(line, "started: %63s", started);
    if (!strncmp(line, "command: ", 9)) snprintf(cmd, sizeof cmd, "%s", line + 9);
    line = next;
  }
  if (pid[0])
    snprintf(out, len, "process %s on %s (%s, started %s)", pid, host[0] ? host : "?",
             cmd[0] ? cmd : "hvsph", started[0] ? started : "?");
}

int runfolder_lock(struct runfolder_lock *l, const char *dir, const char *what, int quiet,
                   struct hv_error *err)
{
  runfolder_lock_init(l);
  if ((size_t)snprintf(l->path, sizeof l->path, "%s/%s", dir, RUNFOLDER_LOCK) >= sizeof l->path)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: folder name too long", dir);
  /* a holder that ends between our open and our lock has removed the file we opened:
     we then hold the lock of a file no longer in the folder, and try again */
  for (int attempt = 0; attempt < 20; attempt++) {
    /* not through a symbolic link, and only a regular file: the holder truncates and
       writes it */
    const int fd = open(l->path, O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0666);
    struct stat a, b;
    if (fd < 0)
      return hv_error_set(err, HV_EXIT_INPUT, "cannot create the lock file %s: %s", l->path,
                          strerror(errno));
    if (fstat(fd, &a) || !S_ISREG(a.st_mode)) {
      close(fd);
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s is not a regular file: remove it (it is "
                          "hvsph's lock file)",
                          l->path);
    }
    struct flock fl = {.l_type = F_WRLCK, .l_whence = SEEK_SET, .l_start = 0, .l_len = 0};
    if (fcntl(fd, F_SETLK, &fl)) {
      const int e = errno;
      if (e == EACCES || e == EAGAIN) {
        char who[512];
        holder_of(fd, who, sizeof who);
        close(fd);
        return hv_error_set(err, HV_EXIT_INPUT,
                            "%s is in use by another hvsph %s (lock file "
                            "%s): one process at a time writes a run folder; wait for it to "
                            "end, or stop it (Ctrl-C, or kill PID: it writes its state and "
                            "a checkpoint), then try again",
                            dir, who[0] ? who : "process (it is just starting)", l->path);
      }
      /* a file system without record locks: going on unlocked beats refusing to run */
      hv_warn("cannot lock %s (%s): nothing keeps a second hvsph from writing %s at the "
              "same time",
              l->path, strerror(e), dir);
      l->fd = fd;
      return 0;
    }
    if (stat(l->path, &b) || a.st_dev != b.st_dev || a.st_ino != b.st_ino) {
      close(fd); /* removed (or replaced) by a holder that just ended: again */
      continue;
    }
    char who[512];
    holder_of(fd, who, sizeof who);
    if (who[0] && !quiet)
      hv_info("%s: took over the lock left by hvsph %s, which ended without releasing it "
              "(killed, or its machine went down): the folder holds what it had written by "
              "then",
              dir, who);
    struct utsname u;
    char started[32];
    const time_t now = time(NULL);
    struct tm tm;
    gmtime_r(&now, &tm);
    strftime(started, sizeof started, "%Y-%m-%dT%H:%M:%SZ", &tm);
    char text[1024];
    const int n =
        snprintf(text, sizeof text,
                 "pid: %ld\nhost: %s\nstarted: %s\ncommand: hvsph "
                 "%s\nversion: %s\n",
                 (long)getpid(), uname(&u) >= 0 ? u.nodename : "?", started, what, HVSPH_VERSION);
    /* the content only names the holder for others' messages: a failure to write it
       leaves the lock as good */
    if (ftruncate(fd, 0) == 0 && pwrite(fd, text, (size_t)n, 0) != n) {}
    l->fd = fd;
    l->locked = 1;
    return 0;
  }
  return hv_error_set(err, HV_EXIT_INPUT,
                      "%s: the lock file %s keeps changing: another hvsph "
                      "is starting and ending there",
                      dir, l->path);
}

void runfolder_unlock(struct runfolder_lock *l)
{
  if (l->fd < 0) return;
  if (l->locked) unlink(l->path); /* while still held: see runfolder_lock's retry */
  close(l->fd);
  runfolder_lock_init(l);
}

/* name is PREFIX, five or more digits, SUFFIX */
static int numbered(const char *name, const char *prefix, const char *suffix)
{
  const size_t lp = strlen(prefix), ls = strlen(suffix), n = strlen(name);
  if (n < lp + 5 + ls || strncmp(name, prefix, lp) || strcmp(name + n - ls, suffix)) return 0;
  for (size_t k = lp; k < n - ls; k++)
    if (name[k] < '0' || name[k] > '9') return 0;
  return 1;
}

static const char *const single_files[] = {"checkpoint.hvc",   "summary.csv",
                                           "measurements.csv", "run.pvd",
                                           "run_segments.csv", "used_parameters.yaml"};
#define NSINGLE ((int)(sizeof single_files / sizeof single_files[0]))

int runfolder_is_run_file(const char *name)
{
  for (int k = 0; k < NSINGLE; k++)
    if (!strcmp(name, single_files[k])) return 1;
  return numbered(name, "particles_", ".vtu") || numbered(name, "particles_", ".csv") ||
         numbered(name, "fragments_", ".csv");
}

int runfolder_earlier_run(const char *dir, char *what, size_t len)
{
  what[0] = '\0';
  DIR *d = opendir(dir);
  if (!d) return 0;
  int total = 0, snaps = 0, frags = 0, has[NSINGLE] = {0};
  struct dirent *e;
  while ((e = readdir(d))) {
    if (!runfolder_is_run_file(e->d_name)) continue;
    total++;
    if (!strncmp(e->d_name, "particles_", 10))
      snaps++;
    else if (!strncmp(e->d_name, "fragments_", 10))
      frags++;
    for (int k = 0; k < NSINGLE; k++) has[k] |= !strcmp(e->d_name, single_files[k]);
  }
  closedir(d);
  size_t n = 0; /* in a fixed order, the checkpoint first */
  for (int k = 0; k < NSINGLE; k++)
    if (has[k] && n < len)
      n += (size_t)snprintf(what + n, len - n, "%s%s", n ? ", " : "", single_files[k]);
  if (snaps && n < len)
    n += (size_t)snprintf(what + n, len - n, "%s%d particle snapshot file%s", n ? ", " : "", snaps,
                          snaps == 1 ? "" : "s");
  if (frags && n < len)
    snprintf(what + n, len - n, "%s%d fragment file%s", n ? ", " : "", frags,
             frags == 1 ? "" : "s");
  return total;
}

int runfolder_remove_run(const char *dir, struct hv_error *err)
{
  char path[4400];
  int n = 0;
  /* the checkpoint first: stopped half-way, the folder must not offer a restart of a
     run whose outputs are partly gone */
  snprintf(path, sizeof path, "%s/checkpoint.hvc", dir);
  if (remove(path) == 0)
    n++;
  else if (errno != ENOENT)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: cannot remove this file of the earlier run "
                        "(--overwrite): %s",
                        path, strerror(errno));
  DIR *d = opendir(dir);
  if (!d) return n;
  struct dirent *e;
  while ((e = readdir(d))) {
    if (!runfolder_is_run_file(e->d_name)) continue;
    snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
    if (remove(path) && errno != ENOENT) {
      const int en = errno;
      closedir(d);
      return hv_error_set(err, HV_EXIT_INPUT,
                          "%s: cannot remove this file of the earlier "
                          "run (--overwrite): %s",
                          path, strerror(en));
    }
    n++;
  }
  closedir(d);
  return n;
}
