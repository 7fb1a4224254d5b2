/* measure.h — what the experimenters measured, taken from the particles.
 *
 * The paper (seed 000, §2.2–3) compares simulations with post-test cavities in thick
 * targets (penetration depth L, cavity diameter D), bumper holes, debris clouds
 * (velocity, half spray angle), backwall damage (crater depth, damaged area, peak
 * pressure at the centre) and the shock in a gas behind a vessel wall. Each function
 * below computes one of these from a particle set; definitions, defaults and their
 * resolution limits are in docs/measurements.md as well as here.
 *
 * Conventions. SI units. The projectile flies along +x. A plate (or block, backwall)
 * initially occupies x0 <= x <= x0 + thickness, normal to x; the impact point on it is
 * (x0, yc, 0) and the axis is the line y = yc, z = 0. The symmetry plane is z = 0: in a
 * half model only z >= 0 is simulated, and measurements that need the full picture
 * mirror the particles across z = 0 (hole areas, fragment and cloud masses); radial
 * distances ρ = sqrt((y − yc)² + z²) are mirror-symmetric anyway.
 * Only real particles [0, p->n) are examined, never ghosts. A particle is taken when
 * it belongs to the named body (body < 0: any body) and, if a mask is given, mask[i]
 * is non-zero; particles with a non-finite position are ignored.
 * Particle footprint: a particle stands for the lattice cell around it, so material
 * is taken to extend `footprint` (default Δ/2, Δ = the body's initial lattice spacing)
 * from a particle centre; material-free distances are measured to that edge.
 *
 * Every *_defaults() fills the documented defaults from the geometry; change fields
 * after calling it. The functions are pure (no globals, no output) and serial, so
 * their results do not depend on the thread count. They return 0, or -1 with err set
 * (HV_EXIT_INPUT) for invalid parameters.
 */
#ifndef HV_MEASURE_H
#define HV_MEASURE_H

#include <stddef.h>

#include "core/error.h"
#include "particles/particles.h"

#define HV_MEAS_PI 3.14159265358979323846

/* Where a plate-like body was and how it was built. */
struct meas_geom {
  int body;         /* body index of the plate, block or backwall (< 0: any body) */
  double x0;        /* [m] original front (impact-side) face: the plane x = x0 */
  double thickness; /* [m] original thickness: the body filled x0 <= x <= x0 + thickness */
  double yc;        /* [m] the impact point is (x0, yc, 0); the axis is y = yc, z = 0 */
  double spacing;   /* [m] initial lattice spacing Δ of the body */
  int half_model;   /* 1: only z >= 0 is simulated (symmetry plane z = 0) */
  /* 1: only y >= 0, z >= 0 (planes y = 0 and z = 0; yc is 0; half_model is 1 too) */
  int quarter_model;
};

/* The copies of the full picture each simulated particle stands for: 1, 2 (a half
 * model) or 4 (a quarter model). */
static inline int meas_images(int half_model, int quarter_model)
{
  return quarter_model ? 4 : half_model ? 2 : 1;
}

/* The largest friends-of-friends piece of a plate or wall among the particles with
 * sel[i] != 0 (links FOF_B_FACTOR × g->spacing, × scale[i] per particle when scale is
 * given; g->half_model joins mirror images): clears sel for every other particle.
 * Used by the plate (attached_only) and the backwall's columns. */
int meas_keep_largest_piece(const struct particles *p, const struct meas_geom *g,
                            const double *scale, unsigned char *sel, struct hv_error *err);

