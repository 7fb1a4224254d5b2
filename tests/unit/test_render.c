/* test_render.c — pictures checked by their numbers: the column-integrated kernel, mass
 * conservation of the areal density picture (mirrored: twice), the peak areal density of
 * a uniform sphere (2Rρ) and of a plate (ρt), the colour map's lightness order, the PNG
 * written by `hvsph render` (size, background, atomic replacement) and its errors, and
 * `hvsph render RUNDIR -o FRAMEDIR` on a tiny run: one frame per snapshot of its run.pvd
 * (or summary.csv), none for an earlier run's left in the folder, frames numbered
 * contiguously, one size, and each frame exactly the picture of its snapshot alone with
 * the union of the frames' extents and colour ranges given as --box and --range.
 */
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <unistd.h>

#include "io/atomic_file.h"
#include "io/snapshot.h"
#include "render/render.h"
#include "render/render_internal.h"
#include "testlib.h"
#include "testparticles.h"

#define PI        3.14159265358979323846
#define RHO_STEEL 7850.0

/* ---- particle sets ------------------------------------------------------ */

static void put(struct particles *p, double x, double y, double z, double m, double h, double rho,
                int mat, double vx)
{
  const size_t i = tp_add(p, x, y, z, m, h, rho, 0);
  p->v[0][i] = vx;
  p->mat[i] = mat;
  p->p[i] = 1e9 * vx / 3000.0;
}

/* Sphere of radius R about c on a cubic lattice (points at c + (k + 1/2)dx, so none lies
 * on a plane through the centre); half: only z >= c_z. h = 1.2 dx, m = ρ dx³. */
static void add_sphere(struct particles *p, const double c[3], double R, double dx, double rho,
                       int mat, int half, double vx)
{
  int n = (int)ceil(R / dx) + 1;
  for (int k = -n; k < n; k++)
    for (int j = -n; j < n; j++)
      for (int i = -n; i < n; i++) {
        double x = (i + 0.5) * dx, y = (j + 0.5) * dx, z = (k + 0.5) * dx;
        /* half 1: z > 0 (a half model); 2: y > 0 too (a quarter model) */
        if (x * x + y * y + z * z > R * R || (half && z < 0) || (half > 1 && y < 0)) continue;
        put(p, c[0] + x, c[1] + y, c[2] + z, rho * dx * dx * dx, 1.2 * dx, rho, mat, vx);
      }
}

/* Plate normal to x: x0 <= x < x0 + t, |y| < W/2, z in [zlo, W/2), without the hole of
 * radius rh about the x axis. */
static void add_plate(struct particles *p, double x0, double t, double W, double zlo, double dx,
                      double rho, int mat, double rh)
{
  int nx = (int)lround(t / dx), ny = (int)lround(W / dx);
  for (int k = 0; k < ny; k++)
    for (int j = 0; j < ny; j++)
      for (int i = 0; i < nx; i++) {
        double x = x0 + (i + 0.5) * dx, y = -0.5 * W + (j + 0.5) * dx,
               z = -0.5 * W + (k + 0.5) * dx;
        if (z < zlo || y * y + z * z < rh * rh) continue;
        put(p, x, y, z, rho * dx * dx * dx, 1.2 * dx, rho, mat, 0.0);
      }
}

static double total_mass(const struct particles *p)
{
  double m = 0.0;
  for (size_t i = 0; i < p->n; i++) m += p->m[i];
  return m;
}

/* Areal density picture of p: mass in it [kg], peak [kg/m2] and the value at (u, v). */
struct sig {
  double mass, peak, at;
};

static struct sig areal(const struct particles *p, const struct render_options *o, double u,
                        double v, struct render_view *view_out)
{
  struct render_view v0;
  struct hv_error err;
  hv_error_clear(&err);
  struct sig s = {0, 0, NAN};
  if (view_out) memset(view_out, 0, sizeof *view_out);
  if (render_view_setup(p, o, &v0, &err)) {
    CHECK(0, "view setup: %s", err.msg);
    return s;
  }
  double *sigma = malloc((size_t)v0.nu * (size_t)v0.nv * sizeof *sigma);
  render_areal_density(p, &v0, sigma);
  for (size_t k = 0; k < (size_t)v0.nu * (size_t)v0.nv; k++) {
    s.mass += sigma[k] * v0.pix * v0.pix;
    s.peak = fmax(s.peak, sigma[k]);
  }
  int i = (int)floor((u - v0.u0) / v0.pix), j = (int)floor((v0.v1 - v) / v0.pix);
  if (i >= 0 && j >= 0 && i < v0.nu && j < v0.nv)
    s.at = sigma[(size_t)j * (size_t)v0.nu + (size_t)i];
  free(sigma);
  if (view_out) *view_out = v0;
  return s;
}

/* ---- checks ----------------------------------------------------------- */

static void test_kernel_column(void)
{
  CHECK_CLOSE(render_kernel_column(0.0), 1.5 / PI, 1e-7, "F(0) = 3/(2 pi)");
  CHECK(render_kernel_column(2.0) == 0.0 && render_kernel_column(2.5) == 0.0, "F(s >= 2) = 0");
  double sum = 0.0;
  int n = 4000;
  for (int k = 0; k <= n; k++) {
    double s = 2.0 * k / n;
    sum += 2 * PI * s * render_kernel_column(s) * (k == 0 || k == n ? 1 : (k % 2 ? 4 : 2));
  }
  CHECK_CLOSE(sum * (2.0 / n) / 3.0, 1.0, 1e-5, "integral of 2 pi s F(s) ds");
}

static double lstar(const unsigned char c[3])
{
  double y = 0.0, w[3] = {0.2126, 0.7152, 0.0722};
  for (int k = 0; k < 3; k++) {
    double v = c[k] / 255.0;
    y += w[k] * (v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4));
  }
  return y > 0.008856 ? 116.0 * cbrt(y) - 16.0 : 903.3 * y;
}

static void test_colormap(void)
{
  unsigned char c[3];
  double prev = -1.0, lo = 0, hi = 0;
  int mono = 1;
  for (int k = 0; k <= 63; k++) { /* steps of 1/63: above the 8-bit rounding of L* */
    render_colormap(k / 63.0, c);
    double L = lstar(c);
    if (k == 0) lo = L;
    hi = L;
    if (L <= prev) mono = 0;
    prev = L;
  }
  CHECK(mono, "colour map lightness L* rises (64 samples)");
  CHECK(lo < 20.0 && hi > 85.0, "colour map spans L* %.1f to %.1f", lo, hi);
}

/* No mirror; a 10 mm square box around the origin, a plot area of 400 x 400 px (25 µm
 * pixels): the picture adds the left axis margin (40 px), the bottom axis band (16) and
 * the caption band (36). */
static void single_view(struct render_options *o)
{
  render_options_default(o);
  o->mirror = 0;
  o->have_box = 1;
  const double box[6] = {-5e-3, 5e-3, -5e-3, 5e-3, -1, 1};
  memcpy(o->box, box, sizeof box);
  o->width = 440;
  o->height = 452;
}

static void test_single_particle(void)
{
  struct particles p;
  particles_init(&p);
  put(&p, 0.0, 0.0, 0.0, 2e-3, 1e-3, 7850, 0, 0);
  struct render_options o;
  single_view(&o); /* pix = 25 µm: h = 40 px */
  struct render_view v;
  struct sig s = areal(&p, &o, 0.0, 0.0, &v);
  CHECK_CLOSE(s.mass, 2e-3, 2e-3 * 1e-3, "wide kernel: mass in the picture [kg]");
  CHECK_CLOSE(s.peak, 2e-3 * 1.5 / PI / 1e-6, 0.01 * 2e-3 * 1.5 / PI / 1e-6,
              "wide kernel: peak = m F(0)/h^2 [kg/m2]");
  p.h[0] = 1.5625e-4; /* support radius 12.5 px: the narrowest midpoint-rule kernel */
  p.x[0][0] = 0.37e-3;
  s = areal(&p, &o, 0.0, 0.0, NULL);
  CHECK_CLOSE(s.mass, 2e-3, 2e-3 * 1e-3, "midpoint-rule kernel: mass in the picture [kg]");
  p.h[0] = 2e-6; /* under one pixel: cloud in cell */
  p.x[0][0] = 1.13e-3;
  s = areal(&p, &o, 0.0, 0.0, NULL);
  CHECK_CLOSE(s.mass, 2e-3, 1e-12, "tiny kernel: mass in the picture [kg]");
  p.h[0] = 5e-5; /* footprint of 4 px: sampled and normalised */
  s = areal(&p, &o, 0.0, 0.0, NULL);
  CHECK_CLOSE(s.mass, 2e-3, 1e-12, "small kernel: mass in the picture [kg]");
  particles_free(&p);
}

static void test_sphere(void)
{
  const double R = 5e-3, dx = R / 16.0, c[3] = {0, 0, 0};
  struct particles full, half;
  particles_init(&full);
  particles_init(&half);
  add_sphere(&full, c, R, dx, RHO_STEEL, 0, 0, 0);
  add_sphere(&half, c, R, dx, RHO_STEEL, 0, 1, 0);
  struct render_options o;
  render_options_default(&o);
  o.width = 400;
  struct render_view v;
  double M = total_mass(&full), peak = 2 * R * RHO_STEEL;

  struct sig s = areal(&full, &o, 0, 0, &v);
  CHECK(v.mirror == 0, "a full model is not mirrored by default");
  CHECK_CLOSE(s.mass / M, 1.0, 0.01, "full sphere along z: picture mass / particle mass");
  CHECK_CLOSE(s.at / peak, 1.0, 0.05, "full sphere: areal density at the centre / 2R rho");
  CHECK_CLOSE(s.peak / peak, 1.0, 0.05, "full sphere: peak areal density / 2R rho");

  double Mh = total_mass(&half);
  s = areal(&half, &o, 0, 0, &v);
  CHECK(v.mirror == 1 && v.mirror_y == 0,
        "a half model (z >= 0) is mirrored by default, across z = 0 only");
  CHECK_CLOSE(s.mass / (2 * Mh), 1.0, 0.01,
              "half sphere along z, mirrored: mass / twice the particle mass");
  CHECK_CLOSE(s.at / peak, 1.0, 0.05, "half sphere along z, mirrored: centre / 2R rho");
  o.axis = 1;
  s = areal(&half, &o, 0, 0, &v);
  CHECK(v.iu == 0 && v.iv == 2 && v.v0 < -R, "along y the picture shows x and z, both halves");
  CHECK_CLOSE(s.mass / (2 * Mh), 1.0, 0.01,
              "half sphere along y, mirrored: mass / twice the particle mass");
  CHECK_CLOSE(s.at / peak, 1.0, 0.05, "half sphere along y, mirrored: centre / 2R rho");
  o.axis = 2;
  o.mirror = 0;
  s = areal(&half, &o, 0, 0, &v);
  CHECK_CLOSE(s.mass / Mh, 1.0, 0.01, "half sphere, --no-mirror: mass / particle mass");
  CHECK_CLOSE(s.at / (0.5 * peak), 1.0, 0.05, "half sphere, --no-mirror: centre / R rho");
  /* a quarter model (y >= 0, z >= 0): mirrored across both planes, the whole sphere */
  struct particles quarter;
  particles_init(&quarter);
  add_sphere(&quarter, c, R, dx, RHO_STEEL, 0, 2, 0);
  const double Mq = total_mass(&quarter);
  o.mirror = -1;
  for (int ax = 0; ax < 3; ax++) {
    o.axis = ax;
    s = areal(&quarter, &o, 0, 0, &v);
    CHECK(v.mirror == 1 && v.mirror_y == 1 && v.u0 < -R && v.v0 < -R,
          "a quarter model along %c: mirrored across y = 0 and z = 0, the whole picture",
          "xyz"[ax]);
    CHECK_CLOSE(s.mass / (4 * Mq), 1.0, 0.01, "quarter sphere, mirrored: mass / 4 x particle mass");
    CHECK_CLOSE(s.at / peak, 1.0, 0.05, "quarter sphere, mirrored: centre / 2R rho");
  }
  o.axis = 2;
  o.mirror = 0;
  s = areal(&quarter, &o, 0, 0, &v);
  CHECK(v.mirror == 0 && v.mirror_y == 0, "quarter sphere, --no-mirror: neither mirror");
  particles_free(&quarter);
  particles_free(&full);
  particles_free(&half);
}

