/*
 * options.h — the rayscad command line, parsed into one struct.  Flag names
 * follow OpenSCAD's where OpenSCAD has the flag.
 */
#ifndef RAYSCAD_CLI_OPTIONS_H
#define RAYSCAD_CLI_OPTIONS_H

#include "../../include/rayscad.h"

enum { CLI_MAX_DEFINES = 256, CLI_MAX_OUTPUTS = 64 };

/* --view's parts, as openscad 2021.01 names them: the library's
 * RAYSCAD_VIEW_* bits, and wireframe (which changes no image). */
enum { CLI_VIEW_WIREFRAME = 16 };

typedef struct cli_options {
    const char *input; /* "-": the standard input */
    /* -o, in order ("-": the standard output); -s and -x are old names of
     * -o (deprecated_flags has bit 1 for -s, 2 for -x: main says so). */
    const char *outputs[CLI_MAX_OUTPUTS];
    int output_count;
    int deprecated_flags;
    const char *export_format; /* --export-format: every output's format */
    /* openscad's modes: --render (images as its CGAL render, $preview
     * false), --preview[=throwntogether] (the default). */
    int render, throwntogether;
    int quiet;                  /* -q: only errors on stderr */
    int hardwarnings;           /* stop at the first warning, exit 1 */
    int check_parameters;       /* --check-parameters, default true */
    int check_parameter_ranges; /* --check-parameter-ranges, default false */
    int info;                   /* --info: what rayscad is built with */
    int animate;                /* --animate N: frames, 0 none */
    const char *param_file;     /* -p: customizer parameter file */
    const char *param_set;      /* -P: the set in it */
    const char *deps_file;      /* -d: a Makefile rule of every file read */
    const char *make_cmd;       /* -m: run it for a missing file */
    int view_flags;             /* --view: RAYSCAD_VIEW_*, CLI_VIEW_WIREFRAME */
    int csglimit;               /* --csglimit (accepted; no limit needed) */
    const char *debug;          /* --debug[=WHAT] (NULL: off) */
    const char *defines[CLI_MAX_DEFINES];
    int define_count;
    rayscad_view view;
    int width, height;
    const char *colorscheme;
    int samples;
    int threads;
    int help, version;
    rayscad_facets facets; /* --facets=auto|smooth|openscad */
    /* Evaluation limits (0: the library's default): --max-recursion,
     * --max-steps, --max-list, --max-string. */
    int max_recursion, max_list, max_string;
    long max_steps;
    /* Output and memory limits (0: the default below; main resolves
     * max_memory): --max-pixels, --max-intervals, --max-mesh-cells,
     * --max-memory (bytes). */
    long long max_pixels, max_mesh_cells;
    int max_intervals;
    unsigned long long max_memory;
    int max_memory_given;    /* --max-memory was on the command line */
    int max_memory_enforced; /* 1: main set the process's data limit to
                                max_memory; 2: the data limit rayscad was
                                started under (ulimit -d) was lower, and
                                max_memory is that one; 0: none */
    /* The opt-in light model (--shadows, --light, --bounces, --refract,
     * --aperture, --focus, --xray, --absorb, --light-samples, --seed): only
     * the fields of rayscad_render_options below `ud` are set, the rest are
     * 0, and an image's options start from these. */
    rayscad_render_options optics;
    /* Meshes and measurement (mesh_output.h). */
    double mesh_size;         /* --mesh-size: grid spacing > 0; 0 = derived from the model */
    double mesh_tolerance;    /* --mesh-tolerance (or --decimate) D; 0: none; < 0: the model's */
    int ascii;                /* --ascii: text STL / PLY */
    int measure;              /* --measure (also set by --json) */
    double measure_tolerance; /* --measure-tolerance T > 0; 0: the library's */
    int json;                 /* --json: the measurement as JSON */
    /* No -o and no --measure: the viewer (viewer.h), its window
     * --imgsize (800x600 when not given); --stats: a line per frame. */
    int viewer, imgsize_given, stats;
} cli_options;

/* The pixels a rendered image may have (--max-pixels): 2^28, a 16384 ×
 * 16384 image, whose float buffer alone is 4 GiB.  Whatever --max-pixels
 * says, a side may have at most CLI_MAX_IMAGE_SIDE pixels (JPEG stops at
 * 65500, and the renderer counts tiles in an int). */
#define CLI_MAX_PIXELS_DEFAULT (1LL << 28)
enum { CLI_MAX_IMAGE_SIDE = 65536 };

/* Parse argv into *o.  -o may be left out when --measure or --info is
 * given.  Returns 0, or -1 with a message in err (a usage
 * error: the caller prints it and exits 2). */
int cli_options_parse(int argc, char **argv, cli_options *o, char *err, size_t errlen);

/* The --help text: cli_usage, cli_usage_light (the light model and
 * meshes), then cli_usage_openscad (the flags of options_openscad.c). */
extern const char cli_usage[];
extern const char cli_usage_light[];
extern const char cli_usage_openscad[];

#endif
