/* vtu_read.c — reading back the particle snapshots io_write_vtu writes (vtu.c has the
 * layout), so that `hvsph render`, `hvsph measure` and `hvsph validate` work on a run
 * that wrote only its default VTU files.
 *
 * Only hvsph's own form is read: UnstructuredGrid, header_type="UInt64", appended
 * raw data in the byte order of this machine, uncompressed or compressed by
 * vtkZLibDataCompressor. The XML header (everything before the appended block's '_')
 * is parsed for the DataArray elements of PointData and Points and for FieldData TIME and
 * GEOMETRY (1: an axisymmetric run's rings, which sets p->axisym; io_take_geometry);
 * each array's block is then read at its offset, its byte count (compressed: its block
 * count and sizes) checked against NumberOfPoints × components × type size and
 * against the file's size before anything is stored; a compressed block must inflate
 * to exactly its size.
 */
#define _FILE_OFFSET_BITS 64
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <zlib.h>

#include "core/infile.h"
#include "io/io_internal.h"
#include "io/snapshot.h"

#define VTU_HEADER_MAX (16u << 20) /* the XML before the data: a few kB in practice */
#define VTU_MAX_ARRAYS 64
#define VTU_CHUNK      4096 /* tuples per de-interleaving buffer */

struct vtu_array {
  char name[64], type[16];
  int ncomp;
  long long offset; /* from the byte after '_' */
};

static size_t vtk_size(const char *type)
{
  if (!strcmp(type, "Float64") || !strcmp(type, "Int64") || !strcmp(type, "UInt64")) return 8;
  if (!strcmp(type, "Int32") || !strcmp(type, "Float32") || !strcmp(type, "UInt32")) return 4;
  if (!strcmp(type, "UInt8") || !strcmp(type, "Int8")) return 1;
  return 0;
}

static const char *vtk_name(enum pf_type t)
{
  return t == PF_INT32 ? "Int32" : t == PF_INT64 ? "Int64" : "Float64";
}

struct vtu_header {
  size_t n;             /* NumberOfPoints */
  int zlib;             /* compressor="vtkZLibDataCompressor" */
  double time;          /* FieldData TIME, NaN when absent */
  int axisym;           /* FieldData GEOMETRY 1 (axisymmetric); 0 when absent or 0 */
  long long data_start; /* file position of the byte after '_' */
  int narr;
  struct vtu_array arr[VTU_MAX_ARRAYS]; /* PointData and Points */
};

static int bad(struct hv_error *err, const char *path, const char *what)
{
  return hv_error_set(err, HV_EXIT_INPUT, "'%s': %s (not a VTU snapshot written by hvsph?)", path,
                      what);
}