static void test_plate(void)
{
  const double t = 2e-3, dx = 0.25e-3;
  struct particles p;
  particles_init(&p);
  add_plate(&p, 0.0, t, 20e-3, 0.0, dx, RHO_STEEL, 0, 0.0);
  struct render_options o;
  render_options_default(&o);
  o.axis = 0; /* face on */
  o.width = 300;
  struct render_view v;
  struct sig s = areal(&p, &o, 0.0, 5e-3, &v);
  CHECK(v.mirror == 1 && v.iu == 1 && v.iv == 2, "plate along x: y right, z up, mirrored");
  CHECK_CLOSE(s.mass / (2 * total_mass(&p)), 1.0, 0.01,
              "plate face on: mass / twice the particle mass");
  CHECK_CLOSE(s.at / (RHO_STEEL * t), 1.0, 0.01, "plate face on: areal density / rho t");
  o.have_box = 1; /* a box and a size: exactly that size, square pixels, box inside */
  double box[6] = {-1e-3, 3e-3, -8e-3, 8e-3, -8e-3, 8e-3};
  memcpy(o.box, box, sizeof box);
  o.width = 300;
  o.height = 200;
  s = areal(&p, &o, 0.0, 0.0, &v);
  CHECK(v.width == 300 && v.height == 200 && v.nu == 300 - v.ml && v.nv == 200 - v.mb - v.band,
        "box + size: %dx%d picture, plot %dx%d", v.width, v.height, v.nu, v.nv);
  CHECK(v.u0 <= -8e-3 && v.u1 >= 8e-3 && v.v0 <= -8e-3 && v.v1 >= 8e-3, "box inside the view");
  CHECK_CLOSE(s.at / (RHO_STEEL * t), 1.0, 0.01, "plate in a box: areal density / rho t");
  particles_free(&p);
}

/* A kernel far wider than the picture (h of a billion pixels): it covers every pixel with
 * m F(0)/h², it is not lost to an int overflow of its pixel range. A box whose pixel
 * cannot be a finite positive length is refused, not drawn with NaN. */
static void test_extremes(void)
{
  struct particles p;
  particles_init(&p);
  put(&p, 0.0, 0.0, 0.0, 1.0, 1e6, 7850, 0, 0);
  struct render_options o;
  single_view(&o);
  struct render_view v;
  struct sig s = areal(&p, &o, 0.0, 0.0, &v);
  double expect = 1.0 * 1.5 / PI / 1e12; /* m F(0) / h² [kg/m2] */
  CHECK(2.0 * p.h[0] / v.pix > 2147483647.0, "the kernel spans %g pixels", 2.0 * p.h[0] / v.pix);
  CHECK_CLOSE(s.at / expect, 1.0, 1e-3,
              "kernel wider than INT_MAX pixels: sigma at the centre / m F(0)/h^2");
  CHECK_CLOSE(s.mass / (expect * 1e-4), 1.0, 1e-3,
              "kernel wider than INT_MAX pixels: mass in the picture");

  struct hv_error err;
  const double bad[2][6] = {{0, 5e-324, 0, 5e-324, -1, 1}, {-1e308, 1e308, -1, 1, -1, 1}};
  for (int k = 0; k < 2; k++) {
    memcpy(o.box, bad[k], sizeof o.box);
    hv_error_clear(&err);
    int rc = render_view_setup(&p, &o, &v, &err);
    CHECK(rc != 0 && err.code == HV_EXIT_USAGE && strstr(err.msg, "--box"),
          "box %g..%g: refused (%d, code %d): %s", bad[k][0], bad[k][1], rc, err.code, err.msg);
  }
  particles_free(&p);
}

/* ---- the command ------------------------------------------------------ */

/* Sphere (13.5 mm steel, 3 km/s) behind a 2 mm steel plate with a 20 mm hole and a debris
 * cloud of small clusters; a half model z >= 0. Body 0 the projectile, body 1 the bumper
 * and its debris; material 0 projectile, 1 bumper, or with swap the other way round (as a
 * case whose materials are numbered in another order). solid: 1 with a damage column, 2
 * with an alpha column (viscosity switch), 3 both; 4 adds each particle's time step, dt
 * (1 ns in the projectile, 0.1 us in the bumper). */
static const char *write_scene(const char *name, int solid, int swap)
{
  struct particles p;
  particles_init(&p);
  if (solid & 1) particles_enable_solid(&p);
  if (solid & 2) particles_enable_av(&p);
  const double c[3] = {25e-3, 0, 0};
  add_sphere(&p, c, 6.75e-3, 0.45e-3, 7700, 0, 1, 3000);
  add_plate(&p, 0.0, 2e-3, 60e-3, 0.0, 0.5e-3, 7850, 1, 10e-3);
  unsigned long r = 12345;
  for (int k = 0; k < 300; k++) { /* clusters on a cone ahead of the hole */
    double a[4];
    for (int q = 0; q < 4; q++) {
      r = r * 6364136223846793005UL + 1442695040888963407UL;
      a[q] = (double)(r >> 11) / 9007199254740992.0;
    }
    double ang = 0.6 * a[0], phi = PI * a[1], dist = 10e-3 + 22e-3 * a[2];
    double x = 2e-3 + dist * cos(ang), y = dist * sin(ang) * cos(phi),
           z = dist * sin(ang) * sin(phi);
    int n = 1 + (int)(6 * a[3]);
    for (int q = 0; q < n; q++)
      put(&p, x + 0.4e-3 * (q % 2), y + 0.4e-3 * (q / 2 % 2), z + 0.4e-3 * (q / 4), 7850 * 1.25e-10,
          0.6e-3, 7850, 1, 2500 * cos(ang));
  }
  if (solid & 2)
    for (size_t i = 0; i < p.n; i++) p.alpha[i] = 0.1 + 0.9 * (double)(i % 7) / 6.0;
  if (solid & 4)
    for (size_t i = 0; i < p.n; i++) p.dt[i] = p.mat[i] == 0 ? 1e-9 : 1e-7;
  if (solid & 1)
    for (size_t i = 0; i < p.n; i++)
      p.damage[i] = p.mat[i] == 1 ? (hypot(p.x[1][i], p.x[2][i]) < 14e-3 ? 1.0 : 0.0) : 0.1;
  for (size_t i = 0; i < p.n; i++) {
    p.body[i] = p.mat[i];
    if (swap) p.mat[i] = 1 - p.mat[i];
  }
  const char *names[2] = {"steel-projectile", "steel-bumper"};
  if (swap) {
    names[0] = "steel-bumper";
    names[1] = "steel-projectile";
  }
  struct snapshot_meta meta = {.time = 12e-6,
                               .step = 400,
                               .version = "test",
                               .case_name = "scene",
                               .material_names = names,
                               .nmat = 2};
  static char path[8][4096];
  static int slot = 0;
  char *out = path[slot++ % 8];
  snprintf(out, 4096, "%s/%s", test_tmpdir(), name);
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(io_write_particles_csv(out, &p, &meta, &err) == 0, "scene written (%zu particles) %s", p.n,
        err.msg);
  particles_free(&p);
  return out;
}

/* Reads a PNG as 8-bit RGB; returns the pixels (malloc) and the size, or NULL. */
static unsigned char *read_png(const char *path, int *w, int *h)
{
  png_image img;
  memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, path)) return NULL;
  img.format = PNG_FORMAT_RGB;
  unsigned char *buf = malloc(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, NULL, buf, 0, NULL)) {
    free(buf);
    return NULL;
  }
  *w = (int)img.width;
  *h = (int)img.height;
  return buf;
}

static int run(const char *args, char *out, size_t len)
{
  char cmd[16384];
  snprintf(cmd, sizeof cmd, "'%s' render %s", test_bin(), args);
  return test_run(cmd, out, len);
}

static int tmp_files_left(void)
{
  DIR *d = opendir(test_tmpdir());
  int n = 0;
  struct dirent *e;
  while (d && (e = readdir(d)))
    if (strstr(e->d_name, ".tmp.")) n++;
  if (d) closedir(d);
  return n;
}

