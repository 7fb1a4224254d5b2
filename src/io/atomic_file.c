/* atomic_file.c — files written whole or not at all (see atomic_file.h), and mkdir -p. */
#include "io/atomic_file.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

/* Splits `path` into its folder ("." when none) and base name. Returns -1 when
 * the path is empty, ends in '/', or does not fit. */
static int split_path(const char *path, char *dir, size_t dlen, char *base, size_t blen)
{
  const char *slash = strrchr(path, '/');
  const char *b = slash ? slash + 1 : path;
  if (!*b) return -1;
  if ((size_t)snprintf(base, blen, "%s", b) >= blen) return -1;
  if (!slash) return (size_t)snprintf(dir, dlen, ".") >= dlen ? -1 : 0;
  size_t dl = (size_t)(slash - path);
  if (dl == 0) dl = 1; /* "/name": the folder is "/" */
  if (dl >= dlen) return -1;
  memcpy(dir, path, dl);
  dir[dl] = '\0';
  return 0;
}

int atomic_file_open(struct atomic_file *af, const char *path, struct hv_error *err)
{
  char dir[4096], base[1024];
  af->f = NULL;
  af->tmp[0] = '\0';
  af->path[0] = '\0';
  if (!path || (size_t)snprintf(af->path, sizeof af->path, "%s", path) >= sizeof af->path ||
      split_path(path, dir, sizeof dir, base, sizeof base))
    return hv_error_set(err, HV_EXIT_RUN, "cannot write '%s': not a usable file name",
                        path ? path : "(null)");
  const char *sep = strcmp(dir, "/") == 0 ? "" : "/";
  if ((size_t)snprintf(af->tmp, sizeof af->tmp, "%s%s.%s.tmp.%ld", dir, sep, base,
                       (long)getpid()) >= sizeof af->tmp) {
    af->tmp[0] = '\0';
    return hv_error_set(err, HV_EXIT_RUN, "cannot write '%s': path too long", path);
  }
  af->f = fopen(af->tmp, "wb");
  if (!af->f) {
    int e = errno;
    hv_error_set(err, HV_EXIT_RUN, "cannot create '%s' (temporary file '%s'): %s", path, af->tmp,
                 strerror(e));
    af->tmp[0] = '\0';
    return -1;
  }
  return 0;
}

/* The errno behind a stream's error flag. When a large fwrite fails, glibc may
 * leave the buffer empty, so fflush() succeeds and errno is lost; the file is
 * being discarded anyway, so one probe byte recovers the cause (e.g. ENOSPC). */
static int stream_errno(FILE *f)
{
  errno = 0;
  if (fflush(f) != 0 && errno) return errno;
  if (!ferror(f)) return 0;
  clearerr(f);
  errno = 0;
  if ((fputc('\n', f) == EOF || fflush(f) != 0) && errno) return errno;
  return EIO;
}

static int commit_fail(struct atomic_file *af, struct hv_error *err, const char *what, int e)
{
  hv_error_set(err, HV_EXIT_RUN, "cannot write '%s' (%s): %s", af->path, what, strerror(e));
  atomic_file_abort(af);
  return -1;
}

int atomic_file_commit(struct atomic_file *af, struct hv_error *err)
{
  if (!af->f)
    return hv_error_set(err, HV_EXIT_RUN, "cannot write '%s': file is not open", af->path);
  int e = stream_errno(af->f);
  if (e) return commit_fail(af, err, "write", e);
  /* EINVAL: a special file that cannot be synchronised; nothing was lost. */
  if (fsync(fileno(af->f)) != 0 && errno != EINVAL) return commit_fail(af, err, "fsync", errno);
  FILE *f = af->f;
  af->f = NULL;
  if (fclose(f) != 0) return commit_fail(af, err, "close", errno);
  if (rename(af->tmp, af->path) != 0) {
    e = errno;
    hv_error_set(err, HV_EXIT_RUN, "cannot write '%s' (rename from '%s'): %s", af->path, af->tmp,
                 strerror(e));
    atomic_file_abort(af);
    return -1;
  }
  af->tmp[0] = '\0';
  return 0;
}

void atomic_file_abort(struct atomic_file *af)
{
  if (af->f) {
    (void)fclose(af->f); /* the contents are being thrown away; a close error changes nothing */
    af->f = NULL;
  }
  if (af->tmp[0]) {
    if (unlink(af->tmp) != 0 && errno != ENOENT)
      hv_warn("cannot remove temporary file '%s': %s", af->tmp, strerror(errno));
    af->tmp[0] = '\0';
  }
}

int atomic_file_write(struct atomic_file *af, const void *buf, size_t len, struct hv_error *err)
{
  if (len == 0) return 0;
  errno = 0;
  if (fwrite(buf, 1, len, af->f) != len) {
    int e = errno ? errno : EIO;
    return hv_error_set(err, HV_EXIT_RUN, "cannot write '%s': %s", af->path, strerror(e));
  }
  return 0;
}

int atomic_file_printf(struct atomic_file *af, struct hv_error *err, const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  errno = 0;
  int r = vfprintf(af->f, fmt, ap);
  int e = errno ? errno : EIO;
  va_end(ap);
  if (r < 0) return hv_error_set(err, HV_EXIT_RUN, "cannot write '%s': %s", af->path, strerror(e));
  return 0;
}

/* mkdir for one level; an existing folder is fine. */
static int mkdir_one(const char *d, const char *whole, struct hv_error *err)
{
  struct stat st;
  if (mkdir(d, 0777) == 0) return 0;
  int e = errno;
  if (e == EEXIST && stat(d, &st) == 0 && S_ISDIR(st.st_mode)) return 0;
  const char *why = e == EEXIST ? "exists and is not a folder" : strerror(e);
  if (strcmp(d, whole) == 0)
    return hv_error_set(err, HV_EXIT_INPUT, "cannot create folder '%s': %s", whole, why);
  return hv_error_set(err, HV_EXIT_INPUT, "cannot create folder '%s' (at '%s'): %s", whole, d, why);
}

int io_mkdir_p(const char *dir, struct hv_error *err)
{
  char buf[4096];
  if (!dir || !*dir) return hv_error_set(err, HV_EXIT_INPUT, "cannot create folder: empty name");
  size_t len = (size_t)snprintf(buf, sizeof buf, "%s", dir);
  if (len >= sizeof buf)
    return hv_error_set(err, HV_EXIT_INPUT, "cannot create folder '%s': name too long", dir);
  while (len > 1 && buf[len - 1] == '/') buf[--len] = '\0';
  for (char *q = buf + 1; *q; q++) {
    if (*q != '/' || q[-1] == '/') continue;
    *q = '\0';
    int r = mkdir_one(buf, dir, err);
    *q = '/';
    if (r) return -1;
  }
  return mkdir_one(buf, dir, err);
}

int atomic_file_remove_stale(const char *dir)
{
  DIR *d = opendir(dir);
  if (!d) return 0;
  int removed = 0;
  struct dirent *e;
  char path[4400];
  while ((e = readdir(d))) {
    /* ".<base>.tmp.<pid>" */
    const char *t = e->d_name[0] == '.' ? strstr(e->d_name, ".tmp.") : NULL;
    if (!t) continue;
    char *end;
    long pid = strtol(t + 5, &end, 10);
    if (*end || pid <= 0 || pid == (long)getpid()) continue;
    if (kill((pid_t)pid, 0) == 0 || errno != ESRCH) continue; /* that writer may live */
    if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, e->d_name) < sizeof path &&
        unlink(path) == 0)
      removed++;
  }
  closedir(d);
  return removed;
}
