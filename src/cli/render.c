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
#include "cli/cli.h"
#include "cli/options.h"
#include "render/render_internal.h"

static void render_usage(FILE *f)
{
  fprintf(
      f,
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
      "  --mirror | --no-mirror        reflect across z = 0 (and y = 0 for a quarter model;\n"
      "                                default: on for a half or quarter model)\n"
      "  an axisymmetric snapshot (rings) is seen across its axis, x right and r up, both\n"
      "  halves (--no-mirror: r >= 0 only); its radiograph is through the body revolved\n"
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

static const char *const modes[] = {"radiograph", "particles"};
static const char *const axes[] = {"x", "y", "z"};
static const char *const colors[] = {"material", "damage", "velocity", "pressure",
                                     "density",  "alpha",  "dt"};

/* The mistakes on render's command line, in its words. */
static int render_fail(const struct cli_cmd *c, enum cli_error e, const char *arg)
{
  (void)c;
  switch (e) {
  case CLI_NO_VALUE: return fail_usage("option %s needs a value", arg);
  case CLI_TAKES_NO_VALUE: return fail_usage("option %s takes no value", arg);
  case CLI_EXTRA: return fail_usage("unexpected argument '%s': one snapshot at a time", arg);
  default: return fail_usage("unknown option '%s'", arg);
  }
}

static int set_mode(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                    const char *val)
{
  (void)c;
  (void)opt;
  const int k = pick(val, modes, 2);
  if (k < 0) return fail_usage("--mode must be radiograph or particles, not '%s'", val);
  *(enum render_mode *)o->dest = (enum render_mode)k;
  return CLI_GO_ON;
}

static int set_axis(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                    const char *val)
{
  (void)c;
  (void)opt;
  const int k = pick(val, axes, 3);
  if (k < 0) return fail_usage("--axis must be x, y or z, not '%s'", val);
  *(int *)o->dest = k;
  return CLI_GO_ON;
}

static int set_color(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                     const char *val)
{
  (void)c;
  (void)opt;
  const int k = pick(val, colors, 7);
  if (k < 0)
    return fail_usage("--color must be material, damage, velocity, pressure, density, alpha "
                      "or dt, not '%s'",
                      val);
  *(enum render_color *)o->dest = (enum render_color)k;
  return CLI_GO_ON;
}

/* --size (dest: the render options) */
static int set_size(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                    const char *val)
{
  (void)c;
  (void)opt;
  struct render_options *ro = o->dest;
  if (parse_size(val, &ro->width, &ro->height))
    return fail_usage("--size needs WxH or W in pixels, not '%s'", val);
  return CLI_GO_ON;
}

/* --box (dest: the render options) */
static int set_box(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                   const char *val)
{
  (void)c;
  (void)opt;
  struct render_options *ro = o->dest;
  char msg[512];
  if (parse_list(val, 6, UNIT_LENGTH, ro->box, msg, sizeof msg)) {
    fprintf(stderr, "hvsph render: --box '%s': %s\n", val, msg);
    return HV_EXIT_USAGE;
  }
  ro->have_box = 1;
  return CLI_GO_ON;
}

static int set_mu(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                  const char *val)
{
  (void)c;
  (void)opt;
  double *mu = o->dest;
  char *end = NULL;
  *mu = strcmp(val, "auto") ? strtod(val, &end) : RENDER_MU_AUTO;
  if (end && (end == val || *end || !(*mu > 0.0) || !isfinite(*mu)))
    return fail_usage("--mu needs a positive number in m2/kg or auto, not '%s'", val);
  return CLI_GO_ON;
}

/* What the options say together: a snapshot or a run folder (*is_series), -o for it,
 * and --range for the colour quantity. Returns CLI_GO_ON or the exit status. */
static int check_args(const char *in, const char *out, const char *range, struct render_options *o,
                      int *is_series)
{
  char msg[512] = "";
  if (!in) return fail_usage("%s", "missing snapshot file");
  struct stat st;
  const int series = *is_series = stat(in, &st) == 0 && S_ISDIR(st.st_mode);
  if (!out) return fail_usage("%s", series ? "missing -o FRAMEDIR" : "missing -o FILE.png");
  const size_t olen = strlen(out);
  if (series && olen >= 4 && !strcmp(out + olen - 4, ".png"))
    return fail_usage("'%s' is a run folder: -o names the folder of its frames, not a .png "
                      "file",
                      in);
  if (range) {
    static const enum unit_dim dim[] = {[RENDER_COLOR_MATERIAL] = UNIT_NONE,
                                        [RENDER_COLOR_DAMAGE] = UNIT_NONE,
                                        [RENDER_COLOR_VELOCITY] = UNIT_VELOCITY,
                                        [RENDER_COLOR_PRESSURE] = UNIT_PRESSURE,
                                        [RENDER_COLOR_DENSITY] = UNIT_DENSITY,
                                        [RENDER_COLOR_ALPHA] = UNIT_NONE,
                                        [RENDER_COLOR_DT] = UNIT_TIME};
    if (o->mode != RENDER_PARTICLES || o->color == RENDER_COLOR_MATERIAL)
      return fail_usage("%s", "--range needs --mode particles and a --color quantity");
    if (parse_list(range, 2, dim[o->color], o->range, msg, sizeof msg) ||
        !(o->range[0] < o->range[1])) {
      fprintf(stderr, "hvsph render: --range '%s': %s\n", range,
              msg[0] ? msg : "low end must be below high end");
      return HV_EXIT_USAGE;
    }
    if (o->color == RENDER_COLOR_DT) { /* given as times, coloured by their log10 */
      if (!(o->range[0] > 0.0)) return fail_usage("--range '%s': time steps are positive", range);
      o->range[0] = log10(o->range[0]);
      o->range[1] = log10(o->range[1]);
    }
    o->have_range = 1;
  }
  if (o->mode == RENDER_RADIOGRAPH && o->color != RENDER_COLOR_MATERIAL)
    hv_info("note: --color applies to --mode particles only");
  if (o->mode == RENDER_PARTICLES && o->axis == 2 && o->mirror == 1)
    hv_info("note: particles seen along z are not mirrored (the view shows the cut at "
            "z = 0; an axisymmetric snapshot's rings are, both halves of the cut)");
  return CLI_GO_ON;
}

/* One snapshot rendered into the PNG `out`. */
static int render_one(const char *in, const char *out, const struct render_options *o)
{
  struct hv_error err;
  hv_error_clear(&err);
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
    if (!rc) rc = render_png(out, &p, o, &info, &err);
    if (!rc) hv_info("wrote %s (%zu %s)", out, p.n, p.axisym ? "rings" : "particles");
  }
  particles_free(&p);
  if (rc) {
    hv_log(0, "%s", err.msg);
    return err.code ? err.code : HV_EXIT_RUN;
  }
  return HV_EXIT_OK;
}

int cli_render(int argc, char **argv)
{
  struct render_options o;
  render_options_default(&o);
  const char *in = NULL, *out = NULL, *range = NULL;
  const struct cli_opt opts[] = {
      {"--help", "-h", CLI_HELP, .dest = NULL},
      {"--output", "-o", CLI_VALUE, .eq = 1, .dest = &out},
      {"--mode", NULL, CLI_VALUE, .eq = 1, .dest = &o.mode, .convert = set_mode},
      {"--axis", NULL, CLI_VALUE, .eq = 1, .dest = &o.axis, .convert = set_axis},
      {"--color", "--colour", CLI_VALUE, .eq = 1, .dest = &o.color, .convert = set_color},
      {"--size", NULL, CLI_VALUE, .eq = 1, .dest = &o, .convert = set_size},
      {"--box", NULL, CLI_VALUE, .eq = 1, .dest = &o, .convert = set_box},
      {"--quiet", "-q", CLI_FLAG, .dest = &hv_log_level, .flag = 1},
      {"--mirror", NULL, CLI_FLAG, .dest = &o.mirror, .flag = 1},
      {"--no-mirror", NULL, CLI_FLAG, .dest = &o.mirror, .flag = 0},
      {"--no-labels", NULL, CLI_FLAG, .dest = &o.labels, .flag = 0},
      {"--mu", NULL, CLI_VALUE, .eq = 1, .dest = &o.mu, .convert = set_mu},
      {"--range", NULL, CLI_VALUE, .eq = 1, .dest = &range},
  };
  const struct cli_cmd cmd = {.name = "render",
                              .opts = opts,
                              .nopts = (int)(sizeof opts / sizeof opts[0]),
                              .positional = &in,
                              .eq_strict = 1,
                              .lone_dash = 1,
                              .fail = render_fail,
                              .help = render_usage};
  int series = 0, st = cli_parse(&cmd, argc, argv);
  if (st == CLI_GO_ON) st = check_args(in, out, range, &o, &series);
  if (st != CLI_GO_ON) return st;
  if (!series) return render_one(in, out, &o);
  struct hv_error err;
  hv_error_clear(&err);
  struct stat st_out;
  if (stat(out, &st_out) == 0 && !S_ISDIR(st_out.st_mode)) {
    hv_log(0, "-o '%s' is a file: the frames of run folder '%s' go into a folder", out, in);
    return HV_EXIT_INPUT;
  }
  if (render_series(in, out, &o, &err)) {
    hv_log(0, "%s", err.msg);
    return err.code ? err.code : HV_EXIT_RUN;
  }
  return HV_EXIT_OK;
}
