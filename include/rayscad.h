/*
 * rayscad.h — the rayscad library: OpenSCAD files evaluated into CSG trees,
 * rendered by ray casting with interval lists, meshed and measured from the
 * same ray queries.  This is the one public header; the rayscad command is
 * a user of it like any other.
 *
 * The pipeline:
 *
 *     rayscad_model_load      a .scad file (or text) → an evaluated model
 *     rayscad_scene_new       the model's trees → a scene ready for rays
 *     rayscad_camera_frame    OpenSCAD's view of the scene → a camera
 *     rayscad_render          the scene through the camera → RGBA pixels
 *     rayscad_image_write     pixels → PNG, JPEG, TIFF, EXR … (OpenImageIO)
 *     rayscad_sampling_new    the scene's solid sampled by three ray families
 *     rayscad_sampling_mesh   … contoured into a closed triangle mesh
 *     rayscad_mesh_write      … written as STL, OFF, OBJ, PLY (OpenMesh), AMF or 3MF
 *
 * Conventions:
 * - Every fallible call returns a rayscad_status: RAYSCAD_OK (0), or a
 *   negative code with a one-line message in the caller's err buffer
 *   (errlen bytes; may be NULL).  A message names what failed first and
 *   says why ("cannot write 'x.png': Permission denied"); it carries no
 *   "error:" and no location prefix: the caller adds its own.
 * - The library never prints and never exits.  What an evaluation says
 *   (echo(), OpenSCAD's warnings, errors with their file:line:col) goes to
 *   the caller's message callback, worded as OpenSCAD 2021.01 words it.
 * - Every _new or _load has a _free; each declaration says who owns what it
 *   returns.  Strings and arrays passed in are borrowed for the call.
 * - Threads: a model, scene, sampling or mesh may be used by one thread at
 *   a time; a committed scene is read-only and several threads may render
 *   it at once.  Evaluation runs on a thread of its own (with a large
 *   stack); the message callback and the services are called from that
 *   thread, one call at a time, while the calling thread waits.  Progress
 *   callbacks are called from the calling thread.
 */
#ifndef RAYSCAD_H
#define RAYSCAD_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define RAYSCAD_VERSION_MAJOR 0
#define RAYSCAD_VERSION_MINOR 2
#define RAYSCAD_VERSION_PATCH 0
#define RAYSCAD_VERSION_STRING "0.2.0"

/* The library's version string, as built (may differ from the header's). */
const char *rayscad_version(void);

/* The libraries rayscad runs with, one "name: version" line each
 * (OpenImageIO, OpenMesh, lib3mf, FreeType, HarfBuzz, fontconfig, the
 * fonts fontconfig knows, cairo), NUL-terminated, into buf (len bytes,
 * truncated to fit).  Loads the image adapter to ask OpenImageIO. */
void rayscad_library_info(char *buf, size_t len);

/* ---- status ------------------------------------------------------------------ */

typedef enum rayscad_status {
    RAYSCAD_OK = 0,
    /* Failed: the model (an evaluation error, reported through the message
     * callback too), a file, an operation; the message says why. */
    RAYSCAD_ERROR = -1,
    RAYSCAD_ERROR_MEMORY = -2,    /* out of memory */
    RAYSCAD_ERROR_INTERVALS = -3, /* a ray's interval list passed max_intervals */
    RAYSCAD_ERROR_CELLS = -4,     /* a sampling grid passed max_cells */
    /* An argument the call cannot take: an unknown colour scheme, a camera
     * whose eye and centre coincide, an unknown output format. */
    RAYSCAD_ERROR_ARGUMENT = -5,
    /* The caller's cancel hook asked to stop (rayscad_render_options,
     * rayscad_measure_options). */
    RAYSCAD_CANCELLED = -6,
    /* An exact measurement needed more rays than max_rays
     * (rayscad_measure_options). */
    RAYSCAD_ERROR_RAYS = -7
} rayscad_status;

/* ---- evaluation --------------------------------------------------------------- */

typedef enum rayscad_message_kind {
    RAYSCAD_MSG_ECHO,    /* "ECHO: …" as OpenSCAD prints it */
    RAYSCAD_MSG_WARNING, /* "WARNING: … in file x.scad, line 3", "DEPRECATED: …" */
    RAYSCAD_MSG_ERROR,   /* "file:line:col: error: …": the evaluation failed */
    RAYSCAD_MSG_NOTE,    /* "file:line:col: note: …": rayscad's own, about input
                            OpenSCAD accepts but rayscad does not fully build; never
                            part of OpenSCAD's .echo stream */
    RAYSCAD_MSG_TRACE    /* after an error, OpenSCAD's own account of it ("ERROR: …
                            in file x.scad, line N", "TRACE: called by …"): the
                            lines openscad writes to an .echo file */
} rayscad_message_kind;

/* One whole line, without its newline. */
typedef void (*rayscad_message_fn)(void *ud, rayscad_message_kind kind, const char *line);

/* What the evaluation reads from outside.  Every member may be NULL: the
 * library's own (the file system, OpenMesh, OpenImageIO) is used instead,
 * so a caller replaces only what it needs to (a test serving includes from
 * memory, a command wrapping image reads in its own memory policy).  Each
 * returns 0, or -1 with a message in err; arrays it returns are malloc'd
 * and freed by the library. */
