/* vtu.c — particle snapshots as VTK XML UnstructuredGrid files (.vtu).
 *
 * Layout (VTK file formats, "XML File Formats", appended raw data):
 *   <?xml?>, then two comments: the version and case, the material names
 *   <VTKFile type="UnstructuredGrid" version="1.0" byte_order=".." header_type="UInt64"
 *            [compressor="vtkZLibDataCompressor"]>
 *     FieldData, ascii: TIME [s] (Float64), STEP (Int64), GEOMETRY (Int32 1, only for an
 *       axisymmetric run: points in the (x, r) half-plane, m the ring mass; absent: 3D,
 *       read back as p->axisym), and per material and per body
 *       an Int32 array named "mat <name>" or "body <name>" holding its index (the value
 *       of the PointData mat and body): the names, readable in ParaView's Information
 *       panel, by vtk and by meshio (a String array would be more direct, but meshio 7.0
 *       refuses the whole file for it)
 *     Piece NumberOfPoints=n NumberOfCells=n
 *       PointData: every PF_OUT field except x, format="appended"
 *       Points: x (Float64, 3 components)
 *       Cells: connectivity 0..n-1, offsets 1..n, types 1 (VTK_VERTEX)
 *     <AppendedData encoding="raw">_ then one block per array, in the REVERSE of the
 *       order the DataArrays are declared in (types first, the first PointData array
 *       last); offset= is where an array's block starts, counted from the byte after '_'.
 *   An uncompressed block: a UInt64 byte count, then the values (host byte order;
 *   vectors interleaved x0 y0 z0 x1 ...).
 *   A compressed block (output.compress): the UInt64 header [number of blocks b, block
 *   size VTU_ZBLOCK, size of the last block if it is partial (else 0), the compressed
 *   size of each block], then the b zlib streams, each of VTU_ZBLOCK bytes of the same
 *   values (the last may be shorter).
 *
 * Why reversed: meshio 7.0 (Debian 12) re-encodes raw appended data as base64 and, walking
 * the blocks in file order, finds each block's DataArray by the block's raw offset, while
 * the DataArrays it has done already carry their new base64 offsets; the first DataArray of
 * the document with that value wins. In declaration order an earlier array's new offset
 * can equal a later one's raw offset (3,024 particles: body's new offset 48408 is m's raw
 * offset, so body was read from m's 24,192 bytes as 6,048 Int32). In reverse order the
 * array looked for comes, in the document, before every array already done, so it is the
 * one found. ParaView, vtk and hvsph read each array at its offset, in any order.
 *
 * Real particles only; written whole through atomic_file. A compressed file is built in memory
 * (the offsets in the XML depend on the compressed sizes): at most about the size of the
 * uncompressed snapshot, besides the particles.
 */
#include <inttypes.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "io/atomic_file.h"
#include "io/io_internal.h"
#include "io/snapshot.h"

#define VTU_CHUNK  32768 /* bytes of an array's values staged at a time; a multiple of 8 */
#define VTU_ZBLOCK 32768 /* uncompressed bytes per zlib block: VTK's own default */
/* zlib's fastest level: a snapshot's doubles are nearly random in their low bytes, so a
   higher level gains little (measured on a bumper-1 snapshot: docs/output-files.md) */
#define VTU_ZLEVEL     Z_BEST_SPEED
#define VTU_MAX_ARRAYS (HV_MAX_FIELDS + 3)

enum vtu_source { SRC_FIELD, SRC_CONNECTIVITY, SRC_OFFSETS, SRC_TYPES };

struct vtu_array {
  const char *name, *type;
  int ncomp; /* 0: no NumberOfComponents attribute (the cell arrays) */
  enum vtu_source src;
  const struct pfield *f; /* SRC_FIELD */
  size_t esize;           /* bytes per value */
  uint64_t bytes;         /* of the values */
  uint64_t block;         /* of the appended block: header and data */
  uint64_t offset;        /* of the block, from the byte after '_' */
  uint64_t *zhdr;         /* compressed: the header (3 + blocks entries) */
  unsigned char *z;       /* compressed: the zlib streams, back to back */
  size_t zlen;
};

