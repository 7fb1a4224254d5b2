/* test_measure_table.c — measurements.csv: rows added, replaced at the same time, written
 * whole (the exact text), quoting, NaN, the rows of each measurement, and a failed write
 * that leaves the previous file intact.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "diag/measure_table.h"
#include "testlib.h"

static char *slurp(const char *path)
{
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  char *b = calloc(1 << 16, 1);
  size_t n = fread(b, 1, (1 << 16) - 1, f);
  b[n] = '\0';
  fclose(f);
  return b;
}

static int count_rows(const struct meas_table *t, const char *quantity, const char *object)
{
  int c = 0;
  for (size_t k = 0; k < t->n; k++)
    c += strcmp(t->rows[k].quantity, quantity) == 0 && strcmp(t->rows[k].object, object) == 0;
  return c;
}

static void test_rows_and_text(void)
{
  struct meas_table t;
  meas_table_init(&t);
  meas_table_add(&t, 0.0, "perforated", 0, "", "bumper");
  meas_table_add(&t, 1e-5, "hole_diameter", 0.011, "m", "bumper");
  meas_table_add(&t, 1e-5, "hole_diameter", 0.0105, "m", "bumper"); /* replaces */
  meas_table_add(&t, 1e-5, "hole_diameter", 0.007, "m", "bumper 2");
  meas_table_add(&t, 2e-5, "cloud_velocity_mean", NAN, "m/s", "cloud, \"behind\" bumper");
  meas_table_add(&t, 2e-5, "note", 1, NULL, NULL);
  CHECK(t.n == 5, "rows: 5 (one replaced), got %zu", t.n);
  char path[4200];
  snprintf(path, sizeof path, "%s/measurements.csv", test_tmpdir());
  struct hv_error err;
  hv_error_clear(&err);
  CHECK(meas_table_write(&t, path, "hvsph test\nsecond line", &err) == 0, "writes: %s", err.msg);
  char *text = slurp(path);
  const char *expect =
      "# hvsph test\n"
      "# second line\n"
      "time,quantity,value,unit,object\n"
      "0,perforated,0,,bumper\n"
      "1.0000000000000001e-05,hole_diameter,0.010500000000000001,m,bumper\n"
      "1.0000000000000001e-05,hole_diameter,0.0070000000000000001,m,bumper 2\n"
      "2.0000000000000002e-05,cloud_velocity_mean,nan,m/s,\"cloud, \"\"behind\"\" bumper\"\n"
      "2.0000000000000002e-05,note,1,,\n";
  CHECK(text && strcmp(text, expect) == 0, "file text:\n%s", text ? text : "(none)");
  free(text);

  /* read back: the same rows, quotes undone, nan kept */
  struct meas_table back;
  meas_table_init(&back);
  int same = meas_table_read(&back, path, &err) == 0 && back.n == t.n;
  for (size_t k = 0; same && k < t.n; k++) {
    const struct meas_row *a = &t.rows[k], *b = &back.rows[k];
    same = a->time == b->time && !strcmp(a->quantity, b->quantity) && !strcmp(a->unit, b->unit) &&
           !strcmp(a->object, b->object) &&
           (a->value == b->value || (isnan(a->value) && isnan(b->value)));
  }
  CHECK(same,
        "meas_table_read gives back the %zu rows written (object with a comma and "
        "quotes: '%s')",
        back.n, back.n > 3 ? back.rows[3].object : "");
  meas_table_free(&back);

  /* a line break inside a quoted field (written as RFC 4180 asks) reads back too */
  struct meas_table nl;
  meas_table_init(&nl);
  meas_table_add(&nl, 3e-5, "hole_diameter", 0.012, "m", "bumper\nfront, \"outer\"");
  meas_table_add(&nl, 3e-5, "hole_area", 1e-4, "m2", "after");
  char nlpath[4200];
  snprintf(nlpath, sizeof nlpath, "%s/measurements_nl.csv", test_tmpdir());
  CHECK(meas_table_write(&nl, nlpath, NULL, &err) == 0, "writes: %s", err.msg);
  meas_table_init(&back);
  CHECK(meas_table_read(&back, nlpath, &err) == 0 && back.n == 2 &&
            !strcmp(back.rows[0].object, nl.rows[0].object) && back.rows[0].value == 0.012 &&
            !strcmp(back.rows[1].quantity, "hole_area") && !strcmp(back.rows[1].object, "after"),
        "a quoted field with a line break reads back (%zu rows, first object '%s')", back.n,
        back.n ? back.rows[0].object : "");
  meas_table_free(&back);
  meas_table_free(&nl);

  CHECK(meas_table_read(&back, "/nonexistent/measurements.csv", &err) == -1 &&
            err.code == HV_EXIT_INPUT,
        "a missing file: an error");

  /* a failed write (folder missing) reports the file and leaves nothing behind */
  char bad[4300];
  snprintf(bad, sizeof bad, "%s/no/such/folder/measurements.csv", test_tmpdir());
  hv_error_clear(&err);
  CHECK(meas_table_write(&t, bad, NULL, &err) == -1 && err.code == HV_EXIT_RUN &&
            strstr(err.msg, "measurements.csv") != NULL,
        "write into a missing folder fails with a message naming the file: %s", err.msg);
  text = slurp(path);
  CHECK(text && strcmp(text, expect) == 0, "the earlier file is intact");
  free(text);
  meas_table_free(&t);
  CHECK(t.n == 0 && t.rows == NULL, "freed");
}

