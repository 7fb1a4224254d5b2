/* test_io.c — snapshot and table writers, the CSV reader, atomic files, mkdir -p.
 *
 * Round trips are checked bit for bit (memcmp), the VTU is parsed minimally here
 * (header, appended block sizes, first point) and read back by io_read_particles_vtu
 * (bit for bit; files cut short or altered are refused), and failures (abort, unwritable
 * target, missing folder, a full disk through /dev/full) must leave an earlier
 * file of the same name intact and no temporary file behind.
 */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/snapshot.h"
#include "particles/particles.h"
#include "testlib.h"

#define NP         100
#define HV_PI_TEST 3.14159265358979323846

static char dir[4096];

static const char *path_in(const char *name)
{
  static char buf[8][4200];
  static int k = 0;
  char *b = buf[k++ % 8];
  snprintf(b, sizeof buf[0], "%s/%s", dir, name);
  return b;
}

/* Reads a whole file; returns NULL when it cannot. *len gets the size. */
/* Number of leftover temporary files (".<name>.tmp.<pid>") in the scratch folder. */
static int count_tmp(void)
{
  DIR *d = opendir(dir);
  int n = 0;
  struct dirent *e;
  if (!d) return -1;
  while ((e = readdir(d)))
    if (e->d_name[0] == '.' && strstr(e->d_name, ".tmp.")) n++;
  closedir(d);
  return n;
}

static void fill(struct particles *p)
{
  size_t first = particles_add(p, NP);
  for (size_t k = 0; k < NP; k++) {
    size_t i = first + k;
    double s = (double)k;
    p->id[i] = ((int64_t)1 << 40) + (int64_t)k * 7919;
    p->mat[i] = (int32_t)(k % 3) - 1;
    p->body[i] = (int32_t)(k % 2);
    p->m[i] = 1.0 / 3.0 * (s + 1.0);
    p->h[i] = 1e-3 * sqrt(s + 2.0);
    p->rho[i] = 2700.0 + 0.1 * s;
    p->e[i] = k == 5 ? -0.0 : 1e5 * sin(s);
    p->p[i] = k == 7 ? 4.9406564584124654e-324 : 1e9 * cos(s); /* a subnormal too */
    p->cs[i] = k == 9 ? 1e300 : 5000.0 + exp(-s);
    p->drho[i] = 1.0; /* not PF_OUT: must not travel */
    for (int c = 0; c < 3; c++) {
      p->x[c][i] = 0.1 * s + (c + 1) / 7.0 - 0.5;
      p->v[c][i] = -6200.0 * (c == 0) + tan(s + c);
      p->a[c][i] = 42.0;
    }
  }
}

/* Every PF_OUT field of a and b equal bit for bit over a's n particles. */
static int same_out_fields(struct particles *a, struct particles *b, const char **bad)
{
  struct pfield fa[HV_MAX_FIELDS], fb[HV_MAX_FIELDS];
  int nf = particles_fields(a, fa);
  particles_fields(b, fb);
  for (int k = 0; k < nf; k++) {
    if (!(fa[k].flags & PF_OUT)) continue;
    size_t bytes = a->n * pf_type_size(fa[k].type);
    for (int c = 0; c < fa[k].ncomp; c++)
      if (bytes && memcmp(fa[k].comp[c], fb[k].comp[c], bytes)) {
        *bad = fa[k].name;
        return 0;
      }
  }
  return 1;
}

static const char *mats[] = {"al-2024", "steel 4340", "W--alloy"};
static const char *bodies[] = {"bumper", "rod <W&\"Fe\">"};

static struct snapshot_meta meta(void)
{
  return (struct snapshot_meta){.time = 1.2345678901234567e-6,
                                .step = 4242,
                                .version = "v0.1-test",
                                .case_name = "demo",
                                .material_names = mats,
                                .nmat = 3,
                                .body_names = bodies,
                                .nbody = 2};
}

static void test_csv(struct particles *p)
{
  struct hv_error err;
  hv_error_clear(&err);
  struct snapshot_meta m = meta();
  const char *path = path_in("particles.csv");
  CHECK(io_write_particles_csv(path, p, &m, &err) == 0, "CSV written: %s", err.msg);
  char *text = test_slurp(path, NULL);
  CHECK(text &&
            strncmp(text, "# hvsph v0.1-test case demo time 1.2345678901234567e-06 s step 4242\n",
                    67) == 0,
        "CSV comment line");
  CHECK(text && strstr(text, "\n# materials 0=al-2024 1=steel_4340 2=W--alloy\n"),
        "materials line");
  CHECK(text && strstr(text, "\nid,x,y,z,vx,vy,vz,m,rho,p,e,h,mat,body,cs,dt\n"), "CSV header");
  int lines = 0;
  for (char *q = text; q && *q; q++) lines += *q == '\n';
  CHECK(lines == 3 + NP, "CSV has %d lines (3 + %d reals, no ghosts)", lines, NP);
  free(text);

  struct particles q;
  double t = 0.0;
  particles_init(&q);
  CHECK(io_read_particles_csv(path, &q, &t, &err) == 0, "CSV read: %s", err.msg);
  CHECK(q.n == NP, "read %zu particles", q.n);
  CHECK(memcmp(&t, &m.time, sizeof t) == 0, "time read back exactly (%.17g)", t);
  const char *bad = "";
  CHECK(q.n == NP && same_out_fields(p, &q, &bad), "every output value bitwise equal (%s)", bad);
  CHECK(q.n == NP && q.drho[3] == 0.0 && q.a[1][3] == 0.0, "non-output fields not written");
  CHECK(q.n == NP && signbit(q.e[5]) && q.p[7] > 0.0, "-0 and subnormal survive");
  CHECK(io_read_particles_csv(path, &q, NULL, &err) == 0 && q.n == 2 * NP, "read appends");
  particles_free(&q);
}