static const char *vtk_type(enum pf_type t)
{
  switch (t) {
  case PF_INT32: return "Int32";
  case PF_INT64: return "Int64";
  case PF_DOUBLE: return "Float64";
  }
  return "Float64";
}

static int is_point_data(const struct pfield *f)
{
  return (f->flags & PF_OUT) && strcmp(f->name, "x") != 0;
}

/* The bytes [start, start + len) of a's values into buf; start and len are multiples of
   a->esize. */
static void fill(const struct vtu_array *a, uint64_t start, size_t len, unsigned char *buf)
{
  const size_t s = a->esize, m = len / s;
  const uint64_t e0 = start / s;
  if (a->src == SRC_TYPES) {
    memset(buf, 1, len); /* VTK_VERTEX */
    return;
  }
  if (a->src != SRC_FIELD) { /* connectivity 0, 1, ...; offsets 1, 2, ... */
    const int64_t d = a->src == SRC_OFFSETS;
    for (size_t k = 0; k < m; k++) {
      const int64_t v = (int64_t)(e0 + k) + d;
      memcpy(buf + 8 * k, &v, 8);
    }
    return;
  }
  const size_t nc = (size_t)a->f->ncomp;
  if (nc == 1) {
    memcpy(buf, (const char *)a->f->comp[0] + e0 * s, len);
    return;
  }
  for (size_t k = 0; k < m; k++) {
    const uint64_t e = e0 + k;
    memcpy(buf + k * s, (const char *)a->f->comp[e % nc] + (e / nc) * s, s);
  }
}

/* Compresses a's values into a->zhdr and a->z, block by block. */
static int compress_array(struct vtu_array *a, unsigned char *buf, const char *path,
                          struct hv_error *err)
{
  const uint64_t nb = (a->bytes + VTU_ZBLOCK - 1) / VTU_ZBLOCK;
  const uLong bound = compressBound(VTU_ZBLOCK);
  unsigned char *zb = hv_malloc(bound, "snapshot compression");
  a->zhdr = hv_malloc((size_t)(3 + nb) * sizeof *a->zhdr, "snapshot compression");
  a->zhdr[0] = nb;
  a->zhdr[1] = VTU_ZBLOCK;
  a->zhdr[2] = a->bytes % VTU_ZBLOCK;
  size_t cap = 0;
  a->zlen = 0;
  for (uint64_t b = 0; b < nb; b++) {
    const uint64_t pos = b * VTU_ZBLOCK;
    const size_t len = a->bytes - pos < VTU_ZBLOCK ? (size_t)(a->bytes - pos) : VTU_ZBLOCK;
    fill(a, pos, len, buf);
    uLongf zl = bound;
    const int zrc = compress2(zb, &zl, buf, (uLong)len, VTU_ZLEVEL);
    if (zrc != Z_OK) {
      free(zb);
      return hv_error_set(err, HV_EXIT_RUN,
                          "cannot write '%s': zlib compression of array "
                          "'%s' failed (%d)",
                          path, a->name, zrc);
    }
    if (a->zlen + zl > cap) {
      cap = 2 * cap + 4 * (size_t)bound;
      a->z = hv_realloc(a->z, cap, "snapshot compression");
    }
    memcpy(a->z + a->zlen, zb, zl);
    a->zlen += zl;
    a->zhdr[3 + b] = zl;
  }
  free(zb);
  if (a->zlen) a->z = hv_realloc(a->z, a->zlen, "snapshot compression"); /* the slack back */
  a->block = 8 * (3 + nb) + a->zlen;
  return 0;
}