typedef struct rayscad_services {
    void *ud;
    /* The bytes of the file at path (include, use, the main file, DXF and
     * .dat heightmaps): *data NUL-terminated after *len bytes.  A file
     * larger than max bytes is refused (fail with a message). */
    int (*read_file)(void *ud, const char *path, size_t max, char **data, size_t *len, char *err,
                     size_t errlen);
    /* 1 when path is a regular file that can be read, else 0; *mtime
     * (may be NULL) gets its modification time in seconds (.csg prints
     * it). */
    int (*stat_file)(void *ud, const char *path, long long *mtime);
    /* import() of stl, off, obj, ply, amf, 3mf: 3 floats per vertex, 3
     * indices per triangle, counter-clockwise seen from outside.  err holds
     * "" when called; a reader may leave warnings in it even when it
     * returns 0 (lines separated by '\n'; one that starts "note: " is a
     * remark rather than a warning), and import() shows them. */
    int (*read_mesh)(void *ud, const char *path, float **v, int *nv, int32_t **t, int *nt,
                     char *err, size_t errlen);
    /* surface() of a PNG: channels floats per pixel, row-major from the
     * top, sRGB-encoded in [0, 1]. */
    int (*read_image)(void *ud, const char *path, int *width, int *height, int *channels,
                      float **pixels, char *err, size_t errlen);
    /* Told of every file the evaluation has read (the main file, include,
     * use, imports, surfaces, the font files text() opened), as the path
     * it was opened by, each time it is read: openscad's -d. */
    void (*file_read)(void *ud, const char *path);
    /* Asked for a file to import (a mesh, DXF, SVG, image or .dat) that
     * does not exist, before it is read: openscad's -m runs make for it.
     * The library reads it after the call either way. */
    void (*make_file)(void *ud, const char *path);
} rayscad_services;

/* An OpenSCAD value's type. */
typedef enum rayscad_value_type {
    RAYSCAD_VALUE_UNDEF = 0,
    RAYSCAD_VALUE_BOOL,
    RAYSCAD_VALUE_NUMBER,
    RAYSCAD_VALUE_STRING,
    RAYSCAD_VALUE_VECTOR,
    RAYSCAD_VALUE_RANGE,
    RAYSCAD_VALUE_FUNCTION
} rayscad_value_type;

/* A file's top-level assignments as openscad's customizer sees them (see
 * rayscad_eval_options.parameters): the main file's and its include<>d
 * files', one per name (a later assignment of a name keeps the first's
 * place), then the -D names the file lacks.  default_type(ctx, i)
 * evaluates assignment i's expression, after the -D overrides, in an empty
 * context as openscad 2021.01 does (no variables, no functions: `sin(30)`
 * and `k + 1` are undef, `2 * 3` is a number), its warnings through the
 * message callback, and returns the value's type. */
typedef struct rayscad_parameter_query {
    int count;
    const char *const *names;
    rayscad_value_type (*default_type)(void *ctx, int i);
    void *ctx;
} rayscad_parameter_query;

/* How round primitives are built: SMOOTH exact; OPENSCAD the polytope or
 * polygon OpenSCAD 2021.01 tessellates them into; AUTO smooth, unless the
 * user's $fn/$fa/$fs ask for at most 16 fragments, where facets are meant
 * to show. */
typedef enum rayscad_facets {
    RAYSCAD_FACETS_AUTO = 0,
    RAYSCAD_FACETS_SMOOTH,
    RAYSCAD_FACETS_OPENSCAD
} rayscad_facets;

