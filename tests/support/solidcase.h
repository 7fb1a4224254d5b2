/* solidcase.h — helpers for the solid verification tests (tests/verification/test_{hugoniot,
 * elastic_wave,rings,taylor,spall}.c): run an example case with the hvsph binary, read
 * its particle snapshots back (with the solid fields), follow particles by id, group
 * a quasi-1D body into its initial lattice layers, find a wave front, fit a line.
 *
 * Every case is run with `--threads N` (1 by default: `make check` runs two tests at a
 * time on two cores; the environment variable HVSPH_TEST_THREADS overrides it) and
 * `--quiet`. HVSPH_CASE_ARGS, when set, is appended to every run's command line: e.g.
 * HVSPH_CASE_ARGS="--set resolution=8" runs a test at a finer resolution (the numbers
 * in docs/verification-solids.md).
 */
#ifndef HV_SOLIDCASE_H
#define HV_SOLIDCASE_H

#include <stddef.h>

#include "particles/particles.h"

/* Runs `$HVSPH_BIN run $HVSPH_SOURCE_DIR/examples/verification/<example>.yaml
 * -o $HVSPH_TMP/<outname> --overwrite --quiet --threads N <extra>` (the folder is the
 * test's, holding its last run: replaced; extra may be NULL: a string of
 * further arguments, e.g. "--set time.end=1e-6"; then $HVSPH_CASE_ARGS). Returns the exit status; *seconds
 * (may be NULL) gets the wall time [s]. On failure the last lines of the output are
 * printed. */
int sc_run(const char *example, const char *outname, const char *extra, double *seconds);

/* sc_run, then opens its output: CHECKs that the case ran (label names it in the
 * message) and wrote at least min_snap snapshots. Returns the output folder (sc_outdir)
 * and *nsnap, or NULL after a failed CHECK. */
const char *sc_run_open(const char *example, const char *outname, const char *extra,
                        const char *label, int min_snap, int *nsnap);

/* A quasi-1D case of two bodies (0 and 1): reads snapshot 0 of dir into p0 and numbers
 * each body's lattice layers along x (sc_layers, tolerance 0.2 h): layer[b] (malloc'd,
 * indexed by particle id) and nl[b]. Returns 0, or -1 after a failed CHECK. */
int sc_two_bodies(const char *dir, struct particles *p0, int *layer[2], int nl[2]);

/* $HVSPH_TMP/<outname> (static buffer, rotates 4). */
const char *sc_outdir(const char *outname);

/* Number of consecutive snapshots particles_00000.csv, particles_00001.csv, ... */
int sc_count_snapshots(const char *dir);

/* Reads <dir>/particles_<k>.csv into p (initialised here, solid fields on); *t [s]
 * gets its time (may be NULL). Returns 0, or -1 with a message printed. */
int sc_read(const char *dir, int k, struct particles *p, double *t);

/* slot[id] = the slot of particle id in p, for ids 0 .. nid-1 (SIZE_MAX where absent).
 * Returns a malloc'd array. */
size_t *sc_slots_by_id(const struct particles *p, size_t nid);

/* Quasi-1D bodies: numbers the lattice layers of the particles with sel[i] != 0 by
 * their coordinate x[dim] in p (the initial snapshot): particles closer than tol in
 * that coordinate share a layer; layers are numbered 0, 1, ... with increasing
 * coordinate. layer_of_id[id] gets the layer (-1 for unselected particles; ids must be
 * below nid). Returns the number of layers. */
int sc_layers(const struct particles *p, const unsigned char *sel, int dim, double tol,
              int *layer_of_id, size_t nid);

/* Mean over each layer of a per-slot field f (f[slot]) at a later snapshot p:
 * out[l] for l < nlayer (NAN for an empty layer). */
void sc_layer_mean(const struct particles *p, const double *f, const int *layer_of_id, size_t nid,
                   int nlayer, double *out);

/* The position where the profile v(X) (layers in order, X increasing) first crosses
 * `level`, scanning from the last layer towards the first when from_end is 1 (from the
 * first towards the last otherwise); linear interpolation between the two layers.
 * Returns NAN when it never crosses. */
double sc_front(const double *X, const double *v, int n, double level, int from_end);

/* Mean of f over the layers whose position X lies between the fractions lo and hi of
 * the way from the contact plane x = 0 to `front` (lo < X/front < hi): a shocked
 * plateau away from the contact's wall heating and the front's width. *count (may be
 * NULL) gets the number of layers; NAN when there are none. */
double sc_plateau(const double *X, const double *f, int n, double front, double lo, double hi,
                  int *count);

/* Mie–Grüneisen with the Murnaghan cold curve, the paper's §2.1 (written out here,
 * independently of src/eos, as the tests' reference):
 *   p = ρ₀c₀²/n (ηⁿ − 1) + Γρ (E − E_c),  E_c = c₀²/n ((ηⁿ⁻¹ − 1)/(n − 1) − 1 + 1/η),
 * η = ρ/ρ₀. [Pa] from SI inputs. */
double sc_mg_pressure(double rho0, double c0, double n, double Gamma, double rho, double E);

/* The shocked state of that material at rest ahead (p₀ = 0, E₀ = 0) for the particle
 * speed jump up: the jump conditions ρ₀Us = ρ₁(Us − up), p₁ = ρ₀Us·up,
 * E₁ = ½p₁(1/ρ₀ − 1/ρ₁), closed by p₁ = sc_mg_pressure(ρ₁, E₁) and solved for ρ₁ in
 * (ρ₀, 4ρ₀) by bisection to round-off. Gives ρ₁ [kg/m³], Us [m/s], p₁ [Pa]. */
void sc_mg_hugoniot(double rho0, double c0, double n, double Gamma, double up, double *rho1,
                    double *Us, double *p1);

/* Least-squares line y = a + b x through n points; returns b, *a gets a (may be NULL),
 * *rms the rms residual (may be NULL). */
double sc_linfit(const double *x, const double *y, int n, double *a, double *rms);

/* Number of threads given to the runs. */
int sc_threads(void);

#endif