static void test_command(void)
{
  const char *scene = write_scene("scene.csv", 1, 0);
  const char *gas = write_scene("scene_gas.csv", 0, 0);
  const char *swapped = write_scene("scene_swapped.csv", 1, 1);
  const char *dir = test_tmpdir();
  char args[8192], out[4096];
  int w = 0, h = 0;

  snprintf(args, sizeof args, "'%s' -o '%s/radiograph_y.png' --axis y --size 640x400", scene, dir);
  int st = run(args, out, sizeof out);
  CHECK(st == 0, "radiograph along y: exit %d %s", st, out);
  snprintf(args, sizeof args, "%s/radiograph_y.png", dir);
  unsigned char *img = read_png(args, &w, &h);
  CHECK(img && w == 640 && h == 400, "radiograph PNG read back: %dx%d (640x400)", w, h);
  if (img) {
    CHECK(img[0] == RENDER_BG_R && img[1] == RENDER_BG_G && img[2] == RENDER_BG_B,
          "background pixel (0,0) is white: %d %d %d", img[0], img[1], img[2]);
    int dark = 0;
    for (int k = 0; k < w * (h - 72); k++) dark += img[3 * k] < 64;
    CHECK(dark > 100, "the projectile and the plate are dark (%d pixels below 64)", dark);
  }
  free(img);

  snprintf(args, sizeof args, "'%s' -o '%s/radiograph_z.png' --size=500x400", scene, dir);
  st = run(args, out, sizeof out);
  CHECK(st == 0, "radiograph along z: exit %d %s", st, out);

  snprintf(args, sizeof args,
           "'%s' -o '%s/particles_mat.png' --mode particles --axis y --size 800x500", scene, dir);
  st = run(args, out, sizeof out);
  snprintf(args, sizeof args, "%s/particles_mat.png", dir);
  img = read_png(args, &w, &h);
  CHECK(st == 0 && img && w == 800 && h == 500, "particles by material: exit %d, %dx%d", st, w, h);
  if (img)
    CHECK(img[0] == 255 && img[1] == 255 && img[2] == 255, "particles: background pixel is white");

  /* the same bodies with their materials numbered the other way round: the same picture,
   * legend included (colours follow the bodies' order, not the material index) */
  snprintf(args, sizeof args,
           "'%s' -o '%s/particles_swapped.png' --mode particles --axis y --size 800x500", swapped,
           dir);
  st = run(args, out, sizeof out);
  snprintf(args, sizeof args, "%s/particles_swapped.png", dir);
  int w2 = 0, h2 = 0;
  unsigned char *img2 = read_png(args, &w2, &h2);
  CHECK(st == 0 && img2 && w2 == w && h2 == h,
        "particles by material, materials renumbered: exit %d, %dx%d", st, w2, h2);
  if (img && img2 && w2 == w && h2 == h) {
    long differ = 0, colored = 0;
    for (long k = 0; k < 3L * w * h; k++) differ += img[k] != img2[k];
    for (long k = 0; k < (long)w * h; k++)
      colored += img[3 * k] != img[3 * k + 1] || img[3 * k] != img[3 * k + 2];
    CHECK(
        differ == 0 && colored > 1000,
        "materials renumbered: the same picture (%ld of %ld bytes differ, 0; %ld coloured pixels)",
        differ, 3L * w * h, colored);
  }
  free(img2);
  free(img);

  const char *colors[] = {"velocity", "damage", "pressure", "density"};
  for (int k = 0; k < 4; k++) {
    snprintf(args, sizeof args,
             "'%s' -o '%s/particles_%s.png' --mode particles --color %s --axis %s", scene, dir,
             colors[k], colors[k], k % 2 ? "z" : "y");
    st = run(args, out, sizeof out);
    CHECK(st == 0, "particles by %s: exit %d %s", colors[k], st, out);
  }
  CHECK(tmp_files_left() == 0, "no temporary files left behind");

  /* one particle whose disc (0.6 h) is wider than INT_MAX pixels: it covers the picture */
  {
    struct particles big;
    particles_init(&big);
    put(&big, 0.0, 0.0, 0.0, 1.0, 1e6, 7850, 0, 0.0);
    struct snapshot_meta meta = {.time = 0.0, .step = 0, .version = "test", .case_name = "big"};
    char bigpath[4096];
    snprintf(bigpath, sizeof bigpath, "%s/big.csv", dir);
    struct hv_error e;
    hv_error_clear(&e);
    CHECK(io_write_particles_csv(bigpath, &big, &meta, &e) == 0, "big particle written %s", e.msg);
    particles_free(&big);
    snprintf(args, sizeof args,
             "'%s' -o '%s/big.png' --mode particles --axis y --no-mirror "
             "--box -5mm,5mm,-1,1,-5mm,5mm --size 400x300",
             bigpath, dir);
    st = run(args, out, sizeof out);
    snprintf(args, sizeof args, "%s/big.png", dir);
    img = read_png(args, &w, &h);
    CHECK(st == 0 && img && w == 400 && h == 300, "a huge disc: exit %d %s", st, out);
    if (img) {
      unsigned char c[3];
      render_palette(0, c);
      const unsigned char *q = img + 3 * (100 * 400 + 200);
      CHECK(q[0] == c[0] && q[1] == c[1] && q[2] == c[2],
            "a huge disc covers the picture: "
            "centre pixel %d %d %d (%d %d %d)",
            q[0], q[1], q[2], c[0], c[1], c[2]);
    }
    free(img);
  }

  /* --range with --color alpha: alpha is dimensionless like damage (the range's units
   * were looked up past the end of a table) */
  const char *avscene = write_scene("scene_av.csv", 3, 0);
  snprintf(args, sizeof args,
           "'%s' -o '%s/particles_alpha.png' --mode particles --color alpha "
           "--range 0,1 --axis y --size 640x400",
           avscene, dir);
  st = run(args, out, sizeof out);
  CHECK(st == 0, "particles by alpha with --range 0,1: exit %d (0) %s", st, out);
  snprintf(args, sizeof args,
           "'%s' -o '%s/particles_alpha.png' --mode particles --color alpha "
           "--range 0,1km/s",
           avscene, dir);
  st = run(args, out, sizeof out);
  CHECK(st == 1 && strstr(out, "--range"), "alpha --range with a unit: exit %d (1) %s", st, out);

  /* --color dt: each particle's time step on a log scale; --range in time units, > 0.
   * The scene's projectile allows 1 ns, its bumper 0.1 us: with --range 1ns,0.1us they
   * take the colour map's two ends; with 10ns,1us the bumper (log10 -7) is mid-map and
   * no disc has the top end. Counted in the plot, above the caption band. */
  const char *dtscene = write_scene("scene_dt.csv", 5, 0);
  static const struct {
    const char *scene; /* "dt": the scene with dt, "av": without the column */
    const char *opts;
    int status, top;    /* exit status; whether the top colour must be drawn */
    const char *needle; /* in the output, or NULL */
  } dtc[] = {
      {"dt", "--axis y", 0, -1, NULL},
      {"dt", "--range 1ns,0.1us --axis y", 0, 1, NULL},
      {"dt", "--range 10ns,1us --axis y", 0, 0, NULL},
      {"dt", "--range 0,1us", 1, -1, "time steps are positive"},
      {"dt", "--range 1,2km/s", 1, -1, "--range"},
      {"av", "", 2, -1, "no dt column"}, /* a snapshot without the column (an older hvsph's) */
  };
  for (size_t k = 0; k < sizeof dtc / sizeof dtc[0]; k++) {
    snprintf(args, sizeof args,
             "'%s' -o '%s/particles_dt.png' --mode particles --color dt "
             "--size 640x400 %s",
             dtc[k].scene[0] == 'd' ? dtscene : avscene, dir, dtc[k].opts);
    st = run(args, out, sizeof out);
    CHECK(st == dtc[k].status && (!dtc[k].needle || strstr(out, dtc[k].needle)),
          "--color dt %s: exit %d (%d) %s", dtc[k].opts, st, dtc[k].status, out);
    if (dtc[k].top < 0 || st != 0) continue;
    snprintf(args, sizeof args, "%s/particles_dt.png", dir);
    img = read_png(args, &w, &h);
    unsigned char lo[3], hi[3];
    render_colormap(0.0, lo);
    render_colormap(1.0, hi);
    long nlo = 0, nhi = 0;
    for (int y = 0; img && y < h - 120; y++)
      for (int x = 0; x < w; x++) {
        const unsigned char *q = img + 3 * ((size_t)y * (size_t)w + (size_t)x);
        nlo += q[0] == lo[0] && q[1] == lo[1] && q[2] == lo[2];
        nhi += q[0] == hi[0] && q[1] == hi[1] && q[2] == hi[2];
      }
    CHECK(img && nlo > 200 && (dtc[k].top ? nhi > 200 : nhi == 0),
          "--color dt %s: %ld pixels of the map's low end (projectile, > 200), %ld of its top "
          "(bumper, %s)",
          dtc[k].opts, nlo, nhi, dtc[k].top ? "> 200" : "none");
    free(img);
  }

  /* a --range narrower than the rounding of its ends: the colour bar's ticks must not
   * loop for ever */
  {
    char cmd[8192];
    snprintf(cmd, sizeof cmd,
             "timeout 60 '%s' render '%s' -o '%s/particles_narrow.png' --mode "
             "particles --color velocity --range 1,1.0000000000000002 --size 640x400",
             test_bin(), scene, dir);
    st = test_run(cmd, out, sizeof out);
    CHECK(st == 0, "a --range 1,1.0000000000000002: exit %d (0, 124: hung) %s", st, out);
  }
  CHECK(tmp_files_left() == 0, "no temporary files left behind");

  /* failures: the previous picture stays as it was */
  snprintf(args, sizeof args, "'%s' -o '%s/particles_mat.png' --mode particles --color damage", gas,
           dir);
  st = run(args, out, sizeof out);
  CHECK(st == 2 && strstr(out, "damage"), "damage colour without a damage column: exit %d (2): %s",
        st, out);
  snprintf(args, sizeof args, "'%s' -o '%s/particles_mat.png' --mode particles --color alpha", gas,
           dir);
  st = run(args, out, sizeof out);
  CHECK(st == 2 && strstr(out, "alpha"), "alpha colour without an alpha column: exit %d (2): %s",
        st, out);
  snprintf(args, sizeof args, "%s/particles_mat.png", dir);
  img = read_png(args, &w, &h);
  CHECK(img && w == 800 && h == 500, "a failed render leaves the previous file whole");
  free(img);

  /* a CSV snapshot named .vtu: read as VTU and refused */
  snprintf(args, sizeof args, "cp '%s' '%s/notvtu.vtu'", scene, dir);
  CHECK(system(args) == 0, "copy %s", args);
  static const struct {
    const char *args;
    int status;
    const char *says;
  } bad[] = {
      {"", 1, "missing snapshot"},
      {"SCENE", 1, "missing -o"},
      {"'/nonexistent/snap.csv' -o DIR/x.png", 2, "cannot open"},
      {"SCENE -o DIR/x.png --axis w", 1, "--axis"},
      {"SCENE -o DIR/x.png --mode xray", 1, "--mode"},
      {"SCENE -o DIR/x.png --color hue --mode particles", 1, "--color"},
      {"SCENE -o DIR/x.png --size 10x10", 1, "--size"},
      {"SCENE -o DIR/x.png --size 12by4", 1, "--size"},
      {"SCENE -o DIR/x.png --mu -1", 1, "--mu"},
      {"SCENE -o DIR/x.png --box 0,1,0,1,0", 1, "--box"},
      {"SCENE -o DIR/x.png --box 0,1,0,1,2kg,3", 1, "--box"},
      {"SCENE -o DIR/x.png --box 1,0,0,1,0,1", 1, "--box"},
      {"SCENE -o DIR/x.png --frobnicate", 1, "unknown option"},
      {"SCENE -o DIR/x.png --mode particles --color velocity --range 5,1", 1, "--range"},
      {"SCENE -o DIR/no/such/folder/x.png", 2, "cannot create"},
      {"DIR/notvtu.vtu -o DIR/x.png", 2, "not a VTU snapshot written by hvsph"},
      {"DIR/radiograph_y.png -o DIR/x.png", 2, "radiograph_y.png"},
  };
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
    char a[4096] = "";
    for (const char *s = bad[k].args; *s;) { /* SCENE and DIR stand for the paths */
      if (!strncmp(s, "SCENE", 5)) {
        strcat(a, scene);
        s += 5;
      } else if (!strncmp(s, "DIR", 3)) {
        strcat(a, dir);
        s += 3;
      } else {
        strncat(a, s++, 1);
      }
    }
    st = run(a, out, sizeof out);
    char *nl = strchr(out, '\n');
    int one_line = nl && nl[1] == '\0';
    CHECK(st == bad[k].status && strstr(out, bad[k].says) && one_line,
          "render %s: exit %d (%d), one line saying '%s': %s", bad[k].args, st, bad[k].status,
          bad[k].says, out);
  }
}

