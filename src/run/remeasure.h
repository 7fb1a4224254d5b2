/* remeasure.h — `hvsph measure RUNDIR`: a run's measurements taken again from its
 * particle snapshots (see remeasure.c). */
#ifndef HV_REMEASURE_H
#define HV_REMEASURE_H

/* argv holds the arguments after "measure"; returns an exit status (enum hv_exit). */
int remeasure_main(int argc, char **argv);

#endif
