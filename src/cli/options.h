/*
 * options.h — the rayscad command line, parsed into one struct.  Flag names
 * follow OpenSCAD's where OpenSCAD has the flag.
 */
#ifndef RAYSCAD_CLI_OPTIONS_H
#define RAYSCAD_CLI_OPTIONS_H

#include "../render/render.h"

enum { CLI_MAX_DEFINES = 256 };

typedef struct cli_options {
    const char *input;
    const char *output;
    const char *defines[CLI_MAX_DEFINES];
    int define_count;
    render_view view;
    int width, height;
    const char *colorscheme;
    int samples;
    int threads;
    int help, version;
    int facets; /* a scad_facets: --facets=auto|smooth|openscad */
    /* Evaluation limits (0: the library's default): --max-recursion,
     * --max-steps, --max-list, --max-string. */
    int max_recursion, max_list, max_string;
    long max_steps;
    /* The opt-in light model (--shadows, --light, --bounces, --refract,
     * --aperture, --focus, --xray, --absorb, --light-samples, --seed): only
     * the fields of render_options below `ud` are set. */
    render_options optics;
    /* Meshes and measurement (mesh_output.h). */
    double mesh_size; /* --mesh-size: grid spacing > 0; 0 = derived from the model */
    double decimate;  /* --decimate TOL >= 0; < 0 when not asked for */
    int ascii;        /* --ascii: text STL / PLY */
    int measure;      /* --measure (also set by --json) */
    int json;         /* --json: the measurement as JSON */
} cli_options;

/* Copy the light-model fields of o->optics into *ro (leaving the rest). */
void cli_options_apply_optics(const cli_options *o, render_options *ro);

/* Parse argv into *o.  -o may be left out when --measure is given (then
 * o->output is NULL).  Returns 0, or -1 with a message in err (a usage
 * error: the caller prints it and exits 2). */
int cli_options_parse(int argc, char **argv, cli_options *o, char *err, size_t errlen);

/* The --help text. */
extern const char cli_usage[];

#endif
