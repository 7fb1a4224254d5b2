/* checkpoint.h — a file of named binary records, for checkpoint/restart.
 *
 * Layout (native byte order; the header's byte-order mark refuses a file from a
 * machine of the other order):
 *   header   "HVSPHCKP" (8 bytes), uint32 format version (1), uint32 0x01020304
 *   records  each: char name[56] (NUL-padded), uint32 type, uint32 0,
 *            uint64 count, then count elements of the type
 *   end      a record named "end" with count 0
 *   crc      uint32 CRC-32 (zlib) of every byte before it
 * The writer goes through atomic_file (temporary file, fsync, rename), so the previous
 * checkpoint of that name stays intact until the new one is complete. The reader
 * checks the CRC over the whole file when it opens it, keeps an index of the
 * records, and reads a record's data only when asked; a record asked for with the
 * wrong type or length, or missing, is an error that names the file and the record.
 * What the records hold is the caller's business (run/restart.c: a simulation).
 */
#ifndef HV_CHECKPOINT_H
#define HV_CHECKPOINT_H

#include <stddef.h>
#include <stdint.h>

#include "core/error.h"
#include "io/atomic_file.h"

enum ckpt_type { CKPT_BYTES = 1, CKPT_I32 = 2, CKPT_I64 = 3, CKPT_F64 = 4 };

#define CKPT_NAME_LEN 56

struct ckpt_writer {
  struct atomic_file af;
  uint32_t crc;
};

/* Opens path (through atomic_file) and writes the header. */
int ckpt_write_open(struct ckpt_writer *w, const char *path, struct hv_error *err);
/* Appends one record of `count` elements of `type` from data (NULL when count is 0). */
int ckpt_put(struct ckpt_writer *w, const char *name, enum ckpt_type type, size_t count,
             const void *data, struct hv_error *err);
/* Appends a record made of several arrays of the same type, one after the other
 * (e.g. the three components of a vector field): `count` elements each. */
int ckpt_put_parts(struct ckpt_writer *w, const char *name, enum ckpt_type type, size_t count,
                   const void *const *parts, int nparts, struct hv_error *err);
/* Writes the end record and the CRC, and renames the file into place. */
int ckpt_write_commit(struct ckpt_writer *w, struct hv_error *err);
/* Drops the unfinished file; the previous one of that name is untouched. */
void ckpt_write_abort(struct ckpt_writer *w);

struct ckpt_record {
  char name[CKPT_NAME_LEN + 1];
  enum ckpt_type type;
  uint64_t count;
  long long offset; /* of the data in the file */
};

struct ckpt_file {
  char path[4096];
  void *f; /* FILE * */
  struct ckpt_record *rec;
  int nrec;
};

/* Opens and checks a checkpoint (header, record structure, CRC). Errors carry
 * HV_EXIT_INPUT and name the file. */
int ckpt_open(struct ckpt_file *c, const char *path, struct hv_error *err);
void ckpt_close(struct ckpt_file *c);
/* The record of that name, or NULL. */
const struct ckpt_record *ckpt_find(const struct ckpt_file *c, const char *name);
/* Reads record `name`, which must have `type` and exactly `count` elements, into dst. */
int ckpt_get(struct ckpt_file *c, const char *name, enum ckpt_type type, size_t count, void *dst,
             struct hv_error *err);
/* Same for a record written by ckpt_put_parts: count elements into each part. */
int ckpt_get_parts(struct ckpt_file *c, const char *name, enum ckpt_type type, size_t count,
                   void *const *parts, int nparts, struct hv_error *err);
/* Reads a record of any length of `type` into a new buffer (*count elements; for
 * CKPT_BYTES a NUL is added after the data). The caller frees *out. */
int ckpt_get_alloc(struct ckpt_file *c, const char *name, enum ckpt_type type, void **out,
                   size_t *count, struct hv_error *err);

#endif
