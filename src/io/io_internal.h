/* io_internal.h — helpers shared by the writers in src/io/ (not a public API). */
#ifndef HV_IO_INTERNAL_H
#define HV_IO_INTERNAL_H

#include <stddef.h>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/snapshot.h"

/* Copies src (or fallback when src is NULL or empty) into dst for use inside a
 * one-line comment: control characters and bytes that are not part of well-formed
 * UTF-8 become '_', and when xml_comment is set "--" (not allowed inside an XML
 * comment) becomes "-_". Truncates to len - 1, never inside a UTF-8 character. */
void io_clean_text(char *dst, size_t len, const char *src, const char *fallback, int xml_comment);

/* Writes "<prefix>materials 0=name0 1=name1 ...<suffix>" when meta lists
 * materials; writes nothing otherwise. Returns -1 on a write error (err set). */
int io_put_materials(struct atomic_file *af, const struct snapshot_meta *meta, const char *prefix,
                     const char *suffix, int xml_comment, struct hv_error *err);

/* Writes the first two lines of a VTU or PVD file: the XML declaration and the comment
 * "<!-- hvsph VERSION case NAME -->" (both cleaned by io_clean_text); -1 on a write error. */
int io_put_xml_prologue(struct atomic_file *af, const struct snapshot_meta *meta,
                        struct hv_error *err);

/* This machine's byte order as a VTKFile's byte_order attribute names it. */
const char *io_byte_order(void);

/* Writes s as the value of an XML attribute (escaping & < > " '); -1 on a write error. */
int io_put_xml_attr(struct atomic_file *af, const char *s, struct hv_error *err);

/* The value of the attribute `name` in the XML tag [s, end) (the tag's text from its
 * '<'), the five character entities decoded, into buf (len bytes); -1 when the tag has no
 * such attribute, its value is not closed or does not fit, or holds another entity
 * (hvsph's writers write none). Reads the VTU and PVD files back. */
int io_xml_attr(const char *s, const char *end, const char *name, char *buf, size_t len);

/* The geometry of a snapshot just read (axisym: 1 axisymmetric, 0 3D) given to the store p,
 * whose particles [n0, p->n) came from path: p->axisym is set to it. Refused (HV_EXIT_INPUT,
 * naming the file): a store that already held particles of the other geometry (n0 > 0),
 * and in an axisymmetric snapshot a particle off the half-plane (r = y < 0 or z != 0),
 * which no measurement or picture could place; the message names its index and id. */
int io_take_geometry(struct particles *p, size_t n0, int axisym, const char *path,
                     struct hv_error *err);

#endif