/* Parses the XML text h[0, len) up to the appended block's '_'. */
static int parse_header(const char *path, const char *h, size_t len, struct vtu_header *vh,
                        struct hv_error *err)
{
  const char *end = h + len;
  /* the root element starts a line (the comments before it are one line each, their
     text cleaned of control characters, so a case named "<VTKFile" cannot match) */
  const char *file = strstr(h, "\n<VTKFile ");
  if (!file) return bad(err, path, "no <VTKFile> element");
  const char *fe = strchr(file, '>');
  if (!fe) return bad(err, path, "unterminated <VTKFile> element");
  char v[64];
  if (io_xml_attr(file, fe, "type", v, sizeof v) || strcmp(v, "UnstructuredGrid"))
    return bad(err, path, "not an UnstructuredGrid");
  if (io_xml_attr(file, fe, "header_type", v, sizeof v) || strcmp(v, "UInt64"))
    return bad(err, path, "block headers are not UInt64");
  const unsigned short one = 1;
  unsigned char little;
  memcpy(&little, &one, 1);
  if (io_xml_attr(file, fe, "byte_order", v, sizeof v) ||
      strcmp(v, little ? "LittleEndian" : "BigEndian"))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "'%s': written in the other byte order (%s); "
                        "this machine reads only its own",
                        path, v);
  vh->zlib = 0;
  if (!io_xml_attr(file, fe, "compressor", v, sizeof v)) {
    if (strcmp(v, "vtkZLibDataCompressor"))
      return hv_error_set(err, HV_EXIT_INPUT,
                          "'%s': compressed by '%s'; hvsph reads "
                          "vtkZLibDataCompressor only",
                          path, v);
    vh->zlib = 1;
  }
  const char *piece = strstr(fe, "<Piece");
  if (!piece) return bad(err, path, "no <Piece> element");
  const char *pe = strchr(piece, '>');
  char *stop;
  if (!pe || io_xml_attr(piece, pe, "NumberOfPoints", v, sizeof v))
    return bad(err, path, "no NumberOfPoints");
  errno = 0;
  long long np = strtoll(v, &stop, 10);
  if (stop == v || *stop || np < 0 || errno) return bad(err, path, "NumberOfPoints is not a count");
  if (np > (1LL << 31))
    return hv_error_set(err, HV_EXIT_INPUT, "'%s': %lld points, more than hvsph reads", path, np);
  vh->n = (size_t)np;
  vh->time = NAN;
  /* FieldData TIME (ascii), before the Piece */
  const char *t = strstr(fe, "Name=\"TIME\"");
  if (t && t < piece) {
    const char *gt = strchr(t, '>');
    if (gt) {
      double tv = strtod(gt + 1, &stop);
      if (stop != gt + 1) vh->time = tv;
    }
  }
  /* FieldData GEOMETRY (ascii Int32), before the Piece: 1 axisymmetric, 0 or absent 3D */
  vh->axisym = 0;
  const char *g = strstr(fe, "Name=\"GEOMETRY\"");
  if (g && g < piece) {
    const char *gt = strchr(g, '>');
    long gv = gt ? strtol(gt + 1, &stop, 10) : -1;
    if (!gt || stop == gt + 1 || *stop != '<' || (gv != 0 && gv != 1))
      return hv_error_set(err, HV_EXIT_INPUT,
                          "'%s': FieldData GEOMETRY is not 0 (3D) or 1 (axisymmetric)", path);
    vh->axisym = (int)gv;
  }
  const char *app = strstr(pe, "<AppendedData");
  if (!app) return bad(err, path, "no <AppendedData> element");
  const char *piece2 = strstr(pe, "<Piece");
  if (piece2 && piece2 < app) return bad(err, path, "more than one <Piece>");
  const char *ae = strchr(app, '>');
  if (!ae || io_xml_attr(app, ae, "encoding", v, sizeof v) || strcmp(v, "raw"))
    return bad(err, path, "appended data not raw");
  const char *us = memchr(ae, '_', (size_t)(end - ae));
  if (!us) return bad(err, path, "no '_' before the appended data");
  vh->data_start = (long long)(us + 1 - h);
  /* the arrays of PointData and Points (Cells are not needed) */
  const char *cells = strstr(pe, "<Cells>");
  const char *last = cells && cells < app ? cells : app;
  vh->narr = 0;
  for (const char *d = strstr(pe, "<DataArray"); d && d < last; d = strstr(d + 1, "<DataArray")) {
    const char *de = strchr(d, '>');
    if (!de) return bad(err, path, "unterminated <DataArray>");
    if (vh->narr == VTU_MAX_ARRAYS) return bad(err, path, "too many arrays");
    struct vtu_array *a = &vh->arr[vh->narr];
    char fmt[16] = "", nc[16] = "1", off[32];
    if (io_xml_attr(d, de, "Name", a->name, sizeof a->name) ||
        io_xml_attr(d, de, "type", a->type, sizeof a->type))
      return bad(err, path, "a DataArray without Name or type");
    io_xml_attr(d, de, "NumberOfComponents", nc, sizeof nc);
    if (io_xml_attr(d, de, "format", fmt, sizeof fmt) || strcmp(fmt, "appended") ||
        io_xml_attr(d, de, "offset", off, sizeof off))
      return hv_error_set(err, HV_EXIT_INPUT, "'%s': array '%s' is not in the appended block", path,
                          a->name);
    for (int k = 0; k < vh->narr; k++)
      if (!strcmp(vh->arr[k].name, a->name))
        return hv_error_set(err, HV_EXIT_INPUT, "'%s': array '%s' appears twice", path, a->name);
    char *stop2;
    errno = 0;
    const long ncl = strtol(nc, &stop2, 10);
    a->ncomp = stop2 != nc && !*stop2 && ncl >= 1 && ncl <= 6 ? (int)ncl : 0;
    a->offset = strtoll(off, &stop, 10);
    if (stop == off || *stop || errno || a->offset < 0 || a->ncomp == 0)
      return hv_error_set(err, HV_EXIT_INPUT, "'%s': array '%s': bad offset or component count",
                          path, a->name);
    vh->narr++;
  }
  return 0;
}

