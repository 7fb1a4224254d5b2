/* measure.h — `hvsph measure RUNDIR`: a run's measurements taken again from its
 * particle snapshots (see measure.c). */
#ifndef HV_CLI_MEASURE_H
#define HV_CLI_MEASURE_H

/* argv holds the arguments after "measure"; returns an exit status (enum hv_exit). */
int remeasure_main(int argc, char **argv);

#endif