/* ---- Thick target: penetration depth L and cavity diameter D -------------------
 * Target particles (of g->body, not masked out, no faster than v_max) are binned in
 * axial slices of thickness `slice` from the original surface x0 downwards (+x).
 * Cavity radius of slice k: r_k = ρ_(min_count) − footprint, where ρ_(j) is the j-th
 * smallest radial distance from the axis among the slice's target particles (∞ when
 * the slice holds none). Slice k is open when r_k > r_open (default Δ: a cavity
 * wider than one particle spacing). The cavity is the run of open slices from the
 * surface, k = 0 .. K−1, with slice K the first closed one.
 * L: depth of the deepest point of the cavity below x0: L = x_b − footprint − x0,
 *    x_b the smallest x of the target particles of slice K that close it
 *    (ρ − footprint <= r_open); if no slice closes (no target material left on the
 *    axis below the cavity) the block is perforated and L = the depth of the deepest
 *    target particle plus the footprint (the rear of the material). Target material
 *    more than 2Δ behind the original rear face x0 + thickness (spall, a plug or
 *    fragments thrown through) is left out of the slices (thickness 0: nothing is).
 * D: the largest cavity diameter over the depth, D = 2 max_k r_k over the open slices
 *    with target material (matching the experimenters' post-test cross-sections,
 *    which show the widest section); D_mean averages 2 r_k over the same slices.
 * No cavity (slice 0 closed): L = D = 0. Resolution: L within about one slice plus the
 * lattice's half spacing, D within about Δ.
 * The wall by filled volume (D_wall, D_wall_mean), robust to single particles inside the
 * cavity and independent of the lattice: the target is cut in slabs `wall_slab` thick
 * from x0 and each slab in annuli `wall_dr` wide about the axis; each target particle
 * fills a cube of its volume m/ρ, spread evenly over its edge (m/ρ)^(1/3) in depth and in
 * radius, and an annulus's filled fraction is the volume it receives over its own (half
 * of it in a half model). The slab's wall radius is where the fraction first crosses `wall_fill`,
 * interpolated between annulus centres, in the first annulus that reaches it with the
 * next one (a single filled annulus of stray particles is passed over). D_wall = 2 max
 * and D_wall_mean = the mean of the wall radius over the slabs that lie wholly within
 * x0 .. x0 + L; 0 when none does. Resolution: about wall_dr where the wall is sharp. */
#define MEAS_CAVITY_MAX_COUNT 8 /* the largest min_count */

struct meas_cavity_params {
  double slice;              /* [m] slice thickness (default Δ/2) */
  double footprint;          /* [m] (default Δ/2) */
  double r_open;             /* [m] open-slice threshold on the cavity radius (default Δ) */
  double v_max;              /* [m/s] target particles faster than this are flying debris, not
                        cavity wall (default INFINITY: all taken) */
  int min_count;             /* 1..MEAS_CAVITY_MAX_COUNT: the radius is set by the min_count-th
                        nearest particle, so min_count − 1 stray particles inside the
                        cavity are ignored (default 1) */
  double wall_slab;          /* [m] slab thickness of the filled-volume wall (default 4Δ) */
  double wall_dr;            /* [m] annulus width of the filled-volume wall (default Δ/4) */
  double wall_fill;          /* filled fraction that marks the wall, in (0, 1) (default 0.5) */
  const unsigned char *mask; /* optional [p->n] */
};
struct meas_cavity {
  double L;           /* [m] penetration depth */
  double D;           /* [m] largest cavity diameter */
  double D_mean;      /* [m] mean cavity diameter over the open slices */
  double depth_at_D;  /* [m] depth (slice centre) of the widest slice */
  double D_wall;      /* [m] largest wall diameter by filled volume (slabs within L) */
  double D_wall_mean; /* [m] mean wall diameter by filled volume over the same slabs */
  size_t nwall;       /* slabs wholly within L (those D_wall and D_wall_mean cover) */
  int perforated;     /* the cavity runs through all the target material */
  size_t
      nslice; /* slices examined (x0 to the deepest target particle within 2Δ of the rear face) */
  size_t nopen;      /* open slices from the surface (K) */
  double slice;      /* [m] slice thickness used */
  double *r_profile; /* [nslice] cavity radius r_k of slice k, depth (k + ½) slice [m];
                         INFINITY where a slice has no target particle */
};
void meas_cavity_defaults(struct meas_cavity_params *par, const struct meas_geom *g);
int measure_cavity(const struct particles *p, const struct meas_geom *g,
                   const struct meas_cavity_params *par, struct meas_cavity *out,
                   struct hv_error *err);
