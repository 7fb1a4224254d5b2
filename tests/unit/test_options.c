/* test_options.c — the subcommands' one option parser (src/cli/options.c) on a table
 * with one option of each kind: flags (one of them a --no-... that stores 0), a value
 * with and without "--name=value", a converted value, a repeatable list with a
 * capacity, the words after an option, a refused option, --help and a positional
 * argument; and each mistake reported once, as the right kind, naming the argument,
 * with the parse stopped there (the options after it untouched).
 * test_cli checks the commands' messages built on it; this checks the parser alone, so
 * that a change to it that one command's table happens not to exercise still fails. */
#include <string.h>

#include "cli/options.h"
#include "testlib.h"

static enum cli_error last_error;
static const char *last_arg;
static int nfail, nhelp;

static int fail(const struct cli_cmd *c, enum cli_error e, const char *arg)
{
  (void)c;
  last_error = e;
  last_arg = arg;
  nfail++;
  return 7; /* an exit status the parser hands back as it is */
}

static void help(FILE *f)
{
  (void)f;
  nhelp++;
}

/* a whole number in [o->lo, o->hi], else exit status 9 */
static int number(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                  const char *val)
{
  (void)c;
  (void)opt;
  long v;
  if (cli_long(val, o->lo, o->hi, &v)) return 9;
  *(long *)o->dest = v;
  return CLI_GO_ON;
}

struct got {
  int quiet, mirror;
  const char *out, *pos;
  long n;
  const char *setv[2], *wordv[4];
  struct cli_list sets, words;
};

/* Parses the argument string (words separated by one space) against the test table. */
static int parse(const char *args, struct got *g, int eq_strict, int lone_dash)
{
  static char buf[512];
  static char *argv[32];
  int argc = 0;
  snprintf(buf, sizeof buf, "%s", args);
  for (char *t = strtok(buf, " "); t && argc < 32; t = strtok(NULL, " ")) argv[argc++] = t;
  memset(g, 0, sizeof *g);
  g->mirror = 1;
  g->sets = (struct cli_list){g->setv, 0, 2};
  g->words = (struct cli_list){g->wordv, 0, 4};
  const struct cli_opt opts[] = {
      {"--quiet", "-q", CLI_FLAG, .dest = &g->quiet, .flag = 1},
      {"--no-mirror", NULL, CLI_FLAG, .dest = &g->mirror, .flag = 0},
      {"--output", "-o", CLI_VALUE, .eq = 1, .dest = &g->out},
      {"--count", NULL, CLI_VALUE, .dest = &g->n, .convert = number, .lo = 1, .hi = 10},
      {"--set", NULL, CLI_LIST, .eq = 1, .dest = &g->sets},
      {"--only", NULL, CLI_WORDS, .dest = &g->words},
      {"--material", NULL, CLI_REFUSED, .dest = NULL},
      {"--help", "-h", CLI_HELP, .dest = NULL},
  };
  const struct cli_cmd cmd = {.name = "test",
                              .opts = opts,
                              .nopts = (int)(sizeof opts / sizeof opts[0]),
                              .positional = &g->pos,
                              .eq_strict = eq_strict,
                              .lone_dash = lone_dash,
                              .fail = fail,
                              .help = help};
  nfail = nhelp = 0;
  last_arg = NULL;
  return cli_parse(&cmd, argc, argv);
}

