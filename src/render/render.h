/* render.h — pictures of particle snapshots (PNG): simulated flash radiographs and
 * particle side views. `hvsph render` (cli_render, cli/render.c) is the command line;
 * the rest is the library the command and the tests use.
 *
 * Geometry. The line of sight is one coordinate axis (`axis`); the picture shows the
 * other two, first to the right, second up:
 *   axis z (default): x right, y up      axis y: x right, z up      axis x: y right, z up
 * Half models are simulated in z >= 0 with the symmetry plane z = 0. Mirroring reflects
 * every particle across z = 0 (a copy at -z), so a picture shows the whole body: along y
 * or x the lower half of the picture is the mirror image; along z every column is counted
 * twice, as an x-ray through the full body would. Quarter models (y >= 0, z >= 0) are
 * reflected across y = 0 as well (render_copy_pos: four copies of each particle).
 *
 * Radiograph (docs/rendering.md): each particle's mass is spread over the picture with
 * the cubic-spline kernel integrated along the line of sight,
 *   Σ(R, h) = F(R/h) / h²,  F(s) = ∫ W₁(√(s² + t²)) dt,  ∫ 2πs F(s) ds = 1,
 * (W₁ the M4 kernel of kernel.h with h = 1), so the picture holds the areal density
 * σ = ∫ρ dl [kg/m²], and the film shows the transmitted fraction T = exp(−μ σ) as grey
 * (white: no material). Pixels are square; the mass in the picture is conserved to
 * rounding (kernels that reach past the edge lose only the part outside). Unless --mu
 * gives it, μ is chosen from the picture: the lower quartile of the areal densities of
 * the pixels that hold a particle's centre gets T = 1/2 (render_auto_mu), so thin aluminium debris shows
 * as well as a steel plate.
 *
 * Particles: discs of radius 0.6 h, far ones first (painter's algorithm; the viewer sits on
 * the negative side of the view axis), coloured by material or by a quantity through a
 * sequential colour map with monotonic lightness (render_colormap).
 *
 * Both modes get axes with ticks in mm along the left and bottom edges of the plot
 * (axes.c) and each body's name near its projected centre where the label fits.
 *
 * A series (render_series, series.c): every snapshot of a run folder as a frame of a movie,
 * all with one extent, mirroring, size and colour scale, so that the picture does not jump.
 */
#ifndef HV_RENDER_H
#define HV_RENDER_H

#include "core/error.h"
#include "particles/particles.h"

enum render_mode { RENDER_RADIOGRAPH = 0, RENDER_PARTICLES = 1 };

enum render_color {
  RENDER_COLOR_MATERIAL = 0, /* fixed palette by material index */
  RENDER_COLOR_DAMAGE,       /* 0..1 */
  RENDER_COLOR_VELOCITY,     /* |v| [m/s], labelled in km/s */
  RENDER_COLOR_PRESSURE,     /* p [Pa], labelled in GPa */
  RENDER_COLOR_DENSITY,      /* rho [kg/m3], labelled in g/cm3 */
  RENDER_COLOR_ALPHA,        /* the viscosity switch's α (sph.viscosity.switch), 0..its max */
  RENDER_COLOR_DT            /* the time step a particle allows [s], coloured by its log10 */
};

#define RENDER_MU_AUTO 0.0 /* --mu not given: chosen from the areal densities in view */
#define RENDER_MU_FALLBACK                                                                         \
  0.05                             /* [m2/kg] the automatic μ of a picture without material
                                    (about iron's at 90 keV) */
#define RENDER_MAX_COORD     1e6   /* [m] a position farther from the origin is bad data */
#define RENDER_WIDTH_DEFAULT 1200  /* [px] picture width when --size is not given */
#define RENDER_MIN_WIDTH     200   /* [px] */
#define RENDER_MIN_HEIGHT    100   /* [px] */
#define RENDER_MAX_SIDE      16384 /* [px] */
/* Background of both modes and of the caption band: white. */
#define RENDER_BG_R 255
#define RENDER_BG_G 255
#define RENDER_BG_B 255

struct render_options {
  enum render_mode mode;
  int axis;                /* line of sight: 0 x, 1 y, 2 z */
  enum render_color color; /* particles mode */
  int width, height;       /* [px] the whole picture (plot + caption band); 0: automatic */
  int have_box;
  double box[6]; /* [m] xmin, xmax, ymin, ymax, zmin, zmax */
  int mirror;    /* -1: automatic (on for a half model), 0 off, 1 on */
  double mu;     /* [m2/kg] mass attenuation coefficient (radiograph);
                                RENDER_MU_AUTO: render_auto_mu of the picture */
  int labels;    /* 1: each body's name where it fits (default), 0: none */
  int have_range;
  double range[2]; /* colour range in SI units of the quantity (particles mode) */
};

