/*
 * main.c — the rayscad command: parse the flags, evaluate the .scad file
 * into a model, commit it to a scene, and write every -o (outputs.c says
 * which format each one is).  A thin user of include/rayscad.h: only main
 * and the writers it calls print, and main chooses the exit codes: 0 ok, 1
 * the model or an output failed (a limit hit included), 2 usage.
 *
 * Evaluations: as openscad 2021.01, $preview is true for images (unless
 * --render), .echo and .csg, and false for meshes and --measure, so a run
 * evaluates the file at most once for each: the tree outputs (.echo, .csg,
 * .ast, .term: one evaluation without geometry; .ast and .term are
 * printed from a parse of their own), the preview model (images) and the
 * rendered model (meshes, --measure, --render images).  Messages reach
 * stderr (or the .echo) from the first of them only.  --animate N does all
 * of it N times with $t = i/N, each output named as openscad names frames.
 *
 * Memory: main caps the process's data (memory.c) at --max-memory before
 * anything is evaluated, so a model that asks for too much sees its
 * allocations fail — each part of the library then stops with an "out of
 * memory" error, which the command prints with the limit named — instead
 * of the machine swapping or the kernel killing it.
 */
#include "deps.h"
#include "info.h"
#include "memory.h"
#include "mesh_output.h"
#include "options.h"
#include "outputs.h"
#include "params.h"
#include "progress.h"
#include "viewer.h"
#include "settings.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { EXIT_MODEL = 1, EXIT_USAGE = 2 };

/* Messages from the evaluator: kept for an .echo output, else printed
 * (only errors with -q, and only errors once an earlier evaluation of the
 * same frame has said the rest). */
typedef struct messages {
    int to_buffer, errors_only;
    int drop; /* a second parse's: everything was said by the first */
    char *buf;
    size_t len, cap;
    const cli_options *o;
    progress bar;          /* the evaluation's (eval_options starts it) */
    char first_error[512]; /* the viewer's title shows it */
} messages;

static void on_message(void *ud, rayscad_message_kind kind, const char *line)
{
    messages *m = ud;
    if (m->drop) return;
    if (kind == RAYSCAD_MSG_TRACE && !m->to_buffer) return; /* the ERROR line said it */
    int error = kind == RAYSCAD_MSG_ERROR || kind == RAYSCAD_MSG_NOTE;
    if (kind == RAYSCAD_MSG_ERROR && !m->first_error[0])
        snprintf(m->first_error, sizeof m->first_error, "%s", line);
    if (!m->to_buffer || error) {
        if (!error && (m->errors_only || m->o->quiet)) return;
        /* An error (file:line:col: error: …) that was an allocation
         * failing gets the memory limit's note here; the .echo keeps
         * OpenSCAD's wording. */
        char note[96];
        progress_break(&m->bar);
        fprintf(stderr, "%s%s\n", line,
                kind == RAYSCAD_MSG_ERROR ? cli_memory_note(m->o, line, note, sizeof note) : "");
        return;
    }
    size_t n = strlen(line);
    if (m->len + n + 2 > m->cap) {
        size_t cap = m->cap ? m->cap * 2 : 4096;
        while (cap < m->len + n + 2)
            cap *= 2;
        char *b = realloc(m->buf, cap);
        if (!b) return; /* the write step reports the shortfall */
        m->buf = b;
        m->cap = cap;
    }
    memcpy(m->buf + m->len, line, n);
    m->len += n;
    m->buf[m->len++] = '\n';
}

/* -p/-P: the parameter set's values as more -D overrides, asked for by
 * the library once the file is parsed (rayscad_eval_options.parameters). */
typedef struct param_hook {
    const cli_options *o;
    messages *msgs;
    const rayscad_parameter_query *q;
    char **assign; /* the overrides made, freed after the load */
    int n;
} param_hook;

static cli_param_type param_default_type(void *ud, int i)
{
    const param_hook *h = ud;
    return (cli_param_type)h->q->default_type(h->q->ctx, i); /* the same order */
}

static void param_message(void *ud, const char *line)
{
    const param_hook *h = ud;
    on_message(h->msgs, RAYSCAD_MSG_WARNING, line);
}

