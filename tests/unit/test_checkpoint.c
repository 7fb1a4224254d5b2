/* test_checkpoint.c — the checkpoint file format (io/checkpoint.h).
 *
 * Round trip of records of every type (an empty one, a multi-part one, 10⁶ doubles
 * that cross the reader's 4 MiB chunks); asking for a record with the wrong type,
 * the wrong length or a name that is not there; and files that must be refused with
 * a message naming the file: one byte changed anywhere (header, record header, data,
 * CRC), truncated at several lengths (down to empty), another byte order and an
 * unknown format version (with a valid CRC), a file written on a machine of the other byte
 * order (its CRC in that order too), a file that is no checkpoint at all, a missing file.
 * A failed write (its folder missing) leaves no file.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "io/checkpoint.h"
#include "testlib.h"

#define NBIG 1000000

static int write_sample(const char *path, const double *big)
{
  struct hv_error err;
  struct ckpt_writer w;
  const int32_t i32[3] = {-7, 0, 2147483647};
  const int64_t i64[2] = {-9000000000LL, 42};
  const double a[2] = {1.5, -0.0}, b[2] = {NAN, 1e-300};
  const void *parts[2] = {a, b};
  if (ckpt_write_open(&w, path, &err)) return -1;
  if (ckpt_put(&w, "text", CKPT_BYTES, 5, "hello", &err) ||
      ckpt_put(&w, "empty", CKPT_F64, 0, NULL, &err) ||
      ckpt_put(&w, "i32", CKPT_I32, 3, i32, &err) || ckpt_put(&w, "i64", CKPT_I64, 2, i64, &err) ||
      ckpt_put_parts(&w, "vec", CKPT_F64, 2, parts, 2, &err) ||
      ckpt_put(&w, "big", CKPT_F64, NBIG, big, &err))
    return -1;
  return ckpt_write_commit(&w, &err);
}

/* Opening must fail with a message that names the file and contains `word`. */
static void refused(const char *path, const char *word, const char *what)
{
  struct ckpt_file c;
  struct hv_error err;
  hv_error_clear(&err);
  int rc = ckpt_open(&c, path, &err);
  CHECK(rc != 0 && err.code == HV_EXIT_INPUT && strstr(err.msg, path) && strstr(err.msg, word),
        "%s: refused (%s)", what, rc ? err.msg : "opened!");
  if (rc == 0) ckpt_close(&c);
}

static void write_bytes(const char *path, const unsigned char *b, size_t n)
{
  FILE *f = fopen(path, "wb");
  if (f) {
    fwrite(b, 1, n, f);
    fclose(f);
  }
}