typedef struct rayscad_eval_options {
    /* -D overrides, each "name=value" (value an OpenSCAD expression),
     * applied after the file's own top-level assignment of that name. */
    const char *const *defines;
    int define_count;
    rayscad_message_fn message; /* may be NULL: messages are dropped */
    void *message_ud;
    /* Limits; 0 picks the default.  Each one hit is an error naming it
     * ("file:line:col: error: recursion deeper than 10000 calls …"). */
    int max_recursion; /* nested module and function calls, default 10000 */
    long max_steps;    /* calls plus loop values, default 10^7 */
    int max_list;      /* elements of one list, default 2^26 */
    int max_string;    /* bytes of one string, default 2^28 */
    rayscad_facets facets;
    /* 1: evaluate as openscad does to export a mesh (its CGAL render):
     * $preview is false.  0: as for its preview, $preview true. */
    int for_mesh;
    /* 1: evaluate as openscad does to export a 2D model (SVG, DXF): as
     * for_mesh, with OpenSCAD's facets whatever `facets` says, and the
     * model kept as one polygon set (rayscad_model_region), not as trees
     * to render.  A model whose top level is not 2D (3D, or empty) fails
     * the load with openscad's error "Current top level object is not a
     * 2D object." */
    int for_2d;
    /* Folders searched for use <…> and include <…> after the including
     * file's own, ':'-separated, before /usr/share/openscad/libraries, as
     * openscad's OPENSCADPATH; NULL: the OPENSCADPATH environment
     * variable. */
    const char *library_path;
    const rayscad_services *services; /* NULL: the library's own */
    /* openscad's --hardwarnings: the first warning stops the evaluation as
     * an error does (the load fails). */
    int hard_warnings;
    /* openscad's --check-parameters=false: no "variable x not specified as
     * parameter" for user modules and functions (0, the default, warns). */
    int no_parameter_check;
    /* openscad's --check-parameter-ranges=true: its warnings for cube,
     * square, circle, sphere and cylinder sizes <= 0 (off by default). */
    int range_check;
    /* openscad's customizer parameter sets (-p, -P), may be NULL: called
     * once the file is parsed and the -D overrides applied, before
     * anything is evaluated.  It returns 0 and, in *overrides (kept alive
     * by the caller until the load returns), *count more "name=value"
     * overrides, applied as the -D ones are; or -1 to fail the load (the
     * hook has said why). */
    int (*parameters)(void *ud, const rayscad_parameter_query *q, const char *const **overrides,
                      int *count);
    void *parameters_ud;
    /* May be NULL: told on the calling thread how far the evaluation has
     * come, done in [0, 1] the share of the main file's top-level
     * statements finished (each counts alike; an include<>d file's count
     * where it stands), called after each one and every 2^16 steps of work
     * between (with the same share, so a caller can show time passing). */
    void (*progress)(void *ud, double done);
    void *progress_ud;
    /* The view the file is evaluated for, as openscad's window sets $vpr,
     * $vpt and $vpd to its camera at each preview; view_set 0: its
     * command line's values (0,0,0; 0,0,0; 500). */
    int view_set;
    double vpr[3], vpt[3], vpd;
} rayscad_eval_options;

/* An evaluated file: its top-level objects, the '#' and '%' subtrees, and
 * what the file says about its view and scene ($vp*, $rs_ settings). */
typedef struct rayscad_model rayscad_model;

/* Parse and evaluate the file at path (read through the services).
 * RAYSCAD_OK and *out, owned by the caller (rayscad_model_free); or
 * RAYSCAD_ERROR after at least one RAYSCAD_MSG_ERROR message (*out NULL),
 * every syntax error reported. */
rayscad_status rayscad_model_load(const char *path, const rayscad_eval_options *o,
                                  rayscad_model **out);
/* The same for source text in memory; name is used in messages and as the
 * folder relative includes and imports are found from. */
rayscad_status rayscad_model_load_string(const char *name, const char *src,
                                         const rayscad_eval_options *o, rayscad_model **out);
void rayscad_model_free(rayscad_model *m);

/* The file's own camera variables, which OpenSCAD 2021.01 uses when no
 * camera is given (Camera::updateView): set has bit 1 for a usable $vpr,
 * 2 $vpt, 4 $vpd, 8 $vpf; auto_off is 1 when the file sets any of them at
 * all (viewall and autocenter are then off). */
typedef struct rayscad_file_view {
    int set, auto_off;
    double vpr[3], vpt[3], vpd, vpf;
} rayscad_file_view;

void rayscad_model_file_view(const rayscad_model *m, rayscad_file_view *out);

/* The file's top-level $rs_ variables that hold a number or a boolean (as
 * 0 or 1), in file order: scene settings such as $rs_aperture that a caller
 * may apply (OpenSCAD ignores them).  Returns the name (borrowed from m) of
 * setting i in [0, rayscad_model_setting_count), its value in *value. */
int rayscad_model_setting_count(const rayscad_model *m);
const char *rayscad_model_setting(const rayscad_model *m, int i, double *value);

/* The evaluated tree in OpenSCAD's .csg format, as `openscad -o x.csg`
 * (2021.01) writes it: modules expanded into group(), transforms as
 * multmatrix, $fn/$fa/$fs resolved.  An evaluation of its own, without
 * geometry, as openscad's: its messages are exactly those of an .echo
 * output.  RAYSCAD_OK and *text (NUL-terminated, *len bytes, len may be
 * NULL; the caller frees it with free()), or RAYSCAD_ERROR after an error
 * message (*text NULL).  text NULL: the evaluation for its messages only
 * (an .echo output), no text made. */
rayscad_status rayscad_csg_text(const char *path, const rayscad_eval_options *o, char **text,
                                size_t *len);
rayscad_status rayscad_csg_text_string(const char *name, const char *src,
                                       const rayscad_eval_options *o, char **text, size_t *len);

/* The parsed file as `openscad -o x.ast` (2021.01) writes it: each scope's
 * functions, modules, assignments and instantiations printed back in
 * OpenSCAD's layout, included files inline, the -D overrides and the
 * parameter set applied, and the customizer annotations of the top-level
 * assignments ("//Parameter([0 : 10])") above them.  Only a parse: its
 * messages are the parse's (syntax errors, includes not found).
 * RAYSCAD_OK and *text (NUL-terminated, *len bytes, len may be NULL; the
 * caller frees it with free()), or RAYSCAD_ERROR after an error message
 * (*text NULL). */
rayscad_status rayscad_ast_text(const char *path, const rayscad_eval_options *o, char **text,
                                size_t *len);
rayscad_status rayscad_ast_text_string(const char *name, const char *src,
                                       const rayscad_eval_options *o, char **text, size_t *len);

