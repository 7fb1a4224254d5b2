/* options.c — the subcommands' one option parser (see options.h). */
#include "cli/options.h"

#include <stdlib.h>
#include <string.h>

int cli_long(const char *s, long lo, long hi, long *out)
{
  char *end;
  double v = strtod(s, &end); /* accepts 1e6 */
  if (end == s || *end || v < (double)lo || v > (double)hi || v != (double)(long)v) return -1;
  *out = (long)v;
  return 0;
}

int cli_decimal(const char *s, long lo, long hi, long *out)
{
  char *end;
  const long v = strtol(s, &end, 10);
  if (end == s || *end || v < lo || v > hi) return -1;
  *out = v;
  return 0;
}

/* The option named `name` (its name or alias, whole), or NULL. */
static const struct cli_opt *find(const struct cli_cmd *c, const char *name)
{
  for (int k = 0; k < c->nopts; k++) {
    const struct cli_opt *o = &c->opts[k];
    if (!strcmp(name, o->name) || (o->alias && !strcmp(name, o->alias))) return o;
  }
  return NULL;
}

static int takes_value(const struct cli_opt *o)
{
  return o->kind == CLI_VALUE || o->kind == CLI_LIST;
}

/* One value for o: stored, converted or appended. */
static int put_value(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                     const char *val)
{
  if (o->kind == CLI_LIST) {
    struct cli_list *l = o->dest;
    if (l->n >= l->max) return c->fail(c, CLI_FULL, opt);
    l->v[l->n++] = val;
    return CLI_GO_ON;
  }
  if (o->convert) return o->convert(c, o, opt, val);
  *(const char **)o->dest = val;
  return CLI_GO_ON;
}

/* The option argv[*i] names with its value as "--name=value", or NULL when argv[*i]
 * is not written so; *val is then set. name receives the part before '='. */
static const struct cli_opt *split_eq(const struct cli_cmd *c, const char *a, char *name,
                                      size_t len, const char **val)
{
  const char *eq = strncmp(a, "--", 2) == 0 ? strchr(a, '=') : NULL;
  if (!eq) return NULL;
  snprintf(name, len, "%.*s", (int)(eq - a), a);
  *val = eq + 1;
  return find(c, name);
}

/* Consumes the arguments after argv[*i] that are not options into o's list. */
static int put_words(const struct cli_cmd *c, const struct cli_opt *o, int argc, char **argv,
                     int *i)
{
  struct cli_list *l = o->dest;
  const int before = l->n;
  while (*i + 1 < argc && argv[*i + 1][0] != '-' && l->n < l->max) l->v[l->n++] = argv[++*i];
  return l->n == before ? c->fail(c, CLI_NO_VALUE, argv[*i]) : CLI_GO_ON;
}

/* argv[*i], an option or the positional argument; advances *i past its value. */
static int parse_one(const struct cli_cmd *c, int argc, char **argv, int *i)
{
  const char *a = argv[*i], *val;
  char name[64];
  const struct cli_opt *o = split_eq(c, a, name, sizeof name, &val);
  if (o && o->eq && takes_value(o)) return put_value(c, o, name, val);
  if (c->eq_strict && strncmp(a, "--", 2) == 0 && strchr(a, '='))
    return c->fail(c, CLI_TAKES_NO_VALUE, name);
  o = find(c, a);
  if (!o) {
    const int option = a[0] == '-' && (a[1] || !c->lone_dash);
    if (option || !c->positional) return c->fail(c, option ? CLI_UNKNOWN : CLI_EXTRA, a);
    if (*c->positional) return c->fail(c, CLI_EXTRA, a);
    *c->positional = a;
    return CLI_GO_ON;
  }
  switch (o->kind) {
  case CLI_FLAG: *(int *)o->dest = o->flag; return CLI_GO_ON;
  case CLI_WORDS: return put_words(c, o, argc, argv, i);
  case CLI_REFUSED: return c->fail(c, CLI_REFUSE, a);
  case CLI_HELP: c->help(stdout); return 0;
  case CLI_VALUE:
  case CLI_LIST:
    if (*i + 1 >= argc) return c->fail(c, CLI_NO_VALUE, a);
    ++*i;
    return put_value(c, o, a, argv[*i]);
  }
  return CLI_GO_ON;
}

int cli_parse(const struct cli_cmd *c, int argc, char **argv)
{
  for (int i = 0; i < argc; i++) {
    const int st = parse_one(c, argc, argv, &i);
    if (st != CLI_GO_ON) return st;
  }
  return CLI_GO_ON;
}
