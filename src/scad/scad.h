/*
 * scad.h — the OpenSCAD language: lexer, parser and evaluator that turn a
 * .scad file into CSG trees (csg.h).
 *
 * The library never prints: ECHO and WARNING lines, and errors, go to the
 * caller's callback as whole lines, worded as OpenSCAD 2021.01 words them
 * ("ECHO: a = 1", "WARNING: Ignoring unknown module 'foo' in file x.scad,
 * line 3"); errors read "file:line:col: error: message".
 */
#ifndef RAYSCAD_SCAD_H
#define RAYSCAD_SCAD_H

#include <stddef.h>
#include <stdint.h>

#include "../../include/rayscad.h"
#include "../csg/csg.h"

/* Message kinds are the public ones (RAYSCAD_MSG_ECHO …, rayscad.h). */
typedef rayscad_message_kind scad_msg_kind;

/* What the language needs from outside src/scad — files, images, polygon
 * clipping, fonts, meshing — injected by the caller, so that src/scad
 * depends on csg only (src/cli wires src/io and src/mesh in: cli/services.c).
 * Every member may be NULL; a module that needs a missing one reports an
 * error at its call ("import() is not available here") and builds nothing.
 * Each returns 0, or -1 with a message in err (errlen bytes); arrays it
 * returns are malloc'ed and freed by the evaluator with free(). */
/* Closed 2D paths: path i is pts[start[i] .. start[i+1]), start holds
 * npaths + 1 entries.  Arrays a service returns are malloc'ed (free both). */
typedef struct scad_paths {
    double (*pts)[2];
    int *start;
    int npaths;
} scad_paths;

/* How offset() joins edges: round (r), miter (delta), square (chamfer). */
typedef enum scad_join { SCAD_JOIN_ROUND, SCAD_JOIN_MITER, SCAD_JOIN_SQUARE } scad_join;

/* text()'s arguments, as OpenSCAD 2021.01 takes them (strings borrowed,
 * never NULL; "" where the user gave none, except the defaults noted). */
typedef struct scad_text_params {
    const char *text;
    double size;                               /* default 10 */
    const char *font;                          /* "": Liberation Sans */
    const char *halign, *valign;               /* default "left", "baseline" */
    double spacing;                            /* default 1 */
    const char *direction, *language, *script; /* language default "en" */
    int segments;                              /* points per Bézier curve */
    const char *const *font_files;             /* fonts the files `use`, to be */
    int nfont_files;                           /* found before the system's */
} scad_text_params;