/* The file's CSG term as `openscad -o x.term` (2021.01) writes it, which is
 * "No top-level CSG object\n" for every file that parses: openscad builds
 * the term without geometry, so each of its leaves is empty.  Only a parse,
 * as rayscad_ast_text; the same results. */
rayscad_status rayscad_term_text(const char *path, const rayscad_eval_options *o, char **text,
                                 size_t *len);
rayscad_status rayscad_term_text_string(const char *name, const char *src,
                                        const rayscad_eval_options *o, char **text, size_t *len);

/* ---- scenes and cameras ---------------------------------------------------------- */

/* A model's trees committed for ray casting: bounds, hierarchies, the
 * three roots (0 the model, 1 the '#' subtrees drawn over it, 2 the '%'
 * subtrees drawn see-through), read-only from then on. */
typedef struct rayscad_scene rayscad_scene;

enum { RAYSCAD_ROOT_MODEL = 0, RAYSCAD_ROOT_HIGHLIGHT = 1, RAYSCAD_ROOT_BACKGROUND = 2 };

/* Commit m's trees (taken: m keeps its view and settings, not its trees).
 * RAYSCAD_OK and *out (rayscad_scene_free), or an error with a message. */
rayscad_status rayscad_scene_new(rayscad_model *m, rayscad_scene **out, char *err, size_t errlen);
void rayscad_scene_free(rayscad_scene *s);
/* The least deviation from the true surface that OpenSCAD's facets would
 * give one of the model's round primitives (spheres, cylinders and discs
 * kept round, revolves): r·(1 − cos(180°/n)) for n fragments at its
 * $fn/$fa/$fs and radius r in world units.  0 when the model has none.  A
 * mesh simplified to it (rayscad_mesh_options.tolerance) is as close to
 * the model as OpenSCAD's own would be. */
double rayscad_scene_facet_deviation(const rayscad_scene *s);

/* The bounds of root r, padded outward by a relative 1e-9 (so that no
 * rounding of a ray's test ever clips the solid): 0, or -1 when the root is
 * empty.  Components may be infinite (an unbounded intersection). */
int rayscad_scene_bounds(const rayscad_scene *s, int r, double lo[3], double hi[3]);

/* The view as OpenSCAD's command line states it. */
typedef enum rayscad_camera_kind {
    RAYSCAD_CAMERA_DEFAULT, /* no --camera: rotation 55,0,25, viewall + autocenter */
    RAYSCAD_CAMERA_GIMBAL,  /* --camera=tx,ty,tz,rx,ry,rz,dist */
    RAYSCAD_CAMERA_EYE      /* --camera=ex,ey,ez,cx,cy,cz */
} rayscad_camera_kind;

typedef struct rayscad_view {
    rayscad_camera_kind kind;
    double v[7];    /* the --camera numbers */
    int viewall;    /* --viewall */
    int autocenter; /* --autocenter */
    int ortho;      /* --projection=o */
    /* With kind DEFAULT, the file's own $vp* (rayscad_model_file_view),
     * as OpenSCAD 2021.01's Camera::updateView takes them. */
    rayscad_file_view file;
} rayscad_view;

/* A resolved pinhole or orthographic camera in world space. */
typedef struct rayscad_camera {
    double eye[3];            /* position (perspective) / reference point (ortho) */
    double forward[3];        /* unit view direction */
    double up[3];             /* unit, orthogonal to forward */
    double right[3];          /* unit, forward × up */
    double fovy_deg;          /* vertical field of view, perspective */
    double ortho_half_height; /* half the visible height, orthographic */
    int ortho;                /* 1: orthographic projection */
    /* The depth range OpenSCAD's projection keeps, along forward from eye:
     * perspective [0.1·dist, 100·dist], orthographic [-100·dist,
     * 100·dist].  Both 0: no clipping. */
    double clip_near, clip_far;
} rayscad_camera;

/* The camera OpenSCAD 2021.01 would show s with for view v in an image of
 * width × height pixels: its 22.5° field of view, and for viewall and
 * autocenter its framing of the bounds of all three roots (as OpenSCAD
 * frames the '#' and '%' subtrees too), so images line up pixel for pixel.
 * RAYSCAD_OK, or RAYSCAD_ERROR_ARGUMENT for a view with no camera: eye and
 * centre coincide, or (kind DEFAULT) the file's $vp* give a distance that
 * is zero, negative or not finite. */
rayscad_status rayscad_camera_frame(const rayscad_scene *s, const rayscad_view *v, int width,
                                    int height, rayscad_camera *out, char *err, size_t errlen);

/* ---- images ----------------------------------------------------------------------- */

/* An OpenSCAD colour scheme, sRGB in [0, 1]. */
typedef struct rayscad_colors {
    float background[3];
    float face[3];                /* objects with no color() */
    float back[3];                /* subtracted surfaces with no color() */
    float highlight[4];           /* '#' subtrees: OpenSCAD's transparent pink */
    float background_modifier[4]; /* '%' subtrees: transparent grey */
    float axes[3];                /* --view=axes and scales */
    float crosshair[3];           /* --view=crosshairs */
} rayscad_colors;