/* Scatters the bytes [pos, pos + len) of an array's values (vectors interleaved) into
   field f at slots from first on; pos and len are multiples of the value size. */
static void scatter(const struct pfield *f, size_t first, uint64_t pos, const unsigned char *buf,
                    size_t len)
{
  const size_t s = pf_type_size(f->type), nc = (size_t)f->ncomp;
  const uint64_t e0 = pos / s;
  if (nc == 1) {
    memcpy((char *)f->comp[0] + (first + e0) * s, buf, len);
    return;
  }
  for (size_t k = 0; k < len / s; k++) {
    const uint64_t e = e0 + k;
    memcpy((char *)f->comp[e % nc] + (first + e / nc) * s, buf + k * s, s);
  }
}

static int cut_short(struct hv_error *err, const char *path, const struct vtu_array *a)
{
  return hv_error_set(err, HV_EXIT_INPUT,
                      "'%s': array '%s': the file ends inside its "
                      "block (cut short?)",
                      path, a->name);
}

static int short_read(FILE *fp, struct hv_error *err, const char *path, const struct vtu_array *a)
{
  return hv_error_set(err, HV_EXIT_INPUT, "cannot read '%s' (array '%s'): %s", path, a->name,
                      ferror(fp) ? strerror(errno ? errno : EIO) : "the file ends early");
}

static int wrong_size(struct hv_error *err, const char *path, const struct vtu_array *a,
                      uint64_t nb, size_t n, uint64_t want)
{
  return hv_error_set(err, HV_EXIT_INPUT,
                      "'%s': array '%s' holds %llu bytes, %zu points "
                      "need %llu",
                      path, a->name, (unsigned long long)nb, n, (unsigned long long)want);
}

/* A compressed block at the file's position (after fseeko): the header [blocks, block
   size, last partial block's size, compressed sizes], checked against want and the file's
   size; with f->comp[0], every zlib stream inflated into f. */