typedef struct scad_services {
    void *ud;
    /* The files the language reads (the main file, include, use, DXF and
     * .dat heightmaps), as rayscad_services.read_file and stat_file say:
     * the language opens no file itself (src/scad/files.c). */
    int (*read_file)(void *ud, const char *path, size_t max, char **data, size_t *len, char *err,
                     size_t errlen);
    int (*stat_file)(void *ud, const char *path, long long *mtime);
    /* A file to import is about to be looked at (may be NULL): the caller
     * may make it first (rayscad_services.make_file). */
    void (*want_file)(void *ud, const char *path);
    /* import(): a triangle mesh file (stl, off, obj, ply, amf, 3mf) as 3
     * floats per vertex and 3 indices per triangle, counter-clockwise seen
     * from outside; err may hold warnings after a success, as
     * rayscad_services.read_mesh says. */
    int (*read_mesh)(void *ud, const char *path, float **v, int *nv, int32_t **t, int *nt,
                     char *err, size_t errlen);
    /* surface() from an image: channels floats per pixel, row-major from
     * the top, sRGB-encoded in [0, 1]. */
    int (*read_image)(void *ud, const char *path, int *width, int *height, int *channels,
                      float **pixels, char *err, size_t errlen);
    /* --- 2D geometry (offset, projection, text, minkowski) goes below --- */
    /* Polygon sets cross this boundary as scad_paths.  A set the service
     * returns is non-overlapping, outlines counter-clockwise and holes
     * clockwise, so even-odd and nonzero filling agree on it. */
    /* Boolean a op b (Clipper): op is a csg_op (DIFFERENCE: a minus b);
     * a_evenodd / b_evenodd pick each operand's fill rule (else nonzero).
     * b may be empty (npaths 0): a union then just normalises a. */
    int (*paths_clip)(void *ud, int op, const scad_paths *a, int a_evenodd, const scad_paths *b,
                      int b_evenodd, scad_paths *out, char *err, size_t errlen);
    /* offset() (ClipperOffset, OpenSCAD's parameters): a (filled nonzero)
     * grown by delta (negative: shrunk); join is a scad_join; arc_tolerance
     * is the largest distance of a round join's chords from the arc. */
    int (*paths_offset)(void *ud, const scad_paths *a, double delta, int join, double miter_limit,
                        double arc_tolerance, scad_paths *out, char *err, size_t errlen);
    /* An SVG stroke (libsvg's offset_path): the open polyline pts[0 .. n)
     * widened by width / 2 each side, mitre joins, ends by cap (0 butt, 1
     * round, 2 square); out holds outlines and holes, as Clipper gives
     * them. */
    int (*paths_stroke)(void *ud, const double (*pts)[2], int n, double width, int cap,
                        scad_paths *out, char *err, size_t errlen);
    /* The Minkowski sum of two sets (each filled nonzero), any shapes. */
    int (*paths_minkowski)(void *ud, const scad_paths *a, const scad_paths *b, scad_paths *out,
                           char *err, size_t errlen);
    /* A closed triangle mesh of the solid tree root (taken: the service
     * frees it, whatever happens), sampled at grid spacing h (model units;
     * <= 0: the service picks one); arrays as read_mesh returns them. */
    int (*mesh_tree)(void *ud, csg_node *root, double h, float **v, int *nv, int32_t **t, int *nt,
                     char *err, size_t errlen);
    /* text(): the glyph outlines of p, as OpenSCAD 2021.01 lays them out;
     * 0, 1 when there is no font to draw with (a warning: nothing drawn, as
     * in OpenSCAD), or -1 (failure), with a message in err. */
    int (*text)(void *ud, const scad_text_params *p, scad_paths *out, char *err, size_t errlen);
} scad_services;

typedef struct scad_options {
    /* -D overrides, each "name=value" (value is an OpenSCAD expression),
     * applied after the file's own top-level assignments of that name. */
    const char *const *defines;
    int define_count;
    /* Receives every message line (no trailing newline); may be NULL. */
    void (*message)(void *ud, scad_msg_kind kind, const char *line);
    void *ud;
    /* Limits; 0 picks the default.  Each one hit is an error naming it
     * ("file:line:col: error: recursion deeper than 10000 calls …"). */
    int max_recursion; /* nested module/function calls, default 10000 */
    int max_list;      /* elements of one list, default 2^26 */
    int max_string;    /* bytes of one string, default 2^28 */
    /* Steps of work: function calls, module instantiations (builtin ones
     * and children() included) and every value a loop iterates over or a
     * list is built from (concat's copies included); default 10^7 (seconds
     * of work), so that nested loops and exponential recursion end with
     * "evaluation took more than N steps". */
    long max_steps;
    /* How round primitives are built (a rayscad_facets; 0 is AUTO). */
    int facets;
    /* $preview is false (rayscad_eval_options.for_mesh). */
    int for_mesh;
    /* Evaluated for a 2D export (rayscad_eval_options.for_2d): $preview
     * false, OpenSCAD's facets whatever `facets` says, and the model
     * flattened into scad_result.region instead of csg trees. */
    int for_2d;
    /* Folders searched for use and include (rayscad_eval_options). */
    const char *library_path;
    /* Outside services (may be NULL: none). */
    const scad_services *services;
    /* rayscad_eval_options: hard_warnings, no_parameter_check, range_check,
     * parameters. */
    int hard_warnings, no_parameter_check, range_check;
    int (*parameters)(void *ud, const rayscad_parameter_query *q, const char *const **overrides,
                      int *count);
    void *parameters_ud;
    void (*progress)(void *ud, double done); /* rayscad_eval_options.progress */
    void *progress_ud;
    int view_set; /* rayscad_eval_options: $vpr, $vpt, $vpd */
    double vpr[3], vpt[3], vpd;
} scad_options;