/* Scheme name ("Cornfield", "Metallic", "Sunset", "Starnight",
 * "BeforeDawn", "Nature", "DeepOcean", "Solarized", "Tomorrow", "Tomorrow
 * Night", "Monotone") into *out: RAYSCAD_OK, or RAYSCAD_ERROR_ARGUMENT. */
rayscad_status rayscad_colors_by_name(const char *name, rayscad_colors *out);
/* The name of scheme i, in OpenSCAD's order from 0; NULL past the last. */
const char *rayscad_colors_name(int i);

/* A point light, or with radius > 0 a spherical area light whose shadow
 * rays are spread, stratified, over the disc it shows each shaded point. */
typedef struct rayscad_light {
    double pos[3];    /* world position */
    double radius;    /* >= 0, world units */
    double intensity; /* > 0; 1 gives a face squarely toward it 0.2 + 1 */
} rayscad_light;

enum { RAYSCAD_MAX_LIGHTS = 16 };

typedef struct rayscad_render_options {
    int width, height;
    int samples; /* samples per pixel is samples², stratified; >= 1 */
    int threads; /* worker threads; <= 0: all cores */
    /* Spans one interval list may hold while a ray is traced; <= 0: 2^20. */
    int max_intervals;
    rayscad_colors colors;
    /* Called from the calling thread with the fraction done; may be NULL. */
    void (*progress)(void *ud, double done);
    void *ud;
    /* May be NULL: asked by the worker threads before each tile; when it
     * returns nonzero the render stops with RAYSCAD_CANCELLED (the image
     * then half drawn).  It must be safe to call from any thread. */
    int (*cancelled)(void *cancel_ud);
    void *cancel_ud;

    /* ---- opt-in light model ---------------------------------------------
     * Every field below left 0 (and no $rs_ material in the scene) gives
     * OpenSCAD's preview look, byte for byte. */
    int shadows;                              /* 1: shadow rays; with no lights, from
                                                 the preview's own key light */
    rayscad_light lights[RAYSCAD_MAX_LIGHTS]; /* replace the preview's lights */
    int nlights;
    int light_samples; /* area lights: n×n shadow rays per light; 0: 4 */
    int bounces;       /* depth limit of mirror and refraction rays; 0: 4
                          (path tracing: 8) */
    double ior;        /* > 1: transparent solids without $rs_ior refract with
                          this index */
    double aperture;   /* thin-lens diameter, world units; 0: pinhole */
    double focus;      /* focal distance from the eye; 0: to the centre of the
                          model's bounds */
    double xray;       /* in (0, 1]: every surface at most this opaque */
    double absorb;     /* > 0: a transparent solid's alpha is the opacity of
                          this thickness, Beer–Lambert over its spans */
    unsigned seed;     /* the jitter's seed; pixels derive their own streams */
    /* 0: the picture as always.  k > 0: pass k of a progressive series
     * whose mean converges to the exact pixels: every sample moves within
     * its stratum to the k-th point of the R2 sequence (the light model and
     * the path tracer: their random numbers come from stream k), so the
     * mean of passes 0..K samples each pixel ever more finely. */
    int pass;
    /* 1: the path tracer leaves pixels brighter than white above 1 (the
     * sRGB curve continued), so that the mean of passes in linear light is
     * the light's; 0: clamped to 1, for an image to show or save. */
    int unclamped;
    int path_trace; /* > 0: path-trace with this many samples per pixel
                       (interreflection, next-event estimation, Fresnel
                       glass); samples is then unused */

    /* A section view: the model cut by the plane ax + by + cz = d given
     * as {a, b, c, d}, the side where ax + by + cz > d taken away; the cut
     * faces in the colour of the solid they cut, lit with the plane's
     * normal.  {0, 0, 0, *}: none.  Every ray sees the cut model: shadows,
     * mirrors, refraction and the path tracer as well as the primary rays. */
    double section[4];
    /* What openscad's --view draws over the image (RAYSCAD_VIEW_*): crease
     * and silhouette lines, the axes (with scale ticks and numbers when
     * SCALES is set too), crosshairs at the view centre.  0: none. */
    int view;
} rayscad_render_options;

enum {
    RAYSCAD_VIEW_AXES = 1,
    RAYSCAD_VIEW_SCALES = 2, /* drawn only with AXES, as openscad does */
    RAYSCAD_VIEW_CROSSHAIRS = 4,
    RAYSCAD_VIEW_EDGES = 8
};

/* Fill o with the defaults: 512 × 512, one sample, all cores, Cornfield,
 * the preview's light. */
void rayscad_render_options_default(rayscad_render_options *o);

/* Render the roots of s through cam into rgba: width·height·4 floats,
 * row-major from the top row, sRGB-encoded, alpha 1 where the background
 * shows.  Identical for any thread count.  RAYSCAD_OK, or an error with a
 * message (RAYSCAD_ERROR_INTERVALS: a ray needed more than max_intervals);
 * nothing is promised about rgba after a failure. */
rayscad_status rayscad_render(const rayscad_scene *s, const rayscad_camera *cam,
                              const rayscad_render_options *o, float *rgba, char *err,
                              size_t errlen);

