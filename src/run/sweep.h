/* sweep.h — `hvsph sweep CASE -o DIR`: a case run over a grid of values (--vary) and,
 * at each grid point, the critical value of one key found by bisection on a yes/no
 * measurement (--bisect): the ballistic-limit curve of a shield (docs/ballistic-limit.md,
 * docs/cli.md). Each point is an ordinary run folder DIR/points/<name>; a stopped sweep
 * goes on where it was (finished points are reused, unfinished ones restarted from
 * their checkpoints). */
#ifndef HV_SWEEP_H
#define HV_SWEEP_H

/* Returns an exit status (enum hv_exit): 0 when every point ran (a bisection whose
 * range holds no limit included), 2 for bad input (before any run), 3 when a point
 * failed (the others still ran). */
int sweep_main(int argc, char **argv);

#endif