static void test_measurement_rows(void)
{
  struct meas_table t;
  meas_table_init(&t);
  struct meas_cavity cav = {.L = 0.08, .D = 0.0125, .D_mean = 0.012};
  struct meas_plate pl = {.perforated = 1, .d_circle = 0.0105, .d_equiv = 0.011, .area = 9e-5};
  struct meas_debris db = {.count = 10,
                           .m = 1e-3,
                           .v_mean = 3000,
                           .v_lead = 6000,
                           .v_max = 6500,
                           .x_lead = 0.05,
                           .half_angle = HV_MEAS_PI / 6,
                           .half_angle_front = HV_MEAS_PI / 12,
                           .gap = 0.2};
  struct meas_backwall bw = {.crater_depth = 0.004, .r_damage = 0.15};
  struct meas_gas_front gf = {.n_shocked = 5, .x_axial = 0.03, .r_radial = 0.02, .r_max = 0.031};
  struct fof_fragment fr[3] = {{.m = 0.5, .count = 10, .multiplicity = 1},
                               {.m = 0.2, .count = 3, .multiplicity = 2},
                               {.m = 0.01, .count = 1, .multiplicity = 2}};
  struct fof_result fo = {.nfrag = 3, .frag = fr, .n_full = 5, .m_total = 0.5 + 0.4 + 0.02};
  for (int rep = 0; rep < 2; rep++) { /* the second round replaces, at the same time */
    meas_table_add_cavity(&t, 1e-4, "target", &cav);
    meas_table_add_plate(&t, 1e-4, "bumper", &pl);
    meas_table_add_debris(&t, 1e-4, "cloud1", &db);
    meas_table_add_backwall(&t, 1e-4, "backwall", &bw);
    meas_table_add_gas(&t, 1e-4, "nitrogen", &gf);
    meas_table_add_fragments(&t, 1e-4, "all", &fo);
  }
  CHECK(t.n == 6 + 6 + 9 + 8 + 4 + 6, "one row per quantity and object: %zu", t.n);
  CHECK(count_rows(&t, "penetration_depth", "target") == 1 &&
            count_rows(&t, "hole_diameter", "bumper") == 1 &&
            count_rows(&t, "cloud_half_angle", "cloud1") == 1 &&
            count_rows(&t, "crater_depth", "backwall") == 1 &&
            count_rows(&t, "crater_depth_local", "backwall") == 1 &&
            count_rows(&t, "shock_front_axial", "nitrogen") == 1 &&
            count_rows(&t, "fragments_count", "all") == 1,
        "the documented quantity names");
  for (size_t k = 0; k < t.n; k++) {
    const struct meas_row *r = &t.rows[k];
    if (strcmp(r->quantity, "cloud_half_angle") == 0)
      CHECK(fabs(r->value - 30.0) < 1e-12 && strcmp(r->unit, "deg") == 0, "angle in degrees");
    if (strcmp(r->quantity, "cloud_half_angle_front") == 0)
      CHECK(fabs(r->value - 15.0) < 1e-12 && strcmp(r->unit, "deg") == 0,
            "front's angle in degrees");
    if (strcmp(r->quantity, "fragment_mass_largest") == 0)
      CHECK(r->value == 0.5, "largest fragment 0.5 kg");
    if (strcmp(r->quantity, "fragment_mass_second") == 0)
      CHECK(r->value == 0.2, "second largest: one of a twin pair, 0.2 kg");
    if (strcmp(r->quantity, "fragments_count") == 0) CHECK(r->value == 5, "5 fragments in full");
    if (strcmp(r->quantity, "fragments_count_multi") == 0)
      CHECK(r->value == 3, "fragments of >= 2 particles: 1 + twin pair = 3");
    if (strcmp(r->quantity, "fragment_mass_mean") == 0)
      CHECK(fabs(r->value - (0.25 + 2 * 0.04 + 2 * 1e-4) / 0.92) < 1e-12,
            "mass-weighted mean fragment mass");
    if (strcmp(r->quantity, "penetration_depth") == 0)
      CHECK(r->value == 0.08 && strcmp(r->unit, "m") == 0, "L in m");
  }
  meas_table_free(&t);
}

int main(void)
{
  test_rows_and_text();
  test_measurement_rows();
  return test_finish();
}