static int read_zblock(FILE *fp, const char *path, const struct vtu_array *a,
                       const struct pfield *f, size_t first, size_t n, uint64_t want, uint64_t room,
                       struct hv_error *err)
{
  const size_t s = pf_type_size(f->type);
  uint64_t h[3];
  if (room < sizeof h || fread(h, 8, 3, fp) != 3) return cut_short(err, path, a);
  const uint64_t nb = h[0], bs = h[1], last = h[2];
  if (bs == 0 || bs > (1u << 30) || bs % s || last >= bs || (nb == 0 && last))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "'%s': array '%s': a compression header hvsph "
                        "does not read (%llu blocks of %llu bytes, the last %llu)",
                        path, a->name, (unsigned long long)nb, (unsigned long long)bs,
                        (unsigned long long)last);
  if (nb > (room - sizeof h) / 8) return cut_short(err, path, a);
  const uint64_t total = nb == 0 ? 0 : last ? (nb - 1) * bs + last : nb * bs;
  if (total != want) return wrong_size(err, path, a, total, n, want);
  uint64_t *cs = malloc((size_t)(nb ? nb : 1) * sizeof *cs);
  if (!cs) return hv_error_set(err, HV_EXIT_RUN, "out of memory reading '%s'", path);
  int rc = 0;
  if (nb && fread(cs, 8, (size_t)nb, fp) != nb) rc = cut_short(err, path, a);
  /* zlib never makes more of bs bytes than compressBound(bs), so this bounds the buffer */
  const uint64_t bound = compressBound((uLong)bs);
  uint64_t left = room - sizeof h - 8 * nb;
  for (uint64_t b = 0; !rc && b < nb; b++) {
    if (cs[b] > bound)
      rc = hv_error_set(err, HV_EXIT_INPUT,
                        "'%s': array '%s': block %llu claims %llu "
                        "compressed bytes, more than zlib makes of %llu",
                        path, a->name, (unsigned long long)b, (unsigned long long)cs[b],
                        (unsigned long long)bs);
    else if (cs[b] > left)
      rc = cut_short(err, path, a);
    else
      left -= cs[b];
  }
  if (rc || !f->comp[0]) { /* with no storage: the check only */
    free(cs);
    return rc;
  }
  unsigned char *zin = malloc((size_t)bound), *out = malloc((size_t)bs);
  if (!zin || !out) rc = hv_error_set(err, HV_EXIT_RUN, "out of memory reading '%s'", path);
  for (uint64_t b = 0; !rc && b < nb; b++) {
    const uint64_t expect = b + 1 == nb && last ? last : bs;
    uLongf ol = (uLongf)bs;
    errno = 0;
    if (fread(zin, 1, (size_t)cs[b], fp) != cs[b]) {
      rc = short_read(fp, err, path, a);
      break;
    }
    const int zrc = uncompress(out, &ol, zin, (uLong)cs[b]);
    if (zrc != Z_OK || ol != expect)
      rc = hv_error_set(err, HV_EXIT_INPUT,
                        "'%s': array '%s': block %llu does not inflate "
                        "to its %llu bytes (zlib: %s; a damaged file?)",
                        path, a->name, (unsigned long long)b, (unsigned long long)expect,
                        zrc == Z_OK ? "another size" : zError(zrc));
    else
      scatter(f, first, b * bs, out, (size_t)ol);
  }
  free(zin);
  free(out);
  free(cs);
  return rc;
}

/* Checks one array's block (its byte count against n × components × size, and its
 * extent against the file's size) and, with f->comp[0], reads it into field f at slots
 * [first, first + n). */
static int read_block(FILE *fp, const char *path, const struct vtu_header *vh,
                      const struct vtu_array *a, const struct pfield *f, size_t first,
                      long long fsize, struct hv_error *err)
{
  const size_t s = pf_type_size(f->type), nc = (size_t)f->ncomp, n = vh->n;
  const uint64_t want = (uint64_t)n * nc * s;
  uint64_t nb = 0;
  if (a->offset > fsize - vh->data_start - 8) /* data_start < fsize: cannot overflow */
    return hv_error_set(err, HV_EXIT_INPUT,
                        "'%s': array '%s': its block lies beyond the end "
                        "of the file (cut short?)",
                        path, a->name);
  const long long pos = vh->data_start + a->offset;
  errno = 0;
  if (fseeko(fp, (off_t)pos, SEEK_SET))
    return hv_error_set(err, HV_EXIT_INPUT,
                        "'%s': array '%s': its block lies beyond the end "
                        "of the file (cut short?)",
                        path, a->name);
  if (vh->zlib) return read_zblock(fp, path, a, f, first, n, want, (uint64_t)(fsize - pos), err);
  if (fread(&nb, 8, 1, fp) != 1) return cut_short(err, path, a);
  if (nb != want) return wrong_size(err, path, a, nb, n, want);
  if (nb > (uint64_t)(fsize - pos - 8)) return cut_short(err, path, a);
  if (!f->comp[0]) return 0; /* the check only */
  /* VTU_CHUNK tuples of at most 6 values of 8 bytes: a multiple of every value size */
  const size_t chunk = VTU_CHUNK * 48;
  unsigned char *buf = malloc(chunk);
  if (!buf) return hv_error_set(err, HV_EXIT_RUN, "out of memory reading '%s'", path);
  for (uint64_t at = 0; at < nb; at += chunk) {
    const size_t len = nb - at < chunk ? (size_t)(nb - at) : chunk;
    if (fread(buf, 1, len, fp) != len) {
      free(buf);
      return short_read(fp, err, path, a);
    }
    scatter(f, first, at, buf, len);
  }
  free(buf);
  return 0;
}