static int apply_param_set(void *ud, const rayscad_parameter_query *q,
                           const char *const **overrides, int *count)
{
    param_hook *h = ud;
    h->q = q;
    cli_param_file f = {q->count, q->names, param_default_type, param_message, h};
    char msg[1024], line[1100];
    int rc =
        cli_params_load(h->o->param_file, h->o->param_set, &f, &h->assign, &h->n, msg, sizeof msg);
    if (rc == CLI_PARAMS_FATAL) {
        if (!h->msgs->drop) fprintf(stderr, "rayscad: error: %s\n", msg);
        return -1;
    }
    if (rc == CLI_PARAMS_ERROR) { /* openscad's words, and it goes on */
        snprintf(line, sizeof line, "ERROR: %s", msg);
        on_message(h->msgs, RAYSCAD_MSG_WARNING, line);
    }
    *overrides = (const char *const *)h->assign;
    *count = h->n;
    return 0;
}

/* One run's outputs: what each is, and its name in the current frame. */
typedef struct run {
    cli_options *o;
    const char *src; /* the model from stdin ("-"), else NULL */
    cli_output out[CLI_MAX_OUTPUTS];
    const char *path[CLI_MAX_OUTPUTS];
    char frame_path[CLI_MAX_OUTPUTS][4096];
    int n;
    const char *defines[CLI_MAX_DEFINES + 1]; /* o's, then $t when animating */
    int define_count;
    int said; /* an evaluation of this frame has shown its messages */
} run;

static double seconds_since(const struct timespec *t0)
{
    struct timespec t1;
    clock_gettime(CLOCK_MONOTONIC, &t1);
    return (double)(t1.tv_sec - t0->tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0->tv_nsec);
}

static void debug_time(const cli_options *o, const char *what, const struct timespec *t0)
{
    if (o->debug) fprintf(stderr, "rayscad: debug: %s in %.3f s\n", what, seconds_since(t0));
}

typedef struct bytes {
    const char *data;
    size_t len;
} bytes;

static int write_bytes_to(void *ctx, const char *path, char *err, size_t errlen)
{
    const bytes *b = ctx;
    return rayscad_file_write(path, b->data, b->len, err, errlen) == RAYSCAD_OK ? 0 : -1;
}

/* Write bytes to output i; 0 or EXIT_MODEL (printed). */
static int write_bytes(run *r, int i, const char *data, size_t len)
{
    char err[512];
    bytes b = {data, len};
    if (cli_output_write(&r->out[i], r->path[i], write_bytes_to, &b, err, sizeof err) == 0)
        return 0;
    cli_print_error(r->o, err);
    return EXIT_MODEL;
}

/* Load the model (from the standard input's text when there is one). */
static rayscad_status load_model(const run *r, const rayscad_eval_options *eo,
                                 rayscad_model **model)
{
    return r->src ? rayscad_model_load_string("<stdin>", r->src, eo, model)
                  : rayscad_model_load(r->o->input, eo, model);
}

static void eval_options(run *r, messages *msgs, const rayscad_services *services, int for_mesh,
                         param_hook *params, rayscad_eval_options *eo)
{
    const cli_options *o = r->o;
    *params = (param_hook){.o = o, .msgs = msgs};
    progress_start_after(&msgs->bar, o->quiet ? NULL : "evaluating", 1.0);
    *eo = (rayscad_eval_options){
        .progress = progress_update,
        .progress_ud = &msgs->bar,
        .defines = r->defines,
        .define_count = r->define_count,
        .message = on_message,
        .message_ud = msgs,
        .max_recursion = o->max_recursion,
        .max_steps = o->max_steps,
        .max_list = o->max_list,
        .max_string = o->max_string,
        .facets = o->facets,
        /* openscad renders for a mesh: $preview is false, 2D objects
         * beside 3D ones are left out */
        .for_mesh = for_mesh,
        .services = services,
        .hard_warnings = o->hardwarnings,
        .no_parameter_check = !o->check_parameters,
        .range_check = o->check_parameter_ranges,
        .parameters = o->param_file && o->param_set ? apply_param_set : NULL,
        .parameters_ud = params,
    };
}

static int has_kind(const run *r, output_kind k)
{
    for (int i = 0; i < r->n; i++)
        if (r->out[i].kind == k) return 1;
    return 0;
}