void meas_cavity_free(struct meas_cavity *c);

/* ---- Plate: perforation and hole diameter ----------------------------------------
 * Plate particles: those of g->body (and mask) within the slab
 * x0 − slab_front <= x <= x0 + thickness + slab_rear (ejecta and debris that have left
 * the slab are not plate) and, with attached_only (the default), in the largest
 * connected piece among them (friends-of-friends at 1.5 Δ, fof.h): a fragment that has
 * broken loose and drifts in the plane of the hole is debris, not the plate an
 * experiment recovers and measures. Their positions are projected along x onto the (y, z)
 * plane — the view through the plate along the flight direction — and, in a half
 * model, mirrored to (y, −z). A square grid of cells of edge `cell` covers the window
 * |y − yc| <= W, |z| <= W (W = r_max, or the projected extent of the plate); a cell is
 * material when its centre lies within `tol` of a projected particle (tol = Δ bridges
 * the gaps of a stretched or hcp-projected plate), else empty.
 * Hole: the 4-connected empty cells containing the empty cell nearest the impact point
 * (yc, 0), provided that cell lies within seed_radius of it. Perforated = such a hole
 * exists: there is a line of sight through the whole thickness at the impact point.
 * d_circle: diameter of the largest material-free circle inside the hole — its centre
 *    maximises r(c) = min_i |c − y_i| − footprint over the projected particles y_i
 *    (started from the grid's distance transform, then refined on the exact particle
 *    distances); circle_center is that centre (y, z).
 * d_circle_impact: 2 r at the impact point itself (the circle centred there).
 * d_equiv: equivalent-area diameter, 2 sqrt(A/π) + 2 (tol − footprint), A = the area of
 *    the hole's cells (full mirrored plane); the term 2 (tol − footprint) moves the edge
 *    from tol back to the footprint distance from the edge particles, as for d_circle.
 * hole_open: the hole reaches the edge of the window (the plate is gone across the
 *    whole window): the diameters are then lower bounds.
 * Not perforated: the diameters and area are 0. Resolution: about Δ on the diameters
 * (the circle also depends on the rim particles' placement, within Δ/2 in radius).
 * A plate of several bodies of different spacings (a plate refined near the impact
 * point: a fine disc inside a coarse plate) is measured with g->body < 0, a mask of its
 * bodies, g->spacing the finest and `scale` [p->n] = Δ_i/Δ, each particle's own body
 * spacing over the finest: particle i then covers the plane within scale_i tol, has the
 * footprint scale_i footprint and links at 1.5 scale_i Δ (FoF linking (b_i + b_j)/2), so
 * that the coarse part is as solid as it is alone; d_equiv's edge term keeps the finest
 * spacing (the hole's rim lies in the fine part). */
struct meas_plate_params {
  double tol;         /* [m] a projected particle covers the plane within tol (default Δ) */
  double footprint;   /* [m] (default Δ/2) */
  double cell;        /* [m] projection grid cell (default Δ/4; enlarged when the window
                          would need more than 4096 cells a side) */
  double slab_front;  /* [m] (default max(thickness, 2Δ)) */
  double slab_rear;   /* [m] (default max(thickness, 2Δ)) */
  double seed_radius; /* [m] the hole must come this close to the impact point (default Δ) */
  double r_max;       /* [m] half-width W of the window (default 0: the plate's extent) */
  const unsigned char *mask; /* optional [p->n] */
  const double *scale;       /* optional [p->n]: Δ_i/Δ per particle (a plate of several bodies);
                          NULL: 1 for all */
  int attached_only;         /* 1 (default): only the plate's largest connected piece is plate */
};
struct meas_plate {
  int perforated;
  int hole_open;           /* the hole reaches the window's edge */
  double d_circle;         /* [m] largest material-free circle in the hole */
  double circle_center[2]; /* [m] its centre (y, z) */
  double d_circle_impact;  /* [m] material-free circle centred at the impact point */
  double d_equiv;          /* [m] equivalent-area diameter */
  double area;             /* [m2] hole area (full plane, mirrored) */
  double cell;             /* [m] grid cell used */
  size_t n_plate;          /* particles taken as plate */
  size_t n_detached;       /* particles in the slab left out as loose fragments */
};
void meas_plate_defaults(struct meas_plate_params *par, const struct meas_geom *g);
int measure_plate(const struct particles *p, const struct meas_geom *g,
                  const struct meas_plate_params *par, struct meas_plate *out,
                  struct hv_error *err);

