/* render.c (cli) — `hvsph render SNAPSHOT.csv|SNAPSHOT.vtu -o FILE.png [options]`, and
 * `hvsph render RUNDIR -o FRAMEDIR [options]`.
 *
 * Reads a particle snapshot, CSV or VTU (io_read_particles; the time from its comment
 * line or FieldData, the material names from its "materials" comment), renders it
 * (render_png) and writes the PNG whole or not at all. A folder instead of a snapshot is
 * a run's output folder: every snapshot of the run becomes a frame of a movie, all framed
 * and coloured alike (render_series, series.c). Lengths and colour ranges may carry units
 * ("-50mm", "6.2km/s"); bare numbers are SI. Exit status: 0 written, 1 bad command line,
 * 2 bad or missing input (or an output folder that cannot take the file), 3 write failure.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/units.h"
#include "io/snapshot.h"
#include "cli/render.h"
#include "render/render_internal.h"

static void render_usage(FILE *f)
{
  fprintf(f,
          "usage: hvsph render SNAPSHOT.vtu|SNAPSHOT.csv -o FILE.png [options]\n"
          "       hvsph render RUNDIR -o FRAMEDIR [options]\n"
          "  RUNDIR                        a run's output folder: each of its snapshots becomes\n"
          "                                FRAMEDIR/frame_NNNNN.png, all framed and coloured alike\n"
          "  --mode radiograph|particles   simulated flash x-ray (default) or particle discs\n"
          "  --axis x|y|z                  line of sight (default z); the picture shows x right\n"
          "                                and y up (along z), x and z (along y), y and z (along x)\n"
          "  --color material|damage|velocity|pressure|density|alpha|dt   particles mode (default\n"
          "                                material; alpha: the viscosity switch's coefficient;\n"
          "                                dt: the time step each particle allows, log scale)\n"
          "  --size WxH | W                picture size in pixels, caption included (default 1200 wide)\n"
          "  --box xmin,xmax,ymin,ymax,zmin,zmax   region shown; units allowed (\"-50mm\"), bare = m\n"
          "  --mirror | --no-mirror        reflect across z = 0 (default: on for a half model)\n"
          "  --mu M|auto                   film mass attenuation [m2/kg] (default auto: the lower\n"
          "                                quartile of the material's areal densities at T = 1/2)\n"
          "  --range LO,HI                 colour range of the quantity (units allowed)\n"
          "  --no-labels                   no body names on the picture (default: each body's\n"
          "                                name from the run's used_parameters.yaml where it fits)\n"
          "  --quiet, -q                   no line per picture written (warnings and errors only)\n"
          "see docs/rendering.md\n");
}

/* "a,b,c" -> n quantities of dimension dim. */
static int parse_list(const char *s, int n, enum unit_dim dim, double *out, char *msg, size_t len)
{
  char buf[512];
  if (snprintf(buf, sizeof buf, "%s", s) >= (int)sizeof buf) {
    snprintf(msg, len, "too long");
    return -1;
  }
  char *tok = buf;
  for (int k = 0; k < n; k++) {
    char *comma = strchr(tok, ',');
    if ((k < n - 1) != (comma != NULL)) {
      snprintf(msg, len, "expected %d comma-separated values", n);
      return -1;
    }
    if (comma) *comma = '\0';
    if (units_parse(tok, dim, &out[k], msg, len)) return -1;
    tok = comma + 1;
  }
  return 0;
}

static int parse_size(const char *s, int *w, int *h)
{
  char *end;
  long a = strtol(s, &end, 10), b = 0;
  if (end == s || a <= 0 || a > RENDER_MAX_SIDE) return -1;
  if (*end == 'x' || *end == 'X') {
    const char *q = end + 1;
    b = strtol(q, &end, 10);
    if (end == q || b <= 0 || b > RENDER_MAX_SIDE) return -1;
  }
  if (*end) return -1;
  *w = (int)a;
  *h = (int)b;
  return 0;
}

static int pick(const char *s, const char *const *names, int n)
{
  for (int k = 0; k < n; k++)
    if (!strcmp(s, names[k])) return k;
  return -1;
}

