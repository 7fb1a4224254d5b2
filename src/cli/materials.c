/* materials.c — `hvsph materials [NAME]`: the material library, every entry in a line or
 * one entry's parameters with their units (the listing itself is the library's,
 * material/library.c). Every mistake on its command line prints the usage to standard
 * error (exit status 1), as it always has; --help prints it to standard output. */
#include <stdio.h>

#include "cli/cli.h"
#include "cli/options.h"
#include "core/error.h"
#include "material/material_read.h"

static int materials_fail(const struct cli_cmd *c, enum cli_error e, const char *arg)
{
  (void)c;
  (void)e;
  (void)arg;
  material_library_usage(stderr);
  return HV_EXIT_USAGE;
}

int cli_materials(int argc, char **argv)
{
  const char *name = NULL;
  const struct cli_opt opts[] = {
      {"--help", "-h", CLI_HELP, .dest = NULL},
  };
  const struct cli_cmd cmd = {.name = "materials",
                              .opts = opts,
                              .nopts = (int)(sizeof opts / sizeof opts[0]),
                              .positional = &name,
                              .fail = materials_fail,
                              .help = material_library_usage};
  const int st = cli_parse(&cmd, argc, argv);
  if (st != CLI_GO_ON) return st;
  return material_library_list(name);
}