void render_options_default(struct render_options *o);

/* Where the picture lies in space and on the page. */
struct render_view {
  int axis, iu, iv;      /* line of sight; coordinates shown right (iu) and up (iv) */
  int mirror;            /* particles are reflected across z = 0 (copies at -z) */
  int mirror_y;          /* and across y = 0 (a quarter model: copies at -y) */
  double u0, u1, v0, v1; /* [m] extent of the plot area (square pixels) */
  double ext[4];         /* [m] the extent asked for, u0, u1, v0, v1 before it was grown to
                                the plot area's aspect: the box's, or the particles' with their
                                supports and the margin */
  double d0, d1;         /* [m] slab along the line of sight (particle centres), ±inf by default */
  double pix;            /* [m] pixel edge */
  int nu, nv;            /* [px] plot area, at the top of the picture right of the
                                left axis margin: columns ml..ml+nu-1, rows 0..nv-1 */
  int ml, mb;            /* [px] left margin (y axis' ticks and labels), bottom axis band */
  int width, height;     /* [px] whole picture: ml + nu wide, nv + mb + band high */
  int band;              /* [px] caption band height */
  int scale;             /* font scale of the caption (1 or 2) */
};

/* Chooses mirroring, the extent (the box, or every particle with its 2h support plus a
 * margin, grown about its centre to the picture's aspect) and the layout. Fails
 * (HV_EXIT_INPUT) for an empty snapshot, HV_EXIT_USAGE for a size or box that cannot work. */
int render_view_setup(const struct particles *p, const struct render_options *o,
                      struct render_view *view, struct hv_error *err);

/* 1 when p is a half model (every particle at z >= -h/2): mirroring's automatic choice. */
int render_half_model(const struct particles *p);
/* 1 when p is also a quarter model: every particle at y >= -h/2, and one within h of
 * y = 0 (a body the plane cuts, not a full or half model's body that lies at y > 0). */
int render_quarter_model(const struct particles *p);

/* Copy `copy` (0..3) of particle i in view v: bit 0 its mirror image across z = 0, bit 1
 * across y = 0. Returns 0 for a copy the view does not draw (its mirror is off). */
static inline int render_copy_pos(const struct particles *p, size_t i, int copy,
                                  const struct render_view *v, double x[3])
{
  if (((copy & 1) && !v->mirror) || ((copy & 2) && !v->mirror_y)) return 0;
  x[0] = p->x[0][i];
  x[1] = copy & 2 ? -p->x[1][i] : p->x[1][i];
  x[2] = copy & 1 ? -p->x[2][i] : p->x[2][i];
  return 1;
}
#define RENDER_COPIES 4 /* render_copy_pos's copies, mirrored or not */

/* F(s) of the header: the M4 cubic spline integrated along a line at distance s·h from the
 * particle, times h²; F(0) = 3/(2π), zero for s >= 2. */
double render_kernel_column(double s);

/* The attenuation a radiograph of areal densities sigma[0..npix) gets by default: the
 * lower quartile of σ over the pixels holding material (σ > 0) and, where occupied is not
 * NULL, a particle's centre (occupied[k] != 0, render_occupied) is given
 * T = exp(−μσ) = 1/2, so μ = ln 2 / quartile; RENDER_MU_FALLBACK when no pixel
 * qualifies. *quartile gets that σ (0 when none). radiograph.c and docs/rendering.md argue the choice. */
double render_auto_mu(const double *sigma, const unsigned char *occupied, size_t npix,
                      double *quartile);
/* occupied[j * nu + i] = 1 for the view's plot pixels that hold the centre of a particle
 * in view (mirror copies included), 0 for the others. */
void render_occupied(const struct particles *p, const struct render_view *v,
                     unsigned char *occupied);

/* The tick step of an axis: the smallest 1, 2 or 5 × 10ᵏ (in the units of span) whose
 * ticks lie at least min_px apart on an axis of npx pixels showing span (> 0). */
double render_tick_step(double span, double npx, double min_px);

/* Refuses values that cannot be drawn or mean corrupt data: a position not finite or
 * beyond RENDER_MAX_COORD, a velocity not finite, a mass or smoothing length not
 * positive, a density negative or not finite, a material index below 0 or not among
 * the snapshot's nmat materials (nmat 0: names unknown, any index below
 * RENDER_MATERIAL_CAP), a negative body index. Error (HV_EXIT_INPUT): the file, the
 * first bad particle (index and id), the field and its value, and how many more. */