static int fail_usage(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static int fail_usage(const char *fmt, ...)
{
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "hvsph render: ");
  vfprintf(stderr, fmt, ap);
  fprintf(stderr, " (see hvsph render --help)\n");
  va_end(ap);
  return HV_EXIT_USAGE;
}

int render_main(int argc, char **argv)
{
  static const char *modes[] = {"radiograph", "particles"};
  static const char *axes[] = {"x", "y", "z"};
  static const char *colors[] = {"material", "damage", "velocity", "pressure", "density", "alpha",
                                 "dt"};
  struct render_options o;
  render_options_default(&o);
  const char *in = NULL, *out = NULL, *range = NULL;
  char msg[512];
  for (int i = 0; i < argc; i++) {
    const char *a = argv[i], *val = ""; /* set below for the options that take one */
    char opt[64];
    const char *eq = strncmp(a, "--", 2) == 0 ? strchr(a, '=') : NULL;
    snprintf(opt, sizeof opt, "%.*s", eq ? (int)(eq - a) : (int)strlen(a), a);
    int takes = !strcmp(opt, "-o") || !strcmp(opt, "--output") || !strcmp(opt, "--mode") ||
                !strcmp(opt, "--axis") || !strcmp(opt, "--color") || !strcmp(opt, "--colour") ||
                !strcmp(opt, "--size") || !strcmp(opt, "--box") || !strcmp(opt, "--mu") ||
                !strcmp(opt, "--range");
    if (takes) {
      if (eq) val = eq + 1;
      else if (i + 1 < argc) val = argv[++i];
      else return fail_usage("option %s needs a value", opt);
    } else if (eq) {
      return fail_usage("option %s takes no value", opt);
    }
    int k;
    if (!strcmp(opt, "--help") || !strcmp(opt, "-h")) {
      render_usage(stdout);
      return HV_EXIT_OK;
    } else if (!strcmp(opt, "-o") || !strcmp(opt, "--output")) out = val;
    else if (!strcmp(opt, "--mode")) {
      if ((k = pick(val, modes, 2)) < 0) return fail_usage("--mode must be radiograph or particles, not '%s'", val);
      o.mode = (enum render_mode)k;
    } else if (!strcmp(opt, "--axis")) {
      if ((k = pick(val, axes, 3)) < 0) return fail_usage("--axis must be x, y or z, not '%s'", val);
      o.axis = k;
    } else if (!strcmp(opt, "--color") || !strcmp(opt, "--colour")) {
      if ((k = pick(val, colors, 7)) < 0)
        return fail_usage("--color must be material, damage, velocity, pressure, density, alpha "
                          "or dt, not '%s'", val);
      o.color = (enum render_color)k;
    } else if (!strcmp(opt, "--size")) {
      if (parse_size(val, &o.width, &o.height)) return fail_usage("--size needs WxH or W in pixels, not '%s'", val);
    } else if (!strcmp(opt, "--box")) {
      if (parse_list(val, 6, UNIT_LENGTH, o.box, msg, sizeof msg)) {
        fprintf(stderr, "hvsph render: --box '%s': %s\n", val, msg);
        return HV_EXIT_USAGE;
      }
      o.have_box = 1;
    } else if (!strcmp(opt, "--quiet") || !strcmp(opt, "-q")) hv_log_level = 1;
    else if (!strcmp(opt, "--mirror")) o.mirror = 1;
    else if (!strcmp(opt, "--no-mirror")) o.mirror = 0;
    else if (!strcmp(opt, "--no-labels")) o.labels = 0;
    else if (!strcmp(opt, "--mu")) {
      char *end = NULL;
      o.mu = strcmp(val, "auto") ? strtod(val, &end) : RENDER_MU_AUTO;
      if (end && (end == val || *end || !(o.mu > 0.0) || !isfinite(o.mu)))
        return fail_usage("--mu needs a positive number in m2/kg or auto, not '%s'", val);
    } else if (!strcmp(opt, "--range")) range = val;
    else if (a[0] == '-' && a[1]) return fail_usage("unknown option '%s'", a);
    else if (in) return fail_usage("unexpected argument '%s': one snapshot at a time", a);
    else in = a;
  }
  if (!in) return fail_usage("%s", "missing snapshot file");
  struct stat st;
  const int series = stat(in, &st) == 0 && S_ISDIR(st.st_mode);
  if (!out) return fail_usage("%s", series ? "missing -o FRAMEDIR" : "missing -o FILE.png");
  const size_t olen = strlen(out);
  if (series && olen >= 4 && !strcmp(out + olen - 4, ".png"))
    return fail_usage("'%s' is a run folder: -o names the folder of its frames, not a .png "
                      "file", in);
  if (range) {
    static const enum unit_dim dim[] = {
        [RENDER_COLOR_MATERIAL] = UNIT_NONE,    [RENDER_COLOR_DAMAGE] = UNIT_NONE,
        [RENDER_COLOR_VELOCITY] = UNIT_VELOCITY, [RENDER_COLOR_PRESSURE] = UNIT_PRESSURE,
        [RENDER_COLOR_DENSITY] = UNIT_DENSITY,  [RENDER_COLOR_ALPHA] = UNIT_NONE,
        [RENDER_COLOR_DT] = UNIT_TIME};
    if (o.mode != RENDER_PARTICLES || o.color == RENDER_COLOR_MATERIAL)
      return fail_usage("%s", "--range needs --mode particles and a --color quantity");
    if (parse_list(range, 2, dim[o.color], o.range, msg, sizeof msg) || !(o.range[0] < o.range[1])) {
      fprintf(stderr, "hvsph render: --range '%s': %s\n", range, msg[0] ? msg : "low end must be below high end");
      return HV_EXIT_USAGE;
    }
    if (o.color == RENDER_COLOR_DT) {   /* given as times, coloured by their log10 */
      if (!(o.range[0] > 0.0))
        return fail_usage("--range '%s': time steps are positive", range);
      o.range[0] = log10(o.range[0]);
      o.range[1] = log10(o.range[1]);
    }
    o.have_range = 1;
  }
  if (o.mode == RENDER_RADIOGRAPH && o.color != RENDER_COLOR_MATERIAL)
    hv_info("note: --color applies to --mode particles only");
  if (o.mode == RENDER_PARTICLES && o.axis == 2 && o.mirror == 1)
    hv_info("note: particles seen along z are not mirrored (the view shows the cut at "
            "z = 0)");
  struct hv_error err;
  hv_error_clear(&err);
  if (series) {
    if (stat(out, &st) == 0 && !S_ISDIR(st.st_mode)) {
      hv_log(0, "-o '%s' is a file: the frames of run folder '%s' go into a folder", out, in);
      return HV_EXIT_INPUT;
    }
    if (render_series(in, out, &o, &err)) {
      hv_log(0, "%s", err.msg);
      return err.code ? err.code : HV_EXIT_RUN;
    }
    return HV_EXIT_OK;
  }
  struct particles p;
  particles_init(&p);
  double t = NAN;
  int rc = io_read_particles(in, &p, &t, &err);
  if (!rc && p.n == 0) rc = hv_error_set(&err, HV_EXIT_INPUT, "'%s' holds no particles", in);
  if (!rc) {
    char names[RENDER_MAX_MATERIALS][64] = {{0}};
    const char *ptr[RENDER_MAX_MATERIALS];
    int nm = io_read_material_names(in, names, RENDER_MAX_MATERIALS);
    for (int k = 0; k < RENDER_MAX_MATERIALS; k++) ptr[k] = names[k][0] ? names[k] : NULL;
    /* the body names: render_png reads them from the snapshot's folder */
    struct render_info info = {.time = t, .material_names = ptr, .nmat = nm, .source = in};
    rc = render_check_particles(&p, nm, in, &err);
    if (!rc) rc = render_png(out, &p, &o, &info, &err);
    if (!rc) hv_info("wrote %s (%zu particles)", out, p.n);
  }
  particles_free(&p);
  if (rc) {
    hv_log(0, "%s", err.msg);
    return err.code ? err.code : HV_EXIT_RUN;
  }
  return HV_EXIT_OK;
}