/* ---- Debris cloud behind a plate ------------------------------------------------
 * Cloud: particles (of `body`, < 0 any, and mask) with x_rear + margin < x < x_limit,
 * x_rear the plate's original rear face x0 + thickness and x_limit the next plate's
 * front face (INFINITY: none). With masses m_i (full picture: doubled in a half model):
 * v_mean: mass-mean axial velocity Σ m_i v_x,i / Σ m_i.
 * v_lead: leading-edge axial velocity, the q_lead (0.99) mass quantile of v_x: the
 *    fastest 1 % of the cloud's mass moves at least this fast (robust against a few
 *    stray particles; v_max is the largest v_x).
 * x_lead: the q_lead mass quantile of x, minus x_rear: how far the leading edge is
 *    behind the rear face.
 * half_angle: the q_angle (0.90) mass quantile of θ_i = atan2(ρ_i, x_i − x_rear), the
 *    angle from the axis seen from the point (x_rear, yc, 0) on the rear face: the cone
 *    about the axis that holds 90 % of the cloud's mass.
 * half_angle_front: the same quantile over the cloud's front only, the particles with
 *    x_i − x_rear >= front_fraction (0.5) x_lead: the main debris bubble seen from the
 *    impact point, without the ejecta thrown off the hole's rim close to the plate
 *    (which the 90 % cone takes in; docs/measurements.md).
 * An empty cloud gives count 0 and NaN for the velocities, x_lead and the angle. */
struct meas_debris_params {
  int body;              /* body of the cloud's particles (< 0: any) */
  double x_rear;         /* [m] rear face of the plate, x0 + thickness */
  double yc;             /* [m] axis y */
  double margin;         /* [m] cloud starts at x_rear + margin (default 2Δ) */
  double x_limit;        /* [m] cloud ends before x_limit (default INFINITY) */
  double q_lead;         /* leading-edge mass quantile (default 0.99) */
  double q_angle;        /* spray-cone mass quantile (default 0.90) */
  double front_fraction; /* the front: x − x_rear >= front_fraction x_lead (default 0.5) */
  int half_model;
  int quarter_model;
  const unsigned char *mask; /* optional [p->n] */
};
struct meas_debris {
  size_t count;            /* simulated particles in the cloud */
  double m;                /* [kg] cloud mass (full picture) */
  double v_mean;           /* [m/s] */
  double v_lead;           /* [m/s] */
  double v_max;            /* [m/s] */
  double x_lead;           /* [m] */
  double half_angle;       /* [rad] */
  double half_angle_front; /* [rad] the same over the cloud's front */
  double gap;              /* [m] x_limit − x_rear: how far the leading edge can go (INFINITY:
                         no next plate) */
};
/* Defaults for the cloud behind plate g: body any, x_rear = x0 + thickness, margin 2Δ. */
void meas_debris_defaults(struct meas_debris_params *par, const struct meas_geom *g);
int measure_debris(const struct particles *p, const struct meas_debris_params *par,
                   struct meas_debris *out, struct hv_error *err);