/* ---- exposure, axes, labels, bad data ----------------------------------- */

/* Pixels of two PNG files: -1 when either cannot be read or the sizes differ, else the
 * count of differing bytes. */
static long png_differ(const char *a, const char *b)
{
  int wa = 0, ha = 0, wb = 0, hb = 0;
  unsigned char *x = read_png(a, &wa, &ha), *y = read_png(b, &wb, &hb);
  long d = -1;
  if (x && y && wa == wb && ha == hb) {
    d = 0;
    for (long k = 0; k < 3L * wa * ha; k++) d += x[k] != y[k];
  }
  free(x);
  free(y);
  return d;
}

/* The tick step: the smallest 1, 2 or 5 x 10^k whose ticks lie min_px apart. */
static void test_tick_step(void)
{
  static const struct {
    double span, npx, min_px, step;
  } c[] = {
      {100.0, 1000.0, 80.0, 10.0}, /* 8 wanted: 10 */
      {37.0, 500.0, 60.0, 5.0},    /* 4.44: 5 */
      {3.0, 400.0, 60.0, 0.5},     /* 0.45: 0.5 */
      {200.0, 1000.0, 10.0, 2.0},  /* exactly 2: 2, not 5 */
      {0.01, 500.0, 84.0, 0.002},  /* 0.00168: 0.002 */
      {283.0, 1120.0, 84.0, 50.0}, /* 21.2: 50 (20 is too close) */
      {1.0, 10.0, 84.0, 10.0},     /* ticks farther apart than the axis: one at most */
  };
  for (size_t k = 0; k < sizeof c / sizeof c[0]; k++) {
    const double st = render_tick_step(c[k].span, c[k].npx, c[k].min_px);
    CHECK(fabs(st - c[k].step) <= 1e-12 * c[k].step,
          "tick step for %g mm on %g px, %g px "
          "apart: %g (%g)",
          c[k].span, c[k].npx, c[k].min_px, st, c[k].step);
  }
  CHECK(render_tick_step(0.0, 100.0, 10.0) == 0.0 && render_tick_step(NAN, 100.0, 10.0) == 0.0,
        "no step for an empty or undefined span");
  /* the rule on many spans: a 1-2-5 value, wide enough, and the next smaller of the
   * series (half, or 0.4 times 5) too narrow */
  int ok = 1;
  double worst = 0.0;
  for (int k = 0; k < 2000; k++) {
    const double span = pow(10.0, -3.0 + 7.0 * k / 1999.0), want = span * 42.0 / 777.0;
    const double st = render_tick_step(span, 777.0, 42.0);
    const double e = pow(10.0, floor(log10(st) + 1e-9)), m = st / e;
    const int series = fabs(m - 1.0) < 1e-9 || fabs(m - 2.0) < 1e-9 || fabs(m - 5.0) < 1e-9;
    const double smaller = fabs(m - 5.0) < 1e-9 ? 0.4 * st : 0.5 * st;
    if (!series || st < want * (1 - 1e-9) || smaller >= want) ok = 0;
    worst = fmax(worst, st / want);
  }
  CHECK(ok && worst <= 2.5 + 1e-9,
        "2000 spans from 1 um to 10 m: each step 1, 2 or 5 x 10^k, "
        "the smallest wide enough (at most %.3g times the least)",
        worst);
}

/* The automatic exposure: the lower quartile of the pixels holding a particle at
 * T = 1/2. */
static void test_auto_mu(void)
{
  const double sig[9] = {0.0, 4.0, 0.0, 1.0, 2.0, 100.0, 0.0, 0.01, 3.0};
  const unsigned char occ[9] = {1, 1, 0, 1, 1, 1, 0, 0, 1};
  double q = -1.0;
  CHECK_CLOSE(render_auto_mu(sig, occ, 9, &q), log(2.0) / 2.0, 1e-15,
              "lower quartile of 1, 2, 3, 4, 100 is 2: mu = ln 2 / 2 (empty pixels and the rim "
              "without a particle, 0.01, left out)");
  CHECK(q == 2.0, "quartile %g (2)", q);
  CHECK_CLOSE(render_auto_mu(sig, NULL, 9, &q), log(2.0), 1e-15,
              "without the mask: every pixel with sigma > 0, 0.01 to 100, quartile 1");
  const double none[3] = {0.0, 0.0, 0.0};
  CHECK(render_auto_mu(none, NULL, 3, &q) == RENDER_MU_FALLBACK && q == 0.0,
        "no material in view: the fallback mu");
}

/* Grey levels of the plot pixel under (u, v) [m] in a PNG drawn with view v. */
static int grey_at(const unsigned char *img, int w, const struct render_view *v, double u,
                   double vv)
{
  const int i = (int)floor((u - v->u0) / v->pix), j = (int)floor((v->v1 - vv) / v->pix);
  if (i < 0 || j < 0 || i >= v->nu || j >= v->nv) return -1;
  return img[3 * ((size_t)j * (size_t)w + (size_t)(v->ml + i))];
}

static int cmp_int(const void *a, const void *b) { return *(const int *)a - *(const int *)b; }

/* Writes p as dir/name with materials names[0..nmat) and renders it with the options
 * (library call, as the command does); returns the picture (malloc) and its view. */
static unsigned char *picture(const struct particles *p, const struct render_options *o,
                              const char *name, struct render_view *v, int *w, int *h)
{
  char path[4200];
  snprintf(path, sizeof path, "%s/%s", test_tmpdir(), name);
  struct hv_error err;
  hv_error_clear(&err);
  const struct render_info info = {.time = 1e-5};
  if (render_view_setup(p, o, v, &err) || render_png(path, p, o, &info, &err)) {
    CHECK(0, "%s: %s", name, err.msg);
    return NULL;
  }
  return read_png(path, w, h);
}

/* Aluminium debris: a 1.5 mm aluminium plate (a bumper) with a 10 mm hole, seen edge on,
 * and 300 clusters of 1 to 7 particles (0.4 mm, 0.17 mg each: the fragments of a
 * Whipple shield at the demo's resolution) on a cone ahead of it. At the old fixed
 * mu = 0.05 m2/kg a particle's column (m F(0)/h^2 = 0.35 kg/m2 at its centre) transmits
 * 98 %, a cluster's a few times that: the median cluster centre is under 20 grey levels
 * (8 %) below white, barely told from the paper. By default the debris must stand out:
 * at least 60 levels (a quarter of the scale) below white. A steel sphere (13.5 mm) behind a 2 mm steel plate, the scene the old
 * default was made for, must not turn black: its centre (104 kg/m2) and a column at
 * 0.8 of its radius (62 kg/m2) both above black and 20 levels apart. */
static void test_exposure(void)
{
  struct particles al, st;
  particles_init(&al);
  particles_init(&st);
  add_plate(&al, 0.0, 1.5e-3, 60e-3, 0.0, 0.5e-3, 2700, 0, 5e-3);
  double cl[300][2];
  unsigned long r = 777;
  for (int k = 0; k < 300; k++) {
    double a[4];
    for (int q = 0; q < 4; q++) {
      r = r * 6364136223846793005UL + 1442695040888963407UL;
      a[q] = (double)(r >> 11) / 9007199254740992.0;
    }
    const double ang = 0.7 * a[0], phi = PI * a[1], dist = 8e-3 + 30e-3 * a[2];
    const double x = 2e-3 + dist * cos(ang), y = dist * sin(ang) * cos(phi),
                 z = dist * sin(ang) * sin(phi);
    cl[k][0] = x;
    cl[k][1] = z;
    const int n = 1 + (int)(7 * a[3]);
    for (int q = 0; q < n; q++)
      put(&al, x + 0.4e-3 * (q % 2), y + 0.4e-3 * (q / 2 % 2), z + 0.4e-3 * (q / 4), 2700 * 6.4e-11,
          0.48e-3, 2700, 1, 6000 * cos(ang));
  }
  for (size_t i = 0; i < al.n; i++) al.body[i] = al.mat[i];
  struct render_options o;
  render_options_default(&o);
  o.axis = 1;
  o.width = 900;
  o.labels = 0;
  struct render_view v;
  int w = 0, h = 0, dark[2][300];
  for (int pass = 0; pass < 2; pass++) {
    o.mu = pass ? 0.05 : RENDER_MU_AUTO;
    unsigned char *img = picture(&al, &o, pass ? "al_mu005.png" : "al_auto.png", &v, &w, &h);
    int n = 0;
    for (int k = 0; img && k < 300; k++) {
      const int g = grey_at(img, w, &v, cl[k][0], cl[k][1]);
      if (g >= 0) dark[pass][n++] = 255 - g;
    }
    free(img);
    qsort(dark[pass], (size_t)n, sizeof dark[pass][0], cmp_int);
    CHECK(n == 300, "the clusters are in the picture (%d of 300)", n);
    if (n == 300)
      CHECK(pass ? dark[1][150] < 20 : dark[0][150] >= 60,
            "aluminium debris, %s: the median "
            "cluster centre %d grey levels below white (%s)",
            pass ? "--mu 0.05" : "by default", dark[pass][150],
            pass ? "under 20: why the default changed" : "at least 60");
  }

  const double c[3] = {25e-3, 0, 0}, R = 6.75e-3;
  add_sphere(&st, c, R, 0.45e-3, 7850, 0, 1, 3000);
  add_plate(&st, 0.0, 2e-3, 60e-3, 0.0, 0.5e-3, 7850, 1, 10e-3);
  o.mu = RENDER_MU_AUTO;
  unsigned char *img = picture(&st, &o, "steel_auto.png", &v, &w, &h);
  const int g0 = img ? grey_at(img, w, &v, c[0], 0.0) : -1,
            g8 = img ? grey_at(img, w, &v, c[0], 0.8 * R) : -1;
  free(img);
  CHECK(g0 >= 8 && g8 >= g0 + 20,
        "steel sphere and plate by default: not saturated, grey %d "
        "at the sphere's centre (>= 8), %d at 0.8 R (20 lighter)",
        g0, g8);
  particles_free(&al);
  particles_free(&st);
}