static int put_block(struct atomic_file *af, const struct vtu_array *a, unsigned char *buf,
                     struct hv_error *err)
{
  if (a->zhdr)
    return atomic_file_write(af, a->zhdr, (size_t)(3 + a->zhdr[0]) * sizeof *a->zhdr, err) ||
           atomic_file_write(af, a->z, a->zlen, err);
  if (atomic_file_write(af, &a->bytes, sizeof a->bytes, err)) return -1;
  for (uint64_t pos = 0; pos < a->bytes; pos += VTU_CHUNK) {
    const size_t len = a->bytes - pos < VTU_CHUNK ? (size_t)(a->bytes - pos) : VTU_CHUNK;
    fill(a, pos, len, buf);
    if (atomic_file_write(af, buf, len, err)) return -1;
  }
  return 0;
}

/* FieldData arrays "<prefix> <name>" holding each name's index. */
static int put_names(struct atomic_file *af, const char *prefix, const char *const *names, int n,
                     struct hv_error *err)
{
  for (int k = 0; names && k < n; k++) {
    char name[256];
    io_clean_text(name, sizeof name, names[k], "?", 0);
    if (atomic_file_printf(af, err, "      <DataArray type=\"Int32\" Name=\"%s ", prefix) ||
        io_put_xml_attr(af, name, err) ||
        atomic_file_printf(af, err, "\" NumberOfTuples=\"1\" format=\"ascii\">%d</DataArray>\n", k))
      return -1;
  }
  return 0;
}

static int put_array_tag(struct atomic_file *af, const struct vtu_array *a, struct hv_error *err)
{
  char nc[48] = "";
  if (a->ncomp) snprintf(nc, sizeof nc, " NumberOfComponents=\"%d\"", a->ncomp);
  return atomic_file_printf(af, err,
                            "        <DataArray type=\"%s\" Name=\"%s\"%s format=\"appended\""
                            " offset=\"%" PRIu64 "\"/>\n",
                            a->type, a->name, nc, a->offset);
}

static int vtu_header(struct atomic_file *af, const struct vtu_array *arr, int na, int npd,
                      size_t n, int axisym, const struct snapshot_meta *meta, struct hv_error *err)
{
  if (io_put_xml_prologue(af, meta, err) || io_put_materials(af, meta, "<!-- ", " -->\n", 1, err) ||
      atomic_file_printf(af, err,
                         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"%s\""
                         " header_type=\"UInt64\"%s>\n  <UnstructuredGrid>\n    <FieldData>\n"
                         "      <DataArray type=\"Float64\" Name=\"TIME\" NumberOfTuples=\"1\""
                         " format=\"ascii\">%.17g</DataArray>\n"
                         "      <DataArray type=\"Int64\" Name=\"STEP\" NumberOfTuples=\"1\""
                         " format=\"ascii\">%ld</DataArray>\n",
                         io_byte_order(),
                         meta && meta->vtu_zlib ? " compressor=\"vtkZLibDataCompressor\"" : "",
                         meta ? meta->time : 0.0, meta ? meta->step : 0L) ||
      (axisym && atomic_file_printf(af, err,
                                    "      <DataArray type=\"Int32\" Name=\"GEOMETRY\""
                                    " NumberOfTuples=\"1\" format=\"ascii\">1</DataArray>\n")) ||
      (meta && put_names(af, "mat", meta->material_names, meta->nmat, err)) ||
      (meta && put_names(af, "body", meta->body_names, meta->nbody, err)) ||
      atomic_file_printf(af, err,
                         "    </FieldData>\n    <Piece NumberOfPoints=\"%zu\""
                         " NumberOfCells=\"%zu\">\n      <PointData>\n",
                         n, n))
    return -1;
  for (int k = 0; k < na; k++) {
    if (k == npd && atomic_file_printf(af, err, "      </PointData>\n      <Points>\n")) return -1;
    if (k == npd + 1 && atomic_file_printf(af, err, "      </Points>\n      <Cells>\n")) return -1;
    if (put_array_tag(af, &arr[k], err)) return -1;
  }
  return atomic_file_printf(af, err,
                            "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
                            "  <AppendedData encoding=\"raw\">\n   _");
}

