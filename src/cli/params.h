/*
 * params.h — openscad 2021.01's customizer parameter files (-p FILE.json
 * -P SET) as -D assignments.  params.c says, at its top, what openscad does
 * with such a file, as measured.
 *
 * openscad overrides a variable only by a value of the type its default
 * already has, so the module needs the file's own defaults: the caller
 * describes the file's top-level assignments (cli_param_file) and
 * evaluates a default when asked (main.c hands over the library's
 * rayscad_parameter_query).
 */
#ifndef RAYSCAD_CLI_PARAMS_H
#define RAYSCAD_CLI_PARAMS_H

#include <stddef.h>

/* A value's type, as openscad 2021.01's Value::type(). */
typedef enum cli_param_type {
    CLI_PARAM_UNDEF = 0,
    CLI_PARAM_BOOL,
    CLI_PARAM_NUMBER,
    CLI_PARAM_STRING,
    CLI_PARAM_VECTOR,
    CLI_PARAM_RANGE,
    CLI_PARAM_FUNCTION
} cli_param_type;

/* The .scad file's top-level assignments as openscad's parser leaves them:
 * the main file's and its include<>d files' (not use<>d ones), one entry
 * per name (a second assignment of a name replaces the first's expression
 * and keeps its place), then the -D names the file lacks, in -D order.
 *
 * default_type(ud, i) evaluates assignment i's expression as it stands
 * after the -D overrides, as openscad's applyParameterSet does: in an empty
 * context, with no variables and no builtin functions (`sin(30)` and
 * `k + 1` are undef, `2 * 3` and `[1, k]` are not).  That evaluation's
 * warnings ("Ignoring unknown variable 'k' in file f.scad, line 3") are
 * part of openscad's output, before the evaluation proper: the callback
 * is where to emit them.  It is called at most once per i, only for names
 * that the set has, in file order, and never after cli_params_load fails
 * a boolean. */
typedef struct cli_param_file {
    int count;
    const char *const *names; /* count names, borrowed */
    cli_param_type (*default_type)(void *ud, int i);
    /* May be NULL.  A message openscad prints while it checks a value's
     * type, in order with default_type's: the whole line, with no
     * location, e.g. "WARNING: begin is greater than the end, but step is
     * positive" for [1:1:0] (printed for every variable it is checked
     * against, and again by openscad when the value is used, which the
     * -D's evaluation will do with its own location). */
    void (*message)(void *ud, const char *line);
    void *ud;
} cli_param_file;

enum {
    CLI_PARAMS_OK = 0,    /* the assignments; msg is "" */
    CLI_PARAMS_ERROR = 1, /* openscad's ERROR message in msg, and it goes on */
    CLI_PARAMS_FATAL = -1 /* openscad would abort (or we are out of memory) */
};

/* Read parameter file `path` and return set `set`'s values for `file` as
 * -D assignments: *assignments gets *count strings "name=expr" (each an
 * OpenSCAD assignment, evaluated as -D evaluates one, applied after the
 * command's own -D ones since a set overrides -D), in file order, owned by
 * the caller (cli_params_free; *assignments is NULL when *count is 0).
 * msg (msglen bytes, may be 0) gets the message, "" when there is none.
 *
 * Returns CLI_PARAMS_OK; or CLI_PARAMS_ERROR with the text openscad prints
 * after "ERROR: " (an ordinary message: in an .echo output when writing
 * one, else on stderr) and goes on with the assignments made so far (none
 * when the file could not be read), exit status 0:
 *   Cannot open Parameter Set 'F': F: cannot open file
 *   Cannot open Parameter Set 'F': F(LINE): expected ':'          (bad JSON)
 *   Cannot apply Parameter Set 'conversion of data to type "b" failed'
 * or CLI_PARAMS_FATAL (*count 0) where openscad 2021.01 aborts (a folder
 * for a file; a file with members but no "parameterSets" for a .scad file
 * with assignments), or past a limit (a file over 64 MiB, JSON nested
 * deeper than 1000), or out of memory: msg says which; the caller's exit
 * status should be non-zero.
 *
 * path or set NULL or "" is openscad with -p or -P missing: OK, nothing
 * read, no assignments. */
int cli_params_load(const char *path, const char *set, const cli_param_file *file,
                    char ***assignments, int *count, char *msg, size_t msglen);

/* Free what cli_params_load returned (NULL is fine). */
void cli_params_free(char **assignments, int count);

#endif