static void test_csv_errors(void)
{
  struct hv_error err;
  hv_error_clear(&err);
  struct particles q;
  double t = 0.0;
  particles_init(&q);
  const char *nid = test_write_file("io_noid.csv", "x,y,z,foo\n1,2,3,4\n");
  CHECK(io_read_particles_csv(nid, &q, &t, &err) != 0 && strstr(err.msg, "'id'") &&
            err.code == HV_EXIT_INPUT,
        "missing id column: %s", err.msg);
  CHECK(isnan(t), "no comment line: time is NaN");
  const char *ok = test_write_file("io_min.csv", "# hvsph x case c time 2.5 s step 3\n"
                                                 "z,unknown,y,id,x\n3,9,2,17,1\n");
  CHECK(io_read_particles_csv(ok, &q, &t, &err) == 0 && q.n == 1 && q.id[0] == 17 &&
            q.x[0][0] == 1.0 && q.x[2][0] == 3.0 && t == 2.5,
        "columns by name, unknown ignored: %s", err.msg);
  const char *bad = test_write_file("io_bad.csv", "id,x,y,z\n1,0,0,0\n2,0,zero,0\n");
  CHECK(io_read_particles_csv(bad, &q, NULL, &err) != 0 && strstr(err.msg, "line 3") &&
            strstr(err.msg, "'y'"),
        "bad value names line and column: %s", err.msg);
  CHECK(q.n == 1, "failed read leaves the store as it was (n = %zu)", q.n);
  const char *shrt = test_write_file("io_short.csv", "id,x,y,z\n1,0,0\n");
  CHECK(io_read_particles_csv(shrt, &q, NULL, &err) != 0 && strstr(err.msg, "3 values"),
        "short row: %s", err.msg);
  CHECK(io_read_particles_csv(path_in("nope.csv"), &q, NULL, &err) != 0 &&
            strstr(err.msg, "nope.csv") && strstr(err.msg, "No such file"),
        "missing file: %s", err.msg);
  particles_free(&q);
}

/* Finds attr="..." after `from` and returns its numeric value (or -1). */
static long long attr_after(const char *text, const char *from, const char *attr)
{
  const char *s = strstr(text, from);
  char key[64];
  snprintf(key, sizeof key, "%s=\"", attr);
  s = s ? strstr(s, key) : NULL;
  return s ? strtoll(s + strlen(key), NULL, 10) : -1;
}

static void test_vtu(struct particles *p)
{
  struct hv_error err;
  hv_error_clear(&err);
  struct snapshot_meta m = meta();
  const char *path = path_in("particles_000001.vtu");
  CHECK(io_write_vtu(path, p, &m, &err) == 0, "VTU written: %s", err.msg);
  size_t len = 0;
  char *text = test_slurp(path, &len);
  CHECK(text != NULL, "VTU read back");
  if (!text) return;
  CHECK(strstr(text, "NumberOfPoints=\"100\"") && strstr(text, "NumberOfCells=\"100\""),
        "header declares 100 points and cells");
  CHECK(strstr(text, "header_type=\"UInt64\"") && strstr(text, "type=\"UnstructuredGrid\""),
        "UnstructuredGrid with UInt64 headers");
  CHECK(
      strstr(text, "Name=\"TIME\" NumberOfTuples=\"1\" format=\"ascii\">1.2345678901234567e-06<") &&
          strstr(text, "Name=\"STEP\" NumberOfTuples=\"1\" format=\"ascii\">4242<"),
      "FieldData TIME and STEP");
  CHECK(strstr(text, "<!-- hvsph v0.1-test case demo -->") && strstr(text, "W-_alloy"),
        "version in a comment, '--' kept out of comments");
  CHECK(strstr(text, "type=\"Float64\" Name=\"v\" NumberOfComponents=\"3\"") &&
            strstr(text, "type=\"Int32\" Name=\"mat\"") &&
            strstr(text, "type=\"Int64\" Name=\"id\"") && !strstr(text, "Name=\"a\"") &&
            !strstr(text, "Name=\"drho\""),
        "PointData: PF_OUT fields with VTK types");
  char *app = strstr(text, "<AppendedData encoding=\"raw\">");
  char *us = app ? app + strlen("<AppendedData encoding=\"raw\">") : NULL;
  while (us && (*us == '\n' || *us == ' ')) us++;
  CHECK(us && *us == '_', "appended data starts with '_'");
  if (!us || *us != '_') {
    free(text);
    return;
  }
  const unsigned char *base = (const unsigned char *)us + 1;
  long long off = attr_after(text, "<Points>", "offset");
  uint64_t nb = 0;
  double x0[3] = {0, 0, 0};
  int inside = off >= 0 && (size_t)(base - (const unsigned char *)text) + (size_t)off + 32 <= len;
  CHECK(inside, "Points offset %lld inside the file", off);
  if (inside) {
    memcpy(&nb, base + off, 8);
    memcpy(x0, base + off + 8, sizeof x0);
  }
  CHECK(nb == (uint64_t)NP * 3 * 8, "Points block holds %llu bytes", (unsigned long long)nb);
  CHECK(x0[0] == p->x[0][0] && x0[1] == p->x[1][0] && x0[2] == p->x[2][0],
        "first point decodes exactly (%.17g %.17g %.17g)", x0[0], x0[1], x0[2]);
  long long oid = attr_after(text, "Name=\"id\"", "offset");
  int64_t id1 = 0;
  if (oid >= 0) memcpy(&id1, base + oid + 8 + 8, 8);
  CHECK(id1 == p->id[1], "second id decodes (%lld)", (long long)id1);
  /* the blocks in the reverse of the declared order (meshio 7.0 finds them only so):
     types (declared last) first, id (declared first) last, ending the file */
  long long otype = attr_after(text, "Name=\"types\"", "offset");
  CHECK(otype == 0 && base[otype + 8] == 1 && base[otype + 8 + NP - 1] == 1,
        "types are VTK_VERTEX, the first block (offset %lld)", otype);
  CHECK(oid >= 0 &&
            strcmp((const char *)base + oid + 8 + 8 * NP, "\n  </AppendedData>\n</VTKFile>\n") == 0,
        "the file ends after id's block");
  /* the names of the materials and bodies as FieldData: "mat <name>" and "body <name>"
     holding the index, the names escaped for XML (not cleaned as in the comments) */
  CHECK(strstr(text, "<DataArray type=\"Int32\" Name=\"mat steel 4340\" NumberOfTuples=\"1\" "
                     "format=\"ascii\">1</DataArray>") &&
            strstr(text, "Name=\"mat W--alloy\" NumberOfTuples=\"1\" format=\"ascii\">2<") &&
            strstr(text, "Name=\"body bumper\" NumberOfTuples=\"1\" format=\"ascii\">0<") &&
            strstr(text, "Name=\"body rod &lt;W&amp;&quot;Fe&quot;&gt;\" NumberOfTuples=\"1\" "
                         "format=\"ascii\">1<"),
        "FieldData names the materials and bodies");
  char *fd_end = strstr(text, "</FieldData>"), *piece = strstr(text, "<Piece");
  CHECK(fd_end && piece && fd_end < piece && strstr(text, "Name=\"body bumper\"") < fd_end,
        "... inside FieldData, before the Piece");
  free(text);
}

