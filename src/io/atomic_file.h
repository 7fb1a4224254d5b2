/* atomic_file.h — files written whole or not at all, and output folders.
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
 *   struct atomic_file af;
 *   if (atomic_file_open(&af, path, err)) return -1;
 *   if (atomic_file_printf(&af, err, "...") || atomic_file_write(&af, buf, n, err)) {
 *     atomic_file_abort(&af); return -1;
 *   }
 *   return atomic_file_commit(&af, err);
 */
#ifndef HV_ATOMIC_FILE_H
#define HV_ATOMIC_FILE_H

#include <stddef.h>
#include <stdio.h>

#include "core/error.h"

struct atomic_file {
  FILE *f;         /* the temporary file, open for writing; NULL once closed */
  char path[4096]; /* the target */
  char tmp[4096];  /* the temporary file; "" once removed or renamed */
};

/* Creates "<dir>/.<base>.tmp.<pid>" next to `path` and opens it for binary writing.
 * On failure af->f is NULL (atomic_file_abort is then a harmless no-op). */
int atomic_file_open(struct atomic_file *af, const char *path, struct hv_error *err);
/* fflush + ferror check + fsync + fclose + rename over the target. On failure
 * the temporary file is removed, the target untouched, and err says why. */
int atomic_file_commit(struct atomic_file *af, struct hv_error *err);
/* Closes and removes the temporary file; the target is untouched. Safe to call twice. */
void atomic_file_abort(struct atomic_file *af);

/* Checked writes into af->f. On failure they set err (naming the target and
 * strerror) and return -1; the caller then calls atomic_file_abort. */
int atomic_file_write(struct atomic_file *af, const void *buf, size_t len, struct hv_error *err);
int atomic_file_printf(struct atomic_file *af, struct hv_error *err, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* Removes the temporary files ".<base>.tmp.<pid>" in dir left by writers that no
 * longer run (a killed run's unfinished file); returns how many. */
int atomic_file_remove_stale(const char *dir);

/* Like `mkdir -p`: creates `dir` and any missing parents (mode 0777 & ~umask).
 * An existing folder is fine; an existing non-folder is an error. */
int io_mkdir_p(const char *dir, struct hv_error *err);

#endif