/* What a file evaluates to.  Each tree may be NULL (nothing there). */
typedef struct scad_result {
    csg_node *model;      /* the top-level objects, as an implicit union */
    csg_node *highlight;  /* subtrees under '#': also part of model */
    csg_node *background; /* subtrees under '%': not part of model */
    int warnings;         /* how many WARNING lines were sent */
    /* The file's own top-level camera variables, which OpenSCAD 2021.01
     * uses for a render without --camera (Camera::updateView): vp_set has
     * bit SCAD_VP_R for $vpr, _T $vpt, _D $vpd, _F $vpf when the file sets
     * them to a usable value, and vp_auto_off is 1 when it sets any of them
     * at all (viewall and autocenter are then off). */
    int vp_set, vp_auto_off;
    double vpr[3], vpt[3], vpd, vpf;
    /* The file's top-level $rs_ variables that hold a number or a boolean
     * (as 0 or 1), in file order: scene settings such as $rs_aperture that
     * the caller applies where no flag overrides them (OpenSCAD ignores
     * them).  At most SCAD_MAX_SETTINGS; longer names are left out. */
    struct scad_setting {
        char name[32];
        double value;
    } settings[16];
    int nsettings;
    /* The least deviation OpenSCAD's facets would give a round primitive of
     * the model (a sphere, cylinder or disc kept round, a revolve): the
     * sag r·(1 − cos(180°/n)) of a chord over one of its n fragments, r
     * its radius in world units; 0 when the model has none. */
    double facet_sag;
    /* With scad_options.for_2d: the 2D model as one polygon set,
     * normalised by the paths_clip service (no overlaps, outlines
     * counter-clockwise, holes clockwise, at least one path), or a lone
     * square's or circle's outline as made (openscad exports those so);
     * the trees above are then NULL. */
    scad_paths region;
} scad_result;

enum { SCAD_MAX_SETTINGS = 16 };

enum { SCAD_VP_R = 1, SCAD_VP_T = 2, SCAD_VP_D = 4, SCAD_VP_F = 8 };

/* Parse and evaluate the file at path.  On success returns 0 and fills *out;
 * the caller owns the trees (csg_node_free, or hand them to csg_scene_new).
 * On failure returns -1, has sent at least one RAYSCAD_MSG_ERROR line, and *out
 * holds no trees.  Syntax errors are all reported before returning. */
int scad_eval_file(const char *path, const scad_options *opt, scad_result *out);

/* The same for source text in memory; `name` is used in messages. */
int scad_eval_string(const char *name, const char *src, const scad_options *opt, scad_result *out);

void scad_result_free(scad_result *r);

/* The evaluated tree of the file at path in OpenSCAD's .csg format, as
 * `openscad -o x.csg` (2021.01) writes it: modules expanded into group(),
 * transforms as multmatrix([[…]]), $fn/$fa/$fs resolved on the shapes,
 * color([r, g, b, a]), every builtin node (2D shapes, extrusions, text,
 * import …) with its arguments, one node per line, tab-indented.  This is a
 * separate evaluation from scad_eval_file (it sends the same messages) and
 * builds no csg trees.  On success returns 0 and sets *text to a
 * NUL-terminated string the caller frees with free(), and *len (may be
 * NULL) to its length; on failure returns -1 with *text NULL, having sent
 * at least one RAYSCAD_MSG_ERROR line.  text NULL: evaluated for its
 * messages only (an .echo output), no text written. */
int scad_dump_csg_file(const char *path, const scad_options *opt, char **text, size_t *len);

/* The same for source text in memory; `name` is used in messages and as
 * the folder that file names are relative to. */
int scad_dump_csg_string(const char *name, const char *src, const scad_options *opt, char **text,
                         size_t *len);

/* The file at path as `openscad -o x.ast` (2021.01) writes it: the parse
 * (includes inline, the -D overrides and opt->parameters' applied) printed
 * back with OpenSCAD's layout and its customizer annotations.  Nothing is
 * evaluated; the messages are the parse's.  0 and *text (NUL-terminated,
 * *len bytes, len may be NULL; the caller frees it with free()), or -1
 * with *text NULL after at least one RAYSCAD_MSG_ERROR line (a syntax
 * error). */
int scad_dump_ast_file(const char *path, const scad_options *opt, char **text, size_t *len);
int scad_dump_ast_string(const char *name, const char *src, const scad_options *opt, char **text,
                         size_t *len);

#endif
