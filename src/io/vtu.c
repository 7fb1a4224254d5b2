/* vtu.c — particle snapshots as VTK XML UnstructuredGrid files (.vtu).
 *
 * Layout (VTK file formats, "XML File Formats", appended raw data):
 *   <VTKFile type="UnstructuredGrid" version="1.0" byte_order=".." header_type="UInt64">
 *     FieldData: TIME [s] (Float64), STEP (Int64), ascii
 *     Piece NumberOfPoints=n NumberOfCells=n
 *       PointData: every PF_OUT field except x, format="appended"
 *       Points: x (Float64, 3 components)
 *       Cells: connectivity 0..n-1, offsets 1..n, types 1 (VTK_VERTEX)
 *     <AppendedData encoding="raw">_ then, per array in the order declared,
 *       a UInt64 byte count followed by the raw values (host byte order;
 *       vectors interleaved x0 y0 z0 x1 ...). offset= is the position of an
 *       array's byte count, counted from the byte after '_'.
 * Real particles only; written whole through afile.
 */
#include <inttypes.h>
#include <stdint.h>
#include <string.h>

#include "io/afile.h"
#include "io/io_internal.h"
#include "io/snapshot.h"

#define VTU_CHUNK 1024 /* tuples per interleaving buffer */

static const char *vtk_type(enum pf_type t)
{
  switch (t) {
  case PF_INT32: return "Int32";
  case PF_INT64: return "Int64";
  case PF_DOUBLE: return "Float64";
  }
  return "Float64";
}

/* Bytes of one array's appended block: the UInt64 count and the data. */
static uint64_t field_bytes(const struct pfield *f, size_t n)
{
  return (uint64_t)n * (uint64_t)f->ncomp * (uint64_t)pf_type_size(f->type);
}

static int is_point_data(const struct pfield *f)
{
  return (f->flags & PF_OUT) && strcmp(f->name, "x") != 0;
}

static int vtu_header(struct afile *af, const struct pfield *f, int nf, int ix, size_t n,
                      const struct snapshot_meta *meta, struct hv_error *err)
{
  const unsigned short one = 1;
  unsigned char first;
  memcpy(&first, &one, 1);
  char ver[256], name[1024];
  io_clean_text(ver, sizeof ver, meta ? meta->version : NULL, "unknown", 1);
  io_clean_text(name, sizeof name, meta ? meta->case_name : NULL, "unnamed", 1);
  if (afile_printf(af, err,
                   "<?xml version=\"1.0\"?>\n<!-- hvsph %s case %s -->\n", ver, name) ||
      io_put_materials(af, meta, "<!-- ", " -->\n", 1, err) ||
      afile_printf(af, err,
                   "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"%s\""
                   " header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <FieldData>\n"
                   "      <DataArray type=\"Float64\" Name=\"TIME\" NumberOfTuples=\"1\""
                   " format=\"ascii\">%.17g</DataArray>\n"
                   "      <DataArray type=\"Int64\" Name=\"STEP\" NumberOfTuples=\"1\""
                   " format=\"ascii\">%ld</DataArray>\n    </FieldData>\n"
                   "    <Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n"
                   "      <PointData>\n",
                   first ? "LittleEndian" : "BigEndian", meta ? meta->time : 0.0,
                   meta ? meta->step : 0L, n, n))
    return -1;
  uint64_t off = 0;
  for (int k = 0; k < nf; k++) {
    if (!is_point_data(&f[k])) continue;
    if (afile_printf(af, err,
                     "        <DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\""
                     " format=\"appended\" offset=\"%" PRIu64 "\"/>\n",
                     vtk_type(f[k].type), f[k].name, f[k].ncomp, off))
      return -1;
    off += 8 + field_bytes(&f[k], n);
  }
  uint64_t o_conn = off + 8 + field_bytes(&f[ix], n);
  uint64_t o_offs = o_conn + 8 + 8 * (uint64_t)n;
  uint64_t o_type = o_offs + 8 + 8 * (uint64_t)n;
  return afile_printf(
      af, err,
      "      </PointData>\n      <Points>\n"
      "        <DataArray type=\"Float64\" Name=\"x\" NumberOfComponents=\"3\""
      " format=\"appended\" offset=\"%" PRIu64 "\"/>\n      </Points>\n      <Cells>\n"
      "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"appended\""
      " offset=\"%" PRIu64 "\"/>\n"
      "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"appended\""
      " offset=\"%" PRIu64 "\"/>\n"
      "        <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\""
      " offset=\"%" PRIu64 "\"/>\n"
      "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
      "  <AppendedData encoding=\"raw\">\n   _",
      off, o_conn, o_offs, o_type);
}

