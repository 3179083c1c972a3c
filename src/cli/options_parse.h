/*
 * options_parse.h — the value parsers of options.c, shared with the other
 * flag families (options_openscad.c).  Each returns 0 or -1; none prints.
 */
#ifndef RAYSCAD_CLI_OPTIONS_PARSE_H
#define RAYSCAD_CLI_OPTIONS_PARSE_H

#include <stddef.h>

/* A finite number, the whole string. */
int cli_parse_double(const char *s, double *out);
/* A whole number in lo..hi, the whole string. */
int cli_parse_int(const char *s, long lo, long hi, int *out);
/* If argv[*i] is `name` or `name=value`, set *value (taking the next
 * argument for the first form) and return 1; 0 when it is another flag;
 * -1 when the value is missing. */
int cli_flag_value(int argc, char **argv, int *i, const char *name, const char **value);
/* A flag whose value is optional: `name` alone gives 1 with *value NULL,
 * `name=v` gives 1 with *value v; 0 when a is another flag. */
int cli_optional_value(const char *a, const char *name, const char **value);

/* The flags of options_openscad.c: 1 when argv[*i] was one (consumed), 0
 * when not, -1 with a message for a bad value. */
struct cli_options;
int cli_parse_openscad_flag(int argc, char **argv, int *i, struct cli_options *o, char *err,
                            size_t errlen);
/* Append an output path; -1 with a message past CLI_MAX_OUTPUTS. */
int cli_options_add_output(struct cli_options *o, const char *path, char *err, size_t errlen);

#endif
