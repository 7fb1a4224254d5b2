/* sim.h — one simulation: its particles, materials, parameters and clock. */
#ifndef HV_SIM_H
#define HV_SIM_H

#include "boundary/boundary.h"
#include "material/material.h"
#include "neighbours/grid.h"
#include "particles/particles.h"
#include "sph/sph.h"

/* The case file stays with the simulation (the commands read it again), but as an
 * opaque pointer: the physics that includes this header does not see the config layer
 * (test_physics_headers). Whoever reads it includes config/config.h. */
struct cfg;

struct time_params {
  double end;     /* [s] end time */
  double cfl;     /* [-] Courant number on h / vsig */
  double cfl_acc; /* [-] factor on sqrt(h/|a|) */
  double dt_init; /* [s] first step (0: from the CFL condition) */
  double dt_max;  /* [s] largest step (0: no limit) */
  double dt_min;  /* [s] a step below this ends the run as failed */
  double growth;  /* [-] largest ratio between consecutive steps */
  long max_steps; /* 0: none */
  int individual; /* time.individual: block (individual) time steps (step.h) */
  int levels;     /* time.levels: a block's finest step is its length / 2^levels */
};

struct output_params {
  double every;           /* [s] interval between snapshots (0: only start and end) */
  int vtu, csv;           /* which particle files */
  int compress;           /* zlib-compressed VTU arrays */
  long log_every;         /* steps between log lines when not on a terminal */
  int checkpoint;         /* write OUTDIR/checkpoint.hvc (restart) */
  double checkpoint_wall; /* [s] of wall-clock time between checkpoints besides those at
                             output times (0: only at output times and at the end) */
};

struct body_info {
  char name[64];
  int mat;
  size_t count;
  double spacing;      /* [m] lattice spacing */
  double lo[3], hi[3]; /* [m] initial extent of the material (particle centres ± Δ/2) */
  double rho;          /* [kg/m3] initial density */
};

struct sim {
  char case_name[128];
  struct cfg *cfg;
  struct particles p;
  struct material mat[HV_MAX_MATERIALS];
  int nmat;
  struct body_info body[64];
  int nbody;
  /* the piece of each body (bodies[i].part_of, resolved to the root body): bodies of one
     piece interact as one body (sph.piece points here) */
  int32_t piece[64];
  struct sph_params sph;
  struct time_params tp;
  struct output_params out;
  struct boundary bnd;
  struct nbr_grid grid;
  struct sph_cache cache;
  int reorder_every; /* steps between reorderings of the particles by cell */
  double t;          /* [s] */
  double dt;         /* [s] next step (may be shortened to hit an output time) */
  double dt_prop;    /* [s] the step the stability limits proposed last */
  enum dt_limit { DT_CFL = 0, DT_ACCELERATION, DT_GROWTH, DT_MAX, DT_INIT } dt_limit;
  /* which limit set dt_prop */
  int64_t dt_limit_id; /* id of the particle whose CFL or acceleration limit it was */
  int dt_limit_body;   /* and its body */
  long step;
  /* individual time steps (time.individual): the reals' rate evaluations so far (a
     global step makes n per step), the ticks that evaluated some, and the particle
     steps that wanted less than the block's finest step and took it */
  long long evals;
  long eval_ticks, over_steps;
};

/* Reads everything but the bodies (sph, time, output, materials, domain). */
int sim_read_params(struct sim *s, struct cfg *c, struct hv_error *err);
/* An axisymmetric domain (s->bnd.axisym): marks the particle store, takes the 2D kernel,
 * refuses the 3D-only sph options (setup/rz.c). 0 for a 3D one. */
int sim_axisym_params(struct sim *s, struct cfg *c, struct hv_error *err);
void sim_free(struct sim *s);

#endif
