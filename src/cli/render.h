/* render.h (cli) — `hvsph render`: the command line of the pictures (render/). */
#ifndef HV_CLI_RENDER_H
#define HV_CLI_RENDER_H

/* `hvsph render SNAPSHOT.csv -o FILE.png [options]`, or `hvsph render RUNDIR -o FRAMEDIR
 * [options]` (render_series): argv holds the arguments after "render". Returns the exit
 * status (0, 1 usage, 2 input, 3 write failure). */
int render_main(int argc, char **argv);

#endif