/* 1 when s[0, n) is well-formed UTF-8 (what an XML parser without an encoding
 * declaration, e.g. ParaView's expat, requires of every byte of the markup). */
static int utf8_ok(const unsigned char *s, size_t n)
{
  for (size_t i = 0; i < n;) {
    const unsigned c = s[i];
    size_t k = c < 0x80             ? 0
               : (c & 0xe0) == 0xc0 ? 1
               : (c & 0xf0) == 0xe0 ? 2
               : (c & 0xf8) == 0xf0 ? 3
                                    : 9;
    if (k == 9 || (k == 1 && c < 0xc2) || (k == 3 && c > 0xf4) || i + k >= n + (k ? 0 : 1))
      return 0;
    for (size_t j = 1; j <= k; j++)
      if ((s[i + j] & 0xc0) != 0x80) return 0;
    if (k == 2 && ((c == 0xe0 && s[i + 1] < 0xa0) || (c == 0xed && s[i + 1] >= 0xa0))) return 0;
    if (k == 3 && ((c == 0xf0 && s[i + 1] < 0x90) || (c == 0xf4 && s[i + 1] >= 0x90))) return 0;
    i += k + 1;
  }
  return 1;
}

/* Names that are not valid UTF-8 (a stray Latin-1 byte, a sequence cut short) must
 * not make the VTU's XML ill-formed: ParaView would refuse the whole file. */
static void test_vtu_utf8(struct particles *p)
{
  struct hv_error err;
  hv_error_clear(&err);
  const char *badm[2] = {"st\xe4hl", "w\xc3"};
  struct snapshot_meta m = {.time = 1.0,
                            .step = 1,
                            .version = "v\xff"
                                       "1",
                            .case_name = "caf\xc3\xa9 \xfc x\xe2\x82",
                            .material_names = badm,
                            .nmat = 2};
  char path[4200];
  snprintf(path, sizeof path, "%s/utf8.vtu", dir);
  CHECK(io_write_vtu(path, p, &m, &err) == 0, "VTU with odd names written: %s", err.msg);
  size_t len = 0;
  char *text = test_slurp(path, &len);
  const char *app = text ? strstr(text, "<AppendedData") : NULL;
  const char *us = app ? strchr(app, '_') : NULL;
  CHECK(us && utf8_ok((const unsigned char *)text, (size_t)(us - text)),
        "the VTU's XML is valid UTF-8 whatever bytes the names hold");
  CHECK(text && strstr(text, "caf\xc3\xa9"), "valid UTF-8 in a name is kept");
  free(text);
  struct particles q;
  particles_init(&q);
  CHECK(io_read_particles_vtu(path, &q, NULL, &err) == 0 && q.n == p->n, "and reads back: %s",
        err.msg);
  particles_free(&q);
}

/* Writes a copy of src with its first occurrence of `from` replaced by `to` (same
 * length, so offsets stay) or, with cut > 0, only its first cut bytes. */
static const char *vtu_variant(const char *src, const char *name, const char *from, const char *to,
                               size_t cut)
{
  size_t len = 0;
  char *text = test_slurp(src, &len);
  const char *out = path_in(name);
  FILE *f = fopen(out, "wb");
  if (!text || !f) {
    free(text);
    if (f) fclose(f);
    return out;
  }
  char *at = from ? strstr(text, from) : NULL;
  if (at) memcpy(at, to, strlen(to));
  fwrite(text, 1, cut ? cut : len, f);
  fclose(f);
  free(text);
  return out;
}

