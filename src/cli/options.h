/*
 * options.h — the rayscad command line, parsed into one struct.  Flag names
 * follow OpenSCAD's where OpenSCAD has the flag.
 */
#ifndef RAYSCAD_CLI_OPTIONS_H
#define RAYSCAD_CLI_OPTIONS_H

#include "../render/render.h"

#include <sys/resource.h>

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
     * the fields of render_options below `ud` are set. */
    render_options optics;
    /* Meshes and measurement (mesh_output.h). */
    double mesh_size; /* --mesh-size: grid spacing > 0; 0 = derived from the model */
    double decimate;  /* --decimate TOL >= 0; < 0 when not asked for */
    int ascii;        /* --ascii: text STL / PLY */
    int measure;      /* --measure (also set by --json) */
    int json;         /* --json: the measurement as JSON */
} cli_options;

/* The pixels a rendered image may have (--max-pixels): 2^28, a 16384 ×
 * 16384 image, whose float buffer alone is 4 GiB.  Whatever --max-pixels
 * says, a side may have at most CLI_MAX_IMAGE_SIDE pixels (JPEG stops at
 * 65500, and the renderer counts tiles in an int). */
#define CLI_MAX_PIXELS_DEFAULT (1LL << 28)
enum { CLI_MAX_IMAGE_SIDE = 65536 };

/* Copy the light-model fields of o->optics into *ro (leaving the rest). */
void cli_options_apply_optics(const cli_options *o, render_options *ro);

/* Parse argv into *o.  -o may be left out when --measure is given (then
 * o->output is NULL).  Returns 0, or -1 with a message in err (a usage
 * error: the caller prints it and exits 2). */
int cli_options_parse(int argc, char **argv, cli_options *o, char *err, size_t errlen);

/* The default of --max-memory: 3/4 of the machine's memory (or of the
 * cgroup's memory.max, when that is lower), plus what the process reserves
 * for stacks whatever the model — the evaluator's 1 GiB thread stack and
 * two stacks per core or --threads worker (ours and OpenImageIO's pool) —
 * since the limit counts those reservations too (main.c says why). */
unsigned long long cli_default_max_memory(const cli_options *o);

/* bytes as --max-memory reads it back: "300M", "2G", "1536K"; one decimal
 * when not a whole number of K, M or G ("17.6G"). */
void cli_format_size(unsigned long long bytes, char *buf, size_t len);

/* Print "rayscad: error: MSG" on stderr.  Every library words a failed
 * allocation as "out of memory"; while main's data limit is in force such
 * a message ends with which limit it was: "… (more than --max-memory 2G)". */
void cli_print_error(const cli_options *o, const char *msg);

/* The same note for a message printed some other way (the evaluator's
 * file:line:col lines): " (more than --max-memory 2G)" in buf, or "". */
const char *cli_memory_note(const cli_options *o, const char *msg, char *buf, size_t len);

/* Load the image adapter (OpenImageIO, src/io/image_loader.c) unless it is
 * loaded already, with the process's data limit lifted for the while: the
 * static initialisers of its 260 libraries do not survive a failed
 * allocation (measured: std::bad_alloc and std::system_error thrown out of
 * them, and null dereferences, with limits from 50 to 95 MiB), so the load
 * must not meet --max-memory, whatever the model holds at that moment.
 * Call it before the adapter would be loaded under the limit. */
void cli_load_image_adapter(void);

/* Lift the soft data limit (--max-memory) to the hard one around work the
 * limit must not see: returns 1 when it was lifted, keeping the old limit
 * in *was for cli_data_limit_restore, which puts it back. */
int cli_data_limit_lift(struct rlimit *was);
void cli_data_limit_restore(int lifted, const struct rlimit *was);

/* The --help text. */
extern const char cli_usage[];

#endif