/* .echo and .csg: OpenSCAD's evaluated tree, no geometry — one evaluation
 * for all of them.  As openscad, an .echo holds what the evaluation says
 * (what came before an error and the error itself; the exit status still
 * says the model failed), and a .csg the tree.  .ast and .term come from
 * a parse of their own (its messages dropped: the evaluation said them),
 * written whenever the file parses, as openscad writes them after most
 * errors; openscad evaluates the file for them too, so they share the
 * evaluation and its messages. */
static int write_trees(run *r, const rayscad_services *services)
{
    int echo = has_kind(r, OUTPUT_ECHO), csg = has_kind(r, OUTPUT_CSG);
    int ast = has_kind(r, OUTPUT_AST), term = has_kind(r, OUTPUT_TERM);
    if (!echo && !csg && !ast && !term) return 0;
    messages msgs = {.to_buffer = echo, .errors_only = r->said, .o = r->o};
    rayscad_eval_options eo;
    param_hook params;
    eval_options(r, &msgs, services, 0, &params, &eo);
    char *text = NULL;
    size_t len = 0;
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int failed =
        (r->src ? rayscad_csg_text_string("<stdin>", r->src, &eo, csg ? &text : NULL, &len)
                : rayscad_csg_text(r->o->input, &eo, csg ? &text : NULL, &len)) != RAYSCAD_OK;
    progress_finish(&msgs.bar);
    debug_time(r->o, "evaluated for .echo/.csg", &t0);
    cli_params_free(params.assign, params.n);
    char *parsed[2] = {NULL, NULL}; /* the .ast and .term texts */
    size_t parsed_len[2] = {0, 0};
    for (int k = 0; k < 2; k++) {
        if (!(k ? term : ast)) continue;
        messages quiet = {.drop = 1, .o = r->o};
        eval_options(r, &quiet, services, 0, &params, &eo);
        /* openscad sets an animation's $t in the evaluation, not as a -D
         * line of the parse */
        eo.define_count = r->o->define_count;
        rayscad_status st =
            k ? (r->src
                     ? rayscad_term_text_string("<stdin>", r->src, &eo, &parsed[k], &parsed_len[k])
                     : rayscad_term_text(r->o->input, &eo, &parsed[k], &parsed_len[k]))
              : (r->src
                     ? rayscad_ast_text_string("<stdin>", r->src, &eo, &parsed[k], &parsed_len[k])
                     : rayscad_ast_text(r->o->input, &eo, &parsed[k], &parsed_len[k]));
        cli_params_free(params.assign, params.n);
        if (st != RAYSCAD_OK) failed = 1;
    }
    r->said = 1;
    int rc = 0;
    for (int i = 0; i < r->n && !rc; i++) {
        output_kind k = r->out[i].kind;
        if (k == OUTPUT_ECHO)
            rc = write_bytes(r, i, msgs.buf ? msgs.buf : "", msgs.len);
        else if (k == OUTPUT_CSG && !failed)
            rc = write_bytes(r, i, text, len);
        else if ((k == OUTPUT_AST || k == OUTPUT_TERM) && parsed[k == OUTPUT_TERM])
            rc = write_bytes(r, i, parsed[k == OUTPUT_TERM], parsed_len[k == OUTPUT_TERM]);
    }
    free(text);
    free(parsed[0]);
    free(parsed[1]);
    free(msgs.buf);
    return rc ? rc : failed ? EXIT_MODEL : 0;
}

typedef struct image {
    int width, height;
    const float *rgba;
} image;

static int write_image_to(void *ctx, const char *path, char *err, size_t errlen)
{
    const image *m = ctx;
    return rayscad_image_write(path, m->width, m->height, 4, m->rgba, err, errlen) == RAYSCAD_OK
               ? 0
               : -1;
}

