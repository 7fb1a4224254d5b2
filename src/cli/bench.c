/* bench.c — times full solver steps on a periodic, uniform lattice with small
 * random velocities (~57 neighbours at eta = 1.2) and reports particle-steps per
 * second and memory per particle (peak resident set / N, and the solver's arrays).
 * The material is an ideal gas, or with --solid the paper's aluminium alloy (library
 * al-alloy: Mie-Gruneisen EOS, von Mises strength, Tresca fracture, artificial
 * stress on). */
#include "cli/cli.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/options.h"
#include "integrate/step.h"
#include "run/run.h"
#include "sim/sim.h"

struct bench_options {
  long particles; /* approximate number (a cube of side round(cbrt(N))) */
  long steps;
  long threads;      /* 0: OpenMP default */
  int solid;         /* elastic-plastic al-alloy with fracture instead of a gas */
  const char **sets; /* --set KEY=VALUE overrides of the benchmark's case */
  int nsets;
};

/* cli.h: VmHWM, the peak resident memory */
long cli_peak_rss_kib(void)
{
  FILE *f = fopen("/proc/self/status", "r");
  if (!f) return -1;
  char line[256];
  long kib = -1;
  while (fgets(line, sizeof line, f))
    if (!strncmp(line, "VmHWM:", 6)) kib = strtol(line + 6, NULL, 10);
  fclose(f);
  return kib;
}

static int bench_main(const struct bench_options *o)
{
  if (o->threads > 0) omp_set_num_threads((int)o->threads);
  long side = lround(cbrt((double)o->particles));
  if (side < 8) side = 8;
  double dx = 1.0 / (double)side;
  char yaml[2048];
  if (o->solid)
    snprintf(
        yaml, sizeof yaml,
        "name: bench-solid\n"
        "domain: {min: [0, 0, 0], max: [1, 1, 1], boundary: {x: periodic, y: periodic, z: periodic}}\n"
        "bodies:\n"
        "  - {name: block, material: al-alloy, spacing: %.17g,\n"
        "     shape: {type: box, min: [0, 0, 0], max: [1, 1, 1]}}\n"
        "time: {end: 1e30, max_steps: %ld}\n"
        "output: {vtu: false}\n",
        dx, o->steps);
  else
    snprintf(
        yaml, sizeof yaml,
        "name: bench\n"
        "domain: {min: [0, 0, 0], max: [1, 1, 1], boundary: {x: periodic, y: periodic, z: periodic}}\n"
        "materials: {gas: {eos: ideal-gas, gamma: 1.4}}\n"
        "bodies:\n"
        "  - {name: gas, material: gas, spacing: %.17g, density: 1, pressure: 1,\n"
        "     shape: {type: box, min: [0, 0, 0], max: [1, 1, 1]}}\n"
        "time: {end: 1e30, max_steps: %ld}\n"
        "output: {vtu: false}\n",
        dx, o->steps);
  struct hv_error err;
  hv_error_clear(&err);
  struct cfg *c = cfg_load_string(yaml, "bench", &err);
  for (int k = 0; c && k < o->nsets; k++)
    if (cfg_apply_set(c, o->sets[k], &err)) {
      fprintf(stderr, "hvsph bench: %s\n", err.msg);
      cfg_free(c);
      return err.code ? err.code : HV_EXIT_INPUT;
    }
  struct sim s;
  memset(&s, 0, sizeof s);
  int status = HV_EXIT_OK;
  if (!c || run_setup(&s, c, &err) || cfg_check_unused(c, &err)) {
    status = err.code ? err.code : HV_EXIT_RUN; /* a bad --set: 2 */
    goto fail;
  }
  /* small random velocities (deterministic) so that the viscosity branch runs */
  const double vscale = o->solid ? 1.0 : 0.01; /* [m/s]: elastic for the solid */
  srand(12345);
  for (size_t i = 0; i < s.p.n; i++)
    for (int k = 0; k < 3; k++) s.p.v[k][i] = vscale * ((double)rand() / RAND_MAX - 0.5);
  if (step_init(&s, &err) || step_advance(&s, &err)) { /* warm-up step */
    status = HV_EXIT_RUN;
    goto fail;
  }
  double t0 = omp_get_wtime();
  for (long k = 0; k < o->steps; k++)
    if (step_advance(&s, &err)) {
      status = HV_EXIT_RUN;
      goto fail;
    }
  double el = omp_get_wtime() - t0;
  size_t n = s.p.n;
  double nb = 0;
  for (size_t i = 0; i < n; i += n / 64 + 1) nb += sph_count_neighbours(&s.p, &s.grid, i);
  nb /= (double)((n - 1) / (n / 64 + 1) + 1);
  size_t arrays = s.p.touched * particles_bytes_per_particle(&s.p) + nbr_grid_bytes(&s.grid) +
                  s.bnd.cap * (sizeof *s.bnd.src + sizeof *s.bnd.flip + sizeof *s.bnd.side) +
                  sph_cache_bytes(&s.cache);
  long rss = cli_peak_rss_kib();
  printf("particles            %zu (%ld^3 lattice, periodic, %s)\n", n, side,
         o->solid ? "al-alloy with strength and fracture" : "ideal gas");
  printf("threads              %d\n", omp_get_max_threads());
  printf("steps                %ld\n", o->steps);
  printf("mean neighbours      %.1f\n", nb);
  printf("wall time            %.3f s\n", el);
  printf("particle-steps/s     %.4g\n", (double)n * (double)o->steps / el);
  printf("us per particle-step %.3f (x %d threads = %.3f core-us)\n",
         1e6 * el / ((double)n * (double)o->steps), omp_get_max_threads(),
         1e6 * el * omp_get_max_threads() / ((double)n * (double)o->steps));
  printf(
      "bytes per particle   %.0f (solver arrays in use, incl. ghosts and grid), %.0f (peak RSS)\n",
      (double)arrays / (double)n, rss > 0 ? 1024.0 * (double)rss / (double)n : -1.0);
  sim_free(&s);
  cfg_free(c);
  return 0;
fail:
  fprintf(stderr, "hvsph bench: %s\n", err.msg);
  sim_free(&s);
  if (c) cfg_free(c);
  return status;
}

