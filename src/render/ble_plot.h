/* ble_plot.h — the picture of a ballistic-limit sweep (hvsph sweep's ballistic_limit.png):
 * critical diameter against impact speed, each bisected point as its bracket beside the
 * ballistic-limit equation's curve (diag/ble.h) with its regime boundaries. */
#ifndef HV_BLE_PLOT_H
#define HV_BLE_PLOT_H

#include "core/error.h"
#include "diag/ble.h"

struct ble_plot_point {
  double speed;     /* [m/s] */
  double obliquity; /* [deg] from the target's normal */
  double lo, hi;    /* [m] the bracket of the critical diameter (the range when outside) */
  int state;        /* 0 bracketed, 1 yes at both ends (limit below lo), 2 no at both
                        ends (limit above hi), 3 unfinished or failed */
};

struct ble_plot {
  const struct ble_plot_point *points;
  int npoints;
  int has_ble;
  struct ble_whipple ble; /* the shield's equation (has_ble) */
  char title[256];
};

/* Writes the PNG (900 x 600 px): axes speed [km/s] and diameter [mm] with ticks, the
 * equation's curve for every obliquity among the points (0 when none) and its regime
 * boundaries (dashed verticals at 3/cos θ and 7/cos θ km/s), each point's bracket as a
 * vertical bar with its midpoint marked, an open range as an arrow. 0 or -1 (err). */
int ble_plot_write(const struct ble_plot *bp, const char *path, struct hv_error *err);

#endif