static void test_vtu_read(struct particles *p)
{
  struct hv_error err;
  hv_error_clear(&err);
  struct snapshot_meta m = meta();
  const char *path = path_in("particles_000002.vtu");
  CHECK(io_write_vtu(path, p, &m, &err) == 0, "VTU written: %s", err.msg);
  struct particles q;
  particles_init(&q);
  double t = 0.0;
  CHECK(io_read_particles_vtu(path, &q, &t, &err) == 0, "VTU read: %s", err.msg);
  CHECK(q.n == NP, "read %zu particles of %d", q.n, NP);
  CHECK(memcmp(&t, &m.time, sizeof t) == 0, "time read back exactly (%.17g)", t);
  const char *bad = "";
  CHECK(q.n == NP && same_out_fields(p, &q, &bad), "every output value bitwise equal (%s)", bad);
  CHECK(q.n == NP && q.drho[3] == 0.0 && q.a[1][3] == 0.0, "non-output fields stay zero");
  CHECK(q.n == NP && signbit(q.e[5]) && q.p[7] > 0.0, "-0 and subnormal survive");
  CHECK(io_read_particles(path, &q, NULL, &err) == 0 && q.n == 2 * NP &&
            q.x[1][NP + 3] == p->x[1][3] && q.id[NP + 99] == p->id[99],
        "io_read_particles takes .vtu and appends: %s", err.msg);
  char names[8][64] = {{0}};
  int nm = io_read_material_names(path, names, 8);
  CHECK(nm == 3 && !strcmp(names[0], "al-2024") && !strcmp(names[1], "steel_4340") &&
            !strcmp(names[2], "W-_alloy"),
        "material names from the VTU comment (%d: %s %s %s)", nm, names[0], names[1], names[2]);
  particles_free(&q);

  /* a solid store: S (6 components) and damage come back, and enable the solid arrays */
  struct particles ps;
  particles_init(&ps);
  particles_enable_solid(&ps);
  size_t i0 = particles_add(&ps, 3);
  for (size_t k = 0; k < 3; k++) {
    ps.id[i0 + k] = (int64_t)k;
    ps.x[0][i0 + k] = (double)k;
    ps.damage[i0 + k] = 0.25 * (double)k;
    for (int c = 0; c < 6; c++) ps.S[c][i0 + k] = 1e6 * (double)(c + 1) + (double)k;
  }
  const char *spath = path_in("solid.vtu");
  particles_init(&q);
  int ok =
      io_write_vtu(spath, &ps, NULL, &err) == 0 && io_read_particles_vtu(spath, &q, &t, &err) == 0;
  CHECK(ok && q.solid && q.n == 3 && q.S[4][2] == 5e6 + 2 && q.damage[1] == 0.25 &&
            q.x[0][2] == 2.0 && t == 0.0,
        "solid fields read back into a solid store: %s", err.msg);
  particles_free(&q);
  particles_free(&ps);

  /* a case name that looks like the appended block's start (comments come before the
     root element and must not be taken for it) */
  struct snapshot_meta odd = meta();
  odd.case_name = "x<AppendedData encoding=\"raw\">_y";
  char opath[4200]; /* not path_in: its few buffers hold the paths used below */
  snprintf(opath, sizeof opath, "%s/oddname.vtu", dir);
  particles_init(&q);
  ok = io_write_vtu(opath, p, &odd, &err) == 0 && io_read_particles_vtu(opath, &q, &t, &err) == 0;
  CHECK(ok && q.n == NP && same_out_fields(p, &q, &bad) && t == odd.time,
        "a case named like the appended block reads back: %s", ok ? "" : err.msg);
  particles_free(&q);

  /* bad files: one message naming the file (and the array), nothing appended */
  size_t len = 0;
  char *text = test_slurp(path, &len);
  free(text);
  particles_init(&q);
  const char *cut = vtu_variant(path, "cut.vtu", NULL, NULL, len - 200);
  CHECK(io_read_particles_vtu(cut, &q, NULL, &err) != 0 && strstr(err.msg, "cut.vtu") &&
            strstr(err.msg, "cut short") && err.code == HV_EXIT_INPUT && q.n == 0,
        "file cut short: %s", err.msg);
  const char *nox = vtu_variant(path, "nox.vtu", "Name=\"x\"", "Name=\"q\"", 0);
  CHECK(io_read_particles_vtu(nox, &q, NULL, &err) != 0 && strstr(err.msg, "'x'") && q.n == 0,
        "no positions: %s", err.msg);
  const char *wrong =
      vtu_variant(path, "type.vtu", "type=\"Int64\" Name=\"id\"", "type=\"Int32\" Name=\"id\"", 0);
  CHECK(io_read_particles_vtu(wrong, &q, NULL, &err) != 0 && strstr(err.msg, "'id'") &&
            strstr(err.msg, "Int32") && q.n == 0,
        "wrong type: %s", err.msg);
  const char *np =
      vtu_variant(path, "np.vtu", "NumberOfPoints=\"100\"", "NumberOfPoints=\"101\"", 0);
  CHECK(io_read_particles_vtu(np, &q, NULL, &err) != 0 && strstr(err.msg, "101 points") && q.n == 0,
        "point count not matching the blocks: %s", err.msg);
  const char *huge = vtu_variant(path, "huge.vtu", "NumberOfPoints=\"100\" NumberOfCells=\"100\"",
                                 "NumberOfPoints=\"2000000000\" NumberOfC=\"\"", 0);
  CHECK(io_read_particles_vtu(huge, &q, NULL, &err) != 0 && strstr(err.msg, "2000000000 points") &&
            q.n == 0 && q.cap < 1000,
        "2e9 points claimed: refused before allocating (capacity "
        "%zu): %s",
        q.cap, err.msg);
  const char *twice = vtu_variant(path, "twice.vtu", "Name=\"m\"", "Name=\"h\"", 0);
  CHECK(io_read_particles_vtu(twice, &q, NULL, &err) != 0 && strstr(err.msg, "'h' appears twice") &&
            q.n == 0,
        "an array twice: %s", err.msg);
  const char *noid = vtu_variant(path, "noid.vtu", "Name=\"id\"", "Name=\"iq\"", 0);
  CHECK(io_read_particles_vtu(noid, &q, NULL, &err) != 0 && strstr(err.msg, "'id'") && q.n == 0,
        "no ids: %s", err.msg);
  const char *be =
      vtu_variant(path, "be.vtu", "byte_order=\"LittleEndian\"", "byte_order=\"BigEndianxxx\"", 0);
  CHECK(io_read_particles_vtu(be, &q, NULL, &err) != 0 && strstr(err.msg, "byte order"),
        "other byte order: %s", err.msg);
  const char *csv = test_write_file("io_notvtu.vtu", "id,x,y,z\n1,0,0,0\n");
  CHECK(io_read_particles_vtu(csv, &q, NULL, &err) != 0 && strstr(err.msg, "io_notvtu.vtu") &&
            q.n == 0,
        "not a VTU file: %s", err.msg);
  particles_free(&q);
}

static void test_pvd(void)
{
  struct hv_error err;
  hv_error_clear(&err);
  const double t[3] = {0.0, 1e-6, 2.5e-6};
  const char *files[3] = {"particles_000000.vtu", "particles_000001.vtu", "a&b.vtu"};
  const char *path = path_in("run.pvd");
  /* a case named so that its comment holds what the reader looks for */
  struct snapshot_meta meta = {.version = "0.9.0 (commit abc1234)",
                               .case_name =
                                   "<DataSet timestep=\"9\" file=\"x.vtu\"/> <Collection>"};
  CHECK(io_write_pvd(path, t, files, 3, &meta, &err) == 0, "PVD written: %s", err.msg);
  char *text = test_slurp(path, NULL);
  CHECK(text && strstr(text, "type=\"Collection\""), "PVD is a collection");
  CHECK(text && !strncmp(text,
                         "<?xml version=\"1.0\"?>\n<!-- hvsph 0.9.0 (commit abc1234) case "
                         "<DataSet",
                         58),
        "PVD's comment gives the version and case: %.80s", text ? text : "");
  double *rt = NULL;
  char **rf = NULL;
  int rn = io_read_pvd(path, &rt, &rf, &err);
  CHECK(rn == 3 && rt[1] == 1e-6 && !strcmp(rf[2], "a&b.vtu"),
        "PVD read back: 3 entries, not the comment's (%d)", rn);
  for (int k = 0; k < rn; k++) free(rf[k]);
  free(rf);
  free(rt);
  CHECK(
      text && strstr(text, "timestep=\"0\" group=\"\" part=\"0\" file=\"particles_000000.vtu\"") &&
          strstr(
              text,
              "timestep=\"9.9999999999999995e-07\" group=\"\" part=\"0\" file=\"particles_000001.vtu\"") &&
          strstr(text, "file=\"a&amp;b.vtu\""),
      "PVD lists every (time, file), escaped");
  free(text);
}