/* An image or a .pov of scene as output i. */
static int write_image(run *r, int i, const cli_options *o, const rayscad_scene *scene)
{
    char err[512];
    rayscad_render_options ro = o->optics;              /* the light model; the rest is set here */
    rayscad_colors_by_name(o->colorscheme, &ro.colors); /* checked in main */
    rayscad_camera cam;
    if (rayscad_camera_frame(scene, &o->view, o->width, o->height, &cam, err, sizeof err) !=
        RAYSCAD_OK) {
        fprintf(stderr, "rayscad: error: %s\n", err);
        /* the file's $vp* made the view: the model's fault, not the flags' */
        return o->view.kind == RAYSCAD_CAMERA_DEFAULT ? EXIT_MODEL : EXIT_USAGE;
    }
    ro.width = o->width;
    ro.height = o->height;
    ro.samples = o->samples;
    ro.threads = o->threads;
    ro.max_intervals = o->max_intervals;
    ro.view = o->view_flags & ~CLI_VIEW_WIREFRAME;
    if (r->out[i].kind == OUTPUT_POV) { /* the same scene and camera for POV-Ray */
        char *text;
        size_t len;
        rayscad_status rc = rayscad_pov_export(scene, &cam, &ro, &text, &len, err, sizeof err);
        if (rc != RAYSCAD_OK) {
            cli_print_error(o, err);
            return EXIT_MODEL;
        }
        int wrc = write_bytes(r, i, text, len);
        free(text);
        return wrc;
    }
    /* Before anything large is allocated, and only once the model has
     * evaluated (a failing one exits without the load). */
    cli_load_image_adapter();
    progress bar;
    progress_start(&bar, o->quiet ? NULL : "rendering");
    ro.progress = progress_update;
    ro.ud = &bar;

    float *rgba = malloc((size_t)o->width * (size_t)o->height * 4 * sizeof *rgba);
    if (!rgba) {
        snprintf(err, sizeof err, "out of memory for a %dx%d image", o->width, o->height);
        cli_print_error(o, err);
        return EXIT_MODEL;
    }
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    rayscad_status rc = rayscad_render(scene, &cam, &ro, rgba, err, sizeof err);
    double sec = seconds_since(&t0);
    progress_finish(&bar);
    if (rc == RAYSCAD_OK && getenv("RAYSCAD_STATS")) { /* render-only time, for bench/run.py */
        double rays = (double)o->width * o->height * o->samples * o->samples;
        fprintf(stderr, "rayscad: stats: %.0f rays in %.6f s, %.0f rays/s\n", rays, sec,
                sec > 0 ? rays / sec : 0);
    }
    debug_time(o, "rendered", &t0);
    if (rc == RAYSCAD_ERROR_INTERVALS) {
        fprintf(stderr, "rayscad: error: %s (--max-intervals)\n", err);
        free(rgba);
        return EXIT_MODEL;
    }
    if (rc == RAYSCAD_OK) {
        image img = {o->width, o->height, rgba};
        if (cli_output_write(&r->out[i], r->path[i], write_image_to, &img, err, sizeof err) != 0)
            rc = RAYSCAD_ERROR;
    }
    free(rgba);
    if (rc != RAYSCAD_OK) {
        cli_print_error(o, err);
        return EXIT_MODEL;
    }
    return 0;
}

/* Evaluate the model in one mode (for_mesh: as openscad renders) and write
 * the outputs that mode serves. */
static int write_model_outputs(run *r, const rayscad_services *services, int for_mesh)
{
    int images = 0, meshes = 0;
    for (int i = 0; i < r->n; i++) {
        output_kind k = r->out[i].kind;
        images += (k == OUTPUT_IMAGE || k == OUTPUT_POV) && r->o->render == for_mesh;
        meshes += k == OUTPUT_MESH && for_mesh;
    }
    int measure = for_mesh && r->o->measure;
    if (!images && !meshes && !measure) return 0;
    cli_options fo = *r->o; /* this evaluation's: the file's settings and view join it */
    messages msgs = {.errors_only = r->said, .o = &fo};
    rayscad_eval_options eo;
    param_hook params;
    eval_options(r, &msgs, services, for_mesh, &params, &eo);
    rayscad_model *model;
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    rayscad_status loaded = load_model(r, &eo, &model);
    progress_finish(&msgs.bar);
    debug_time(&fo, for_mesh ? "evaluated as rendered" : "evaluated for preview", &t0);
    cli_params_free(params.assign, params.n);
    r->said = 1;
    if (loaded != RAYSCAD_OK) return EXIT_MODEL;

    cli_settings_apply(&fo, model, fo.quiet ? NULL : stderr); /* the file's $rs_ settings */
    if (fo.view.kind == RAYSCAD_CAMERA_DEFAULT)               /* the file's $vp* camera */
        rayscad_model_file_view(model, &fo.view.file);
    rayscad_scene *scene;
    char err[512];
    clock_gettime(CLOCK_MONOTONIC, &t0);
    rayscad_status made = rayscad_scene_new(model, &scene, err, sizeof err);
    rayscad_model_free(model);
    debug_time(&fo, "scene built", &t0);
    if (made != RAYSCAD_OK) {
        cli_print_error(&fo, err);
        return EXIT_MODEL;
    }
    int rc = 0;
    for (int i = 0; i < r->n && !rc; i++)
        if ((r->out[i].kind == OUTPUT_IMAGE || r->out[i].kind == OUTPUT_POV) &&
            r->o->render == for_mesh)
            rc = write_image(r, i, &fo, scene);
    if (!rc && (meshes || measure)) {
        cli_output mesh_out[CLI_MAX_OUTPUTS];
        const char *mesh_path[CLI_MAX_OUTPUTS];
        int n = 0;
        for (int i = 0; i < r->n; i++)
            if (r->out[i].kind == OUTPUT_MESH) {
                mesh_out[n] = r->out[i];
                mesh_path[n++] = r->path[i];
            }
        clock_gettime(CLOCK_MONOTONIC, &t0);
        rc = cli_mesh_output(&fo, scene, mesh_out, mesh_path, n);
        debug_time(&fo, "meshed and measured", &t0);
    }
    rayscad_scene_free(scene);
    return rc;
}

