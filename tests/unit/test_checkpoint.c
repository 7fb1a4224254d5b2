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
 *
 * Then the records of a run's checkpoint (run/restart.c), each altered with the CRC
 * recomputed, so that only the checks of the values can refuse them: `hvsph restart`
 * must exit 2 with one line naming the checkpoint and the record, and leave the run's
 * files as they were. Before those checks a row count of 10^8 ended in SIGSEGV, an
 * output index of 2^62 never ended, a particle count of 2^40 asked for 11.7 TB and a
 * NaN time went into run.pvd; each restart runs under `timeout -k 5 20` (SIGTERM only
 * asks hvsph to stop after the current step, and the endless loop was before the
 * first: the KILL 5 s later ends it), and the test under alarm, so that a regression
 * fails instead of hanging.
 */
#include <math.h>
#include <stdint.h>
#include <unistd.h>
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

/* ---------------------------------------------------------------- a run's records */

static const char *run_case =
    "name: ck\n"
    "materials:\n"
    "  gas: {eos: ideal-gas, gamma: 1.4}\n"
    "domain: {min: [0, 0, 0], max: [0.1, 0.05, 0.05],\n"
    "         boundary: {x: wall, y: periodic, z: periodic}}\n"
    "bodies:\n"
    "  - {name: slab, material: gas, shape: {type: box, min: [0, 0, 0], max: [0.1, 0.05, 0.05]},\n"
    "     spacing: 6.25 mm, density: 1.0, pressure: 1.0, velocity: [0.3, 0.1, -0.05]}\n"
    "time: {end: 0.01}\n"
    "output: {every: 0.005}\n";

/* One alteration: element `index` of record `rec` set to an int64 or a double. */
struct alteration {
  const char *rec;
  size_t index;
  int is_double;
  int64_t i;
  double d;
  const char *what;
};

/* Copies run folder `from` to `to` and alters its checkpoint as a says (the CRC
 * recomputed); 0 on success. */
static int altered_copy(const char *from, const char *to, const struct alteration *a)
{
  char cmd[9000], ck[4400];
  snprintf(cmd, sizeof cmd, "rm -rf '%s' && cp -r '%s' '%s'", to, from, to);
  if (test_run(cmd, NULL, 0)) return -1;
  snprintf(ck, sizeof ck, "%s/checkpoint.hvc", to);
  struct ckpt_file c;
  struct hv_error err;
  if (ckpt_open(&c, ck, &err)) return -1;
  const struct ckpt_record *r = ckpt_find(&c, a->rec);
  const long long off = r && a->index < r->count ? r->offset + (long long)(8 * a->index) : -1;
  const int type = r ? (int)r->type : 0;
  ckpt_close(&c);
  if (off < 0 || type != (a->is_double ? CKPT_F64 : CKPT_I64)) return -1;
  size_t len;
  unsigned char *raw = (unsigned char *)test_slurp(ck, &len);
  if (!raw) return -1;
  if (a->is_double)
    memcpy(raw + off, &a->d, 8);
  else
    memcpy(raw + off, &a->i, 8);
  const uint32_t crc = (uint32_t)crc32(crc32(0L, Z_NULL, 0), raw, (uInt)(len - 4));
  memcpy(raw + len - 4, &crc, 4);
  write_bytes(ck, raw, len);
  free(raw);
  return 0;
}