static void test_table(void)
{
  struct hv_error err;
  hv_error_clear(&err);
  const char *cols[3] = {"step", "time", "e_total"};
  const double rows[6] = {0, 0.0, 1.5, 1, 1e-6, -3.0};
  const char *path = path_in("summary.csv");
  CHECK(io_write_table_csv(path, cols, 3, rows, 2, "hvsph v\ncase demo", &err) == 0,
        "table written: %s", err.msg);
  char *text = test_slurp(path, NULL);
  const char *want =
      "# hvsph v\n# case demo\nstep,time,e_total\n0,0,1.5\n1,9.9999999999999995e-07,-3\n";
  int same = text && strcmp(text, want) == 0;
  CHECK(same, "table text exact%s%s", same ? "" : ":\n", same ? "" : text ? text : "(none)");
  free(text);
  double *col = NULL;
  int n = io_read_table_column(path, "time", &col, &err);
  CHECK(n == 2 && col[0] == 0.0 && col[1] == 1e-6, "column 'time' read back: %d rows", n);
  free(col);
  CHECK(io_read_table_column(path, "mass", &col, &err) == -1 && strstr(err.msg, "mass"),
        "a missing column: %s", err.msg);
  /* an empty file (no header) or one that cannot be read is an error, not zero rows */
  const char *empty = test_write_file("io_empty_table.csv", "# only a comment\n");
  err.msg[0] = '\0';
  CHECK(io_read_table_column(empty, "time", &col, &err) == -1 &&
            strstr(err.msg, "io_empty_table.csv"),
        "a table without a header: %s", err.msg);
  free(col);
  err.msg[0] = '\0';
  CHECK(io_read_table_column(dir, "time", &col, &err) == -1 && strstr(err.msg, dir),
        "a folder read as a table: %s", err.msg);
  free(col);
  const char *badc[1] = {"a,b"};
  CHECK(io_write_table_csv(path, badc, 1, rows, 1, NULL, &err) != 0, "comma in a column name");
  /* snapshot numbers, sorted, by extension only */
  const char *names[] = {"particles_00010.csv", "particles_00002.csv", "particles_00002.vtu",
                         "particles_x.csv", "particles_00003.csv.tmp"};
  for (int k = 0; k < 5; k++) test_write_file(names[k], "");
  int *nums = NULL;
  n = io_list_snapshots(test_tmpdir(), "csv", &nums);
  CHECK(n == 2 && nums[0] == 2 && nums[1] == 10, "io_list_snapshots: %d csv snapshots (2, 10)", n);
  free(nums);
}

static void test_atomic(struct particles *p)
{
  struct hv_error err;
  hv_error_clear(&err);
  const char *path = path_in("keep.csv");
  const char *cols[1] = {"a"};
  const double rows[2] = {1.0, 2.0};
  CHECK(io_write_table_csv(path, cols, 1, rows, 2, NULL, &err) == 0, "first file written");
  char *before = test_slurp(path, NULL);
  struct atomic_file af;
  CHECK(atomic_file_open(&af, path, &err) == 0 && count_tmp() == 1,
        "atomic_file_open makes one tmp file");
  CHECK(strstr(af.tmp, "/.keep.csv.tmp.") != NULL, "tmp name '%s'", af.tmp);
  CHECK(atomic_file_printf(&af, &err, "garbage\n") == 0, "write to tmp");
  atomic_file_abort(&af);
  atomic_file_abort(&af); /* twice is harmless */
  char *after = test_slurp(path, NULL);
  CHECK(before && after && strcmp(before, after) == 0, "abort leaves the first file intact");
  CHECK(count_tmp() == 0, "no tmp file after abort");
  free(after);

  /* Rename onto a folder fails after the data was written. */
  struct hv_error e2;
  hv_error_clear(&e2);
  CHECK(io_mkdir_p(path_in("adir.vtu"), &e2) == 0, "folder in the way made");
  CHECK(io_write_vtu(path_in("adir.vtu"), p, NULL, &e2) != 0 && strstr(e2.msg, "adir.vtu") &&
            e2.code == HV_EXIT_RUN,
        "rename failure reported: %s", e2.msg);
  CHECK(count_tmp() == 0, "no tmp file after a failed rename");

  /* A folder without write permission (only meaningful when not root). */
  if (geteuid() != 0) {
    const char *ro = path_in("ro");
    io_mkdir_p(ro, &e2);
    chmod(ro, 0555);
    CHECK(io_write_table_csv(path_in("ro/t.csv"), cols, 1, rows, 1, NULL, &e2) != 0 &&
              strstr(e2.msg, "Permission denied"),
          "read-only folder: %s", e2.msg);
    chmod(ro, 0755);
  }

  /* A missing folder: the message names the path. */
  const char *nodir = path_in("no/such/folder/particles.vtu");
  CHECK(io_write_vtu(nodir, p, NULL, &e2) != 0 && strstr(e2.msg, nodir) &&
            strstr(e2.msg, "No such file") && e2.code == HV_EXIT_RUN,
        "missing folder: %s", e2.msg);
  free(before);
}

/* A full disk: the temporary stream is swapped for /dev/full. */
static void test_full_disk(int small_writes)
{
  struct hv_error err;
  hv_error_clear(&err);
  const char *path = path_in("full.csv");
  const char *cols[1] = {"a"};
  const double rows[1] = {7.0};
  if (access("/dev/full", W_OK) != 0) {
    printf("  skip  /dev/full not available\n");
    return;
  }
  CHECK(io_write_table_csv(path, cols, 1, rows, 1, NULL, &err) == 0, "target written");
  char *before = test_slurp(path, NULL);
  struct atomic_file af;
  CHECK(atomic_file_open(&af, path, &err) == 0, "atomic_file_open");
  if (fclose(af.f) != 0) CHECK(0, "fclose tmp");
  af.f = fopen("/dev/full", "w");
  CHECK(af.f != NULL, "open /dev/full");
  if (!af.f) {
    atomic_file_abort(&af);
    free(before);
    return;
  }
  static char block[1 << 16];
  memset(block, 'x', sizeof block);
  for (int k = 0; k < 64; k++) { /* 4 MB; return values ignored on purpose */
    if (small_writes) {
      for (size_t j = 0; j < sizeof block / 64; j++) (void)!fwrite(block, 1, 63, af.f);
    } else {
      (void)!fwrite(block, 1, sizeof block, af.f);
    }
  }
  hv_error_clear(&err);
  CHECK(atomic_file_commit(&af, &err) != 0 && strstr(err.msg, "No space left") &&
            strstr(err.msg, "full.csv") && err.code == HV_EXIT_RUN,
        "commit on a full disk fails (%s writes): %s", small_writes ? "small" : "large", err.msg);
  char *after = test_slurp(path, NULL);
  CHECK(before && after && strcmp(before, after) == 0, "target untouched");
  CHECK(count_tmp() == 0, "no tmp file left");
  CHECK(af.f == NULL, "stream closed");
  free(before);
  free(after);
}

