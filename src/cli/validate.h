/* validate.h — `hvsph validate`: runs the paper's cases and compares. */
#ifndef HV_CLI_VALIDATE_H
#define HV_CLI_VALIDATE_H

/* argv: the arguments after "validate". Returns the exit status. */
int validate_main(int argc, char **argv);

#endif
