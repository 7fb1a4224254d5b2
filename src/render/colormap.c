/* colormap.c — colours for the particles mode.
 *
 * The sequential map runs from dark indigo through blue, teal and green to yellow. Its
 * six control points were chosen for hvsph so that the CIE L* lightness rises steadily
 * (13.5 → 90, about 9.5 L* per eighth of the range), which keeps the order of values
 * readable in colour and in grey print; between control points the sRGB components are
 * interpolated linearly. tests/unit/test_render.c checks that L* increases.
 *
 * The material palette is ten well separated colours (material 0 a steel blue, 1 an
 * orange, ...), repeating after ten.
 */
#include "render/render.h"

static const struct {
  double t;
  unsigned char rgb[3];
} cmap_points[] = {
    {0.0, {48, 18, 80}},   /* dark indigo */
    {0.2, {72, 48, 150}},  /* violet blue */
    {0.4, {40, 110, 170}}, /* blue */
    {0.6, {30, 160, 140}}, /* teal */
    {0.8, {130, 200, 70}}, /* green */
    {1.0, {250, 230, 50}}, /* yellow */
};
#define CMAP_N ((int)(sizeof cmap_points / sizeof cmap_points[0]))

void render_colormap(double t, unsigned char rgb[3])
{
  if (!(t > 0.0)) t = 0.0; /* NaN too */
  if (t > 1.0) t = 1.0;
  int k = 0;
  while (k < CMAP_N - 2 && t > cmap_points[k + 1].t) k++;
  double f = (t - cmap_points[k].t) / (cmap_points[k + 1].t - cmap_points[k].t);
  for (int c = 0; c < 3; c++) {
    double a = cmap_points[k].rgb[c], b = cmap_points[k + 1].rgb[c];
    rgb[c] = (unsigned char)(a + f * (b - a) + 0.5);
  }
}

static const unsigned char palette[10][3] = {
    {70, 110, 190},  /* steel blue */
    {235, 140, 35},  /* orange */
    {55, 160, 75},   /* green */
    {205, 55, 55},   /* red */
    {140, 90, 185},  /* purple */
    {150, 105, 65},  /* brown */
    {225, 115, 180}, /* pink */
    {115, 115, 115}, /* grey */
    {175, 175, 40},  /* olive */
    {50, 180, 195},  /* cyan */
};

void render_palette(int k, unsigned char rgb[3])
{
  if (k < 0) k = -k;
  for (int c = 0; c < 3; c++) rgb[c] = palette[k % 10][c];
}
