/* bench.h — `hvsph bench`: throughput of the solver on a uniform gas lattice. */
#ifndef HV_CLI_BENCH_H
#define HV_CLI_BENCH_H

struct bench_options {
  long particles;   /* approximate number (a cube of side round(cbrt(N))) */
  long steps;
  int threads;      /* 0: OpenMP default */
  int solid;        /* elastic-plastic al-alloy with fracture instead of a gas */
  const char **sets;   /* --set KEY=VALUE overrides of the benchmark's case */
  int nsets;
};

int bench_main(const struct bench_options *o);

#endif
