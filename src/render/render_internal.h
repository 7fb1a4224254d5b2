/* render_internal.h — the pieces of the render module shared between its files:
 * an RGB canvas with a few drawing primitives, the built-in bitmap font, the PNG
 * writer, and the two modes' drawing functions. Not for use outside src/render/.
 */
#ifndef HV_RENDER_INTERNAL_H
#define HV_RENDER_INTERNAL_H

#include <stddef.h>

#include "core/error.h"
#include "particles/particles.h"
#include "render/render.h"

/* 8-bit sRGB picture, rows top to bottom. */
struct canvas {
  int w, h;
  unsigned char *rgb; /* 3 * w * h bytes */
};

void canvas_init(struct canvas *c, int w, int h); /* filled with the background colour */
void canvas_free(struct canvas *c);
/* Mixes colour into pixel (x, y) with opacity a in [0, 1]; outside the canvas: nothing. */
void canvas_blend(struct canvas *c, int x, int y, const unsigned char rgb[3], double a);
/* Fills [x0, x1) × [y0, y1), clipped to the canvas. */
void canvas_rect(struct canvas *c, int x0, int y0, int x1, int y1, const unsigned char rgb[3]);
/* Draws UTF-8 text with its top-left corner at (x, y), each font pixel as a scale × scale
 * square; returns the advance [px]. Characters the font lacks are drawn as '?'. */
int canvas_text(struct canvas *c, int x, int y, int scale, const unsigned char rgb[3],
                const char *text);
/* Width [px] that canvas_text would advance. */
int canvas_text_width(int scale, const char *text);
/* Writes the canvas as an 8-bit RGB PNG through atomic_file, with tEXt chunks Software
 * ("hvsph <version>") and Description. */
int canvas_write_png(const struct canvas *c, const char *path, const char *description,
                     struct hv_error *err);

/* Font: cells of FONT_W × FONT_H pixels (5 × 7 above the baseline plus a descender row),
 * advance FONT_W + 1. font_glyph fills FONT_H row masks (bit 4 the leftmost column) and
 * returns 0, or -1 when the code point has no glyph. */
#define FONT_W       5
#define FONT_H       8
#define FONT_ADVANCE 6
int font_glyph(unsigned long cp, unsigned char rows[FONT_H]);

/* The radiograph: film picture of the areal density into the plot area, and the caption's
 * density wedge. */
void render_film(struct canvas *c, const struct render_view *view, const double *sigma, double mu);

/* The kernel column table and the mass-conserving deposition of radiograph.c, for the
 * axisymmetric radiograph (radiograph_rz.c): render_columns_deposit spreads mass m at
 * (fu, fv) [pixel units, integers at pixel centres] with h = hp pixels into acc
 * (nu × nv, row-major), as radiograph.c spreads a particle. Freed with free(). */
struct render_columns;
struct render_columns *render_columns_new(void);
void render_columns_deposit(const struct render_columns *c, double *acc, int nu, int nv, double fu,
                            double fv, double hp, double m);
#define HV_RENDER_PI 3.14159265358979323846

/* Axes with ticks in mm in the margins of the view: left (v) and bottom (u) edges of the
 * plot area (axes.c). */
void render_axes(struct canvas *c, const struct render_view *v);
/* Body labels drawn into the plot canvas (of the plot area's size): each body's name
 * centred at the mass-weighted centre of its particles in view, where the label lies
 * wholly in the plot and overlaps no label placed before (bodies in index order).
 * Returns the count of labels drawn. */
int render_body_labels(struct canvas *plot, const struct particles *p, const struct render_view *v,
                       const struct render_info *info);
#define RENDER_MAX_BODIES 256 /* bodies labelled: indices below this */

/* The palette slot of each material index 0..nmat-1 (slot[m]): the materials ranked by
 * the first body (lowest body index) made of them, ties and materials without particles
 * by index. A case's bodies come in the case file's order whatever order its materials
 * were numbered in (a `materials:` block, or one made by --set, numbers them otherwise),
 * so the same material of the same case gets the same colour in every run. */
void render_material_slots(const struct particles *p, int nmat, int *slot);
/* Its two steps, so that a series of pictures can rank over all of them: first[m] lowered
 * to the lowest body index of p's particles of material m (start from INT_MAX), and the
 * slots ranked from first[]. */
void render_material_first_body(const struct particles *p, int nmat, int *first);
void render_material_rank(const int *first, int nmat, int *slot);
/* Material indices at or above this are drawn but get no legend entry. */
#define RENDER_MATERIAL_CAP 1024
/* Material names read from a snapshot's "materials" comment. */
#define RENDER_MAX_MATERIALS 64

/* Particles mode: draws the discs into the plot area; *lo, *hi get the colour range used
 * (SI); present[k] is set for every material index drawn (k < nmat_present), whose
 * colour is the palette's entry slot[k]. Returns the count of discs drawn. */
size_t render_discs(struct canvas *c, const struct particles *p, const struct render_view *view,
                    const struct render_options *o, double *lo, double *hi, unsigned char *present,
                    const int *slot, int nmat_present);

/* The caption band below the plot: scale bar, time, view, and the colour key of the mode. */
struct caption_key {
  int kind;      /* 0: film wedge, 1: colour bar, 2: material legend */
  double lo, hi; /* range of the key in SI */
  double unit;   /* SI per display unit (e.g. 1e3 for km/s) */
  const char
      *label[2]; /* quantity and unit, e.g. "|v| [km/s]": long form, short form (may be NULL) */
  double mu;     /* [m2/kg] film wedge */
  const unsigned char *present; /* materials drawn (legend) */
  const int *slot;              /* palette slot of each material (legend order) */
  int nmat;
};
/* what[0]: the long description of the view, what[1] a short one for narrow pictures. */
void render_caption(struct canvas *c, const struct render_view *view,
                    const struct render_info *info, const char *const what[2],
                    const struct caption_key *key);

#endif
