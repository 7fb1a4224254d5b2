/* testparticles.c — see testparticles.h. */
#include "testparticles.h"

size_t tp_add(struct particles *p, double x, double y, double z, double m, double h, double rho,
              int body)
{
  const size_t i = particles_add(p, 1);
  p->x[0][i] = x;
  p->x[1][i] = y;
  p->x[2][i] = z;
  p->m[i] = m;
  p->h[i] = h;
  p->rho[i] = rho;
  p->body[i] = body;
  p->id[i] = (int64_t)i;
  return i;
}
