/* checkpoint.c — see checkpoint.h. */
#include "io/checkpoint.h"

#include "core/infile.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <zlib.h>

static const char MAGIC[8] = {'H', 'V', 'S', 'P', 'H', 'C', 'K', 'P'};
enum { FORMAT_VERSION = 1, BOM = 0x01020304, BOM_SWAPPED = 0x04030201 };
#define HEADER_BYTES        16
#define RECORD_HEADER_BYTES (CKPT_NAME_LEN + 16)

static size_t type_size(enum ckpt_type t)
{
  switch (t) {
  case CKPT_BYTES: return 1;
  case CKPT_I32: return 4;
  case CKPT_I64:
  case CKPT_F64: return 8;
  }
  return 0;
}

static const char *type_name(enum ckpt_type t)
{
  switch (t) {
  case CKPT_BYTES: return "bytes";
  case CKPT_I32: return "int32";
  case CKPT_I64: return "int64";
  case CKPT_F64: return "float64";
  }
  return "unknown";
}

static int wr(struct ckpt_writer *w, const void *buf, size_t len, struct hv_error *err)
{
  const unsigned char *b = buf;
  for (size_t done = 0; done < len;) { /* crc32_z would do; chunks keep uInt safe */
    size_t k = len - done > (1u << 30) ? (1u << 30) : len - done;
    w->crc = (uint32_t)crc32(w->crc, b + done, (uInt)k);
    done += k;
  }
  return atomic_file_write(&w->af, buf, len, err);
}

int ckpt_write_open(struct ckpt_writer *w, const char *path, struct hv_error *err)
{
  memset(w, 0, sizeof *w);
  w->crc = (uint32_t)crc32(0L, Z_NULL, 0);
  if (atomic_file_open(&w->af, path, err)) return -1;
  unsigned char h[HEADER_BYTES];
  const uint32_t v = FORMAT_VERSION, bom = BOM;
  memcpy(h, MAGIC, 8);
  memcpy(h + 8, &v, 4);
  memcpy(h + 12, &bom, 4);
  if (wr(w, h, sizeof h, err)) {
    atomic_file_abort(&w->af);
    return -1;
  }
  return 0;
}

static int put_header(struct ckpt_writer *w, const char *name, enum ckpt_type type, uint64_t count,
                      struct hv_error *err)
{
  unsigned char h[RECORD_HEADER_BYTES];
  memset(h, 0, sizeof h);
  const size_t len = strlen(name);
  if (len == 0 || len > CKPT_NAME_LEN) {
    atomic_file_abort(&w->af);
    return hv_error_set(err, HV_EXIT_RUN,
                        "%s: checkpoint record name '%s' is empty or longer "
                        "than %d characters",
                        w->af.path, name, CKPT_NAME_LEN);
  }
  memcpy(h, name, len);
  const uint32_t t = (uint32_t)type;
  memcpy(h + CKPT_NAME_LEN, &t, 4);
  memcpy(h + CKPT_NAME_LEN + 8, &count, 8);
  if (wr(w, h, sizeof h, err)) {
    atomic_file_abort(&w->af);
    return -1;
  }
  return 0;
}

int ckpt_put_parts(struct ckpt_writer *w, const char *name, enum ckpt_type type, size_t count,
                   const void *const *parts, int nparts, struct hv_error *err)
{
  if (put_header(w, name, type, (uint64_t)count * (uint64_t)nparts, err)) return -1;
  for (int k = 0; k < nparts; k++)
    if (count > 0 && wr(w, parts[k], count * type_size(type), err)) {
      atomic_file_abort(&w->af);
      return -1;
    }
  return 0;
}

int ckpt_put(struct ckpt_writer *w, const char *name, enum ckpt_type type, size_t count,
             const void *data, struct hv_error *err)
{
  return ckpt_put_parts(w, name, type, count, &data, 1, err);
}

int ckpt_write_commit(struct ckpt_writer *w, struct hv_error *err)
{
  if (put_header(w, "end", CKPT_BYTES, 0, err)) return -1;
  const uint32_t crc = w->crc;
  if (atomic_file_write(&w->af, &crc, 4, err)) {
    atomic_file_abort(&w->af);
    return -1;
  }
  return atomic_file_commit(&w->af, err);
}