/* Axes: the ticks along the bottom are the multiples of the step render_tick_step
 * gives for the view, each a mark in the bottom band; the labels put ink under them
 * and left of the plot. */
static void test_axes(void)
{
  struct particles p;
  particles_init(&p);
  const double c[3] = {0, 0, 0};
  add_sphere(&p, c, 5e-3, 0.5e-3, 2700, 0, 0, 0);
  struct render_options o;
  render_options_default(&o);
  o.have_box = 1;
  const double box[6] = {-7e-3, 43e-3, -10e-3, 10e-3, -1, 1};
  memcpy(o.box, box, sizeof box);
  for (int size = 0; size < 2; size++) {
    o.width = size ? 1200 : 400;
    o.height = 0;
    struct render_view v;
    int w = 0, h = 0;
    unsigned char *img = picture(&p, &o, "axes.png", &v, &w, &h);
    if (!img) continue;
    const int s = v.scale;
    const double step = render_tick_step((v.u1 - v.u0) * 1e3, v.nu, 42.0 * s);
    int expect = 0;
    for (double t = ceil(v.u0 * 1e3 / step - 1e-9) * step; t <= v.u1 * 1e3; t += step) expect++;
    /* tick marks: runs of black in a row of the band between the axis line and the text */
    int runs = 0;
    const unsigned char *row = img + 3 * (size_t)(v.nv + 2 * s) * (size_t)w;
    for (int x = v.ml; x < v.ml + v.nu; x++)
      runs += row[3 * x] == 0 && (x == v.ml || row[3 * (x - 1)] != 0);
    long ink_bottom = 0, ink_left = 0;
    for (int y = v.nv + 5 * s; y < v.nv + 12 * s; y++)
      for (int x = v.ml; x < v.ml + v.nu; x++) ink_bottom += img[3 * ((size_t)y * w + x)] == 0;
    for (int y = 12 * s; y < v.nv; y++)
      for (int x = 0; x < v.ml - 5 * s; x++) ink_left += img[3 * ((size_t)y * w + x)] == 0;
    CHECK(step == (size ? 5.0 : 10.0) && runs == expect && expect >= 4,
          "%d px wide: %d ticks every %g mm along x (%d; step 5 mm at 1200 px, 10 at 400)", w, runs,
          step, expect);
    CHECK(ink_bottom > 20 * expect && ink_left > 20,
          "%d px wide: tick labels drawn: %ld "
          "black pixels under the ticks, %ld left of the plot",
          w, ink_bottom, ink_left);
    free(img);
  }
  particles_free(&p);
}

/* Labels: the names of used_parameters.yaml, "body N" without it; one per body where
 * it fits and overlaps no other. */
static void test_labels(void)
{
  char dir[4200], path[4400], args[9000], out[4096];
  snprintf(dir, sizeof dir, "%s/labelled", test_tmpdir());
  snprintf(args, sizeof args, "mkdir -p '%s'", dir);
  CHECK(system(args) == 0, "%s", args);
  snprintf(path, sizeof path, "%s/used_parameters.yaml", dir);
  FILE *f = fopen(path, "w");
  if (f) {
    fputs("name: labels\nbodies:\n  - name: projectile\n    material: al\n"
          "  - name: bumper\n    material: al\n",
          f);
    fclose(f);
  }
  char names[4][64] = {{0}};
  CHECK(render_read_body_names(dir, names, 4) == 2 && !strcmp(names[0], "projectile") &&
            !strcmp(names[1], "bumper"),
        "body names from used_parameters.yaml: '%s', '%s'", names[0], names[1]);
  CHECK(render_read_body_names(test_tmpdir(), names, 4) == 0, "no used_parameters.yaml: none");

  /* bodies 0 and 1 apart; body 2 centred on body 1 (a plate's refined disc) */
  struct particles p;
  particles_init(&p);
  const double c0[3] = {-20e-3, 0, 0}, c1[3] = {20e-3, 0, 0};
  add_sphere(&p, c0, 4e-3, 0.5e-3, 2700, 0, 0, 0);
  const size_t n0 = p.n;
  add_sphere(&p, c1, 8e-3, 0.5e-3, 2700, 0, 0, 0);
  for (size_t i = 0; i < p.n; i++)
    p.body[i] = i < n0 ? 0 : hypot(p.x[1][i], p.x[2][i]) < 3e-3 ? 2 : 1;
  struct render_options o;
  render_options_default(&o);
  o.width = 800;
  struct render_view v;
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(render_view_setup(&p, &o, &v, &err) == 0, "view: %s", err.msg);
  const char *bn[3] = {"projectile", "bumper", "bumper-core"};
  const struct render_info info = {.body_names = bn, .nbody = 3};
  struct canvas plot;
  canvas_init(&plot, v.nu, v.nv);
  const int placed = render_body_labels(&plot, &p, &v, &info);
  /* the projectile's label: black in its box about the projected centre */
  const int cx = (int)((c0[0] - v.u0) / v.pix), cy = (int)((v.v1 - c0[1]) / v.pix);
  const int half = canvas_text_width(v.scale, "projectile") / 2 + 2 * v.scale;
  long ink = 0, elsewhere = 0;
  for (int y = 0; y < v.nv; y++)
    for (int x = 0; x < v.nu; x++) {
      const int black = plot.rgb[3 * ((size_t)y * v.nu + x)] == 0;
      if (abs(x - cx) <= half && abs(y - cy) <= 6 * v.scale)
        ink += black;
      else if (abs(x - (int)((c1[0] - v.u0) / v.pix)) > 60 * v.scale)
        elsewhere += black;
    }
  canvas_free(&plot);
  CHECK(placed == 2 && ink > 50 && elsewhere == 0,
        "labels: %d placed (2: bumper-core's would "
        "overlap bumper's), %ld black pixels at the projectile's centre, %ld elsewhere (0)",
        placed, ink, elsewhere);
  const char *wide[1] = {"a name far too long to fit in a picture of this size, so not drawn "
                         "anywhere in it at all, however the bodies lie"};
  const struct render_info winfo = {.body_names = wide, .nbody = 1};
  canvas_init(&plot, v.nu, v.nv);
  const int nwide = render_body_labels(&plot, &p, &v, &winfo);
  canvas_free(&plot);
  CHECK(nwide == 1,
        "a label wider than the picture is left out; body 1's says \"body 1\", "
        "body 2's would overlap it (%d placed, 1)",
        nwide);

  /* the command: names from the snapshot's folder; --no-labels draws none */
  const char *mn[1] = {"al"};
  struct snapshot_meta meta = {
      .time = 0.0, .version = "test", .case_name = "labels", .material_names = mn, .nmat = 1};
  snprintf(path, sizeof path, "%s/particles_00000.csv", dir);
  CHECK(io_write_particles_csv(path, &p, &meta, &err) == 0, "labelled scene: %s", err.msg);
  particles_free(&p);
  long diff[2] = {-1, -1};
  for (int k = 0; k < 2; k++) {
    /* the radiograph (k = 0), then the particles, with labels and without */
    snprintf(args, sizeof args, "'%s' -o '%s/with.png' --size 800 %s", path, dir,
             k ? "--mode particles --axis y" : "");
    int st = run(args, out, sizeof out);
    snprintf(args, sizeof args, "'%s' -o '%s/without.png' --size 800 --no-labels %s", path, dir,
             k ? "--mode particles --axis y" : "");
    st |= run(args, out, sizeof out);
    char a[4400], b[4400];
    snprintf(a, sizeof a, "%s/with.png", dir);
    snprintf(b, sizeof b, "%s/without.png", dir);
    diff[k] = st ? -2 : png_differ(a, b);
  }
  CHECK(diff[0] > 200 && diff[1] > 200,
        "the command labels the bodies (radiograph: %ld bytes "
        "differ from --no-labels, particles: %ld; > 200)",
        diff[0], diff[1]);
  /* the same snapshot in a folder without used_parameters.yaml: "body N", not the names */
  snprintf(args, sizeof args,
           "mkdir -p '%s/unnamed' && cp '%s' '%s/unnamed/' && '%s' render "
           "'%s/unnamed/particles_00000.csv' -o '%s/unnamed.png' --size 800 --mode particles "
           "--axis y",
           test_tmpdir(), path, test_tmpdir(), test_bin(), test_tmpdir(), dir);
  const int st = test_run(args, out, sizeof out);
  char a[4400], b[4400];
  snprintf(a, sizeof a, "%s/with.png", dir);
  snprintf(b, sizeof b, "%s/unnamed.png", dir);
  const long dn = st ? -2 : png_differ(a, b);
  CHECK(dn > 100,
        "names from the snapshot's used_parameters.yaml, \"body N\" without it: %ld "
        "bytes differ (> 100) %s",
        dn, out);
}

/* Bad data: refused with one line naming the file, the particle and the field, exit 2,
 * for a picture and for a run's frames. */