/* The roots of s as POV-Ray 3.7 SDL: the same solids as analytic POV
 * primitives and CSG, the camera, the preview's lights and the colour
 * scheme's background.  RAYSCAD_OK and *text (NUL-terminated, *len bytes;
 * the caller frees it with free()), or an error with a message. */
rayscad_status rayscad_pov_export(const rayscad_scene *s, const rayscad_camera *cam,
                                  const rayscad_render_options *o, char **text, size_t *len,
                                  char *err, size_t errlen);

/* 1 when the extension of path names an image format rayscad_image_write
 * writes (png, jpg, jpeg, tif, tiff, exr, and whatever else OpenImageIO
 * knows). */
int rayscad_image_format_supported(const char *path);

/* Write width × height pixels of `channels` (3 or 4) floats, sRGB-encoded
 * in [0, 1], straight alpha, through OpenImageIO: 8 bits for PNG, JPEG,
 * TIFF, half floats (linear) for EXR.  Written to a temporary file beside
 * path and renamed, so a failure never leaves half a file and never
 * touches an existing one. */
rayscad_status rayscad_image_write(const char *path, int width, int height, int channels,
                                   const float *pixels, char *err, size_t errlen);

/* Read an image as sRGB-encoded floats (its own channels, 1–4); *pixels is
 * the caller's (free()). */
rayscad_status rayscad_image_read(const char *path, int *width, int *height, int *channels,
                                  float **pixels, char *err, size_t errlen);

/* Load the image adapter (OpenImageIO, about 260 shared libraries, loaded
 * on the first image call otherwise) now: for a caller that must choose
 * the moment, such as before it lowers its memory limit.  The adapter is
 * found beside the library or the program (the build tree), or in
 * ../lib/rayscad/ from it (an installation). */
rayscad_status rayscad_image_load(char *err, size_t errlen);

/* ---- meshes and measurement -------------------------------------------------------- */

typedef struct rayscad_mesh_options {
    /* Grid spacing in model units; <= 0: the longest side of the root's
     * bounds / cells_per_side.  Parts of the model far apart (operands of
     * its top-level unions whose grids would not meet) are sampled each on
     * a grid of its own, the default spacing following each part's size. */
    double h;
    int cells_per_side; /* used when h <= 0; <= 0 means 128 */
    int threads;        /* <= 0: all cores */
    int root;           /* which root (RAYSCAD_ROOT_MODEL) */
    /* Dihedral angle in degrees above which normals count as a sharp
     * feature; <= 0 means 30. */
    double feature_angle_deg;
    /* The most cells the grid may have, nx·ny·nz; <= 0 means 2^32. */
    long long max_cells;
    int max_intervals; /* <= 0: 2^20 */
    /* With h <= 0: when walls or gaps thinner than a few cells hold more
     * than a thousandth of a part's volume, sample it again on a grid up
     * to 16 times finer (a whole factor, within max_cells and about 2^20
     * crossings), so thin parts keep their shape.  1 by default. */
    int resolve_thin;
    /* > 0: the contoured mesh is simplified (rayscad_sampling_mesh) to
     * within about this distance, model units, of the exact surface: flat
     * faces become a few large triangles spanning their corners, curved
     * ones as few as the distance allows (approximated from both sides),
     * sharp edges and corners stay where they are (measured: within about
     * 1.3 times the distance).  <= 0: the contour as it is. */
    double tolerance;
    /* > 0: a contour of more triangles than this is left as it is whatever
     * `tolerance` says (simplifying takes about 2 µs a triangle, more than
     * the contouring), but see the next.  0: no limit. */
    long long simplify_max_triangles;
    /* > 0: a contour past simplify_max_triangles but of no more than this
     * is simplified all the same where fewer than one vertex in a hundred
     * is a corner, three sharp edges (20°) or more meeting there: plane and
     * smooth faces, text, thin walls, which come down to thousands of
     * triangles.  A surface of facets finer than the grid (a heightmap),
     * with such a corner at every few vertices, is left as it is: it
     * simplifies little, at many times the cost.  0: none. */
    long long simplify_max_triangles_smooth;
    /* 0 (default): where the mesh is simplified (tolerance > 0), a part of
     * the model that is one polyhedral primitive alone — a hull, a box, an
     * OpenSCAD-faceted sphere or cylinder, a polyhedron, a prism of
     * polygons, with no other operand of the top-level unions near it — is
     * written as its own faces, exactly (the hull's triangles, a box's
     * twelve), and a part whose every primitive is plane-faced as the exact
     * boundary of its booleans; their walls, however thin, are not reported
     * (rayscad_sampling_thin).  1: they are contoured and simplified like
     * the rest.  Set both before rayscad_sampling_new. */
    int contour_all;
    /* May be NULL: told, on the calling thread, how far a phase has come
     * ("sampling": each grid's rays, again for a refined one; "contouring"),
     * done in [0, 1]. */
    void (*progress)(void *ud, const char *phase, double done);
    void *progress_ud;
} rayscad_mesh_options;

void rayscad_mesh_options_default(rayscad_mesh_options *o);

/* A root's solid sampled by three families of axis-aligned rays on a grid
 * (tri-dexels): every grid edge lies on a ray, so each crossing of the
 * surface and its normal are exact. */
typedef struct rayscad_sampling rayscad_sampling;