/* ---- Backwall: crater depth, damaged area, pressure at the centre -----------------
 * Backwall particles: g->body (and mask) with x >= x0 − margin_front (ejecta thrown back
 * further out are no longer wall). Columns along x of square section `cell` cover the
 * projected wall; a column holds the particles whose projection lies within `tol` of
 * its axis; its front surface is x_f = the smallest x among them.
 * wall_shift: how far the wall far from the impact has moved along x, the (lower) median of
 *    x_f − footprint − x0 over the columns at ρ >= far_fraction R_in, R_in the largest
 *    radius about the axis within the wall's projection (its inscribed radius); 0 with
 *    far_reference 0 or when no column lies there. A wall whose edges are not held
 *    (rigid walls let them slide) drifts back as a whole with the momentum it took.
 * crater_depth: the deepest material-free region below the front face, max over
 *    columns of x_f − footprint − x0 − wall_shift (>= 0): measured like a depth gauge
 *    laid across the crater and resting on the wall far from the impact, so a bulge
 *    adds to it and a drift of the whole wall does not; crater_pos its column (y, z).
 *    Craters (crater_depth, crater_depth_local, r_crater) are read only in the columns
 *    within the inscribed radius about the axis of the centres of the particles the
 *    columns see, less tol (the coarsest scale's): at the rim a column within tol of
 *    only some layers' edges would read the first of them as its front.
 * crater_depth_local: the deepest column below its own surroundings, max over columns of
 *    x_f − the (lower) median x_f of the columns whose centres lie local_inner to
 *    local_outer from its centre (mirrored at z = 0 in a half model): a depth gauge laid
 *    across one crater and resting on the wall around it, so a bulge or a drift of the
 *    whole wall does not add to it; the columns' fronts here see only the wall particles
 *    at most tol ahead of x0 + wall_shift (splash still joined to the wall, as it leaves
 *    the face, is not the surface a gauge rests on); taken over the columns cratered
 *    below x0 + wall_shift; crater_local_pos its column (y, z), crater_local_ref the median front
 *    there (x_f − footprint − x0 − wall_shift: how far its surroundings have bulged).
 * r_crater: the largest radial distance ρ of a column cratered (below x0 + wall_shift)
 *    deeper than crater_min.
 * r_damage_particles: the largest ρ of a wall particle with damage >= damage_min or
 *    plastic strain eps_p >= eps_p_min (solid fields; 0 when the store has none) —
 *    the extent of any damage, however sparse.
 * r_damage: the radius of the damaged area around the axis. A column is damaged when
 *    it is cratered deeper than crater_min, holds a damaged particle (within tol), or
 *    holds no wall material (a hole). Rings of width `ring` around the axis are swept
 *    outwards from ρ = 0; a ring is damaged when at least `area_fraction` of its
 *    columns are; r_damage is the outer radius of the last ring of the unbroken run of
 *    damaged rings from the centre (0 when the first is not). Scattered damage far from
 *    the impact (plate edges at a wall, reflected waves) does not extend it.
 * m_damaged: mass of the damaged particles (full picture).
 * attached_only (default): the columns (crater depth and position, r_crater, the
 * damaged columns of r_damage) see only the wall's largest friends-of-friends piece
 * (links FOF_B_FACTOR Δ): spall and fragments thrown off its rear are not wall, as
 * they are not part of a recovered target; a column they alone fill is a hole. The
 * particle counts (n_damaged, m_damaged, r_damage_particles) take every wall particle.
 * A backwall of several bodies (a fine disc around the axis inside a coarse plate) is
 * measured with g->body < 0, a mask of its bodies, g->spacing the finest and `scale`
 * [p->n] = Δ_i/Δ: particle i then covers the columns within scale_i tol and has the
 * footprint scale_i footprint, so that the coarse part is as solid as it is alone
 * (crater_min, ring and cell keep the finest spacing). */