int render_check_particles(const struct particles *p, int nmat, const char *path,
                           struct hv_error *err);

/* Areal density σ [kg/m²] on the view's nu × nv plot pixels (row 0 at the top, v = v1):
 * sigma[j * nu + i]. Σ sigma · pix² equals the mass in the view (mirror copies included). */
void render_areal_density(const struct particles *p, const struct render_view *view, double *sigma);

/* Axisymmetric snapshots (p->axisym; radiograph_rz.c has the method and its error).
 * render_rz_options: the options of the picture across the axis (line of sight z, x
 * right, r up; --axis y read as z, its box's z range as the up range; the depth slab
 * unbounded; mirroring off, the halves being made by render_rz_halves); --axis x is
 * refused (HV_EXIT_USAGE). render_rz_halves: q (initialised here; particles_free it)
 * gets p's rings as points of the plane z = 0 at (x, r) and, with both, their mirror
 * images at (x, −r) (v_y, S_xy, S_yz negated), with q->axisym 0. render_areal_density_rz:
 * σ [kg/m²] on the view's pixels through the rings revolved about the x axis (as
 * render_areal_density); returns the mass [kg] of rings left out beyond the grid's
 * reach (0 unless a --box far smaller than the body). */
int render_rz_options(const struct render_options *o, struct render_options *orz,
                      struct hv_error *err);
void render_rz_halves(const struct particles *p, int both, struct particles *q);
double render_areal_density_rz(const struct particles *p, const struct render_view *view,
                               double *sigma);

/* Particles mode, a quantity: widens [*lo, *hi] to the values (SI) of the particles drawn
 * in the view (start from HUGE_VAL, -HUGE_VAL); non-finite values are left out. */
void render_color_extend(const struct particles *p, const struct render_view *view,
                         const struct render_options *o, double *lo, double *hi);
/* The colour range drawn, from the data's range [*lo, *hi] (render_color_extend): the
 * --range when given, 0 to 1 for damage or when nothing was drawn, a band of ±5 % about a
 * single value; otherwise the data's. */
void render_color_limits(const struct render_options *o, double *lo, double *hi);

/* The sequential colour map, t in [0, 1] (clamped) -> sRGB; lightness rises with t. */
void render_colormap(double t, unsigned char rgb[3]);
/* The material palette, cycling after 10 entries. */
void render_palette(int k, unsigned char rgb[3]);

/* What the caption says besides the options. */
struct render_info {
  double time;                       /* [s] snapshot time; NaN: not shown */
  const char *const *material_names; /* index -> name; may be NULL */
  int nmat;
  const char *source;       /* snapshot file name, for the PNG's text chunk; may be NULL */
  const int *material_slot; /* palette slot of each material index < nslot, kept the
                                         same over a series of pictures; NULL: ranked from p's
                                         bodies (render.c) */
  int nslot;
  const char *const *body_names; /* body index -> name (labels), may hold NULLs
                                         ("body N"); NULL: render_png reads them from the
                                         used_parameters.yaml in source's folder */
  int nbody;
};

/* The body names of the run whose used_parameters.yaml is in folder dir (bodies[i].name)
 * into names[i] (max entries of 64 bytes); returns how many (0: no such file, or one
 * that cannot be read: the labels then say "body N"). */
int render_read_body_names(const char *dir, char names[][64], int max);

/* Renders p as the options say and writes the PNG (8-bit RGB) to path, whole or not at all.
 * Errors: HV_EXIT_USAGE (options that cannot work), HV_EXIT_INPUT (data missing, e.g. no
 * damage column; unwritable output folder), HV_EXIT_RUN (write failure). */
int render_png(const char *path, const struct particles *p, const struct render_options *o,
               const struct render_info *info, struct hv_error *err);

/* Every snapshot of the run whose output folder is rundir (io_run_snapshots, .vtu
 * preferred; those not among the outputs of its summary.csv skipped) as the frames
 * framedir/frame_NNNNN.png of a movie, NNNNN = 0, 1, ... in the run's order, all with the
 * same mirroring, extent, picture size, colour range and material colours (series.c).
 * framedir is created when missing; one line per frame on stderr, and a last one with an
 * ffmpeg command. Fails (err) for a folder without snapshots or a snapshot that cannot be
 * read, naming it (HV_EXIT_INPUT), or as render_png; frames written before stay, whole. */
int render_series(const char *rundir, const char *framedir, const struct render_options *o,
                  struct hv_error *err);

#endif