/* Cast the rays.  s is borrowed until the sampling is freed: meshing it
 * asks the scene for exact points on sharp edges.  RAYSCAD_OK and *out
 * (rayscad_sampling_free), or an error with a message:
 * RAYSCAD_ERROR_CELLS (checked before anything is cast or allocated),
 * RAYSCAD_ERROR_INTERVALS, RAYSCAD_ERROR (an unbounded root, a grid over
 * 65536 cells a side, out of memory). */
rayscad_status rayscad_sampling_new(const rayscad_scene *s, const rayscad_mesh_options *o,
                                    rayscad_sampling **out, char *err, size_t errlen);
void rayscad_sampling_free(rayscad_sampling *d);
/* The grid used: spacing h, the world position of node (0,0,0), cells per
 * axis (n = {0,0,0} when empty).  Where far-apart parts have grids of their
 * own: the largest spacing, and the first grid's origin and cells. */
void rayscad_sampling_grid(const rayscad_sampling *d, double *h, double origin[3], int n[3]);

typedef struct rayscad_measurement {
    double volume;       /* ∫ dV, exact along every ray, a midpoint rule across */
    double area;         /* from the crossings (a Crofton-type estimator) */
    double centroid[3];  /* centre of mass; 0 when the volume is 0 */
    double lo[3], hi[3]; /* bounds of the sampled surface; lo > hi when empty */
    long long crossings; /* ray–surface crossings used */
} rayscad_measurement;

void rayscad_sampling_measure(const rayscad_sampling *d, rayscad_measurement *out);

/* The exact measurement of a scene, without a grid (src/mesh/exact.c):
 * volume, centre of mass and surface area integrated from rays, exact to
 * rounding for a model of plane faces and within about `tolerance` of the
 * bounding sphere's volume and area for a curved one, converging as the
 * tolerance falls; the bounds of the surface from rays along the axes
 * (a plane-faced model's to rounding, its extremes being corners; a
 * curved one's within about 1e-7 of the span: 6e-8 at the rim of a turned
 * cylinder).  crossings is the number of
 * rays cast. */
#define RAYSCAD_MEASURE_TOLERANCE 1e-6
typedef struct rayscad_measure_options {
    int root;           /* which root (RAYSCAD_ROOT_MODEL) */
    double tolerance;   /* relative; <= 0: RAYSCAD_MEASURE_TOLERANCE */
    long long max_rays; /* past it: RAYSCAD_ERROR_RAYS; <= 0: no limit (a ray of n
                         * intervals counts 1 + n / 4: many cost more) */
    int max_intervals;  /* a ray's interval list past it: RAYSCAD_ERROR_INTERVALS; 0: the default */
    /* May be NULL: asked from the measuring threads every few thousand
     * rays; when it returns nonzero the measurement stops with
     * RAYSCAD_CANCELLED.  It must be safe to call from any thread. */
    int (*cancelled)(void *cancel_ud);
    void *cancel_ud;
} rayscad_measure_options;
void rayscad_measure_options_default(rayscad_measure_options *o);
/* RAYSCAD_OK, RAYSCAD_ERROR_RAYS, RAYSCAD_ERROR_INTERVALS, RAYSCAD_CANCELLED
 * or RAYSCAD_ERROR (an unbounded model, out of memory), with a message in
 * err. */
rayscad_status rayscad_scene_measure(const rayscad_scene *s, const rayscad_measure_options *o,
                                     rayscad_measurement *out, char *err, size_t errlen);

/* Walls (of solid) and gaps (of empty space) thinner than a thickness,
 * found along the rays: parallel opposite faces a contour of that spacing
 * may lose or hole. */
typedef struct rayscad_thin {
    long long walls, gaps;        /* chords through solid / empty space */
    double min_wall, min_gap;     /* the thinnest of each (INFINITY: none) */
    double wall_at[3], gap_at[3]; /* the world midpoint of each */
    double wall_h, gap_h;         /* the spacing of the grid each was found on */
    double volume;                /* the chords' lengths × h², summed: solid and space at stake */
} rayscad_thin;

/* thickness <= 0: each grid's own spacing. */
void rayscad_sampling_thin(const rayscad_sampling *d, double thickness, rayscad_thin *out);

/* An indexed triangle mesh: 3 floats a vertex, 3 indices a triangle,
 * counter-clockwise seen from outside. */
typedef struct rayscad_mesh rayscad_mesh;

/* Contour a sampling (o may be NULL; only feature_angle_deg is read): a
 * closed, 2-manifold, outward mesh without zero-area triangles, each
 * vertex within its grid cell.  RAYSCAD_OK and *out (rayscad_mesh_free). */
rayscad_status rayscad_sampling_mesh(const rayscad_sampling *d, const rayscad_mesh_options *o,
                                     rayscad_mesh **out, char *err, size_t errlen);
void rayscad_mesh_free(rayscad_mesh *m);
int rayscad_mesh_vertex_count(const rayscad_mesh *m);
int rayscad_mesh_triangle_count(const rayscad_mesh *m);
const float *rayscad_mesh_vertices(const rayscad_mesh *m);    /* borrowed from m */
const int32_t *rayscad_mesh_triangles(const rayscad_mesh *m); /* borrowed from m */
double rayscad_mesh_volume(const rayscad_mesh *m);            /* signed: positive when outward */
/* The distance m was simplified to (rayscad_mesh_options.tolerance); 0
 * when it is the contour as it is. */
