/* measure_table.h — OUTDIR/measurements.csv: one row per (time, quantity, object).
 *
 * The run loop keeps one struct meas_table for the whole run, adds the rows of each
 * measurement at every output time (and at the end), and rewrites the whole file
 * through atomic_file after each addition, so that a reader sees either the previous or
 * the new complete file. File layout:
 *   # <comment lines>                                  (optional)
 *   time,quantity,value,unit,object
 *   <time [s], %.17g>,<quantity>,<value, %.17g; nan when undefined>,<unit>,<object>
 * Rows are kept in the order added. Adding a row with the same time (bitwise),
 * quantity and object as an existing row replaces its value and unit (so a final
 * measurement at the last output time is not duplicated). Text fields holding a comma,
 * double quote or line break are quoted as in RFC 4180. The quantities, their units
 * and definitions are listed in docs/measurements.md.
 */
#ifndef HV_MEASURE_TABLE_H
#define HV_MEASURE_TABLE_H

#include <stddef.h>

#include "core/error.h"
#include "diag/fof.h"
#include "diag/measure.h"

struct meas_row {
  double time;    /* [s] */
  char *quantity; /* e.g. "hole_diameter" */
  double value;   /* in `unit` */
  char *unit;     /* e.g. "m", "m/s", "deg", "" for counts and flags */
  char *object;   /* what was measured, e.g. the body's name "bumper" */
};

struct meas_table {
  struct meas_row *rows;
  size_t n, cap;
};

void meas_table_init(struct meas_table *t);
void meas_table_free(struct meas_table *t);
/* Adds (or replaces, see above) one row; the strings are copied (NULL reads as ""). */
void meas_table_add(struct meas_table *t, double time, const char *quantity, double value,
                    const char *unit, const char *object);
/* Rewrites the whole file at path; comment (may be NULL) becomes "# " lines. */
int meas_table_write(const struct meas_table *t, const char *path, const char *comment,
                     struct hv_error *err);
/* Reads a file written by meas_table_write, adding its rows to t (quoted fields
 * unquoted; "nan" and "inf" read back); -1 (err, HV_EXIT_INPUT) when it cannot be read. */
int meas_table_read(struct meas_table *t, const char *path, struct hv_error *err);

/* The rows of each measurement (quantity names and units in docs/measurements.md):
 * cavity:    penetration_depth m, cavity_diameter m, cavity_diameter_mean m,
 *            cavity_diameter_wall m, cavity_diameter_wall_mean m, perforated
 * plate:     perforated, hole_diameter m (largest circle), hole_diameter_equiv m,
 *            hole_diameter_at_impact m, hole_area m2, hole_open
 * debris:    cloud_particles, cloud_mass kg, cloud_velocity_mean m/s, cloud_velocity_lead
 *            m/s, cloud_velocity_max m/s, cloud_lead_distance m, cloud_half_angle deg,
 *            cloud_half_angle_front deg, cloud_gap m
 * backwall:  crater_depth m, wall_shift m, crater_depth_local m, crater_local_ref m,
 *            damage_radius m, crater_radius m, damage_radius_particles m, damaged_mass kg
 * gas:       shock_front_axial m, shock_front_radial m, shock_front_distance m,
 *            shocked_particles
 * fragments: fragments_count, fragments_count_multi (>= 2 particles), fragment_mass_largest
 *            kg, fragment_mass_second kg, fragment_mass_mean kg (mass-weighted, Σm²/Σm),
 *            fragments_mass kg
 * The peak pressure at the backwall's centre is the run loop's running maximum of
 * measure_center_pressure: add it with meas_table_add(t, time, "peak_pressure_center",
 * value, "Pa", object). */
void meas_table_add_cavity(struct meas_table *t, double time, const char *object,
                           const struct meas_cavity *r);
void meas_table_add_plate(struct meas_table *t, double time, const char *object,
                          const struct meas_plate *r);
void meas_table_add_debris(struct meas_table *t, double time, const char *object,
                           const struct meas_debris *r);
void meas_table_add_backwall(struct meas_table *t, double time, const char *object,
                             const struct meas_backwall *r);
void meas_table_add_gas(struct meas_table *t, double time, const char *object,
                        const struct meas_gas_front *r);
void meas_table_add_fragments(struct meas_table *t, double time, const char *object,
                              const struct fof_result *r);

#endif
