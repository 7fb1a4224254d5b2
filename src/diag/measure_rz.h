/* measure_rz.h — the measurements of measure.h on an axisymmetric run's rings
 * (p->axisym: x the axis, y = r >= 0, z = 0, m the ring's mass; particles.h). Called by
 * measure_plate and measure_backwall when p->axisym; not for use elsewhere.
 *
 * The axis is r = 0: g->yc must be 0 and g->half_model 0 (an RZ run has neither).
 * Measurements that need no branch: the cavity (its radial distance ρ is r; only the
 * filled-volume wall's cell edge differs, measure.c), the debris cloud, what went
 * through a wall, the centre pressure and the gas front (ρ = r, masses the rings'), and
 * fragments (friends-of-friends in the (x, r) plane: each fragment a set of rings).
 */
#ifndef HV_MEASURE_RZ_H
#define HV_MEASURE_RZ_H

#include "diag/measure.h"

/* The plate's hole from its selected rings sel (measure_plate's slab and largest piece):
 * ring i projects along x onto the circle of radius r_i, which covers the annulus
 * |ρ − r_i| < tol_i (tol_i = scale_i tol), so the plane is empty within
 * r_h = min_i (r_i − tol_i) of the axis: perforated when r_h > 0 (or no plate ring is
 * left), area π r_h², d_equiv = 2 r_h + 2 (tol − footprint), d_circle = d_circle_impact
 * = 2 min_i (r_i − footprint_i) about the axis (circle_center (yc, 0)); hole_open when
 * r_h reaches the window (r_max, or the plate's outer edge max r_i + tol_i). The same
 * definitions as the 3D grid's, without its cell: exact for rings. */
void measure_plate_rz(const struct particles *p, const struct meas_geom *g,
                      const struct meas_plate_params *par, const unsigned char *sel,
                      struct meas_plate *out);

/* measure_backwall on the rings revolved into 3D points (meas_rz_revolve) of the wall
 * (g->body, par->mask), with n_wall and n_damaged counting rings. */
int measure_backwall_rz(const struct particles *p, const struct meas_geom *g,
                        const struct meas_backwall_params *par, struct meas_backwall *out,
                        struct hv_error *err);

/* The rings i with sel[i] (NULL: all) as 3D points round their circles, at most `step`
 * (× scale[i] when scale is given) apart and at least one a ring: position (x, r cos φ,
 * r sin φ), velocity (v_x, v_r cos φ, v_r sin φ), mass m/N, the other scalars copied
 * (id, body, mat, h, rho, p, e, cs; damage, eps_p when p->solid), into q (initialised
 * here; q->axisym 0). *qscale (when qscale is not NULL; the caller frees) gets each
 * point's ring's scale (1 without scale). Returns the count of points. */
size_t meas_rz_revolve(const struct particles *p, const unsigned char *sel, const double *scale,
                       double step, struct particles *q, double **qscale);

#endif