void ckpt_write_abort(struct ckpt_writer *w) { atomic_file_abort(&w->af); }

/* ---- reading ---- */

static int bad(struct ckpt_file *c, struct hv_error *err, const char *what)
{
  hv_error_set(err, HV_EXIT_INPUT, "%s: not a usable hvsph checkpoint: %s", c->path, what);
  ckpt_close(c);
  return -1;
}

int ckpt_open(struct ckpt_file *c, const char *path, struct hv_error *err)
{
  memset(c, 0, sizeof *c);
  snprintf(c->path, sizeof c->path, "%s", path);
  /* a regular file only (a FIFO would block the open for ever); no bound on its size,
     which the particles set: every record's count is checked against it below */
  FILE *f = hv_open_input(path, "checkpoint", 0, NULL, err);
  if (!f) return -1;
  c->f = f;
  if (fseeko(f, 0, SEEK_END)) return bad(c, err, "cannot seek");
  const long long size = (long long)ftello(f);
  if (size < HEADER_BYTES + RECORD_HEADER_BYTES + 4) return bad(c, err, "too short");
  rewind(f);

  /* what the file is, before its CRC: a file that is no checkpoint, or one from a
     machine of the other byte order (whose CRC is stored in that order too), would
     otherwise be reported as damaged */
  unsigned char h[RECORD_HEADER_BYTES];
  uint32_t v, bom;
  if (fread(h, 1, HEADER_BYTES, f) != HEADER_BYTES || memcmp(h, MAGIC, 8))
    return bad(c, err, "no HVSPHCKP header");
  memcpy(&bom, h + 12, 4);
  if (bom == BOM_SWAPPED) return bad(c, err, "written on a machine of the other byte order");
  rewind(f);

  /* the CRC of everything before the last 4 bytes */
  uint32_t crc = (uint32_t)crc32(0L, Z_NULL, 0), stored;
  enum { CHUNK = 1 << 22 };
  unsigned char *buf = malloc(CHUNK);
  if (!buf) return bad(c, err, "out of memory");
  for (long long left = size - 4; left > 0;) {
    size_t k = left > CHUNK ? CHUNK : (size_t)left;
    if (fread(buf, 1, k, f) != k) {
      free(buf);
      return bad(c, err, "read error");
    }
    crc = (uint32_t)crc32(crc, buf, (uInt)k);
    left -= (long long)k;
  }
  free(buf);
  if (fread(&stored, 4, 1, f) != 1) return bad(c, err, "read error");
  if (crc != stored)
    return bad(c, err, "its checksum does not match its contents (a damaged or incomplete file)");

  rewind(f);
  if (fread(h, 1, HEADER_BYTES, f) != HEADER_BYTES || memcmp(h, MAGIC, 8))
    return bad(c, err, "no HVSPHCKP header");
  memcpy(&v, h + 8, 4);
  memcpy(&bom, h + 12, 4);
  if (bom != BOM) return bad(c, err, "written on a machine of the other byte order");
  if (v != FORMAT_VERSION) return bad(c, err, "format version not understood by this hvsph");
  long long pos = HEADER_BYTES;
  int cap = 0;
  for (;;) {
    if (pos + RECORD_HEADER_BYTES > size - 4 || fseeko(f, (off_t)pos, SEEK_SET) ||
        fread(h, 1, RECORD_HEADER_BYTES, f) != RECORD_HEADER_BYTES)
      return bad(c, err, "its records run past the end (no end record)");
    struct ckpt_record r;
    memset(&r, 0, sizeof r);
    memcpy(r.name, h, CKPT_NAME_LEN);
    uint32_t t;
    memcpy(&t, h + CKPT_NAME_LEN, 4);
    memcpy(&r.count, h + CKPT_NAME_LEN + 8, 8);
    r.type = (enum ckpt_type)t;
    r.offset = pos + RECORD_HEADER_BYTES;
    if (!type_size(r.type)) return bad(c, err, "a record of unknown type");
    if (!strcmp(r.name, "end")) {
      if (r.offset != size - 4) return bad(c, err, "data after the end record");
      break;
    }
    if (r.count > (uint64_t)(size - r.offset) / type_size(r.type))
      return bad(c, err, "a record longer than the file");
    if (c->nrec == cap) {
      cap = cap ? 2 * cap : 32;
      struct ckpt_record *nr = realloc(c->rec, (size_t)cap * sizeof *nr);
      if (!nr) return bad(c, err, "out of memory");
      c->rec = nr;
    }
    c->rec[c->nrec++] = r;
    pos = r.offset + (long long)(r.count * type_size(r.type));
  }
  return 0;
}