/* The arrays in declaration order: PointData (npd of them), Points, the three Cells. */
static int vtu_arrays(const struct pfield *f, int nf, size_t n, struct vtu_array *arr, int *npd)
{
  int na = 0, ix = -1;
  for (int k = 0; k < nf; k++) {
    if (!strcmp(f[k].name, "x")) ix = k;
    if (!is_point_data(&f[k])) continue;
    arr[na++] = (struct vtu_array){.name = f[k].name,
                                   .type = vtk_type(f[k].type),
                                   .ncomp = f[k].ncomp,
                                   .src = SRC_FIELD,
                                   .f = &f[k],
                                   .esize = pf_type_size(f[k].type)};
  }
  HV_CHECK(ix >= 0 && f[ix].ncomp == 3 && f[ix].type == PF_DOUBLE, "no position field x");
  *npd = na;
  arr[na++] = (struct vtu_array){
      .name = "x", .type = "Float64", .ncomp = 3, .src = SRC_FIELD, .f = &f[ix], .esize = 8};
  arr[na++] = (struct vtu_array){
      .name = "connectivity", .type = "Int64", .src = SRC_CONNECTIVITY, .esize = 8};
  arr[na++] =
      (struct vtu_array){.name = "offsets", .type = "Int64", .src = SRC_OFFSETS, .esize = 8};
  arr[na++] = (struct vtu_array){.name = "types", .type = "UInt8", .src = SRC_TYPES, .esize = 1};
  for (int k = 0; k < na; k++) {
    const uint64_t nc = arr[k].src == SRC_FIELD ? (uint64_t)arr[k].f->ncomp : 1;
    arr[k].bytes = (uint64_t)n * nc * arr[k].esize;
    arr[k].block = 8 + arr[k].bytes;
  }
  return na;
}

static int vtu_body(struct atomic_file *af, struct particles *p, const struct snapshot_meta *meta,
                    struct vtu_array *arr, unsigned char *buf, struct hv_error *err)
{
  struct pfield f[HV_MAX_FIELDS];
  const int nf = particles_fields(p, f);
  int npd;
  const int na = vtu_arrays(f, nf, p->n, arr, &npd);
  if (meta && meta->vtu_zlib)
    for (int k = 0; k < na; k++)
      if (compress_array(&arr[k], buf, af->path, err)) return -1;
  uint64_t off = 0; /* the blocks in reverse order (see the file's head) */
  for (int k = na - 1; k >= 0; k--) {
    arr[k].offset = off;
    off += arr[k].block;
  }
  if (vtu_header(af, arr, na, npd, p->n, p->axisym, meta, err)) return -1;
  for (int k = na - 1; k >= 0; k--)
    if (put_block(af, &arr[k], buf, err)) return -1;
  return atomic_file_printf(af, err, "\n  </AppendedData>\n</VTKFile>\n");
}

int io_write_vtu(const char *path, struct particles *p, const struct snapshot_meta *meta,
                 struct hv_error *err)
{
  struct atomic_file af;
  if (atomic_file_open(&af, path, err)) return -1;
  struct vtu_array arr[VTU_MAX_ARRAYS] = {{0}};
  unsigned char *buf = hv_malloc(VTU_CHUNK > VTU_ZBLOCK ? VTU_CHUNK : VTU_ZBLOCK, "snapshot");
  int rc = vtu_body(&af, p, meta, arr, buf, err);
  free(buf);
  for (int k = 0; k < VTU_MAX_ARRAYS; k++) {
    free(arr[k].zhdr);
    free(arr[k].z);
  }
  if (rc) {
    atomic_file_abort(&af);
    return -1;
  }
  return atomic_file_commit(&af, err);
}
