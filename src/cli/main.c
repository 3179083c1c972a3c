/*
 * main.c — the rayscad command: parse the flags, evaluate the .scad file
 * into a model, commit it to a scene, and write what -o asks for (the
 * output's kind comes from its extension; each kind has one branch in
 * main's dispatch).  A thin user of include/rayscad.h: only main and the
 * writers it calls print, and main chooses the exit codes: 0 ok, 1 the
 * model or the output failed (a limit hit included), 2 usage.
 *
 * Memory: main caps the process's data (memory.c) at --max-memory before
 * anything is evaluated, so a model that asks for too much sees its
 * allocations fail — each part of the library then stops with an "out of
 * memory" error, which the command prints with the limit named — instead
 * of the machine swapping or the kernel killing it.
 */
#include "memory.h"
#include "mesh_output.h"
#include "options.h"
#include "progress.h"
#include "settings.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { EXIT_MODEL = 1, EXIT_USAGE = 2 };

/* Messages from the evaluator: kept for an .echo output, else printed. */
typedef struct messages {
    int to_buffer;
    char *buf;
    size_t len, cap;
    const cli_options *o;
} messages;

static void on_message(void *ud, rayscad_message_kind kind, const char *line)
{
    messages *m = ud;
    if (kind == RAYSCAD_MSG_TRACE && !m->to_buffer) return; /* the ERROR line said it */
    if (!m->to_buffer || kind == RAYSCAD_MSG_ERROR || kind == RAYSCAD_MSG_NOTE) {
        /* An error (file:line:col: error: …) that was an allocation
         * failing gets the memory limit's note here; the .echo keeps
         * OpenSCAD's wording. */
        char note[96];
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

static int has_extension(const char *path, const char *ext)
{
    size_t n = strlen(path), e = strlen(ext);
    if (n < e) return 0;
    for (size_t i = 0; i < e; i++) {
        char c = path[n - e + i];
        if (c >= 'A' && c <= 'Z') c = (char)(c - 'A' + 'a');
        if (c != ext[i]) return 0;
    }
    return 1;
}

static int write_image(const cli_options *o, const rayscad_scene *scene)
{
    char err[512];
    rayscad_render_options ro = o->optics; /* the light model; the rest is set here */
    if (rayscad_colors_by_name(o->colorscheme, &ro.colors) != RAYSCAD_OK) {
        fprintf(stderr, "rayscad: error: unknown colour scheme '%s'\n", o->colorscheme);
        return EXIT_USAGE;
    }
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
    if (has_extension(o->output, ".pov")) { /* the same scene and camera for POV-Ray */
        char *text;
        size_t len;
        rayscad_status rc = rayscad_pov_export(scene, &cam, &ro, &text, &len, err, sizeof err);
        if (rc == RAYSCAD_OK) {
            rc = rayscad_file_write(o->output, text, len, err, sizeof err);
            free(text);
        }
        if (rc != RAYSCAD_OK) cli_print_error(o, err);
        return rc != RAYSCAD_OK ? EXIT_MODEL : 0;
    }
    /* Before anything large is allocated, and only once the model has
     * evaluated (a failing one exits without the load). */
    cli_load_image_adapter();
    progress bar;
    progress_start(&bar, "rendering");
    ro.progress = progress_update;
    ro.ud = &bar;

    float *rgba = malloc((size_t)o->width * (size_t)o->height * 4 * sizeof *rgba);
    if (!rgba) {
        snprintf(err, sizeof err, "out of memory for a %dx%d image", o->width, o->height);
        cli_print_error(o, err);
        return EXIT_MODEL;
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    rayscad_status rc = rayscad_render(scene, &cam, &ro, rgba, err, sizeof err);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    progress_finish(&bar);
    if (rc == RAYSCAD_OK && getenv("RAYSCAD_STATS")) { /* render-only time, for bench/run.py */
        double sec = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
        double rays = (double)o->width * o->height * o->samples * o->samples;
        fprintf(stderr, "rayscad: stats: %.0f rays in %.6f s, %.0f rays/s\n", rays, sec,
                sec > 0 ? rays / sec : 0);
    }
    if (rc == RAYSCAD_ERROR_INTERVALS) {
        fprintf(stderr, "rayscad: error: %s (--max-intervals)\n", err);
        free(rgba);
        return EXIT_MODEL;
    }
    if (rc == RAYSCAD_OK)
        rc = rayscad_image_write(o->output, o->width, o->height, 4, rgba, err, sizeof err);
    free(rgba);
    if (rc != RAYSCAD_OK) {
        cli_print_error(o, err);
        return EXIT_MODEL;
    }
    return 0;
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

/* What -o writes, by its extension. */
typedef enum output_kind {
    OUTPUT_NONE, /* no -o (--measure alone) */
    OUTPUT_UNKNOWN,
    OUTPUT_IMAGE, /* also .pov: the scene and camera for POV-Ray */
    OUTPUT_MESH,
    OUTPUT_ECHO,
    OUTPUT_CSG,
} output_kind;

static output_kind output_kind_of(const char *path)
{
    if (!path) return OUTPUT_NONE;
    if (has_extension(path, ".echo")) return OUTPUT_ECHO;
    if (has_extension(path, ".csg")) return OUTPUT_CSG;
    if (cli_mesh_output_is_mesh(path)) return OUTPUT_MESH;
    if (has_extension(path, ".pov") || rayscad_image_format_supported(path)) return OUTPUT_IMAGE;
    return OUTPUT_UNKNOWN;
}

/* Flags that only some outputs use: a message when o asks for one that
 * `kind` would ignore, else NULL. */
static const char *misplaced_flag(const cli_options *o, output_kind kind)
{
    if (kind != OUTPUT_MESH && o->ascii) return "--ascii applies to mesh outputs";
    if (kind != OUTPUT_MESH && o->decimate >= 0) return "--decimate applies to mesh outputs";
    if (kind != OUTPUT_MESH && !o->measure && o->mesh_size > 0)
        return "--mesh-size applies to mesh outputs and --measure";
    if (o->measure && (kind == OUTPUT_ECHO || kind == OUTPUT_CSG))
        return "--measure cannot go with .echo or .csg output";
    return NULL;
}

/* .echo and .csg: OpenSCAD's evaluated tree, no geometry.  As openscad,
 * the .echo holds what the evaluation says (what came before an error and
 * the error itself; the exit status still says the model failed), and the
 * .csg the tree, its messages on stderr. */
static int write_tree(const cli_options *o, const rayscad_eval_options *eo, messages *msgs,
                      int echo)
{
    char err[512], *text = NULL;
    size_t len;
    int failed = rayscad_csg_text(o->input, eo, echo ? NULL : &text, &len) != RAYSCAD_OK;
    rayscad_status rc = RAYSCAD_OK;
    if (echo)
        rc = rayscad_file_write(o->output, msgs->buf ? msgs->buf : "", msgs->len, err, sizeof err);
    else if (!failed)
        rc = rayscad_file_write(o->output, text, len, err, sizeof err);
    free(text);
    if (rc != RAYSCAD_OK) {
        cli_print_error(o, err);
        return EXIT_MODEL;
    }
    return failed ? EXIT_MODEL : 0;
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
        return 0;
    }
    if (o.version) {
        printf("rayscad %s\n", rayscad_version());
        return 0;
    }
    output_kind kind = output_kind_of(o.output);
    if (kind == OUTPUT_UNKNOWN) {
        fprintf(stderr,
                "rayscad: cannot tell the output format from '%s' "
                "(use .png .jpg .tif .exr .stl .off .obj .ply .echo or .csg)\n",
                o.output);
        return EXIT_USAGE;
    }
    const char *misplaced = misplaced_flag(&o, kind);
    if (misplaced) {
        fprintf(stderr, "rayscad: %s\n(rayscad --help lists the options)\n", misplaced);
        return EXIT_USAGE;
    }
    if (kind == OUTPUT_IMAGE && !has_extension(o.output, ".pov") && check_image_size(&o) != 0)
        return EXIT_MODEL;
    cli_apply_memory_limit(&o);

    messages msgs = {.to_buffer = kind == OUTPUT_ECHO, .o = &o};
    const rayscad_services services = {.read_image = cli_read_image};
    rayscad_eval_options eo = {
        .defines = o.defines,
        .define_count = o.define_count,
        .message = on_message,
        .message_ud = &msgs,
        .max_recursion = o.max_recursion,
        .max_steps = o.max_steps,
        .max_list = o.max_list,
        .max_string = o.max_string,
        .facets = o.facets,
        /* openscad -o x.stl renders: $preview is false, 2D objects
         * beside 3D ones are left out */
        .for_mesh = kind == OUTPUT_MESH,
        .services = &services,
    };
    if (kind == OUTPUT_ECHO || kind == OUTPUT_CSG) {
        int rc = write_tree(&o, &eo, &msgs, kind == OUTPUT_ECHO);
        free(msgs.buf);
        return rc;
    }
    rayscad_model *model;
    rayscad_status loaded = rayscad_model_load(o.input, &eo, &model);
    free(msgs.buf);
    if (loaded != RAYSCAD_OK) return EXIT_MODEL;

    cli_settings_apply(&o, model, stderr);     /* the file's $rs_ scene settings */
    if (o.view.kind == RAYSCAD_CAMERA_DEFAULT) /* the file's $vp* camera */
        rayscad_model_file_view(model, &o.view.file);
    rayscad_scene *scene;
    rayscad_status made = rayscad_scene_new(model, &scene, err, sizeof err);
    rayscad_model_free(model);
    if (made != RAYSCAD_OK) {
        cli_print_error(&o, err);
        return EXIT_MODEL;
    }
    int rc = 0;
    switch (kind) {
    case OUTPUT_IMAGE:
        rc = write_image(&o, scene);
        break;
    case OUTPUT_MESH:
        rc = cli_mesh_output(&o, scene, 1);
        break;
    default:
        break;
    }
    if (rc == 0 && o.measure && kind != OUTPUT_MESH) rc = cli_mesh_output(&o, scene, 0);
    rayscad_scene_free(scene);
    return rc;
}