void ckpt_close(struct ckpt_file *c)
{
  if (c->f) fclose(c->f);
  free(c->rec);
  c->f = NULL;
  c->rec = NULL;
  c->nrec = 0;
}

const struct ckpt_record *ckpt_find(const struct ckpt_file *c, const char *name)
{
  for (int i = 0; i < c->nrec; i++)
    if (!strcmp(c->rec[i].name, name)) return &c->rec[i];
  return NULL;
}

static const struct ckpt_record *lookup(struct ckpt_file *c, const char *name, enum ckpt_type type,
                                        struct hv_error *err)
{
  const struct ckpt_record *r = ckpt_find(c, name);
  if (!r) {
    hv_error_set(err, HV_EXIT_INPUT, "%s: the checkpoint has no record '%s'", c->path, name);
    return NULL;
  }
  if (r->type != type) {
    hv_error_set(err, HV_EXIT_INPUT, "%s: checkpoint record '%s' holds %s, expected %s", c->path,
                 name, type_name(r->type), type_name(type));
    return NULL;
  }
  return r;
}

static int read_at(struct ckpt_file *c, const struct ckpt_record *r, long long offset, void *dst,
                   size_t bytes, struct hv_error *err)
{
  if (bytes == 0) return 0;
  if (fseeko(c->f, (off_t)(r->offset + offset), SEEK_SET) || fread(dst, 1, bytes, c->f) != bytes)
    return hv_error_set(err, HV_EXIT_INPUT, "%s: checkpoint record '%s': read error", c->path,
                        r->name);
  return 0;
}

int ckpt_get_parts(struct ckpt_file *c, const char *name, enum ckpt_type type, size_t count,
                   void *const *parts, int nparts, struct hv_error *err)
{
  const struct ckpt_record *r = lookup(c, name, type, err);
  if (!r) return -1;
  if (r->count != (uint64_t)count * (uint64_t)nparts)
    return hv_error_set(err, HV_EXIT_INPUT,
                        "%s: checkpoint record '%s' has %llu elements, "
                        "expected %llu",
                        c->path, name, (unsigned long long)r->count,
                        (unsigned long long)count * (unsigned long long)nparts);
  const size_t bytes = count * type_size(type);
  for (int k = 0; k < nparts; k++)
    if (read_at(c, r, (long long)(k * bytes), parts[k], bytes, err)) return -1;
  return 0;
}

int ckpt_get(struct ckpt_file *c, const char *name, enum ckpt_type type, size_t count, void *dst,
             struct hv_error *err)
{
  return ckpt_get_parts(c, name, type, count, &dst, 1, err);
}

int ckpt_get_alloc(struct ckpt_file *c, const char *name, enum ckpt_type type, void **out,
                   size_t *count, struct hv_error *err)
{
  *out = NULL;
  *count = 0;
  const struct ckpt_record *r = lookup(c, name, type, err);
  if (!r) return -1;
  const size_t bytes = (size_t)r->count * type_size(type);
  char *b = malloc(bytes + 1);
  if (!b)
    return hv_error_set(err, HV_EXIT_RUN, "%s: checkpoint record '%s': out of memory (%zu bytes)",
                        c->path, name, bytes);
  if (read_at(c, r, 0, b, bytes, err)) {
    free(b);
    return -1;
  }
  b[bytes] = 0;
  *out = b;
  *count = (size_t)r->count;
  return 0;
}
