/* options.h — the one option parser of the subcommands: each command describes its
 * options in a table (name, whether it takes a value, whether it repeats, where the
 * value goes) and cli_parse walks argv against it.
 *
 * The parser finds the options and their values; what a value means (a number, a
 * mode's name) is the command's, through the option's convert function, and so is
 * the wording of every message (the command's fail function): the commands grew
 * different messages and exit statuses for the same kinds of mistake, which test_cli
 * and docs/cli.md fix, and one parser keeps them while the walk over argv is written
 * once. Options are matched whole ("--set", never "--se"); an argument that is not an
 * option is the command's positional argument.
 */
#ifndef HV_CLI_OPTIONS_H
#define HV_CLI_OPTIONS_H

#include <stdio.h>

/* What cli_parse and the convert functions return to let the parse go on; anything
 * else is the exit status the command returns at once (0 after --help). */
#define CLI_GO_ON (-1)

/* A repeatable option's values, in the order given; at most max of them (a further
 * one is CLI_FULL). */
struct cli_list {
  const char **v;
  int n, max;
};

enum cli_kind {
  CLI_FLAG,    /* no value: dest (int) is set to .flag */
  CLI_VALUE,   /* one value, the last one given wins: dest (const char *) holds it, or
                   .convert turns it into dest */
  CLI_LIST,    /* repeatable, one value each time: appended to dest (struct cli_list) */
  CLI_WORDS,   /* the arguments that follow, up to the next one starting with '-':
                   appended to dest (struct cli_list); none is CLI_NO_VALUE */
  CLI_REFUSED, /* an option of a sibling command that this one refuses: CLI_REFUSE */
  CLI_HELP,    /* prints the command's help to standard output: exit status 0 */
};

struct cli_opt;
struct cli_cmd;

/* Turns an option's value into o->dest; opt is the option as written. Returns
 * CLI_GO_ON, or an exit status after printing its own message. */
typedef int (*cli_convert_fn)(const struct cli_cmd *c, const struct cli_opt *o, const char *opt,
                              const char *val);

struct cli_opt {
  const char *name, *alias; /* "--output", "-o" (alias NULL when none) */
  enum cli_kind kind;
  int eq;                 /* "--name=value" is accepted as well as "--name value" */
  void *dest;             /* where the value goes (by kind, above) */
  int flag;               /* CLI_FLAG: the value stored (1, or 0 for a --no-... flag) */
  cli_convert_fn convert; /* CLI_VALUE: NULL stores the value itself */
  long lo, hi;            /* a range for convert, where it has one */
};

/* The mistakes cli_parse finds; arg is the argument as written (the option's name
 * alone for CLI_TAKES_NO_VALUE). */
enum cli_error {
  CLI_UNKNOWN,        /* an unknown option */
  CLI_EXTRA,          /* a positional argument the command has no room for */
  CLI_NO_VALUE,       /* an option that takes a value ends argv */
  CLI_TAKES_NO_VALUE, /* "--name=value" for an option without one (eq_strict) */
  CLI_FULL,           /* a repeatable option given more than its list holds */
  CLI_REFUSE,         /* a CLI_REFUSED option */
};

struct cli_cmd {
  const char *name; /* "run": for the messages */
  const struct cli_opt *opts;
  int nopts;
  const char **positional; /* the one positional argument (NULL: none taken) */
  int eq_strict;           /* every "--name=value" is split: one whose name is a
                                     flag or unknown is CLI_TAKES_NO_VALUE (render);
                                     else only the options with .eq are */
  int lone_dash;           /* "-" is a positional argument, not an option */
  /* prints the message of a mistake; returns the exit status */
  int (*fail)(const struct cli_cmd *c, enum cli_error e, const char *arg);
  void (*help)(FILE *f); /* CLI_HELP */
};

/* Walks argv (the arguments after the command's name) against c's table, storing each
 * value where its option says, in order, stopping at the first mistake. Returns
 * CLI_GO_ON or the exit status to return now. */
int cli_parse(const struct cli_cmd *c, int argc, char **argv);

/* A whole number in [lo, hi]; written as a number of any form strtod reads ("1e6")
 * that is a whole number. Returns 0 or -1. */
int cli_long(const char *s, long lo, long hi, long *out);

/* A whole number in [lo, hi] written in decimal digits only (strtol, base 10).
 * Returns 0 or -1. */
int cli_decimal(const char *s, long lo, long hi, long *out);

#endif
