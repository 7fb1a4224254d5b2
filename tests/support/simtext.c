/* simtext.c — see simtext.h. */
#include "simtext.h"

#include <string.h>

#include "core/error.h"
#include "run/run.h"
#include "testlib.h"

int sim_from_text(const char *text, const char *name, struct sim *s, struct cfg **c)
{
  struct hv_error err;
  hv_error_clear(&err);
  memset(s, 0, sizeof *s);
  *c = cfg_load_string(text, name, &err);
  const int ok = *c && !run_setup(s, *c, &err) && !cfg_check_unused(*c, &err);
  CHECK(ok, "%s sets up (%s)", name, ok ? "ok" : err.msg);
  if (ok) return 0;
  if (*c) cfg_free(*c);
  *c = NULL;
  return -1;
}