static void test_bad_data(void)
{
  static const struct {
    const char *field;
    int which; /* 0 x, 1 y, 2 mat, 3 rho, 4 m, 5 h, 6 vx */
    double value;
  } bad[] = {
      {"'x' = nan", 0, NAN},       {"'y' = 1e+300", 1, 1e300}, {"'mat' = 99", 2, 99},
      {"'rho' = -5", 3, -5},       {"'m' = -1", 4, -1},        {"'h' = 0", 5, 0},
      {"'vx' = inf", 6, INFINITY},
  };
  char dir[4200], path[4400], args[9000], out[4096];
  snprintf(dir, sizeof dir, "%s/badvalues", test_tmpdir());
  snprintf(args, sizeof args, "rm -rf '%s' && mkdir -p '%s'", dir, dir);
  CHECK(system(args) == 0, "%s", args);
  const char *names[2] = {"al", "steel"};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
    struct particles p;
    particles_init(&p);
    const double c[3] = {0, 0, 0};
    add_sphere(&p, c, 2e-3, 0.5e-3, 2700, 1, 0, 0);
    const size_t i = 17;
    switch (bad[k].which) {
    case 0:
    case 1: p.x[bad[k].which][i] = bad[k].value; break;
    case 2: p.mat[i] = (int)bad[k].value; break;
    case 3: p.rho[i] = bad[k].value; break;
    case 4: p.m[i] = bad[k].value; break;
    case 5: p.h[i] = bad[k].value; break;
    default: p.v[0][i] = bad[k].value; break;
    }
    p.rho[i + 3] = bad[k].which == 3 ? -1.0 : p.rho[i + 3]; /* a second bad one, counted */
    struct snapshot_meta meta = {
        .time = 0.0, .version = "test", .case_name = "bad", .material_names = names, .nmat = 2};
    struct hv_error err;
    hv_error_clear(&err);
    snprintf(path, sizeof path, "%s/particles_%05zu.csv", dir, k);
    CHECK(io_write_particles_csv(path, &p, &meta, &err) == 0, "bad scene written %s", err.msg);
    particles_free(&p);
    for (int mode = 0; mode < 2; mode++) {
      snprintf(args, sizeof args, "'%s' -o '%s/bad.png' --mode %s", path, dir,
               mode ? "particles" : "radiograph");
      const int st = run(args, out, sizeof out);
      char *nl = strchr(out, '\n');
      CHECK(st == 2 && nl && nl[1] == '\0' && strstr(out, path) && strstr(out, "particle 17 ") &&
                strstr(out, bad[k].field) && (bad[k].which != 3 || strstr(out, "1 particles more")),
            "%s %s: exit %d (2), one line naming the file, particle 17 and %s: %s",
            mode ? "particles" : "radiograph", bad[k].field, st, bad[k].field, out);
    }
  }
  snprintf(path, sizeof path, "%s/bad.png", dir);
  CHECK(access(path, F_OK) != 0, "no picture of bad data written");
  /* a run folder's frames: the same check for every snapshot */
  snprintf(args, sizeof args, "'%s' -o '%s/frames' --size 400", dir, dir);
  const int st = run(args, out, sizeof out);
  CHECK(st == 2 && strstr(out, "particles_00000.csv: particle 17 (id 17), field 'x' = nan"),
        "frames of a folder with bad snapshots: exit %d (2), naming the first: %s", st, out);
}

/* ---- a run's snapshots as movie frames --------------------------------- */

/* A gas blob on the move and expanding (a half model, z >= 0), four outputs: each
 * snapshot alone would be framed and coloured differently. */
static const char *blob_case = "name: blob\n"
                               "materials:\n"
                               "  gas: {eos: ideal-gas, gamma: 1.4}\n"
                               "bodies:\n"
                               "  - name: blob\n"
                               "    material: gas\n"
                               "    shape: {type: box, min: [0, 0, 0], max: [0.05, 0.025, 0.025]}\n"
                               "    spacing: 6.25 mm\n"
                               "    density: 1.0\n"
                               "    pressure: 1.0\n"
                               "    velocity: [5, 0, 0]\n"
                               "    radial_velocity: 1\n"
                               "time:\n"
                               "  end: 0.03\n"
                               "output:\n"
                               "  every: 0.01\n"
                               "  csv: true\n";

/* The frame_NNNNN.png files in dir and their largest number (-1: none). */
static int count_frames(const char *dir, int *last)
{
  DIR *d = opendir(dir);
  int n = 0, k, len;
  *last = -1;
  struct dirent *e;
  while (d && (e = readdir(d)))
    if (sscanf(e->d_name, "frame_%d%n", &k, &len) == 1 && !strcmp(e->d_name + len, ".png")) {
      n++;
      if (k > *last) *last = k;
    }
  if (d) closedir(d);
  return n;
}

static int count_lines(const char *out, const char *what)
{
  int n = 0;
  for (const char *q = out; (q = strstr(q, what)) != NULL; q += strlen(what)) n++;
  return n;
}

/* The one line of out holding `what` contains `also`. */
static int line_has(const char *out, const char *what, const char *also)
{
  const char *q = strstr(out, what);
  if (!q) return 0;
  while (q > out && q[-1] != '\n') q--;
  const char *end = strchr(q, '\n');
  const char *hit = strstr(q, also);
  return hit && (!end || hit < end);
}