/* Every mistake on bench's command line is "bad argument", naming the option (not its
 * value) or the argument. */
static int bench_fail(const struct cli_cmd *c, enum cli_error e, const char *arg)
{
  (void)c;
  (void)e;
  fprintf(stderr, "hvsph bench: bad argument '%s' (see hvsph --help)\n", arg);
  return HV_EXIT_USAGE;
}

/* --particles, --steps and --threads: a whole number in [o->lo, o->hi]. */
static int bench_number(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                        const char *val)
{
  long v;
  if (cli_long(val, o->lo, o->hi, &v)) return bench_fail(c, CLI_UNKNOWN, opt);
  *(long *)o->dest = v;
  return CLI_GO_ON;
}

int cli_bench(int argc, char **argv)
{
  struct bench_options bo = {.particles = 100000, .steps = 10, .threads = 0};
  struct cli_list sets = {hv_calloc((size_t)argc + 1, sizeof *sets.v, "bench arguments"), 0, argc};
  const struct cli_opt opts[] = {
      {"--particles", NULL, CLI_VALUE, .dest = &bo.particles, .convert = bench_number, .lo = 512,
       .hi = 2000000000L},
      {"--steps", NULL, CLI_VALUE, .dest = &bo.steps, .convert = bench_number, .lo = 1,
       .hi = 1000000},
      {"--threads", NULL, CLI_VALUE, .dest = &bo.threads, .convert = bench_number, .lo = 1,
       .hi = 4096},
      {"--solid", NULL, CLI_FLAG, .dest = &bo.solid, .flag = 1},
      {"--set", NULL, CLI_LIST, .eq = 1, .dest = &sets},
  };
  const struct cli_cmd cmd = {.name = "bench",
                              .opts = opts,
                              .nopts = (int)(sizeof opts / sizeof opts[0]),
                              .fail = bench_fail};
  int st = cli_parse(&cmd, argc, argv);
  if (st == CLI_GO_ON) {
    bo.sets = sets.v;
    bo.nsets = sets.n;
    st = bench_main(&bo);
  }
  free(sets.v);
  return st;
}