/* The XML header of an open VTU file parsed into vh: read until the appended block's
 * '_' is in the buffer (nothing of the binary data after it is parsed). Returns 0 or -1
 * with err set. */
static int read_header(FILE *fp, const char *path, struct vtu_header *vh, struct hv_error *err)
{
  /* the header: read until the appended block's '_' is in the buffer */
  size_t cap = 65536, len = 0;
  char *h = NULL;
  int rc = 0;
  while (!rc) {
    char *nh = realloc(h, cap + 1);
    if (!nh) {
      rc = hv_error_set(err, HV_EXIT_RUN, "out of memory reading '%s'", path);
      break;
    }
    h = nh;
    errno = 0;
    len += fread(h + len, 1, cap - len, fp);
    h[len] = '\0';
    if (ferror(fp)) {
      rc = hv_error_set(err, HV_EXIT_INPUT, "cannot read '%s': %s", path,
                        strerror(errno ? errno : EIO));
      break;
    }
    /* searched for after the root element's start: the comments before it hold the
       case and material names, which may contain "<AppendedData" and '_' */
    const char *root = strstr(h, "\n<VTKFile ");
    const char *app = root ? strstr(root, "<AppendedData") : NULL;
    char *us = app ? strchr(app, '_') : NULL;
    if (us) { /* the header ends here: parse nothing of the binary data after it */
      len = (size_t)(us + 1 - h);
      h[len] = '\0';
      break;
    }
    if (len < cap || cap >= VTU_HEADER_MAX) {
      rc = bad(err, path, len < cap ? "no appended data block" : "header too long");
      break;
    }
    cap *= 4;
  }
  if (!rc) rc = parse_header(path, h, len, vh, err);
  free(h);
  return rc;
}