double rayscad_mesh_tolerance(const rayscad_mesh *m);
/* The colours of the model's color() calls that the surface shows; 0 when
 * the model gives none.  rayscad_mesh_colors: 4 floats a colour (sRGB and
 * alpha in [0, 1]); rayscad_mesh_triangle_colors: per triangle, k for
 * colour k - 1, or 0 where the surface had no color().  Each triangle
 * takes the colour of the primitive whose surface it lies on (a subtracted
 * primitive's on the faces it cuts), so colours meet along sharp edges.
 * Both borrowed from m; NULL without colours. */
int rayscad_mesh_color_count(const rayscad_mesh *m);
const float *rayscad_mesh_colors(const rayscad_mesh *m);
const uint16_t *rayscad_mesh_triangle_colors(const rayscad_mesh *m);

/* 1 when the extension of path (any case) is a mesh format: stl, off,
 * obj, ply, amf, 3mf. */
int rayscad_mesh_format_supported(const char *path);

enum {
    RAYSCAD_WRITE_ASCII = 1,    /* STL and PLY as text */
    RAYSCAD_WRITE_NO_COLORS = 2 /* leave the mesh's colours out */
};

/* Write m in the format of path's extension: STL and PLY binary unless
 * flags has RAYSCAD_WRITE_ASCII, OFF and OBJ text (OpenMesh); AMF as
 * openscad 2021.01 writes it; 3MF through lib3mf (one object, one build
 * item, millimetres).  A mesh with colours (rayscad_mesh_color_count) has
 * them written where the format holds them, unless flags has
 * RAYSCAD_WRITE_NO_COLORS: 3MF a colour per triangle (the materials
 * extension's colour group), PLY a red, green, blue and alpha per face,
 * OBJ a material per colour in a material file beside it (path's name with
 * .mtl, written first, named in the OBJ by its file name).  Surfaces of no
 * color() get openscad's default colour for a rendered object (#f9d72c).
 * The file goes to a temporary name beside path, renamed into place. */
rayscad_status rayscad_mesh_write(const rayscad_mesh *m, const char *path, int flags, char *err,
                                  size_t errlen);

/* ---- 2D models: regions and their export ------------------------------------------ */

/* The polygon set of a model loaded with for_2d, borrowed from m: path i
 * is the points (x, y pairs, model units) [path_start[i], path_start[i +
 * 1]) of *points, path_start holding *path_count + 1 entries.  The set is
 * normalised as Clipper (OpenSCAD's polygon library) leaves it: paths do
 * not cross or overlap, outlines run counter-clockwise and holes
 * clockwise, so even-odd and nonzero filling agree; circles are
 * OpenSCAD's polygons, points on its 1/65536 grid.  As in openscad, a
 * lone square() or circle() (whatever transforms or one-child operations
 * hold it) is its outline as made, off the grid.  RAYSCAD_OK (at least
 * one path), or RAYSCAD_ERROR_ARGUMENT when m was not loaded for_2d. */
rayscad_status rayscad_model_region(const rayscad_model *m, const double **points,
                                    const int **path_start, int *path_count);

/* 1 when the extension of path (any case) is a 2D format
 * rayscad_region_write writes: svg, dxf, pdf. */
int rayscad_region_format_supported(const char *path);

/* Write the polygon set of m (loaded with for_2d) in the format of path's
 * extension, laid out as openscad 2021.01 lays out its 2D exports: SVG
 * (one <path>, viewBox from the bounds rounded outwards, y down) and DXF
 * (each edge a LINE on layer 0), numbers with six significant digits; PDF
 * (through cairo) one A4 page, 1 mm to 2.8346 points, the model's origin
 * 30 points in from the bottom-left corner when its bounds (rounded to
 * whole units) are not negative, else at the page's centre, the outlines
 * stroked black and unfilled, with openscad's rulers and scale note; a
 * model larger than the page is cut off by it (see
 * rayscad_region_fits_pdf_page).  The file goes to a temporary name
 * beside path, renamed into place: a failure leaves no partial file and an
 * existing one untouched.
 * RAYSCAD_OK, RAYSCAD_ERROR_ARGUMENT (an unknown extension, m not loaded
 * for_2d) or RAYSCAD_ERROR, with a message in err. */
rayscad_status rayscad_region_write(const rayscad_model *m, const char *path, char *err,
                                    size_t errlen);

/* 0 when m's region reaches past the PDF page rayscad_region_write draws,
 * by openscad 2021.01's test (which then warns "Geometry is too large to
 * fit into A4 size."; it skips each path's first point), else 1; also 1
 * when m holds no region. */
int rayscad_region_fits_pdf_page(const rayscad_model *m);

/* ---- files ------------------------------------------------------------------------ */

/* Write len bytes to path through a temporary file beside it, renamed into
 * place: a failure leaves no partial file and an existing one untouched. */
rayscad_status rayscad_file_write(const char *path, const void *data, size_t len, char *err,
                                  size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
