/* canvas.c — an 8-bit RGB picture in memory, a few drawing primitives (blend, rectangle,
 * bitmap text) and its PNG writer (libpng, written whole or not at all through atomic_file).
 */
#include <errno.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>

#include "io/atomic_file.h"
#include "render/render_internal.h"
#include "version.h"

void canvas_init(struct canvas *c, int w, int h)
{
  c->w = w;
  c->h = h;
  c->rgb = hv_malloc((size_t)w * (size_t)h * 3, "picture");
  for (size_t k = 0; k < (size_t)w * (size_t)h; k++) {
    c->rgb[3 * k] = RENDER_BG_R;
    c->rgb[3 * k + 1] = RENDER_BG_G;
    c->rgb[3 * k + 2] = RENDER_BG_B;
  }
}

void canvas_free(struct canvas *c)
{
  free(c->rgb);
  c->rgb = NULL;
  c->w = c->h = 0;
}

void canvas_blend(struct canvas *c, int x, int y, const unsigned char rgb[3], double a)
{
  if (x < 0 || y < 0 || x >= c->w || y >= c->h || !(a > 0.0)) return;
  if (a > 1.0) a = 1.0;
  unsigned char *q = c->rgb + 3 * ((size_t)y * (size_t)c->w + (size_t)x);
  for (int k = 0; k < 3; k++) q[k] = (unsigned char)(q[k] + a * (rgb[k] - q[k]) + 0.5);
}

void canvas_rect(struct canvas *c, int x0, int y0, int x1, int y1, const unsigned char rgb[3])
{
  if (x0 < 0) x0 = 0;
  if (y0 < 0) y0 = 0;
  if (x1 > c->w) x1 = c->w;
  if (y1 > c->h) y1 = c->h;
  for (int y = y0; y < y1; y++)
    for (int x = x0; x < x1; x++) {
      unsigned char *q = c->rgb + 3 * ((size_t)y * (size_t)c->w + (size_t)x);
      q[0] = rgb[0];
      q[1] = rgb[1];
      q[2] = rgb[2];
    }
}

/* Next code point of UTF-8 text (malformed bytes come back as themselves). */
static unsigned long utf8_next(const char **s)
{
  const unsigned char *u = (const unsigned char *)*s;
  unsigned long cp = u[0];
  int extra = cp >= 0xF0 ? 3 : cp >= 0xE0 ? 2 : cp >= 0xC0 ? 1 : 0;
  for (int k = 1; k <= extra; k++)
    if ((u[k] & 0xC0) != 0x80) extra = 0;
  if (extra) {
    cp &= 0x3Fu >> extra;
    for (int k = 1; k <= extra; k++) cp = (cp << 6) | (u[k] & 0x3Fu);
  }
  *s += 1 + extra;
  return cp;
}

int canvas_text_width(int scale, const char *text)
{
  int n = 0;
  while (*text) {
    utf8_next(&text);
    n++;
  }
  return n * FONT_ADVANCE * scale;
}

int canvas_text(struct canvas *c, int x, int y, int scale, const unsigned char rgb[3],
                const char *text)
{
  int x0 = x;
  while (*text) {
    unsigned char g[FONT_H];
    if (font_glyph(utf8_next(&text), g)) font_glyph('?', g);
    for (int r = 0; r < FONT_H; r++)
      for (int col = 0; col < FONT_W; col++)
        if (g[r] & (0x10u >> col))
          canvas_rect(c, x + col * scale, y + r * scale, x + (col + 1) * scale, y + (r + 1) * scale,
                      rgb);
    x += FONT_ADVANCE * scale;
  }
  return x - x0;
}

/* libpng reports errors by longjmp; its message is kept for ours. */
struct png_err {
  char msg[256];
};

static void png_on_error(png_structp png, png_const_charp msg)
{
  /* libpng's "Write Error" is a failed fwrite: errno says why (a full disk) */
  const int e = errno;
  struct png_err *pe = png_get_error_ptr(png);
  if (pe)
    snprintf(pe->msg, sizeof pe->msg, "%s%s%s%s", msg, e ? " (" : "", e ? strerror(e) : "",
             e ? ")" : "");
  png_longjmp(png, 1);
}

static void png_on_warning(png_structp png, png_const_charp msg)
{
  (void)png;
  hv_warn("libpng: %s", msg);
}

/* Encodes the canvas into f. Returns 0, or -1 with the libpng message in pe. */
static int png_encode(FILE *f, const struct canvas *c, const char *description, png_bytep *rows,
                      struct png_err *pe)
{
  png_structp png =
      png_create_write_struct(PNG_LIBPNG_VER_STRING, pe, png_on_error, png_on_warning);
  if (!png) {
    snprintf(pe->msg, sizeof pe->msg, "libpng could not start");
    return -1;
  }
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    if (!pe->msg[0]) snprintf(pe->msg, sizeof pe->msg, "libpng failed");
    return -1;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, (png_uint_32)c->w, (png_uint_32)c->h, 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_text text[2];
  memset(text, 0, sizeof text);
  text[0].compression = text[1].compression = PNG_TEXT_COMPRESSION_NONE;
  text[0].key = (png_charp) "Software";
  text[0].text = (png_charp) "hvsph " HVSPH_VERSION;
  text[1].key = (png_charp) "Description";
  text[1].text = (png_charp)(description ? description : "");
  png_set_text(png, info, text, 2);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return 0;
}

int canvas_write_png(const struct canvas *c, const char *path, const char *description,
                     struct hv_error *err)
{
  struct atomic_file af;
  if (atomic_file_open(&af, path, err)) {
    err->code = HV_EXIT_INPUT; /* a folder that is missing or not writable: fix the command */
    return -1;
  }
  png_bytep *rows = hv_malloc((size_t)c->h * sizeof *rows, "PNG rows");
  for (int y = 0; y < c->h; y++) rows[y] = c->rgb + 3 * (size_t)y * (size_t)c->w;
  struct png_err pe = {{0}};
  errno = 0;
  int rc = png_encode(af.f, c, description, rows, &pe);
  free(rows);
  if (rc) {
    atomic_file_abort(&af);
    return hv_error_set(err, HV_EXIT_RUN, "cannot write '%s': %s", path, pe.msg);
  }
  return atomic_file_commit(&af, err);
}
