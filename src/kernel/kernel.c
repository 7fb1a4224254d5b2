/* kernel.c — names of the kernels (the functions are inline in kernel.h). */
#include "kernel/kernel.h"

const char *kernel_name(enum kernel_kind k)
{
  switch (KERNEL_BASE(k)) {
  case KERNEL_WENDLAND_C2: return "wendland-c2";
  case KERNEL_QUADRATIC: return "quadratic";
  case KERNEL_CUBIC_SPLINE: break;
  }
  return "cubic-spline";
}