int main(void)
{
  char path[4200], tmp[4200];
  snprintf(path, sizeof path, "%s/sample.hvc", test_tmpdir());
  snprintf(tmp, sizeof tmp, "%s/damaged.hvc", test_tmpdir());
  double *big = malloc(NBIG * sizeof *big), *big2 = malloc(NBIG * sizeof *big2);
  for (int i = 0; i < NBIG; i++) big[i] = sin(0.001 * i) * 1e6 + i;
  CHECK(write_sample(path, big) == 0, "wrote the sample checkpoint");

  struct ckpt_file c;
  struct hv_error err;
  CHECK(ckpt_open(&c, path, &err) == 0, "opened it (%s)", err.msg);
  CHECK(c.nrec == 6, "6 records indexed (got %d)", c.nrec);
  char text[6] = {0};
  int32_t i32[3];
  int64_t i64[2];
  double a[2], b[2];
  void *parts[2] = {a, b};
  CHECK(ckpt_get(&c, "text", CKPT_BYTES, 5, text, &err) == 0 && !strcmp(text, "hello"),
        "bytes read back: '%s'", text);
  CHECK(ckpt_get(&c, "i32", CKPT_I32, 3, i32, &err) == 0 && i32[0] == -7 && i32[1] == 0 &&
        i32[2] == 2147483647, "int32 read back");
  CHECK(ckpt_get(&c, "i64", CKPT_I64, 2, i64, &err) == 0 && i64[0] == -9000000000LL &&
        i64[1] == 42, "int64 read back");
  CHECK(ckpt_get_parts(&c, "vec", CKPT_F64, 2, parts, 2, &err) == 0 && a[0] == 1.5 &&
        a[1] == 0.0 && signbit(a[1]) && isnan(b[0]) && b[1] == 1e-300,
        "two parts read back bit for bit (-0, NaN, 1e-300)");
  CHECK(ckpt_get(&c, "big", CKPT_F64, NBIG, big2, &err) == 0 &&
        !memcmp(big, big2, NBIG * sizeof *big), "10^6 doubles read back bit for bit");
  void *e;
  size_t n;
  CHECK(ckpt_get_alloc(&c, "empty", CKPT_F64, &e, &n, &err) == 0 && n == 0, "empty record");
  free(e);
  char *s;
  CHECK(ckpt_get_alloc(&c, "text", CKPT_BYTES, (void **)&s, &n, &err) == 0 && n == 5 &&
        !strcmp(s, "hello"), "bytes allocated and NUL-terminated");
  free(s);
  CHECK(ckpt_get(&c, "i32", CKPT_I64, 3, i64, &err) != 0 && strstr(err.msg, "'i32'") &&
        strstr(err.msg, "int32") && strstr(err.msg, path), "wrong type refused: %s", err.msg);
  CHECK(ckpt_get(&c, "i32", CKPT_I32, 2, i32, &err) != 0 && strstr(err.msg, "3 elements"),
        "wrong length refused: %s", err.msg);
  CHECK(ckpt_get(&c, "nothere", CKPT_I32, 1, i32, &err) != 0 && strstr(err.msg, "'nothere'"),
        "missing record refused: %s", err.msg);
  ckpt_close(&c);

  /* damaged files */
  size_t len;
  unsigned char *raw = (unsigned char *)test_slurp(path, &len);
  CHECK(raw && len > 8 * NBIG, "sample is %zu bytes", len);
  if (!raw) return test_finish();
  const size_t where[] = {0, 9, 20, 16 + 56, 200, len / 2, len - 5, len - 1};
  for (size_t k = 0; k < sizeof where / sizeof where[0]; k++) {
    raw[where[k]] ^= 0x10;
    write_bytes(tmp, raw, len);
    raw[where[k]] ^= 0x10;
    char what[64];
    snprintf(what, sizeof what, "one byte changed at offset %zu", where[k]);
    refused(tmp, "not a usable hvsph checkpoint", what);
  }
  const size_t cut[] = {0, 10, 100, len / 3, len - 4, len - 1};
  for (size_t k = 0; k < sizeof cut / sizeof cut[0]; k++) {
    write_bytes(tmp, raw, cut[k]);
    char what[64];
    snprintf(what, sizeof what, "truncated to %zu bytes", cut[k]);
    refused(tmp, "not a usable hvsph checkpoint", what);
  }
  refused("/nonexistent/x.hvc", "cannot open", "missing file");
  /* a consistent file (CRC recomputed) from another byte order or format version */
  for (int k = 0; k < 2; k++) {
    unsigned char *r2 = malloc(len);
    memcpy(r2, raw, len);
    if (k == 0) {   /* the byte-order mark reversed */
      for (int q = 0; q < 2; q++) {
        unsigned char t = r2[12 + q];
        r2[12 + q] = r2[15 - q];
        r2[15 - q] = t;
      }
    } else {
      r2[8] = 2;   /* format version 2 */
    }
    uint32_t crc = (uint32_t)crc32(crc32(0L, Z_NULL, 0), r2, (uInt)(len - 4));
    memcpy(r2 + len - 4, &crc, 4);
    write_bytes(tmp, r2, len);
    free(r2);
    refused(tmp, k == 0 ? "other byte order" : "format version",
            k == 0 ? "byte order reversed (CRC valid)" : "format version 2 (CRC valid)");
  }
  /* a checkpoint as a machine of the other byte order writes it: every number in its
     own order, the CRC too; refused as such, not as a damaged file */
  {
    unsigned char *r2 = malloc(len);
    memcpy(r2, raw, len);
    for (int f = 8; f < 16; f += 4)   /* the version and the byte-order mark */
      for (int q = 0; q < 2; q++) {
        unsigned char t = r2[f + q];
        r2[f + q] = r2[f + 3 - q];
        r2[f + 3 - q] = t;
      }
    const uint32_t crc = (uint32_t)crc32(crc32(0L, Z_NULL, 0), r2, (uInt)(len - 4));
    for (int q = 0; q < 4; q++) r2[len - 4 + q] = (unsigned char)(crc >> (24 - 8 * q));
    write_bytes(tmp, r2, len);
    free(r2);
    refused(tmp, "other byte order", "written on a machine of the other byte order");
  }
  /* a file that is not a checkpoint at all (long enough, no header) */
  {
    unsigned char junk[400];
    for (size_t q = 0; q < sizeof junk; q++) junk[q] = (unsigned char)("id,x,y,z\n1,0,0,0\n"[q % 17]);
    write_bytes(tmp, junk, sizeof junk);
    refused(tmp, "no HVSPHCKP header", "a text file");
  }
  free(raw);

  /* a failed write leaves nothing */
  struct ckpt_writer w;
  CHECK(ckpt_write_open(&w, "/nonexistent/dir/x.hvc", &err) != 0 && strstr(err.msg, "/nonexistent"),
        "write into a missing folder fails: %s", err.msg);
  free(big);
  free(big2);
  return test_finish();
}