static void test_series(void)
{
  const char *dir = test_tmpdir();
  char run_dir[4200], cmd[32768], args[8192], path[4400], path2[4400];
  static char out[65536];
  snprintf(run_dir, sizeof run_dir, "%s/blobrun", dir);
  const char *casefile = test_write_file("blob.yaml", blob_case);
  snprintf(cmd, sizeof cmd,
           "cd '%s' && rm -rf blobrun frames_* csvrun mixrun slotrun emptyrun badrun && "
           "'%s' run '%s' -o '%s' --quiet",
           dir, test_bin(), casefile, run_dir);
  int st = test_run(cmd, out, sizeof out);
  CHECK(st == 0, "the tiny run: exit %d %s", st, out);
  /* run.pvd lists the run's snapshots; an earlier run's, left in the folder, is not in it */
  snprintf(path, sizeof path, "%s/run.pvd", run_dir);
  char *pvd = test_slurp(path, NULL);
  const int nsnap = pvd ? count_lines(pvd, "<DataSet") : -1;
  free(pvd);
  CHECK(nsnap == 4, "run.pvd lists %d snapshots (4)", nsnap);
  snprintf(cmd, sizeof cmd, "cp '%s/particles_00001.vtu' '%s/particles_00007.vtu'", run_dir,
           run_dir);
  CHECK(system(cmd) == 0, "%s", cmd);

  /* radiographs: one frame per snapshot of run.pvd, from the .vtu files, all one size */
  snprintf(args, sizeof args, "'%s' -o '%s/frames_xray' --size 400", run_dir, dir);
  st = run(args, out, sizeof out);
  int last, n;
  snprintf(path, sizeof path, "%s/frames_xray", dir);
  n = count_frames(path, &last);
  CHECK(st == 0 && n == nsnap && last == nsnap - 1,
        "series of radiographs: exit %d, %d frames up to %d (%d, numbered 0..%d) %s", st, n, last,
        nsnap, nsnap - 1, out);
  CHECK(count_lines(out, "hvsph: wrote ") == nsnap && !strstr(out, "particles_00007") &&
            count_lines(out, ".vtu, t = ") == nsnap,
        "one line per frame, from the .vtu snapshots, none from particles_00007.vtu: %s", out);
  CHECK(count_lines(out, "film mu = ") == 1 && strstr(out, "for every frame") &&
            strstr(out, "particles_00003.vtu"),
        "one automatic mu for every frame, from the last snapshot: %s", out);
  snprintf(args, sizeof args, "%s/frames_xray/frame_%%05d.png -pix_fmt yuv420p", dir);
  CHECK(strstr(out, "ffmpeg -framerate 10 -i ") && strstr(out, args),
        "the last line names the folder and an ffmpeg command: %s", out);
  /* --quiet: the same frames, not a line said */
  snprintf(args, sizeof args, "'%s' -o '%s/frames_quiet' --size 400 --quiet", run_dir, dir);
  st = run(args, out, sizeof out);
  snprintf(path, sizeof path, "%s/frames_quiet", dir);
  n = count_frames(path, &last);
  CHECK(st == 0 && n == nsnap && out[0] == '\0',
        "--quiet: exit %d, %d frames (%d), nothing "
        "said: '%s'",
        st, n, nsnap, out);
  int w0 = 0, h0 = 0, same = 1;
  for (int k = 0; k < nsnap; k++) {
    int w = 0, h = 0;
    snprintf(path, sizeof path, "%s/frames_xray/frame_%05d.png", dir, k);
    unsigned char *img = read_png(path, &w, &h);
    if (k == 0) {
      w0 = w;
      h0 = h;
    }
    same = same && img && w == w0 && h == h0;
    free(img);
  }
  CHECK(same && w0 == 400 && h0 > 0 && h0 % 2 == 0,
        "every frame %dx%d (400 wide, an even height for video)", w0, h0);

  /* particles by velocity: the union of the frames' own extents and ranges */
  struct render_options o;
  render_options_default(&o);
  o.mode = RENDER_PARTICLES;
  o.color = RENDER_COLOR_VELOCITY;
  o.width = 640;
  double ext[4] = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL}, lo = HUGE_VAL, hi = -HUGE_VAL;
  double own_ext[2][4] = {{0}}, own_lo[2] = {0}, own_hi[2] = {0};
  for (int k = 0; k < nsnap; k++) {
    struct particles p;
    particles_init(&p);
    struct hv_error err;
    hv_error_clear(&err);
    struct render_view v;
    double t;
    snprintf(path, sizeof path, "%s/particles_%05d.vtu", run_dir, k);
    if (io_read_particles(path, &p, &t, &err) || render_view_setup(&p, &o, &v, &err)) {
      CHECK(0, "%s: %s", path, err.msg);
      particles_free(&p);
      continue;
    }
    double flo = HUGE_VAL, fhi = -HUGE_VAL;
    for (size_t i = 0; i < p.n; i++) {
      const double s = sqrt(p.v[0][i] * p.v[0][i] + p.v[1][i] * p.v[1][i] + p.v[2][i] * p.v[2][i]);
      flo = fmin(flo, s);
      fhi = fmax(fhi, s);
    }
    for (int q = 0; q < 4; q++) ext[q] = q % 2 ? fmax(ext[q], v.ext[q]) : fmin(ext[q], v.ext[q]);
    lo = fmin(lo, flo);
    hi = fmax(hi, fhi);
    const int f = k == 0 ? 0 : k == nsnap - 1 ? 1 : -1;
    if (f >= 0) {
      memcpy(own_ext[f], v.ext, sizeof v.ext);
      own_lo[f] = flo;
      own_hi[f] = fhi;
    }
    particles_free(&p);
  }
  for (int f = 0; f < 2; f++) /* else the check below could not tell */
    CHECK(own_ext[f][0] > ext[0] + 0.01 * (ext[1] - ext[0]) ||
              own_ext[f][1] < ext[1] - 0.01 * (ext[1] - ext[0]),
          "snapshot %d alone is framed otherwise: x %g..%g m of %g..%g m", f ? nsnap - 1 : 0,
          own_ext[f][0], own_ext[f][1], ext[0], ext[1]);
  CHECK(own_lo[0] > lo + 0.01 * (hi - lo) || own_hi[0] < hi - 0.01 * (hi - lo),
        "snapshot 0 alone has another range: |v| %g..%g of %g..%g m/s", own_lo[0], own_hi[0], lo,
        hi);
  snprintf(args, sizeof args, "'%s' -o '%s/frames_v' --mode particles --color velocity --size 640",
           run_dir, dir);
  st = run(args, out, sizeof out);
  snprintf(path, sizeof path, "%s/frames_v", dir);
  n = count_frames(path, &last);
  CHECK(st == 0 && n == nsnap, "series of particles by velocity: exit %d, %d frames %s", st, n,
        out);
  int w = 0, h = 0;
  snprintf(path, sizeof path, "%s/frames_v/frame_00000.png", dir);
  unsigned char *img = read_png(path, &w, &h);
  free(img);
  for (int f = 0; f < 2; f++) {
    const int k = f ? nsnap - 1 : 0;
    snprintf(args, sizeof args,
             "'%s/particles_%05d.vtu' -o '%s/alone_%d.png' --mode particles "
             "--color velocity --box %.17g,%.17g,%.17g,%.17g,-1000,1000 --range %.17g,%.17g "
             "--size %dx%d",
             run_dir, k, dir, k, ext[0], ext[1], ext[2], ext[3], lo, hi, w, h);
    st = run(args, out, sizeof out);
    snprintf(path, sizeof path, "%s/frames_v/frame_%05d.png", dir, k);
    snprintf(path2, sizeof path2, "%s/alone_%d.png", dir, k);
    const long d = st == 0 ? png_differ(path, path2) : -2;
    CHECK(d == 0,
          "frame %d is snapshot %d alone with the union box and range: %ld bytes "
          "differ (0; -1 unreadable or sizes differ) %s",
          k, k, d, out);
  }

  /* a run without .vtu files (no run.pvd): the .csv files that match summary.csv; an
   * earlier run's beyond its outputs (00009) and one at another time (00001) left out,
   * and the frames numbered 0, 1, 2 all the same */
  char csv_dir[4200];
  snprintf(csv_dir, sizeof csv_dir, "%s/csvrun", dir);
  snprintf(cmd, sizeof cmd,
           "'%s' run '%s' -o '%s' --quiet --set output.vtu=false && "
           "cp '%s/particles_00001.csv' '%s/particles_00009.csv' && "
           "cp '%s/particles_00000.csv' '%s/particles_00001.csv'",
           test_bin(), casefile, csv_dir, csv_dir, csv_dir, csv_dir, csv_dir);
  st = test_run(cmd, out, sizeof out);
  CHECK(st == 0, "the run without .vtu: exit %d %s", st, out);
  snprintf(args, sizeof args, "'%s' -o '%s/frames_csv' --size 400", csv_dir, dir);
  st = run(args, out, sizeof out);
  snprintf(path, sizeof path, "%s/frames_csv", dir);
  n = count_frames(path, &last);
  CHECK(st == 0 && n == 3 && last == 2 && line_has(out, "frame_00001.png", "particles_00002.csv") &&
            line_has(out, "particles_00001.csv is not one of the outputs", "skipped") &&
            line_has(out, "particles_00009.csv is not one of the outputs", "skipped"),
        "csv run: exit %d, %d frames up to %d (3, 0..2), frame 1 from snapshot 2: %s", st, n, last,
        out);

  /* run.pvd lists a snapshot whose .vtu is gone: its .csv is read instead */
  snprintf(cmd, sizeof cmd, "cp -r '%s' '%s/mixrun' && rm '%s/mixrun/particles_00002.vtu'", run_dir,
           dir, dir);
  CHECK(system(cmd) == 0, "%s", cmd);
  snprintf(args, sizeof args, "'%s/mixrun' -o '%s/frames_mix' --size 400", dir, dir);
  st = run(args, out, sizeof out);
  snprintf(path, sizeof path, "%s/frames_mix", dir);
  n = count_frames(path, &last);
  CHECK(st == 0 && n == nsnap && line_has(out, "frame_00002.png", "particles_00002.csv") &&
            line_has(out, "frame_00003.png", "particles_00003.vtu"),
        "a .vtu missing, its .csv there: exit %d, %d frames (%d), frame 2 from the .csv: %s", st, n,
        nsnap, out);

  /* material colours over the whole series: the plate (body 1) keeps the second colour
   * after the projectile (body 0) has left; snapshot 1 alone would give it the first */
  {
    struct particles a, b;
    particles_init(&a);
    particles_init(&b);
    put(&a, -0.02, 0, 0, 1e-3, 0.01, 1000, 1, 0);
    a.body[0] = 0;
    for (int i = 0; i < 10; i++) {
      put(&a, 0.01 * i, 0, 0, 1e-3, 0.01, 1000, 0, 0);
      put(&b, 0.01 * i, 0, 0, 1e-3, 0.01, 1000, 0, 0);
      a.body[i + 1] = b.body[i] = 1;
    }
    const char *names[2] = {"plate", "projectile"};
    struct snapshot_meta meta = {
        .time = 0.0, .version = "test", .case_name = "slots", .material_names = names, .nmat = 2};
    struct hv_error err;
    hv_error_clear(&err);
    snprintf(cmd, sizeof cmd, "mkdir -p '%s/slotrun'", dir);
    CHECK(system(cmd) == 0, "%s", cmd);
    snprintf(path, sizeof path, "%s/slotrun/particles_00000.csv", dir);
    int wr = io_write_particles_csv(path, &a, &meta, &err);
    meta.time = 1e-6;
    snprintf(path, sizeof path, "%s/slotrun/particles_00001.csv", dir);
    wr = wr || io_write_particles_csv(path, &b, &meta, &err);
    CHECK(wr == 0, "two snapshots written: %s", err.msg);
    particles_free(&a);
    particles_free(&b);
    snprintf(args, sizeof args, "'%s/slotrun' -o '%s/frames_slots' --mode particles --size 400x200",
             dir, dir);
    st = run(args, out, sizeof out);
    snprintf(path, sizeof path, "%s/frames_slots/frame_00001.png", dir);
    img = read_png(path, &w, &h);
    long second = 0, first = 0;
    unsigned char c0[3], c1[3];
    render_palette(0, c0);
    render_palette(1, c1);
    for (long k = 0; img && k < (long)w * (h - 36); k++) {
      first += !memcmp(img + 3 * k, c0, 3);
      second += !memcmp(img + 3 * k, c1, 3);
    }
    free(img);
    CHECK(st == 0 && second > 50 && first == 0,
          "the plate in frame 1 keeps the second colour: "
          "exit %d, %ld pixels of it (> 50), %ld of the first (0) %s",
          st, second, first, out);
  }

  /* the folder of an earlier, longer series: its frames beyond are named */
  snprintf(args, sizeof args, "'%s' -o '%s/frames_xray' --size 400", csv_dir, dir);
  st = run(args, out, sizeof out);
  CHECK(
      st == 0 &&
          strstr(
              out,
              "also holds 1 frame_NNNNN.png of an earlier, longer series (from frame_00003.png on)"),
      "frames of an earlier series beyond this one's: exit %d %s", st, out);

  /* errors: one line naming the folder or file, exit 2; frames already there stay */
  snprintf(cmd, sizeof cmd,
           "mkdir -p '%s/emptyrun' && cp -r '%s' '%s/badrun' && "
           "head -c 600 '%s/particles_00002.vtu' > '%s/badrun/particles_00002.vtu'",
           dir, run_dir, dir, run_dir, dir);
  CHECK(system(cmd) == 0, "%s", cmd);
  snprintf(path, sizeof path, "%s/frames_xray/frame_00000.png", dir);
  size_t before_len = 0, after_len = 0;
  char *before = test_slurp(path, &before_len);
  static const struct {
    const char *in, *o;
    int status;
    const char *says;
  } bad[] = {
      {"emptyrun", "frames_empty", 2, "emptyrun: no particle snapshots"},
      {"badrun", "frames_xray", 2, "badrun/particles_00002.vtu"},
      {"blobrun", "blob.yaml", 2, "blob.yaml' is a file"},
      {"blobrun", "movie.png", 1, "not a .png"},
  };
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
    snprintf(args, sizeof args, "'%s/%s' -o '%s/%s' --size 400", dir, bad[k].in, dir, bad[k].o);
    st = run(args, out, sizeof out);
    char *nl = strchr(out, '\n');
    CHECK(st == bad[k].status && strstr(out, bad[k].says) && nl && nl[1] == '\0',
          "render %s -o %s: exit %d (%d), one line saying '%s': %s", bad[k].in, bad[k].o, st,
          bad[k].status, bad[k].says, out);
  }
  char *after = test_slurp(path, &after_len);
  CHECK(before && after && before_len == after_len && !memcmp(before, after, before_len),
        "a failed series leaves the frames already there as they were");
  free(before);
  free(after);
  snprintf(path, sizeof path, "%s/frames_xray", dir);
  DIR *d = opendir(path);
  int tmp = 0;
  struct dirent *e;
  while (d && (e = readdir(d))) tmp += strstr(e->d_name, ".tmp.") != NULL;
  if (d) closedir(d);
  CHECK(tmp == 0, "no temporary files left in the frames' folder (%d)", tmp);
}

/* ---- axisymmetric snapshots (radiograph_rz.c) ---------------------------------- */

/* A solid cylinder of rings along x: x0 <= x < x0 + nx dx, r < nr dx, lattice rows at
 * (j + 1/2) dx, ring mass 2π r ρ dx², h = hf dx. */
static void add_ring_cylinder(struct particles *p, double x0, int nx, int nr, double dx, double rho,
                              double hf)
{
  for (int i = 0; i < nx; i++)
    for (int j = 0; j < nr; j++) {
      const double r = (j + 0.5) * dx;
      put(p, x0 + (i + 0.5) * dx, r, 0.0, 2.0 * PI * r * rho * dx * dx, hf * dx, rho, 0, 0.0);
    }
  p->axisym = 1;
}

/* σ of the rings p on a view of pixels pix covering x in [u0, u0 + nu pix), y in
 * [v1 - nv pix, v1) (rows top down). */
static double *rz_sigma(const struct particles *p, double u0, double v1, double pix, int nu, int nv,
                        struct render_view *v)
{
  *v = (struct render_view){.axis = 2, .iu = 0, .iv = 1, .pix = pix, .nu = nu, .nv = nv};
  v->u0 = u0;
  v->u1 = u0 + nu * pix;
  v->v1 = v1;
  v->v0 = v1 - nv * pix;
  v->d0 = -HUGE_VAL;
  v->d1 = HUGE_VAL;
  double *sigma = malloc((size_t)nu * (size_t)nv * sizeof *sigma);
  CHECK(render_areal_density_rz(p, v, sigma) == 0.0, "no ring left out of the grid");
  return sigma;
}