static void test_run_records(void)
{
  char base[4200], dir[4200], cmd[13000], out[8192];
  snprintf(base, sizeof base, "%s/run", test_tmpdir());
  char casefile[4200];
  snprintf(casefile, sizeof casefile, "%s/ck.yaml", test_tmpdir());
  write_bytes(casefile, (const unsigned char *)run_case, strlen(run_case));
  snprintf(cmd, sizeof cmd, "rm -rf '%s' && '%s' run '%s' -o '%s' --quiet 2>&1", base, test_bin(),
           casefile, base);
  int rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0, "the run writes its checkpoint (exit %d): %s", rc, out);
  char pvd[4400], sum[4400];
  snprintf(pvd, sizeof pvd, "%s/run.pvd", base);
  snprintf(sum, sizeof sum, "%s/summary.csv", base);
  char *pvd0 = test_slurp(pvd, NULL), *sum0 = test_slurp(sum, NULL);
  const double nan = NAN;
  const struct alteration alt[] = {
      {"out.count.next_k.nrows", 2, 0, 100000000, 0, "10^8 summary rows (was SIGSEGV)"},
      {"out.count.next_k.nrows", 0, 0, 100000000, 0, "10^8 outputs"},
      {"out.count.next_k.nrows", 1, 0, INT64_C(1) << 62, 0, "output index 2^62 (hung)"},
      {"out.count.next_k.nrows", 1, 0, 0, 0, "output index 0"},
      {"step.n.solid", 1, 0, INT64_C(1) << 40, 0, "2^40 particles (asked for 11.7 TB)"},
      {"step.n.solid", 0, 0, -3, 0, "step -3"},
      {"clock", 0, 1, 0, nan, "a NaN time"},
      {"clock", 0, 1, 0, -1.0, "a negative time"},
      {"clock", 1, 1, 0, 0.0, "a next step of 0 s"},
      {"clock", 2, 1, 0, HUGE_VAL, "an infinite proposed step"},
      {"out.t_start", 0, 1, 0, 1.0, "a start after the checkpoint's time"},
      {"out.summary", 18 + 1, 1, 0, nan, "a NaN time in summary row 1"},
      {"out.summary", 2 * 18 + 1, 1, 0, 0.001, "summary times out of order"},
      {"out.snapshot_times", 1, 1, 0, nan, "a NaN snapshot time (went into run.pvd)"},
      {"out.snapshot_times", 2, 1, 0, 0.007, "a snapshot time not its row's"},
      {"absorbed.n", 0, 0, -5, 0, "-5 particles absorbed"},
      {"absorbed", 0, 1, 0, nan, "a NaN absorbed mass"},
      {"measure.next_k", 0, 0, INT64_C(1) << 62, 0, "measurement index 2^62"},
      {"measure.peak_pressure", 0, 1, 0, nan, "a NaN peak pressure"},
      {"p.x", 5, 1, 0, nan, "a NaN position"},
      {"p.h", 3, 1, 0, 0.0, "a smoothing length of 0"},
      {"p.m", 7, 1, 0, -1.0, "a negative mass"},
      {"p.e", 2, 1, 0, HUGE_VAL, "an infinite energy"},
      {"geometry", 0, 0, 1, 0, "an axisymmetric checkpoint for a 3D case"},
      {"geometry", 0, 0, 7, 0, "geometry 7"},
  };
  snprintf(dir, sizeof dir, "%s/altered", test_tmpdir());
  for (size_t k = 0; k < sizeof alt / sizeof alt[0]; k++) {
    if (altered_copy(base, dir, &alt[k])) {
      CHECK(0, "%s: could not prepare the altered copy of record '%s'", alt[k].what, alt[k].rec);
      continue;
    }
    snprintf(cmd, sizeof cmd, "timeout -k 5 20 '%s' restart '%s' --set time.end=0.02 --quiet 2>&1",
             test_bin(), dir);
    rc = test_run(cmd, out, sizeof out);
    char ck[4400], rec[128];
    snprintf(ck, sizeof ck, "%s/checkpoint.hvc", dir);
    snprintf(rec, sizeof rec, "record '%s'", alt[k].rec);
    const char *e = strstr(out, "hvsph: error: ");
    const int one = e && e == strstr(out, "hvsph: error: ") && !strstr(e + 1, "hvsph: error: ");
    /* a count in one record is checked against the record it counts: 2^40 particles
       name step.n.solid (the count), the others their own record */
    CHECK(rc == 2 && one && strstr(e, ck) && strstr(e, rec),
          "%s: exit %d (want 2; 124 or 137: it hung), one line naming the checkpoint and %s: %s",
          alt[k].what, rc, rec, out);
    char apvd[4400], asum[4400];
    snprintf(apvd, sizeof apvd, "%s/run.pvd", dir);
    snprintf(asum, sizeof asum, "%s/summary.csv", dir);
    char *pvd1 = test_slurp(apvd, NULL), *sum1 = test_slurp(asum, NULL);
    CHECK(pvd0 && sum0 && pvd1 && sum1 && !strcmp(pvd0, pvd1) && !strcmp(sum0, sum1),
          "%s: run.pvd and summary.csv left as they were", alt[k].what);
    free(pvd1);
    free(sum1);
  }
  /* the copy unaltered (an alteration that writes the value it holds) continues */
  struct ckpt_file c;
  struct hv_error err;
  int64_t ints[3] = {0, 0, 0};
  char ck[4400];
  snprintf(ck, sizeof ck, "%s/checkpoint.hvc", base);
  if (!ckpt_open(&c, ck, &err)) {
    ckpt_get(&c, "out.count.next_k.nrows", CKPT_I64, 3, ints, &err);
    ckpt_close(&c);
  }
  const struct alteration same = {"out.count.next_k.nrows", 1, 0, ints[1], 0, "unaltered"};
  CHECK(altered_copy(base, dir, &same) == 0, "copied the run");
  snprintf(cmd, sizeof cmd, "timeout -k 5 60 '%s' restart '%s' --set time.end=0.02 --quiet 2>&1",
           test_bin(), dir);
  rc = test_run(cmd, out, sizeof out);
  CHECK(rc == 0, "the unaltered checkpoint continues (exit %d): %s", rc, out);
  free(pvd0);
  free(sum0);
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
            i32[2] == 2147483647,
        "int32 read back");
  CHECK(ckpt_get(&c, "i64", CKPT_I64, 2, i64, &err) == 0 && i64[0] == -9000000000LL && i64[1] == 42,
        "int64 read back");
  CHECK(ckpt_get_parts(&c, "vec", CKPT_F64, 2, parts, 2, &err) == 0 && a[0] == 1.5 && a[1] == 0.0 &&
            signbit(a[1]) && isnan(b[0]) && b[1] == 1e-300,
        "two parts read back bit for bit (-0, NaN, 1e-300)");
  CHECK(ckpt_get(&c, "big", CKPT_F64, NBIG, big2, &err) == 0 &&
            !memcmp(big, big2, NBIG * sizeof *big),
        "10^6 doubles read back bit for bit");
  void *e;
  size_t n;
  CHECK(ckpt_get_alloc(&c, "empty", CKPT_F64, &e, &n, &err) == 0 && n == 0, "empty record");
  free(e);
  char *s;
  CHECK(ckpt_get_alloc(&c, "text", CKPT_BYTES, (void **)&s, &n, &err) == 0 && n == 5 &&
            !strcmp(s, "hello"),
        "bytes allocated and NUL-terminated");
  free(s);
  CHECK(ckpt_get(&c, "i32", CKPT_I64, 3, i64, &err) != 0 && strstr(err.msg, "'i32'") &&
            strstr(err.msg, "int32") && strstr(err.msg, path),
        "wrong type refused: %s", err.msg);
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
    if (k == 0) { /* the byte-order mark reversed */
      for (int q = 0; q < 2; q++) {
        unsigned char t = r2[12 + q];
        r2[12 + q] = r2[15 - q];
        r2[15 - q] = t;
      }
    } else {
      r2[8] = 2; /* format version 2 */
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
    for (int f = 8; f < 16; f += 4) /* the version and the byte-order mark */
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
    for (size_t q = 0; q < sizeof junk; q++)
      junk[q] = (unsigned char)("id,x,y,z\n1,0,0,0\n"[q % 17]);
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

  alarm(900); /* the restarts below end within 25 s each; this is the backstop */
  test_run_records();
  alarm(0);
  return test_finish();
}
