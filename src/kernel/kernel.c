/* kernel.c — names of the kernels (the functions are inline in kernel.h). */
#include "kernel/kernel.h"

const char *kernel_name(enum kernel_kind k)
{
  return k == KERNEL_WENDLAND_C2 ? "wendland-c2" : "cubic-spline";
}