/* One field's block: byte count, then the values (vectors interleaved). */
static int put_field(struct afile *af, const struct pfield *f, size_t n, struct hv_error *err)
{
  uint64_t nb = field_bytes(f, n);
  size_t s = pf_type_size(f->type);
  if (afile_write(af, &nb, sizeof nb, err)) return -1;
  if (f->ncomp == 1) return afile_write(af, f->comp[0], n * s, err);
  const size_t nc = (size_t)f->ncomp;
  unsigned char buf[VTU_CHUNK * 6 * 8];
  for (size_t i0 = 0; i0 < n; i0 += VTU_CHUNK) {
    size_t m = n - i0 < VTU_CHUNK ? n - i0 : VTU_CHUNK;
    for (size_t i = 0; i < m; i++)
      for (size_t c = 0; c < nc; c++)
        memcpy(buf + (i * nc + c) * s, (const char *)f->comp[c] + (i0 + i) * s, s);
    if (afile_write(af, buf, m * nc * s, err)) return -1;
  }
  return 0;
}

/* Int64 block holding first, first + 1, ..., first + n - 1. */
static int put_sequence(struct afile *af, size_t n, int64_t first, struct hv_error *err)
{
  uint64_t nb = 8 * (uint64_t)n;
  int64_t buf[VTU_CHUNK];
  if (afile_write(af, &nb, sizeof nb, err)) return -1;
  for (size_t i0 = 0; i0 < n; i0 += VTU_CHUNK) {
    size_t m = n - i0 < VTU_CHUNK ? n - i0 : VTU_CHUNK;
    for (size_t i = 0; i < m; i++) buf[i] = first + (int64_t)(i0 + i);
    if (afile_write(af, buf, m * sizeof *buf, err)) return -1;
  }
  return 0;
}

static int put_cells(struct afile *af, size_t n, struct hv_error *err)
{
  unsigned char types[VTU_CHUNK];
  uint64_t nb = (uint64_t)n;
  memset(types, 1, sizeof types); /* VTK_VERTEX */
  if (put_sequence(af, n, 0, err) || put_sequence(af, n, 1, err) ||
      afile_write(af, &nb, sizeof nb, err))
    return -1;
  for (size_t i0 = 0; i0 < n; i0 += VTU_CHUNK) {
    size_t m = n - i0 < VTU_CHUNK ? n - i0 : VTU_CHUNK;
    if (afile_write(af, types, m, err)) return -1;
  }
  return 0;
}

static int vtu_body(struct afile *af, struct particles *p, const struct snapshot_meta *meta,
                    struct hv_error *err)
{
  struct pfield f[HV_MAX_FIELDS];
  int nf = particles_fields(p, f), ix = -1;
  for (int k = 0; k < nf; k++)
    if (strcmp(f[k].name, "x") == 0) ix = k;
  HV_CHECK(ix >= 0 && f[ix].ncomp == 3 && f[ix].type == PF_DOUBLE, "no position field x");
  size_t n = p->n;
  if (vtu_header(af, f, nf, ix, n, meta, err)) return -1;
  for (int k = 0; k < nf; k++)
    if (is_point_data(&f[k]) && put_field(af, &f[k], n, err)) return -1;
  if (put_field(af, &f[ix], n, err) || put_cells(af, n, err)) return -1;
  return afile_printf(af, err, "\n  </AppendedData>\n</VTKFile>\n");
}

int io_write_vtu(const char *path, struct particles *p, const struct snapshot_meta *meta,
                 struct hv_error *err)
{
  struct afile af;
  if (afile_open(&af, path, err)) return -1;
  if (vtu_body(&af, p, meta, err)) {
    afile_abort(&af);
    return -1;
  }
  return afile_commit(&af, err);
}