int main(void)
{
  struct got g;
  int st = parse("-q --no-mirror -o a.png --count 1e1 --set x=1 --set=y=2 CASE", &g, 0, 0);
  CHECK(st == CLI_GO_ON && nfail == 0, "a good command line goes on (status %d)", st);
  CHECK(g.quiet == 1 && g.mirror == 0, "flags store their value: quiet %d, mirror %d", g.quiet,
        g.mirror);
  CHECK(g.out && !strcmp(g.out, "a.png"), "-o's value stored");
  CHECK(g.n == 10, "--count converted (1e1 = 10), got %ld", g.n);
  CHECK(g.sets.n == 2 && !strcmp(g.setv[0], "x=1") && !strcmp(g.setv[1], "y=2"),
        "--set repeats, with and without '=' (%d values)", g.sets.n);
  CHECK(g.pos && !strcmp(g.pos, "CASE"), "the positional argument");

  st = parse("--output=b.png --only wp1 wp2 -q", &g, 0, 0);
  CHECK(st == CLI_GO_ON && g.out && !strcmp(g.out, "b.png"), "--output=VALUE");
  CHECK(g.words.n == 2 && !strcmp(g.wordv[1], "wp2") && g.quiet,
        "--only takes the words up to the next option (%d)", g.words.n);

  /* mistakes: the kind, the argument named, the status of fail, the rest not parsed */
  st = parse("--bogus -q", &g, 0, 0);
  CHECK(st == 7 && nfail == 1 && last_error == CLI_UNKNOWN && !strcmp(last_arg, "--bogus") &&
            !g.quiet,
        "an unknown option stops the parse there");
  st = parse("A B", &g, 0, 0);
  CHECK(st == 7 && last_error == CLI_EXTRA && !strcmp(last_arg, "B"), "a second positional");
  st = parse("-o", &g, 0, 0);
  CHECK(st == 7 && last_error == CLI_NO_VALUE && !strcmp(last_arg, "-o"),
        "an option that ends argv without its value");
  st = parse("--count 0", &g, 0, 0);
  CHECK(st == 9 && nfail == 0, "a converter's refusal is its own status (%d)", st);
  st = parse("--set a --set b --set c", &g, 0, 0);
  CHECK(st == 7 && last_error == CLI_FULL && g.sets.n == 2, "a list past its capacity");
  st = parse("--only -q", &g, 0, 0);
  CHECK(st == 7 && last_error == CLI_NO_VALUE, "--only without a word");
  st = parse("--material x", &g, 0, 0);
  CHECK(st == 7 && last_error == CLI_REFUSE && !strcmp(last_arg, "--material"), "a refused option");
  st = parse("--count=3 CASE", &g, 0, 0);
  CHECK(st == 7 && last_error == CLI_UNKNOWN && !strcmp(last_arg, "--count=3"),
        "'=' only for the options that take it (not strict: the whole argument is unknown)");
  st = parse("--quiet=1", &g, 1, 0);
  CHECK(st == 7 && last_error == CLI_TAKES_NO_VALUE && !strcmp(last_arg, "--quiet"),
        "strict: a flag with '=' takes no value, named without it");
  st = parse("--bogus=1", &g, 1, 0);
  CHECK(st == 7 && last_error == CLI_TAKES_NO_VALUE && !strcmp(last_arg, "--bogus"),
        "strict: an unknown option with '='");
  st = parse("-", &g, 0, 0);
  CHECK(st == 7 && last_error == CLI_UNKNOWN, "'-' is an option unless lone_dash");
  st = parse("-", &g, 0, 1);
  CHECK(st == CLI_GO_ON && g.pos && !strcmp(g.pos, "-"), "'-' positional with lone_dash");
  st = parse("-q --help --bogus", &g, 0, 0);
  CHECK(st == 0 && nhelp == 1 && nfail == 0, "--help prints the help and stops with 0");

  long v;
  CHECK(cli_long("1e3", 1, 4096, &v) == 0 && v == 1000, "cli_long reads 1e3");
  CHECK(cli_long("2.5", 1, 4096, &v) < 0, "cli_long refuses a fraction");
  CHECK(cli_decimal("1e3", 1, 4096, &v) < 0, "cli_decimal refuses 1e3");
  CHECK(cli_decimal("4097", 1, 4096, &v) < 0 && cli_decimal("12", 1, 4096, &v) == 0 && v == 12,
        "cli_decimal's range");
  return test_finish();
}
