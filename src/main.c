/* main.c — the hvsph command line: subcommands run, check, restart, bench, materials, render,
 * measure, validate, help, version. It only dispatches: each subcommand parses its own
 * options (src/cli/, through the one parser of cli/options.h) and returns the exit status. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "core/error.h"
#include "version.h"

/* Each command's lines of the usage: `hvsph --help` prints them all, `hvsph CMD --help`
 * its own (render, measure and materials print their own longer help). */
static const struct {
  const char *cmd, *text;
} usage_lines[] = {
    {"run", "  hvsph run CASE.yaml [-o OUTDIR] [--set KEY=VALUE]... [--material OLD=NEW]...\n"
            "            [--threads N] [--quiet] [--overwrite] [--force]\n"
            "      run a case file; results in OUTDIR (default out/<case name>)\n"
            "      --overwrite replaces an earlier run in OUTDIR (refused otherwise)\n"
            "      --force lets a case write more than 10000 outputs (refused otherwise)\n"
            "      --set overrides any key of the case file, e.g. --set time.end=\"35 us\"\n"
            "      --material gives the bodies of material OLD the material NEW instead\n"},
    {"check", "  hvsph check CASE.yaml [--set KEY=VALUE]... [--material OLD=NEW]... [--threads N]\n"
              "      set the case up as run would, write nothing, and print per body its\n"
              "      particles, plate layers and projectile resolution, the first time step,\n"
              "      the estimated steps, memory and wall time (a few steps timed here)\n"},
    {"restart", "  hvsph restart RUNDIR [--set KEY=VALUE]... [--threads N] [--quiet] [--force]\n"
                "      continue a stopped run from RUNDIR/checkpoint.hvc, in RUNDIR; e.g.\n"
                "      --set time.end=\"60 us\" carries a finished run further\n"},
    {"bench",
     "  hvsph bench [--particles N] [--steps K] [--threads T] [--solid] [--set KEY=VALUE]...\n"
     "      solver throughput on a uniform lattice of gas (or, with --solid, of\n"
     "      elastic-plastic aluminium): particle-steps per second, bytes per particle;\n"
     "      --set changes its case, e.g. --set sph.viscosity.reconstruct=true\n"},
    {"materials",
     "  hvsph materials [NAME]\n"
     "      the material library: every entry, or one entry's parameters with units\n"},
    {"render",
     "  hvsph render SNAPSHOT.vtu|csv -o FILE.png [--mode radiograph|particles] [--axis x|y|z] ...\n"
     "  hvsph render RUNDIR -o FRAMEDIR [options]\n"
     "      simulated flash radiograph or particle picture; of a run folder, one\n"
     "      frame per snapshot for a movie (hvsph render --help)\n"},
    {"measure", "  hvsph measure RUNDIR [--case FILE] [--skip-missing] [--quiet]\n"
                "      take a run's measurements again from its particle snapshots\n"
                "      (rewrites RUNDIR/measurements.csv; docs/measurements.md)\n"},
    {"sweep", "  hvsph sweep CASE.yaml -o DIR [--vary KEY=V1,V2,...]... [--bisect KEY=LO..HI]\n"
              "            [--tol DT] [--measure QUANTITY[@OBJECT]] [--jobs N] [--threads T]\n"
              "            [--set KEY=VALUE]... [--emit slurm] [--only I] [--quiet]\n"
              "  hvsph sweep --collect DIR\n"
              "      run a case over a grid of values and bisect one key at each grid point\n"
              "      on a yes/no measurement (perforated): DIR/sweep.csv, ballistic_limit.csv\n"
              "      and .png; resumable; the case's own `sweep:` section needs no options\n"},
    {"validate",
     "  hvsph validate [--rz] [--scale S] [--only NAME...] [-o DIR] [--threads N]\n"
     "                 [--cases DIR] [--no-run] [--resume] [--list] [--set KEY=VALUE]...\n"
     "                 [--material OLD=NEW]...\n"
     "      run the paper's cases (examples/paper, or --cases DIR; particle counts x S)\n"
     "      and compare with its experiments and simulations: DIR/validation.md and .csv;\n"
     "      --rz: the axisymmetric cases of examples/paper/rz; --list: only list them\n"},
};

static const char usage_tail[] =
    "exit status: 0 done, 1 bad command line, 2 bad input (case file, units,\n"
    "materials, output folder), 3 failed run, 130 interrupted (state written)\n"
    "documentation: README.md, docs/cli.md, docs/case-files.md\n";

/* cmd NULL: every command */
static void usage(FILE *f, const char *cmd)
{
  fprintf(f, "hvsph %s — 3D SPH for hypervelocity impact\n\nusage:\n", HVSPH_VERSION);
  for (size_t k = 0; k < sizeof usage_lines / sizeof usage_lines[0]; k++)
    if (!cmd || !strcmp(cmd, usage_lines[k].cmd)) fputs(usage_lines[k].text, f);
  if (!cmd) fputs("  hvsph --version | --help\n", f);
  fprintf(f, "\n%s", usage_tail);
}

/* `hvsph CMD ... --help` (or -h) for the commands that have no help of their own */
static int asks_help(int argc, char **argv)
{
  for (int i = 0; i < argc; i++)
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return 1;
  return 0;
}

/* The subcommands (cli/cli.h; materials is the library's own, material/). own_help: the
 * command prints its own longer help for --help; the others print their usage lines. */
static const struct {
  const char *name;
  int (*main)(int argc, char **argv);
  int own_help;
} commands[] = {
    {"run", cli_run, 0},
    {"check", cli_check, 0},
    {"restart", cli_restart, 0},
    {"bench", cli_bench, 0},
    {"validate", cli_validate, 0},
    {"sweep", cli_sweep, 0},
    {"materials", cli_materials, 1},
    {"render", cli_render, 1},
    {"measure", cli_measure, 1},
};

/* OpenMP threads that wait for work sleep instead of spinning, unless the user chose
 * otherwise: when the threads outnumber the free cores (another run, a build), spinning
 * threads hold the cores the working ones need and a run becomes many times slower,
 * while alone the two policies are equally fast (docs/performance.md, "OpenMP wait
 * policy"). libgomp reads the variable when it is loaded, so it is set and the program
 * executed again once, before anything else. */
static void wait_policy(char **argv)
{
  if (getenv("OMP_WAIT_POLICY")) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1)) return;
  execv("/proc/self/exe", argv); /* returns only on failure: go on as we are */
}

int main(int argc, char **argv)
{
  wait_policy(argv);
  if (argc < 2) {
    usage(stderr, NULL);
    return HV_EXIT_USAGE;
  }
  const char *cmd = argv[1];
  if (!strcmp(cmd, "--help") || !strcmp(cmd, "-h") || !strcmp(cmd, "help")) {
    usage(stdout, NULL);
    return 0;
  }
  if (!strcmp(cmd, "--version") || !strcmp(cmd, "version")) {
    printf("hvsph %s\n", HVSPH_VERSION);
    return 0;
  }
  for (size_t k = 0; k < sizeof commands / sizeof commands[0]; k++) {
    if (strcmp(cmd, commands[k].name)) continue;
    if (!commands[k].own_help && asks_help(argc - 2, argv + 2)) {
      usage(stdout, cmd);
      return 0;
    }
    return commands[k].main(argc - 2, argv + 2);
  }
  fprintf(stderr, "hvsph: unknown command '%s' (see hvsph --help)\n", cmd);
  return HV_EXIT_USAGE;
}