static void test_mkdir(void)
{
  struct hv_error err;
  hv_error_clear(&err);
  struct stat st;
  const char *nested = path_in("m1/m2/m3/");
  CHECK(io_mkdir_p(nested, &err) == 0 && stat(path_in("m1/m2/m3"), &st) == 0 && S_ISDIR(st.st_mode),
        "nested folders made: %s", err.msg);
  CHECK(io_mkdir_p(path_in("m1/m2"), &err) == 0, "existing folder is fine");
  CHECK(io_mkdir_p(path_in("m1//m2/m4"), &err) == 0, "double slash is fine");
  const char *file = test_write_file("io_plain.txt", "x\n");
  char below[4200];
  snprintf(below, sizeof below, "%s/sub", file);
  CHECK(io_mkdir_p(file, &err) != 0 && err.code == HV_EXIT_INPUT && strstr(err.msg, file) &&
            strstr(err.msg, "not a folder"),
        "a file in the way: %s", err.msg);
  CHECK(io_mkdir_p(below, &err) != 0 && strstr(err.msg, below) && strstr(err.msg, "not a folder"),
        "a file as a parent: %s", err.msg);
}

/* output.compress: the arrays as zlib blocks (vtkZLibDataCompressor), read back bit for
 * bit by hvsph; a damaged or cut block is refused naming the file and the array, nothing
 * appended. NP = 100 particles make blocks smaller than one zlib block of 32 kB; the
 * many-block case (several full blocks and a partial one) is a store of 5,000. */