static int write_region_to(void *ctx, const char *path, char *err, size_t errlen)
{
    return rayscad_region_write(ctx, path, err, errlen) == RAYSCAD_OK ? 0 : -1;
}

/* Evaluate as openscad's 2D export and write every SVG, DXF and PDF
 * output.  A model loaded for_2d holds one polygon set and no trees.  A
 * PDF of a model past its A4 page gets openscad's warning (not an error:
 * openscad writes the page, cut off, and exits 0, --hardwarnings or not). */
static int write_2d_outputs(run *r, const rayscad_services *services)
{
    if (!has_kind(r, OUTPUT_2D)) return 0;
    cli_options fo = *r->o;
    messages msgs = {.errors_only = r->said, .o = &fo};
    rayscad_eval_options eo;
    param_hook params;
    eval_options(r, &msgs, services, 1, &params, &eo);
    eo.for_2d = 1;
    rayscad_model *model;
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    rayscad_status loaded = load_model(r, &eo, &model);
    progress_finish(&msgs.bar);
    debug_time(&fo, "evaluated as a 2D export", &t0);
    cli_params_free(params.assign, params.n);
    r->said = 1;
    if (loaded != RAYSCAD_OK) return EXIT_MODEL; /* "… is not a 2D object." said it */
    char err[512];
    int rc = 0;
    for (int i = 0; i < r->n && !rc; i++) {
        if (r->out[i].kind != OUTPUT_2D) continue;
        if (cli_output_write(&r->out[i], r->path[i], write_region_to, model, err, sizeof err) !=
            0) {
            cli_print_error(&fo, err);
            rc = EXIT_MODEL;
        } else if (!strcmp(r->out[i].ext, "pdf") && !fo.quiet &&
                   !rayscad_region_fits_pdf_page(model)) {
            fprintf(stderr, "EXPORT-WARNING: Geometry is too large to fit into A4 size.\n");
        }
    }
    rayscad_model_free(model);
    return rc;
}

/* Every output of one frame (frame < 0: not animating). */
static int run_frame(run *r, int frame, int frames, const rayscad_services *services)
{
    char t[64];
    r->define_count = r->o->define_count;
    if (frame >= 0) {
        snprintf(t, sizeof t, "$t=%.17g", (double)frame / frames);
        r->defines[r->define_count++] = t;
    }
    for (int i = 0; i < r->n; i++)
        r->path[i] = frame < 0 ? r->o->outputs[i]
                               : cli_output_frame_path(r->o->outputs[i], frame, r->frame_path[i],
                                                       sizeof r->frame_path[i]);
    r->said = 0;
    int rc = write_trees(r, services);
    if (!rc) rc = write_model_outputs(r, services, 0);
    if (!rc) rc = write_model_outputs(r, services, 1);
    if (!rc) rc = write_2d_outputs(r, services);
    return rc;
}

/* Refuse an image the limits do not allow, before the model is evaluated:
 * its buffer (16 bytes a pixel) and the writer's copy grow with the pixels,
 * and nothing in the renderer grows with the samples per pixel.  Returns 0,
 * or EXIT_MODEL after the message. */