int io_read_particles_vtu(const char *path, struct particles *p, double *time, struct hv_error *err)
{
  if (time) *time = NAN;
  long long fsize; /* a regular file only: a FIFO would block the open */
  FILE *fp = hv_open_input(path, NULL, 0, &fsize, err);
  if (!fp) return -1;
  struct vtu_header *vh = calloc(1, sizeof *vh);
  int rc = vh ? read_header(fp, path, vh, err)
              : hv_error_set(err, HV_EXIT_RUN, "out of memory reading '%s'", path);
  /* a whole file ends with the closing tag (the writer's last bytes) */
  char tail[32] = "";
  if (!rc && (fsize < 24 || fseeko(fp, (off_t)(fsize - 24), SEEK_SET) ||
              fread(tail, 1, 24, fp) != 24 || !strstr(tail, "</VTKFile>")))
    rc = hv_error_set(err, HV_EXIT_INPUT,
                      "'%s': no closing </VTKFile> at its end (the file "
                      "was cut short?)",
                      path);
  const struct vtu_array *ax = NULL, *aid = NULL;
  int solid = 0, av = 0, crack = 0;
  struct pfield fv[HV_MAX_FIELDS];
  const int nf = particles_fields_all(NULL, fv);
  int match[VTU_MAX_ARRAYS];
  for (int k = 0; !rc && k < vh->narr; k++) {
    const struct vtu_array *a = &vh->arr[k];
    match[k] = -1;
    if (vtk_size(a->type) == 0)
      rc = hv_error_set(err, HV_EXIT_INPUT,
                        "'%s': array '%s' has type '%s', which hvsph "
                        "does not write",
                        path, a->name, a->type);
    for (int j = 0; !rc && j < nf; j++) {
      if (strcmp(a->name, fv[j].name) != 0) continue;
      if (strcmp(a->type, vtk_name(fv[j].type)) || a->ncomp != fv[j].ncomp)
        rc = hv_error_set(err, HV_EXIT_INPUT,
                          "'%s': array '%s' is %s × %d, hvsph's field is "
                          "%s × %d",
                          path, a->name, a->type, a->ncomp, vtk_name(fv[j].type), fv[j].ncomp);
      match[k] = j;
      if (!strcmp(a->name, "x")) ax = a;
      if (!strcmp(a->name, "id")) aid = a;
      if (fv[j].flags & PF_SOLID) solid = 1;
      if (fv[j].flags & PF_AV) av = 1;
      if (fv[j].flags & PF_CRACK) crack = 1;
    }
  }
  if (!rc && !ax) rc = bad(err, path, "no point positions (array 'x')");
  if (!rc && !aid) rc = bad(err, path, "no particle identifiers (array 'id')");
  /* every block checked before anything is allocated: a file claiming more points
     than it holds is refused here, not by running out of memory */
  for (int k = 0; !rc && k < vh->narr; k++)
    if (match[k] >= 0) rc = read_block(fp, path, vh, &vh->arr[k], &fv[match[k]], 0, fsize, err);
  const size_t n0 = p->n;
  if (!rc) {
    if (solid) particles_enable_solid(p);
    if (av) particles_enable_av(p);
    if (crack) particles_enable_crack(p);
    const size_t first = particles_add(p, vh->n);
    struct pfield f[HV_MAX_FIELDS];
    particles_fields_all(p, f); /* after particles_add: the arrays may have moved */
    for (int k = 0; !rc && k < vh->narr; k++)
      if (match[k] >= 0)
        rc = read_block(fp, path, vh, &vh->arr[k], &f[match[k]], first, fsize, err);
    if (!rc) rc = io_take_geometry(p, n0, vh->axisym, path, err);
    if (rc) {
      p->n = n0; /* drop what was read */
      p->n_ghost = 0;
    } else if (time) {
      *time = vh->time;
    }
  }
  free(vh);
  fclose(fp);
  return rc;
}

int io_read_particles(const char *path, struct particles *p, double *time, struct hv_error *err)
{
  const size_t len = strlen(path);
  if (len > 4 && !strcmp(path + len - 4, ".vtu")) return io_read_particles_vtu(path, p, time, err);
  return io_read_particles_csv(path, p, time, err);
}

int io_read_material_names(const char *path, char names[][64], int max)
{
  struct hv_error ignored;
  FILE *f = hv_open_input(path, NULL, 0, NULL, &ignored); /* a FIFO would block */
  if (!f) return 0;
  char line[8192];
  int n = 0;
  /* CSV: the "# materials ..." comment; VTU: "<!-- materials ... -->" in its first lines */
  while (fgets(line, sizeof line, f)) {
    char *m = NULL;
    if (!strncmp(line, "# materials", 11))
      m = line + 11;
    else if (!strncmp(line, "<!-- materials", 14))
      m = line + 14;
    else if (line[0] != '#' && strncmp(line, "<?xml", 5) && strncmp(line, "<!--", 4))
      break;
    if (!m) continue;
    char *close = strstr(m, "-->");
    if (close) *close = '\0';
    char *save = NULL;
    for (char *t = strtok_r(m, " \t\r\n", &save); t; t = strtok_r(NULL, " \t\r\n", &save)) {
      char *eq = strchr(t, '=');
      char *end;
      long k = eq ? strtol(t, &end, 10) : -1;
      if (!eq || end != eq || k < 0 || k >= max) continue;
      snprintf(names[k], 64, "%s", eq + 1);
      if (k + 1 > n) n = (int)k + 1;
    }
  }
  fclose(f);
  return n;
}