static void test_vtu_zlib(struct particles *p)
{
  struct hv_error err;
  hv_error_clear(&err);
  struct snapshot_meta m = meta();
  m.vtu_zlib = 1;
  const char *path = path_in("zlib.vtu");
  CHECK(io_write_vtu(path, p, &m, &err) == 0, "compressed VTU written: %s", err.msg);
  size_t len = 0;
  char *text = test_slurp(path, &len);
  CHECK(text && strstr(text, " header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">"),
        "the root names the compressor");
  struct particles q;
  particles_init(&q);
  double t = 0.0;
  const char *bad = "";
  CHECK(io_read_particles_vtu(path, &q, &t, &err) == 0 && q.n == NP &&
            same_out_fields(p, &q, &bad) && t == m.time,
        "compressed VTU read back, every output value bitwise equal (%s) %s", bad, err.msg);
  particles_free(&q);

  /* 5,000 particles: x and v are 120,000 bytes, 3 full blocks and one of 21,696 */
  struct particles big;
  particles_init(&big);
  const size_t i0 = particles_add(&big, 5000);
  for (size_t k = 0; k < 5000; k++) {
    big.id[i0 + k] = (int64_t)(7 * k);
    for (int d = 0; d < 3; d++) {
      big.x[d][i0 + k] = sin((double)(k * 3 + (size_t)d));
      big.v[d][i0 + k] = 1e3 * cos((double)k) + d;
    }
    big.rho[i0 + k] = 2700.0 + (double)k / 7.0;
    big.mat[i0 + k] = (int32_t)(k % 3);
  }
  const char *bpath = path_in("zlib_big.vtu");
  particles_init(&q);
  int ok =
      io_write_vtu(bpath, &big, &m, &err) == 0 && io_read_particles_vtu(bpath, &q, NULL, &err) == 0;
  CHECK(ok && q.n == 5000 && same_out_fields(&big, &q, &bad),
        "5,000 particles in several zlib blocks read back bitwise (%s) %s", bad, err.msg);
  particles_free(&q);
  /* an empty snapshot: no blocks at all */
  particles_init(&q);
  struct particles none;
  particles_init(&none);
  ok = io_write_vtu(path_in("zlib_empty.vtu"), &none, &m, &err) == 0 &&
       io_read_particles_vtu(path_in("zlib_empty.vtu"), &q, NULL, &err) == 0;
  CHECK(ok && q.n == 0, "an empty compressed snapshot reads back: %s", err.msg);
  particles_free(&none);

  /* damaged: a byte inside x's first zlib stream; then the file cut inside a block */
  size_t blen = 0;
  char *btext = test_slurp(bpath, &blen);
  char *us = btext ? strstr(btext, "<AppendedData encoding=\"raw\">") : NULL;
  us = us ? strchr(us, '_') : NULL;
  long long ox = btext ? attr_after(btext, "<Points>", "offset") : -1;
  if (us && ox >= 0) {
    uint64_t nbx;
    memcpy(&nbx, us + 1 + ox, 8);
    char *z0 = us + 1 + ox + 8 * (3 + (long long)nbx); /* x's first zlib stream */
    z0[40] = (char)(z0[40] ^ 0x5a);
    FILE *f = fopen(path_in("zlib_damaged.vtu"), "wb");
    if (f) {
      fwrite(btext, 1, blen, f);
      fclose(f);
    }
    particles_init(&q);
    CHECK(io_read_particles_vtu(path_in("zlib_damaged.vtu"), &q, NULL, &err) != 0 &&
              strstr(err.msg, "zlib_damaged.vtu") && strstr(err.msg, "'x'") &&
              err.code == HV_EXIT_INPUT && q.n == 0,
          "a damaged zlib block is refused, nothing appended: %s", err.msg);
    particles_free(&q);
    f = fopen(path_in("zlib_cut.vtu"), "wb");
    if (f) { /* x's block cut, the closing tag kept (so the block's extent is checked) */
      fwrite(btext, 1, (size_t)(z0 - btext) + 100, f);
      fputs("\n  </AppendedData>\n</VTKFile>\n", f);
      fclose(f);
    }
    particles_init(&q);
    CHECK(io_read_particles_vtu(path_in("zlib_cut.vtu"), &q, NULL, &err) != 0 &&
              strstr(err.msg, "zlib_cut.vtu") && q.n == 0 && q.cap < 5000,
          "a cut compressed block is refused before allocating: %s", err.msg);
    particles_free(&q);
    /* x's first block claiming 1 GB: more than zlib makes of 32 kB, refused before any
       buffer of that size is taken */
    uint64_t huge = 1000000000;
    memcpy(us + 1 + ox + 24, &huge, 8);
    f = fopen(path_in("zlib_claim.vtu"), "wb");
    if (f) {
      fwrite(btext, 1, blen, f);
      fclose(f);
    }
    particles_init(&q);
    CHECK(io_read_particles_vtu(path_in("zlib_claim.vtu"), &q, NULL, &err) != 0 &&
              strstr(err.msg, "'x': block 0 claims 1000000000 compressed bytes") && q.n == 0,
          "a block claiming 1 GB is refused: %s", err.msg);
    particles_free(&q);
  } else {
    CHECK(0, "x's compressed block found in %s", bpath);
  }
  free(btext);
  particles_free(&big);
  const char *lzma =
      vtu_variant(path, "lzma.vtu", "vtkZLibDataCompressor", "vtkLZMADataCompressor", 0);
  particles_init(&q);
  CHECK(io_read_particles_vtu(lzma, &q, NULL, &err) != 0 &&
            strstr(err.msg, "vtkLZMADataCompressor") && q.n == 0,
        "another compressor is named and refused: %s", err.msg);
  particles_free(&q);
  free(text);
}

static void test_empty_and_ghosts(struct particles *p)
{
  struct hv_error err;
  hv_error_clear(&err);
  struct particles z, q;
  particles_init(&z);
  particles_init(&q);
  CHECK(io_write_vtu(path_in("empty.vtu"), &z, NULL, &err) == 0, "empty VTU: %s", err.msg);
  CHECK(io_write_particles_csv(path_in("empty.csv"), &z, NULL, &err) == 0, "empty CSV");
  CHECK(io_read_particles_csv(path_in("empty.csv"), &q, NULL, &err) == 0 && q.n == 0,
        "empty CSV reads back: %s", err.msg);
  /* A ghost after the reals must not be written. */
  particles_reserve(p, p->n + 1);
  particles_copy(p, p->n, 0, ~0u);
  p->n_ghost = 1;
  int ok = io_write_particles_csv(path_in("ghost.csv"), p, NULL, &err) == 0 &&
           io_read_particles_csv(path_in("ghost.csv"), &q, NULL, &err) == 0;
  CHECK(ok && q.n == p->n, "ghosts not written (%zu of %zu + 1 ghost read) %s", q.n, p->n, err.msg);
  p->n_ghost = 0;
  particles_free(&q);
}

/* A message during a run on a terminal: the status line is rewritten in place without a
 * newline, so a warning (a temporary file that cannot be removed, an allocation that
 * fails) must end it first, or it is printed after the status on the same row. */
static void test_status_line(void)
{
  char path[4200];
  snprintf(path, sizeof path, "%s/stderr.txt", dir);
  fflush(stderr);
  const int saved = dup(STDERR_FILENO);
  FILE *f = fopen(path, "w");
  CHECK(f && saved >= 0, "redirect stderr to %s", path);
  if (!f || saved < 0) return;
  dup2(fileno(f), STDERR_FILENO);
  const int lvl = hv_log_level;
  hv_log_level = 1;
  fputs("\rstep 1", stderr);
  hv_status_line(6);
  hv_info("not shown"); /* below the level: prints nothing, so ends nothing */
  fputs("\rstep 2", stderr);
  hv_warn("a warning"); /* ends the status line first */
  hv_warn("another");   /* no status line now: no empty line */
  hv_log_level = lvl;
  fflush(stderr);
  dup2(saved, STDERR_FILENO);
  close(saved);
  fclose(f);
  char got[256] = "";
  f = fopen(path, "r");
  const size_t n = f ? fread(got, 1, sizeof got - 1, f) : 0;
  got[n] = '\0';
  if (f) fclose(f);
  const char *want = "\rstep 1\rstep 2\nhvsph: warning: a warning\nhvsph: warning: another\n";
  CHECK(!strcmp(got, want) && hv_status_len() == 0,
        "a warning after the status line starts a line of its own: %zu bytes '%s'", n, got);
}

/* An axisymmetric run's rings: FieldData GEOMETRY and "# geometry: axisymmetric" written
 * only for them, read back into p->axisym with every value bit for bit (m the ring mass);
 * 3D files read as 3D; mixing the two in one store, an unknown geometry, and a ring off
 * the half-plane (r < 0, z != 0) refused with the file named, the store left as it was. */
static void test_axisym(void)
{
  struct hv_error err;
  hv_error_clear(&err);
  struct particles r, q;
  particles_init(&r);
  size_t first = particles_add(&r, 40);
  for (size_t k = 0; k < 40; k++) {
    const size_t i = first + k;
    const double rad = (k % 8 + 0.5) * 1e-3; /* rows at r = (j + 1/2) Δ, never on the axis */
    r.id[i] = (int64_t)k + 1;
    r.x[0][i] = (double)(k / 8) * 1e-3;
    r.x[1][i] = rad;
    r.m[i] = 2.0 * HV_PI_TEST * rad * 7800.0 * 1e-6; /* 2π r ρ A */
    r.rho[i] = 7800.0;
    r.h[i] = 1.3e-3;
    r.v[0][i] = 2370.0;
  }
  r.axisym = 1;
  struct snapshot_meta m = meta();
  const char *csv = path_in("rz.csv"), *vtu = path_in("rz.vtu"), *vtz = path_in("rz_z.vtu");
  CHECK(io_write_particles_csv(csv, &r, &m, &err) == 0 && io_write_vtu(vtu, &r, &m, &err) == 0,
        "RZ snapshots written: %s", err.msg);
  m.vtu_zlib = 1;
  CHECK(io_write_vtu(vtz, &r, &m, &err) == 0, "RZ compressed VTU written: %s", err.msg);
  char *text = test_slurp(csv, NULL);
  CHECK(text && strstr(text, "\n# geometry: axisymmetric\nid,x,y,z,"),
        "the CSV's geometry line before its header");
  free(text);
  text = test_slurp(vtu, NULL);
  CHECK(text && strstr(text, "\n      <DataArray type=\"Int32\" Name=\"GEOMETRY\" "
                             "NumberOfTuples=\"1\" format=\"ascii\">1</DataArray>\n"),
        "the VTU's FieldData GEOMETRY");
  free(text);
  const char *paths[3] = {csv, vtu, vtz};
  for (int k = 0; k < 3; k++) {
    particles_init(&q);
    const char *bad = "";
    CHECK(io_read_particles(paths[k], &q, NULL, &err) == 0 && q.axisym == 1 && q.n == 40 &&
              same_out_fields(&r, &q, &bad),
          "%s read back axisymmetric, bit for bit (%s): %s", paths[k], bad, err.msg);
    CHECK(io_read_particles(paths[k], &q, NULL, &err) == 0 && q.n == 80 && q.axisym == 1,
          "a second RZ snapshot appends to an RZ store: %s", err.msg);
    particles_free(&q);
  }
  /* a 3D store: no geometry written, read as 3D; mixing refused */
  struct particles d;
  particles_init(&d);
  fill(&d);
  const char *csv3 = path_in("d3.csv"), *vtu3 = path_in("d3.vtu");
  CHECK(io_write_particles_csv(csv3, &d, &m, &err) == 0 && io_write_vtu(vtu3, &d, &m, &err) == 0,
        "3D snapshots written: %s", err.msg);
  text = test_slurp(csv3, NULL);
  CHECK(text && !strstr(text, "geometry"), "a 3D CSV names no geometry");
  free(text);
  text = test_slurp(vtu3, NULL);
  CHECK(text && !strstr(text, "GEOMETRY"), "a 3D VTU has no GEOMETRY");
  free(text);
  particles_init(&q);
  q.axisym = 1; /* an empty store takes the file's geometry */
  CHECK(io_read_particles(vtu3, &q, NULL, &err) == 0 && q.axisym == 0 && q.n == NP,
        "a 3D VTU read as 3D: %s", err.msg);
  CHECK(io_read_particles(csv, &q, NULL, &err) != 0 && err.code == HV_EXIT_INPUT &&
            strstr(err.msg, "rz.csv") && strstr(err.msg, "cannot mix") && q.n == NP &&
            q.axisym == 0,
        "an RZ CSV after a 3D one refused, the store as it was: %s", err.msg);
  CHECK(io_read_particles(vtu, &q, NULL, &err) != 0 && strstr(err.msg, "cannot mix") && q.n == NP,
        "an RZ VTU after a 3D one refused: %s", err.msg);
  particles_free(&q);
  particles_init(&q);
  CHECK(io_read_particles(csv3, &q, NULL, &err) == 0 && q.axisym == 0, "a 3D CSV read as 3D");
  particles_free(&q);
  /* bad geometry lines and rings off the half-plane */
  const char *unk = test_write_file("io_geo.csv", "# geometry: cylindrical\nid,x,y,z\n1,0,1,0\n");
  particles_init(&q);
  CHECK(io_read_particles_csv(unk, &q, NULL, &err) != 0 && strstr(err.msg, "line 1") &&
            strstr(err.msg, "cylindrical") && q.n == 0,
        "unknown geometry: %s", err.msg);
  const char *neg = test_write_file("io_neg.csv", "# geometry: axisymmetric\nid,x,y,z\n"
                                                  "1,0,1e-3,0\n7,0,-1e-3,0\n");
  CHECK(io_read_particles_csv(neg, &q, NULL, &err) != 0 && strstr(err.msg, "io_neg.csv") &&
            strstr(err.msg, "id 7") && strstr(err.msg, "r = y >= 0") && q.n == 0,
        "a ring at r < 0 refused: %s", err.msg);
  const char *offz = test_write_file("io_offz.csv", "# geometry: axisymmetric\nid,x,y,z\n"
                                                    "3,0,1e-3,1e-3\n");
  CHECK(io_read_particles_csv(offz, &q, NULL, &err) != 0 && strstr(err.msg, "id 3") && q.n == 0,
        "a ring off z = 0 refused: %s", err.msg);
  /* a VTU whose GEOMETRY is neither 0 nor 1 */
  size_t len = 0;
  text = test_slurp(vtu, &len);
  char *g = text ? strstr(text, "Name=\"GEOMETRY\"") : NULL;
  char *one = g ? strstr(g, ">1<") : NULL;
  CHECK(one != NULL, "GEOMETRY's value found in the VTU");
  if (one) {
    one[1] = '7';
    FILE *f = fopen(path_in("rz_bad.vtu"), "wb");
    CHECK(f && fwrite(text, 1, len, f) == len && fclose(f) == 0, "altered VTU written");
    CHECK(io_read_particles(path_in("rz_bad.vtu"), &q, NULL, &err) != 0 &&
              strstr(err.msg, "GEOMETRY") && strstr(err.msg, "rz_bad.vtu") && q.n == 0,
          "GEOMETRY 7 refused: %s", err.msg);
  }
  free(text);
  particles_free(&q);
  particles_free(&d);
  particles_free(&r);
}

int main(void)
{
  snprintf(dir, sizeof dir, "%s/io.%ld", test_tmpdir(), (long)getpid());
  struct hv_error err;
  hv_error_clear(&err);
  if (io_mkdir_p(dir, &err)) {
    fprintf(stderr, "%s\n", err.msg);
    return 1;
  }
  struct particles p;
  particles_init(&p);
  fill(&p);
  test_csv(&p);
  test_csv_errors();
  test_vtu(&p);
  test_vtu_read(&p);
  test_vtu_utf8(&p);
  test_vtu_zlib(&p);
  test_pvd();
  test_table();
  test_atomic(&p);
  test_full_disk(0);
  test_full_disk(1);
  test_mkdir();
  test_empty_and_ghosts(&p);
  test_status_line();
  test_axisym();
  particles_free(&p);
  char cmd[4200];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  if (!test_failed && test_run(cmd, NULL, 0) != 0) printf("  note  could not remove %s\n", dir);
  return test_finish();
}