static int check_image_size(const cli_options *o)
{
    long long pixels = (long long)o->width * o->height;
    long long max = o->max_pixels > 0 ? o->max_pixels : CLI_MAX_PIXELS_DEFAULT;
    if (pixels > max) {
        fprintf(stderr, "rayscad: error: image %dx%d is %lld pixels, more than --max-pixels %lld\n",
                o->width, o->height, pixels, max);
        return EXIT_MODEL;
    }
    if (o->width > CLI_MAX_IMAGE_SIDE || o->height > CLI_MAX_IMAGE_SIDE) {
        fprintf(stderr,
                "rayscad: error: image %dx%d: a side may have at most %d pixels, whatever "
                "--max-pixels allows\n",
                o->width, o->height, CLI_MAX_IMAGE_SIDE);
        return EXIT_MODEL;
    }
    return 0;
}

/* Flags that only some outputs use: a message when o asks for one that no
 * output would use, else NULL. */
static const char *misplaced_flag(const cli_options *o, const run *r)
{
    int mesh = has_kind(r, OUTPUT_MESH);
    if (!mesh && o->ascii) return "--ascii applies to mesh outputs";
    if (!mesh && o->mesh_tolerance >= 0)
        return "--mesh-tolerance (--decimate) applies to mesh outputs";
    if (!mesh && !o->measure && o->mesh_size > 0)
        return "--mesh-size applies to mesh outputs and --measure";
    if (!o->measure && o->measure_tolerance > 0) return "--measure-tolerance applies to --measure";
    return NULL;
}

/* What the run cannot honour, said before it starts (not with -q). */
static void say_limits(const cli_options *o, const run *r)
{
    if (o->quiet) return;
    if (o->deprecated_flags & 1)
        fprintf(stderr, "DEPRECATED: The -s option is deprecated. Use -o instead.\n");
    if (o->deprecated_flags & 2)
        fprintf(stderr, "DEPRECATED: The -x option is deprecated. Use -o instead.\n");
    int images = has_kind(r, OUTPUT_IMAGE);
    if (images && o->throwntogether)
        fprintf(stderr, "rayscad: warning: --preview=throwntogether is drawn as the normal "
                        "preview (exact CSG, subtracted faces in their own colour)\n");
    if (images && (o->view_flags & CLI_VIEW_WIREFRAME))
        fprintf(stderr, "rayscad: note: --view=wireframe changes no image (openscad draws a "
                        "wireframe only in its window's CGAL view)\n");
    if (images && (o->view_flags & RAYSCAD_VIEW_SCALES) && !(o->view_flags & RAYSCAD_VIEW_AXES))
        fprintf(stderr, "rayscad: note: --view=scales draws ticks on the axes only, so with "
                        "axes (as openscad)\n");
    if (images && (o->view_flags & RAYSCAD_VIEW_CROSSHAIRS))
        fprintf(stderr, "rayscad: note: --view=crosshairs drawn; openscad 2021.01 draws them "
                        "in its window only, not in images\n");
}

/* The whole of the standard input, NUL-terminated; NULL (printed) when
 * it cannot be read. */
static char *read_stdin(void)
{
    size_t len = 0, cap = 1 << 16;
    char *buf = malloc(cap);
    for (size_t got; buf; len += got) {
        if (cap - len < 2) {
            char *b = realloc(buf, cap *= 2);
            if (!b) break;
            buf = b;
        }
        got = fread(buf + len, 1, cap - len - 1, stdin);
        if (got == 0) {
            if (ferror(stdin)) break;
            buf[len] = '\0';
            return buf;
        }
    }
    free(buf);
    fprintf(stderr, "rayscad: error: cannot read the model from the standard input\n");
    return NULL;
}

/* The viewer's evaluation (viewer.h): a preview for its view, messages
 * printed, every file read listed. */