struct meas_backwall_params {
  double tol;                /* [m] (default Δ) */
  double footprint;          /* [m] (default Δ/2) */
  double cell;               /* [m] column section (default Δ/2; enlarged beyond 4096 a side) */
  double margin_front;       /* [m] (default max(thickness, 2Δ)) */
  double damage_min;         /* (default 1: split) */
  double eps_p_min;          /* (default 0.1) */
  double crater_min;         /* [m] (default Δ) */
  double ring;               /* [m] ring width for r_damage (default 2Δ) */
  double area_fraction;      /* damaged share of a ring's columns, in (0, 1] (default 0.5) */
  const unsigned char *mask; /* optional [p->n] */
  const double *scale;       /* optional [p->n]: Δ_i/Δ per particle; NULL: 1 for all */
  int attached_only;         /* 1 (default): the columns see only the wall's largest piece */
  int far_reference;         /* 1 (default): depths from the far wall (wall_shift); 0: from x0 */
  double far_fraction;       /* the far wall: ρ >= far_fraction R_in, in (0, 1] (default 0.8) */
  double local_inner;        /* [m] crater_depth_local's ring (default max(thickness/2, 2Δ)) */
  double local_outer;        /* [m] (default max(thickness, 4Δ)); > local_inner */
};
struct meas_backwall {
  double crater_depth;        /* [m] */
  double wall_shift;          /* [m] the far wall's move along x (0: none measured) */
  double crater_pos[2];       /* [m] (y, z) of the deepest column */
  double crater_depth_local;  /* [m] below the column's surroundings */
  double crater_local_pos[2]; /* [m] (y, z) of that column */
  double crater_local_ref;    /* [m] its surroundings' front below the far wall */
  double r_crater;            /* [m] */
  double r_damage_particles;  /* [m] */
  double r_damage;            /* [m] */
  double m_damaged;           /* [kg] */
  size_t n_damaged;
  size_t n_wall; /* particles taken as wall */
};
void meas_backwall_defaults(struct meas_backwall_params *par, const struct meas_geom *g);
int measure_backwall(const struct particles *p, const struct meas_geom *g,
                     const struct meas_backwall_params *par, struct meas_backwall *out,
                     struct hv_error *err);

/* Pressure at the centre of the front face: the mass-weighted mean pressure of the
 * particles of g->body (and mask) within radius r0 of the axis whose x lies in
 * [x_f, x_f + depth], x_f the smallest x of those particles within r0 with
 * x >= x0 − depth. [Pa]; NaN when there is none. *count (may be NULL) gets how many.
 * The run loop keeps the maximum over time (the peak pressure at the centre). */
double measure_center_pressure(const struct particles *p, const struct meas_geom *g, double r0,
                               double depth, const unsigned char *mask, size_t *count);

/* ---- Gas: position of the shock front ------------------------------------------
 * Shocked gas: particles of `body` (and mask) with density rho > factor × rho_ref
 * (default factor 1.1: the shock raises the density by more than 10 %, well above
 * the lattice's SPH noise). Distances are from `origin`, the point where the
 * disturbance enters the gas (for a vessel, (x0 + thickness, yc, 0) on the wall's
 * inner face), with the axis through it along +x:
 * x_axial: the largest x − origin_x among shocked particles within r_axis of the axis;
 * r_radial: the largest distance from the axis among shocked particles;
 * r_max: the largest distance from the origin. 0 when nothing is shocked; x_axial NaN
 * when gas is shocked but none within r_axis of the axis. */
struct meas_gas_params {
  int body;                  /* gas body (< 0: any) */
  double rho_ref;            /* [kg/m3] initial (undisturbed) gas density */
  double factor;             /* (default 1.1) */
  double origin[3];          /* [m] */
  double r_axis;             /* [m] (default 2Δ of the gas) */
  const unsigned char *mask; /* optional [p->n] */
};
struct meas_gas_front {
  size_t n_shocked;
  double x_axial;  /* [m] */
  double r_radial; /* [m] */
  double r_max;    /* [m] */
};
/* Defaults: factor 1.1, r_axis = 2 × spacing (the gas's lattice spacing). */
void meas_gas_defaults(struct meas_gas_params *par, int body, double rho_ref,
                       const double origin[3], double spacing);
int measure_gas_front(const struct particles *p, const struct meas_gas_params *par,
                      struct meas_gas_front *out, struct hv_error *err);

#endif
