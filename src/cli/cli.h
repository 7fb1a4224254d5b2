/* cli.h — the subcommands of hvsph (main.c dispatches to them). Each takes the
 * arguments after its name, parses them with the one option parser (cli/options.h),
 * prints its own messages and returns an exit status (enum hv_exit). Each command
 * file's head comment gives its synopsis; docs/cli.md the whole of it. */
#ifndef HV_CLI_H
#define HV_CLI_H

int cli_run(int argc, char **argv);       /* run.c: hvsph run CASE */
int cli_restart(int argc, char **argv);   /* run.c: hvsph restart RUNDIR */
int cli_check(int argc, char **argv);     /* check.c: hvsph check CASE */
int cli_bench(int argc, char **argv);     /* bench.c: hvsph bench */
int cli_measure(int argc, char **argv);   /* measure.c: hvsph measure RUNDIR */
int cli_validate(int argc, char **argv);  /* validate.c: hvsph validate */
int cli_render(int argc, char **argv);    /* render.c: hvsph render SNAPSHOT|RUNDIR */
int cli_sweep(int argc, char **argv);     /* sweep.c: hvsph sweep CASE -o DIR */
int cli_materials(int argc, char **argv); /* materials.c: hvsph materials [NAME] */

/* The process's peak resident memory in KiB (VmHWM of /proc/self/status), -1 where it
 * cannot be read (bench.c; also hvsph check's estimate). */
long cli_peak_rss_kib(void);

#endif
