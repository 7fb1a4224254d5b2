/* afile.h — files written whole or not at all, and output folders.
 *
 * An output file is written into a temporary file in the same folder,
 * "<dir>/.<base>.tmp.<pid>", and renamed over the target only after every
 * byte has reached the disk (fflush, error check, fsync, fclose, rename).
 * A reader (ParaView, a plotting script, a restart) therefore sees either the
 * previous complete file or the new complete file, never a torn one; a full
 * disk or a killed run leaves the previous file of that name untouched.
 *
 * Errors: write failures carry code HV_EXIT_RUN and a message naming the
 * target file and strerror(errno); io_mkdir_p failures carry HV_EXIT_INPUT
 * (an unwritable output folder is a problem with the input, found at start).
 *
 * Typical use:
 *   struct afile af;
 *   if (afile_open(&af, path, err)) return -1;
 *   if (afile_printf(&af, err, "...") || afile_write(&af, buf, n, err)) {
 *     afile_abort(&af); return -1;
 *   }
 *   return afile_commit(&af, err);
 */
#ifndef HV_AFILE_H
#define HV_AFILE_H

#include <stddef.h>
#include <stdio.h>

#include "core/error.h"

struct afile {
  FILE *f;           /* the temporary file, open for writing; NULL once closed */
  char path[4096];   /* the target */
  char tmp[4096];    /* the temporary file; "" once removed or renamed */
};

/* Creates "<dir>/.<base>.tmp.<pid>" next to `path` and opens it for binary writing.
 * On failure af->f is NULL (afile_abort is then a harmless no-op). */
int afile_open(struct afile *af, const char *path, struct hv_error *err);
/* fflush + ferror check + fsync + fclose + rename over the target. On failure
 * the temporary file is removed, the target untouched, and err says why. */
int afile_commit(struct afile *af, struct hv_error *err);
/* Closes and removes the temporary file; the target is untouched. Safe to call twice. */
void afile_abort(struct afile *af);

/* Checked writes into af->f. On failure they set err (naming the target and
 * strerror) and return -1; the caller then calls afile_abort. */
int afile_write(struct afile *af, const void *buf, size_t len, struct hv_error *err);
int afile_printf(struct afile *af, struct hv_error *err, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Removes the temporary files ".<base>.tmp.<pid>" in dir left by writers that no
 * longer run (a killed run's unfinished file); returns how many. */
int afile_remove_stale(const char *dir);

/* Like `mkdir -p`: creates `dir` and any missing parents (mode 0777 & ~umask).
 * An existing folder is fine; an existing non-folder is an error. */
int io_mkdir_p(const char *dir, struct hv_error *err);

#endif
