/* infile.c — see infile.h. */
#include "core/infile.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* "a directory", "a FIFO"... for a file that is not regular. */
static const char *kind_of(mode_t m)
{
  return S_ISDIR(m)    ? "a directory"
         : S_ISFIFO(m) ? "a FIFO (named pipe)"
         : S_ISCHR(m)  ? "a character device"
         : S_ISBLK(m)  ? "a block device"
         : S_ISSOCK(m) ? "a socket"
                       : "not a regular file";
}

/* Refuses st unless it is a regular file within max_bytes. */
static int check_stat(const struct stat *st, const char *path, const char *what,
                      long long max_bytes, struct hv_error *err)
{
  if (!S_ISREG(st->st_mode))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s%s'%s' is %s: hvsph reads its input only from "
                        "regular files (a FIFO would wait for a writer for ever, a device may "
                        "never end)",
                        what, *what ? " " : "", path, kind_of(st->st_mode));
  if (max_bytes > 0 && (long long)st->st_size > max_bytes)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s%s'%s' is %lld bytes, more than the %lld "
                        "(%g MiB) hvsph reads%s%s: is it the right file?",
                        what, *what ? " " : "", path, (long long)st->st_size, max_bytes,
                        (double)max_bytes / 1048576.0, *what ? " as a " : "", what);
  return 0;
}

/* "cannot open case file 'x': reason" (or "cannot open 'x': ..." without a what). */
static FILE *open_failed(const char *path, const char *what, int e, struct hv_error *err)
{
  hv_error_set(err, HV_EXIT_INPUT, "cannot open %s%s'%s': %s", what, *what ? " " : "", path,
               strerror(e));
  return NULL;
}

FILE *hv_open_input(const char *path, const char *what, long long max_bytes, long long *size,
                    struct hv_error *err)
{
  if (!what) what = "";
  struct stat st;
  /* stat first: a path that is no regular file is not even opened (opening some
     devices has effects of its own) */
  if (stat(path, &st)) return open_failed(path, what, errno, err);
  if (check_stat(&st, path, what, max_bytes, err)) return NULL;
  /* O_NONBLOCK: had the path become a FIFO since the stat, open() would not wait */
  const int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return open_failed(path, what, errno, err);
  const int flags = fcntl(fd, F_GETFL);
  if (fstat(fd, &st) || flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK)) {
    const int e = errno;
    close(fd);
    return open_failed(path, what, e, err);
  }
  if (check_stat(&st, path, what, max_bytes, err)) {
    close(fd);
    return NULL;
  }
  FILE *f = fdopen(fd, "rb");
  if (!f) {
    const int e = errno;
    close(fd);
    return open_failed(path, what, e, err);
  }
  if (size) *size = (long long)st.st_size;
  return f;
}