static rayscad_status viewer_load(void *ud, const double vpr[3], const double vpt[3], double vpd,
                                  rayscad_scene **scene, rayscad_file_view *file, char ***files,
                                  int *n, char *err, size_t errlen)
{
    run *r = ud;
    rayscad_services services = {.read_image = cli_read_image};
    cli_deps deps = {.input = r->o->input};
    cli_deps_hook(&deps, &services);
    messages msgs = {.o = r->o};
    rayscad_eval_options eo;
    param_hook params;
    eval_options(r, &msgs, &services, 0, &params, &eo);
    eo.view_set = 1;
    memcpy(eo.vpr, vpr, sizeof eo.vpr);
    memcpy(eo.vpt, vpt, sizeof eo.vpt);
    eo.vpd = vpd;
    rayscad_model *model;
    rayscad_status st = load_model(r, &eo, &model);
    progress_finish(&msgs.bar);
    cli_params_free(params.assign, params.n);
    if (st == RAYSCAD_OK) {
        rayscad_model_file_view(model, file);
        st = rayscad_scene_new(model, scene, err, errlen);
        rayscad_model_free(model);
    } else {
        snprintf(err, errlen, "%s", msgs.first_error);
    }
    /* the main file is read before the hooks see reads */
    char **paths = realloc(deps.paths, (size_t)(deps.n + 1) * sizeof *paths);
    if (paths) {
        deps.paths = paths;
        if ((paths[deps.n] = strdup(r->o->input))) deps.n++;
    }
    *files = deps.paths; /* taken */
    *n = deps.n;
    deps.paths = NULL;
    deps.n = 0;
    cli_deps_free(&deps);
    return st;
}

int main(int argc, char **argv)
{
    cli_options o;
    char err[512];
    if (cli_options_parse(argc, argv, &o, err, sizeof err) != 0) {
        fprintf(stderr, "rayscad: %s\n(rayscad --help lists the options)\n", err);
        return EXIT_USAGE;
    }
    if (o.help) {
        fputs(cli_usage, stdout);
        fputs(cli_usage_light, stdout);
        fputs(cli_usage_openscad, stdout);
        return 0;
    }
    if (o.version) {
        printf("rayscad %s\n", rayscad_version());
        return 0;
    }
    if (o.info) return cli_print_info(stdout) == 0 ? 0 : EXIT_MODEL;
    static run r;
    r.o = &o;
    r.n = o.output_count;
    for (int i = 0; i < r.n; i++)
        if (cli_output_resolve(o.outputs[i], o.export_format, o.ascii, &r.out[i], err,
                               sizeof err) != 0) {
            fprintf(stderr, "rayscad: %s\n", err);
            return EXIT_MODEL; /* as openscad */
        }
    const char *misplaced = misplaced_flag(&o, &r);
    if (misplaced) {
        fprintf(stderr, "rayscad: %s\n(rayscad --help lists the options)\n", misplaced);
        return EXIT_USAGE;
    }
    if (has_kind(&r, OUTPUT_IMAGE) || has_kind(&r, OUTPUT_POV)) {
        rayscad_colors colors;
        if (rayscad_colors_by_name(o.colorscheme, &colors) != RAYSCAD_OK) {
            fprintf(stderr, "rayscad: error: unknown colour scheme '%s'; the schemes are:\n",
                    o.colorscheme);
            for (int k = 0; rayscad_colors_name(k); k++)
                fprintf(stderr, "%s\n", rayscad_colors_name(k));
            return EXIT_USAGE;
        }
    }
    if (has_kind(&r, OUTPUT_IMAGE) && check_image_size(&o) != 0) return EXIT_MODEL;
    say_limits(&o, &r);
    cli_apply_memory_limit(&o);
    for (int i = 0; i < o.define_count; i++)
        r.defines[i] = o.defines[i];
    char *src = NULL;
    if (!strcmp(o.input, "-") && !(src = read_stdin())) return EXIT_MODEL;
    r.src = src;

    if (o.viewer) return cli_viewer_run(&o, viewer_load, &r);
    rayscad_services services = {.read_image = cli_read_image};
    cli_deps deps = {.input = o.input, .make_cmd = o.make_cmd};
    if (o.deps_file || o.make_cmd) cli_deps_hook(&deps, &services);
    int rc = 0;
    if (!o.animate) rc = run_frame(&r, -1, 1, &services);
    for (int f = 0; f < o.animate && !rc; f++)
        rc = run_frame(&r, f, o.animate, &services);
    if (!rc && o.deps_file &&
        cli_deps_write(&deps, o.deps_file, o.outputs, o.output_count, err, sizeof err) != 0) {
        cli_print_error(&o, err);
        rc = EXIT_MODEL;
    }
    cli_deps_free(&deps);
    free(src);
    return rc;
}