/* The radiograph of rings is the Abel projection of their field: a solid cylinder of
 * radius R = 20 Δ gives 2ρ√(R² − y²) in its middle to within 1 % over |y| <= R − 3h (the
 * smoothed edge, 2h wide, is excluded with a margin of h), on the axis as well as off it
 * (radiograph_rz.c measured 0.5 % at h = 1.3 Δ, pixel Δ/2, and at most 0.9 % for h from
 * Δ to 2Δ with pixels from Δ/4 to Δ; the near-axis rings are projected as 3D points, the
 * others through exact chords: without that split the axis was 4-10 % heavy). The mass
 * is conserved to rounding (1e-12) where kernels span under 12 pixels, to 1e-6 (measured
 * 1.8e-7) where they span 16, radiograph.c's midpoint rule for wide kernels. A sphere of rings (a half disc) gives 2Rρ at its
 * centre to 2 % (3D radiograph's test_sphere: 5 %). */
static void test_axisym_radiograph(void)
{
  const double dx = 1e-3, rho = 1000.0, R = 20 * dx;
  const double cases[2][2] = {{1.3, 0.5}, {2.0, 0.25}}; /* h / Δ, pixel / Δ */
  for (int c = 0; c < 2; c++) {
    struct particles p;
    particles_init(&p);
    add_ring_cylinder(&p, 0.0, 60, 20, dx, rho, cases[c][0]);
    const double pix = cases[c][1] * dx, h = cases[c][0] * dx;
    struct render_view v;
    const int nu = (int)lround(70 * dx / pix), nv = (int)lround(50 * dx / pix);
    double *sigma = rz_sigma(&p, -5 * dx, 25 * dx, pix, nu, nv, &v);
    double mass = 0.0, worst = 0.0, worst_y = 0.0, axis = 0.0;
    for (size_t k = 0; k < (size_t)nu * (size_t)nv; k++) mass += sigma[k] * pix * pix;
    const int i = (int)((30 * dx - v.u0) / pix);
    for (int j = 0; j < nv; j++) {
      const double y = v.v1 - (j + 0.5) * pix;
      if (fabs(y) > R - 3 * h) continue;
      const double rel =
          sigma[(size_t)j * (size_t)nu + (size_t)i] / (2 * rho * sqrt(R * R - y * y)) - 1;
      if (fabs(y) < pix) axis = fmax(axis, fabs(rel));
      if (fabs(rel) > worst) {
        worst = fabs(rel);
        worst_y = y;
      }
    }
    CHECK(fabs(mass / total_mass(&p) - 1.0) < (c == 0 ? 1e-12 : 1e-6),
          "rings (h %.2g Δ, pixel %.2g Δ): the picture's mass is the rings' (%.3g)", cases[c][0],
          cases[c][1], mass / total_mass(&p) - 1.0);
    CHECK(worst < 0.01 && axis < 0.01,
          "solid cylinder of rings (h %.2g Δ, pixel %.2g Δ): sigma / 2ρ√(R² − y²) − 1 at most "
          "%.4f (at y = %.2f mm; %.4f on the axis), within 1 %%",
          cases[c][0], cases[c][1], worst, worst_y * 1e3, axis);
    free(sigma);
    particles_free(&p);
  }
  /* a sphere of radius R: rings of the half disc x² + r² < R² */
  struct particles s;
  particles_init(&s);
  for (int i = -20; i < 20; i++)
    for (int j = 0; j < 20; j++) {
      const double x = (i + 0.5) * dx, r = (j + 0.5) * dx;
      if (x * x + r * r < R * R)
        put(&s, x, r, 0.0, 2 * PI * r * rho * dx * dx, 1.3 * dx, rho, 0, 0);
    }
  s.axisym = 1;
  struct render_view v;
  double *sigma = rz_sigma(&s, -25 * dx, 25 * dx, 0.5 * dx, 100, 100, &v);
  const double centre = 0.25 * (sigma[49 * 100 + 49] + sigma[49 * 100 + 50] + sigma[50 * 100 + 49] +
                                sigma[50 * 100 + 50]);
  CHECK_CLOSE(centre / (2 * R * rho), 1.0, 0.02,
              "sphere of rings: areal density at its centre / 2Rρ");
  free(sigma);
  particles_free(&s);
}

/* render_png of rings: both halves drawn (the view spans −r), the radiograph through the
 * revolved body, --axis x refused, --no-mirror the upper half only. */
static void test_axisym_png(void)
{
  struct particles p;
  particles_init(&p);
  add_ring_cylinder(&p, 0.0, 30, 10, 1e-3, RHO_STEEL, 1.3);
  struct hv_error err;
  hv_error_clear(&err);
  struct render_options o, orz;
  render_options_default(&o);
  o.width = 400;
  char path[4200];
  snprintf(path, sizeof path, "%s/rz_radiograph.png", test_tmpdir());
  CHECK(render_png(path, &p, &o, NULL, &err) == 0, "radiograph of rings written: %s", err.msg);
  o.mode = RENDER_PARTICLES;
  snprintf(path, sizeof path, "%s/rz_particles.png", test_tmpdir());
  CHECK(render_png(path, &p, &o, NULL, &err) == 0, "particle picture of rings written: %s",
        err.msg);
  struct particles q;
  render_rz_halves(&p, 1, &q);
  CHECK(q.n == 2 * p.n && q.x[1][p.n + 7] == -p.x[1][7] && q.m[p.n + 7] == p.m[7] && !q.axisym,
        "both halves: every ring at (x, r) and (x, -r)");
  struct render_view v;
  CHECK(render_rz_options(&o, &orz, &err) == 0 && render_view_setup(&q, &orz, &v, &err) == 0 &&
            v.v0 < -10e-3 && v.v1 > 10e-3 && v.iu == 0 && v.iv == 1,
        "the picture spans the radius both ways (%g..%g m)", v.v0, v.v1);
  particles_free(&q);
  o.axis = 0;
  CHECK(render_png(path, &p, &o, NULL, &err) != 0 && err.code == HV_EXIT_USAGE &&
            strstr(err.msg, "--axis y or z"),
        "a view along the axis refused: %s", err.msg);
  o.axis = 1;
  o.have_box = 1;
  const double box[6] = {-1e-3, 31e-3, -1, 1, -12e-3, 12e-3};
  memcpy(o.box, box, sizeof box);
  CHECK(render_rz_options(&o, &orz, &err) == 0 && orz.axis == 2 && orz.box[2] == -12e-3 &&
            orz.box[3] == 12e-3 && orz.box[4] == -HUGE_VAL,
        "--axis y: the box's z range is the radius shown");
  /* the command on an RZ CSV snapshot (its geometry line read back) */
  char csv[4200], args[9000], out[4096];
  snprintf(csv, sizeof csv, "%s/rz_rings.csv", test_tmpdir());
  CHECK(io_write_particles_csv(csv, &p, NULL, &err) == 0, "RZ CSV written: %s", err.msg);
  snprintf(args, sizeof args, "'%s' -o '%s/rz_cli.png' --size 400x300", csv, test_tmpdir());
  int st = run(args, out, sizeof out);
  CHECK(st == 0 && strstr(out, "(300 rings)"), "hvsph render of an RZ CSV: exit %d %s", st, out);
  snprintf(args, sizeof args, "'%s' -o '%s/rz_cli.png' --mode particles --axis y", csv,
           test_tmpdir());
  st = run(args, out, sizeof out);
  CHECK(st == 0, "hvsph render --mode particles --axis y of rings: exit %d %s", st, out);
  snprintf(args, sizeof args, "'%s' -o '%s/rz_cli.png' --axis x", csv, test_tmpdir());
  st = run(args, out, sizeof out);
  CHECK(st == HV_EXIT_USAGE && strstr(out, "--axis y or z"),
        "hvsph render --axis x of rings: exit %d (usage) %s", st, out);
  particles_free(&p);
}

/* A series of an axisymmetric run's snapshots (CSV rings, no summary.csv): every frame of
 * one size, both halves framed (the picture's extent reaches −r), in both modes. */
static void test_axisym_series(void)
{
  char dir[4200], frames[4200], f0[4300], f1[4300];
  snprintf(dir, sizeof dir, "%s/rz_run", test_tmpdir());
  snprintf(frames, sizeof frames, "%s/rz_frames", test_tmpdir());
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(io_mkdir_p(dir, &err) == 0, "run folder made: %s", err.msg);
  for (int k = 0; k < 2; k++) {
    struct particles p;
    particles_init(&p);
    add_ring_cylinder(&p, 5e-3 * k, 20, 8, 1e-3, RHO_STEEL, 1.3); /* moving along x */
    char path[4400];
    snprintf(path, sizeof path, "%s/particles_%05d.csv", dir, k);
    const struct snapshot_meta m = {.time = 1e-6 * k, .step = k, .version = "test"};
    CHECK(io_write_particles_csv(path, &p, &m, &err) == 0, "RZ snapshot %d written: %s", k,
          err.msg);
    particles_free(&p);
  }
  for (int mode = 0; mode < 2; mode++) {
    struct render_options o;
    render_options_default(&o);
    o.mode = mode ? RENDER_PARTICLES : RENDER_RADIOGRAPH;
    o.width = 300;
    CHECK(render_series(dir, frames, &o, &err) == 0, "series of an RZ run (%s): %s",
          mode ? "particles" : "radiograph", err.msg);
    snprintf(f0, sizeof f0, "%s/frame_00000.png", frames);
    snprintf(f1, sizeof f1, "%s/frame_00001.png", frames);
    int w0 = 0, h0 = 0, w1 = 0, h1 = 0;
    unsigned char *a = read_png(f0, &w0, &h0), *b = read_png(f1, &w1, &h1);
    CHECK(a && b && w0 == 300 && w1 == w0 && h1 == h0 && h0 > 150,
          "RZ frames of one size (%dx%d, %dx%d): the extent spans both halves", w0, h0, w1, h1);
    free(a);
    free(b);
  }
  struct render_options o;
  render_options_default(&o);
  o.axis = 0;
  CHECK(render_series(dir, frames, &o, &err) != 0 && strstr(err.msg, "--axis y or z"),
        "a series along the axis refused: %s", err.msg);
}

int main(void)
{
  test_kernel_column();
  test_colormap();
  test_single_particle();
  test_sphere();
  test_plate();
  test_extremes();
  test_tick_step();
  test_auto_mu();
  test_exposure();
  test_axes();
  test_command();
  test_labels();
  test_bad_data();
  test_series();
  test_axisym_radiograph();
  test_axisym_png();
  test_axisym_series();
  return test_finish();
}
