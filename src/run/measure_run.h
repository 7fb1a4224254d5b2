/* measure_run.h — the measurements a case asks for (`measure:`), taken at output times
 * and at the end, and written to OUTDIR/measurements.csv (and fragments_NNNNN.csv).
 *
 *   measure:
 *     thick_target: target        # penetration depth L, cavity diameter D (or a list of
 *                                 # bodies: a target refined near its axis, [target, core])
 *     plates: [bumper]            # perforated?, hole diameters (an entry may be a list of
 *                                 # bodies: a plate refined near the impact point,
 *                                 # [[bumper, bumper-core]])
 *     debris: [bumper]            # debris cloud behind each of these plates
 *     backwall: backwall          # crater depth, damaged radius, peak centre pressure (or
 *                                 # a list: a backwall refined near the axis, [backwall,
 *                                 # backwall-core])
 *     gas: nitrogen               # shock front position
 *     fragments: true             # friends-of-friends fragments
 *     every: 1 us                 # also between output times (default: only at them)
 *
 * Bodies are named; their geometry (front face, thickness, spacing) comes from their
 * initial particles. Impact along +x, axis y = 0 (measure.axis_y), symmetry plane
 * z = 0 in half models. Definitions: docs/measurements.md.
 */
#ifndef HV_MEASURE_RUN_H
#define HV_MEASURE_RUN_H

#include "diag/measure_table.h"
#include "sim/sim.h"

#define MR_MAX 8

struct measure_run {
  int any;
  double axis_y;               /* [m] */
  int target[MR_MAX], ntarget; /* the thick target's bodies (its rows are named after
                                   the first) */
  int plate[MR_MAX][MR_MAX];   /* plate k's bodies (its rows named after the first) */
  int nplate_body[MR_MAX], nplate;
  int debris[MR_MAX], ndebris;
  int backwall[MR_MAX], nbackwall; /* the backwall's bodies (rows named after the first) */
  int cavity_min_count; /* the thick target's min_count (measure.cavity_min_count, default
                           1): min_count - 1 strays in a slice do not close the cavity */
  int gas;
  int fragments;
  double peak_pressure;     /* [Pa] running maximum at the backwall's centre */
  double p_radius, p_depth; /* [m] the centre pressure's averaging disc and depth
                                (measure.pressure_radius/_depth; 0: 2 x the finest
                                backwall spacing) */
  int crater_original;      /* 1: backwall depths from the original face x0
                            (measure.crater_reference: original-face); 0 (default,
                            far-wall): from the wall far from the impact */
  double every;             /* [s] measurements also at these intervals between output times
                            (measure.every; 0: at output times only) */
  struct meas_table table;
};

int measure_run_read(struct measure_run *mr, struct sim *s, struct cfg *c, struct hv_error *err);
void measure_run_free(struct measure_run *mr);
/* Every step: cheap running quantities (the backwall's peak centre pressure). */
void measure_run_step(struct measure_run *mr, const struct sim *s);

/* The radius about the impact axis within which material behind the wall of bodies[0..nb)
 * went through it (meas_through_params.r_max): the wall's extent across the axis less two
 * spacings, at least one spacing. 3D: the nearer of its edges across y from axis_y; in
 * an axisymmetric run (s->p.axisym), whose rings fill r <= hi[1], that outer radius. */
double measure_run_shadow(const struct sim *s, const int *bodies, int nb, double axis_y,
                          double spacing);
/* At output k: every measurement, appended to the table and written; k < 0: a
 * measurement time between outputs (measure.every): the same rows, no fragments file.
 * Returns 0, MEASURE_FAILED_DATA when a measurement cannot be taken of these particles
 * (err says why: a fragment search over particles spread past 2e6 linking lengths, say),
 * or -1 when a file cannot be written. */
enum { MEASURE_FAILED_DATA = -2 };
int measure_run_output(struct measure_run *mr, const struct sim *s, int k, const char *outdir,
                       const char *const *matnames, struct hv_error *err);

#endif
