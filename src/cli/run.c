/* run.c (cli) — `hvsph run CASE.yaml [-o OUTDIR] [--set KEY=VALUE]... [--material
 * OLD=NEW]... [--threads N] [--quiet] [--overwrite] [--force]` and `hvsph restart RUNDIR
 * [--set KEY=VALUE]... [--threads N] [--quiet] [--force]`: their command lines, read
 * into struct run_options for the driver (run/run.c). */
#include <stdio.h>
#include <stdlib.h>

#include "cli/cli.h"
#include "cli/options.h"
#include "core/error.h"
#include "run/run.h"

/* Every mistake on run's and restart's command line is "unexpected argument". */
static int run_fail(const struct cli_cmd *c, enum cli_error e, const char *arg)
{
  if (e == CLI_REFUSE) {
    fprintf(stderr, "hvsph restart: --material is for hvsph run: a restart goes on with the "
                    "materials of the run's used_parameters.yaml\n");
    return HV_EXIT_USAGE;
  }
  fprintf(stderr, "hvsph %s: unexpected argument '%s' (see hvsph --help)\n", c->name, arg);
  return HV_EXIT_USAGE;
}

static int run_threads(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                       const char *val)
{
  (void)opt;
  long v;
  if (cli_long(val, o->lo, o->hi, &v)) {
    fprintf(stderr, "hvsph %s: --threads needs a positive integer, not '%s'\n", c->name, val);
    return HV_EXIT_USAGE;
  }
  *(int *)o->dest = (int)v;
  return CLI_GO_ON;
}

/* restart: the run folder instead of a case, and no -o, --material or --overwrite (a
 * restart goes on in its folder, with its materials, over its own outputs). */
static int run_or_restart(int argc, char **argv, int restart)
{
  struct run_options ro = {0};
  struct cli_list sets = {hv_calloc((size_t)argc + 1, sizeof *sets.v, "run arguments"), 0, argc};
  struct cli_list swaps = {hv_calloc((size_t)argc + 1, sizeof *swaps.v, "run arguments"), 0, argc};
  const struct cli_opt run_opts[] = {
      {"--output", "-o", CLI_VALUE, .dest = &ro.outdir},
      {"--set", NULL, CLI_LIST, .eq = 1, .dest = &sets},
      {"--material", NULL, CLI_LIST, .dest = &swaps},
      {"--threads", NULL, CLI_VALUE, .dest = &ro.threads, .convert = run_threads, .lo = 1,
       .hi = 4096},
      {"--quiet", "-q", CLI_FLAG, .dest = &ro.quiet, .flag = 1},
      {"--overwrite", NULL, CLI_FLAG, .dest = &ro.overwrite, .flag = 1},
      {"--force", NULL, CLI_FLAG, .dest = &ro.force, .flag = 1},
  };
  const struct cli_opt restart_opts[] = {
      {"--set", NULL, CLI_LIST, .eq = 1, .dest = &sets},
      {"--material", NULL, CLI_REFUSED, .dest = NULL},
      {"--threads", NULL, CLI_VALUE, .dest = &ro.threads, .convert = run_threads, .lo = 1,
       .hi = 4096},
      {"--quiet", "-q", CLI_FLAG, .dest = &ro.quiet, .flag = 1},
      {"--force", NULL, CLI_FLAG, .dest = &ro.force, .flag = 1},
  };
  const struct cli_cmd cmd = {
      .name = restart ? "restart" : "run",
      .opts = restart ? restart_opts : run_opts,
      .nopts = restart ? (int)(sizeof restart_opts / sizeof restart_opts[0])
                       : (int)(sizeof run_opts / sizeof run_opts[0]),
      .positional = &ro.case_path,
      .fail = run_fail,
  };
  int st = cli_parse(&cmd, argc, argv);
  if (st == CLI_GO_ON && !ro.case_path) {
    fprintf(stderr, "hvsph %s: missing %s (see hvsph --help)\n", cmd.name,
            restart ? "run folder" : "case file");
    st = HV_EXIT_USAGE;
  }
  if (st == CLI_GO_ON) {
    ro.sets = sets.v;
    ro.nsets = sets.n;
    ro.swaps = swaps.v;
    ro.nswaps = swaps.n;
    if (restart) ro.restart_dir = ro.case_path;
    st = run_main(&ro);
  }
  free(sets.v);
  free(swaps.v);
  return st;
}

int cli_run(int argc, char **argv) { return run_or_restart(argc, argv, 0); }

int cli_restart(int argc, char **argv) { return run_or_restart(argc, argv, 1); }
