/* plausible.h — the plausibility checks of a set-up case that `hvsph run` and
 * `hvsph check` make (plausible.c). */
#ifndef HV_PLAUSIBLE_H
#define HV_PLAUSIBLE_H

#include "config/config.h"
#include "core/error.h"

struct sim;

/* Steps beyond which a run is not plausible for this code (plausible.c argues the number). */
#define HV_CHECK_STEPS_MAX 1e8

/* After step_init of a new run: the steps to time.end at the first stable step. A bare
 * time.end (SI, so seconds) that needs more than HV_CHECK_STEPS_MAX is bad input naming
 * the file, line and key, with the unit that brings it within ("end: 20" with a 6 ns
 * step: 3e9 steps, "was it 20 us?"); one written with its unit is meant, and warned
 * of. Also the step keys against the first stable step: a time.dt_min not below it is
 * bad input (the run would fail at once), a time.dt_init ten times above it is warned
 * of. Returns 0 or -1 with err set. */
int check_plausible_end(const struct sim *s, struct cfg *c, struct hv_error *err);

/* The smallest step the particles allow at the start [s] (each particle's own CFL and
 * acceleration limit after step_init, within time.dt_max): what the steps to the end
 * are estimated from, time.dt_init aside (the growth limit hands over to it at once). */
double check_first_stable_step(const struct sim *s);

/* The particle layers through a plate of bodies[0..nb-1] (thin along x) at the impact
 * point: the planes of its particles within r (at least two spacings) of the line
 * y = axis_y, z = 0, as `hvsph check` counts them; of the whole plate when none lies
 * there. Perforation with fewer than CHECK_LAYERS_MIN (4) is a lattice effect. */
#define CHECK_LAYERS_MIN 4
int check_plate_layers(const struct sim *s, const int *bodies, int nb, double r, double axis_y);

/* Planes of particles through bodies[0..nb-1] along ax: all their particles (r <= 0),
 * or those within r of the line y = axis_y, z = 0; *thick the extent they span. */
int plate_body_planes(const struct sim *s, const int *bodies, int nb, int ax, double r,
                      double axis_y, double *thick);

/* Body b's initial extent along x, y and z [m] (hi - lo of its body_info), counted whole:
 * a half model's body cut at z = 0 twice its z extent; in an axisymmetric run
 * (s->p.axisym), whose rings fill r <= hi[1], its diameter 2 hi[1] along y and z. */
void check_body_extent(const struct sim *s, int b, double ext[3]);

/* The axis a body is thin along (its plate normal), or -1: its extent along it
 * (check_body_extent) at most half its extent across. *thick gets that extent. */
int check_plate_axis(const struct sim *s, int b, double *thick);
#endif
