/* check.h — `hvsph check`: a case set up and described, nothing written (check.c). */
#ifndef HV_CLI_CHECK_H
#define HV_CLI_CHECK_H

/* `hvsph check CASE [--set K=V]... [--material OLD=NEW]... [--threads N]`; returns an
 * exit status (enum hv_exit). */
int check_main(int argc, char **argv);

#endif
