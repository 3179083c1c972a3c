/*
 * main.c — the rayscad command: parse the flags, evaluate the .scad file into
 * CSG trees, commit them to a scene, and write what -o asks for (the
 * output's kind comes from its extension; each kind has one branch in
 * main's dispatch).  Only main and the writers it calls print, and main
 * chooses the exit codes: 0 ok, 1 the model or the output failed (a limit
 * hit included), 2 usage.
 *
 * Memory: main caps the process's data (RLIMIT_DATA) at --max-memory before
 * anything is evaluated, so a model that asks for too much sees its
 * allocations fail — each library then stops with an "out of memory" error,
 * which the command prints with the limit named — instead of the machine
 * swapping or the kernel killing it.  The data limit rather than the
 * address-space one (RLIMIT_AS): Linux's data count (VmData) is the heap,
 * the thread stacks and the libraries' writable data — memory that can be
 * written to — while the address space also holds the code of every
 * library (the image adapter maps about 370 MB of them) and glibc's 64 MiB
 * reservations per thread arena, none of it the model's doing, which would
 * leave a small limit unable to write a PNG.  Thread stacks do count: the
 * evaluator's thread reserves 1 GiB (scad.c); under a smaller limit it
 * cannot be made, and the evaluator runs on the main thread's stack, where
 * deep recursion stops sooner with its named error.  AddressSanitizer
 * reserves terabytes of shadow memory, so a sanitizer build leaves the
 * limit off.
 */
#include "atomic_file.h"
#include "mesh_output.h"
#include "options.h"
#include "progress.h"
#include "services.h"
#include "settings.h"

#include "../io/io.h"
#include "../render/render.h"
#include "../scad/scad.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#if defined(__SANITIZE_ADDRESS__)
#define UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UNDER_ASAN 1
#endif
#endif

#define RAYSCAD_VERSION "0.1.0"

enum { EXIT_MODEL = 1, EXIT_USAGE = 2 };

/* Messages from the evaluator: kept for an .echo output, else printed. */
typedef struct messages {
    int to_buffer;
    char *buf;
    size_t len, cap;
    const cli_options *o;
} messages;

static void on_message(void *ud, scad_msg_kind kind, const char *line)
{
    messages *m = ud;
    if (kind == SCAD_MSG_TRACE && !m->to_buffer) return; /* the ERROR line said it */
    if (!m->to_buffer || kind == SCAD_MSG_ERROR || kind == SCAD_MSG_NOTE) {
        /* An error (file:line:col: error: …) that was an allocation
         * failing gets the memory limit's note here; the .echo keeps
         * OpenSCAD's wording. */
        char note[96];
        fprintf(stderr, "%s%s\n", line,
                kind == SCAD_MSG_ERROR ? cli_memory_note(m->o, line, note, sizeof note) : "");
        return;
    }
    size_t n = strlen(line);
    if (m->len + n + 2 > m->cap) {
        size_t cap = m->cap ? m->cap * 2 : 4096;
        while (cap < m->len + n + 2) cap *= 2;
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

static int write_image(const cli_options *o, csg_scene *scene)
{
    render_colors colors;
    if (render_colors_by_name(o->colorscheme, &colors) != 0) {
        fprintf(stderr, "rayscad: error: unknown colour scheme '%s'\n", o->colorscheme);
        return EXIT_USAGE;
    }
    /* OpenSCAD frames the highlight and background subtrees too. */
    double lo[3], hi[3];
    int have_bounds = 0;
    for (int r = 0; r < csg_scene_root_count(scene); r++) {
        double l[3], h[3];
        if (csg_scene_view_bounds(scene, r, l, h) != 0) continue;
        for (int k = 0; k < 3; k++) {
            lo[k] = have_bounds && lo[k] < l[k] ? lo[k] : l[k];
            hi[k] = have_bounds && hi[k] > h[k] ? hi[k] : h[k];
        }
        have_bounds = 1;
    }
    render_camera cam;
    if (render_camera_resolve(&o->view, lo, hi, have_bounds, o->width, o->height, &cam) != 0) {
        if (o->view.kind == RENDER_CAMERA_DEFAULT) { /* the file's $vp* made it */
            fprintf(stderr, "rayscad: error: the file's $vpr/$vpt/$vpd/$vpf give no usable "
                            "camera (a distance that is zero, negative or not finite)\n");
            return EXIT_MODEL;
        }
        fprintf(stderr, "rayscad: error: the camera's eye and centre coincide\n");
        return EXIT_USAGE;
    }
    render_options ro = {
        .width = o->width,
        .height = o->height,
        .samples = o->samples,
        .threads = o->threads,
        .max_intervals = o->max_intervals,
        .colors = colors,
    };
    cli_options_apply_optics(o, &ro);
    if (has_extension(o->output, ".pov")) { /* the same scene and camera for POV-Ray */
        char *text, err[512];
        size_t len;
        int rc = render_pov_export(scene, &cam, &ro, &text, &len, err, sizeof err);
        if (rc == 0) {
            rc = atomic_file_write(o->output, text, len, err, sizeof err);
            free(text);
        }
        if (rc != 0) cli_print_error(o, err);
        return rc != 0 ? EXIT_MODEL : 0;
    }
    /* Before anything large is allocated, and only once the model has
     * evaluated (a failing one exits without the load). */
    cli_load_image_adapter();
    progress bar;
    progress_start(&bar, "rendering");
    ro.progress = progress_update;
    ro.ud = &bar;

    float *rgba = malloc((size_t)o->width * (size_t)o->height * 4 * sizeof *rgba);
    char err[512];
    if (!rgba) {
        snprintf(err, sizeof err, "out of memory for a %dx%d image", o->width, o->height);
        cli_print_error(o, err);
        return EXIT_MODEL;
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    int rc = render_image(scene, &cam, &ro, rgba, err, sizeof err);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    progress_finish(&bar);
    if (rc == 0 && getenv("RAYSCAD_STATS")) { /* render-only time, for bench/run.py */
        double sec = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
        double rays = (double)o->width * o->height * o->samples * o->samples;
        fprintf(stderr, "rayscad: stats: %.0f rays in %.6f s, %.0f rays/s\n", rays, sec,
                sec > 0 ? rays / sec : 0);
    }
    if (rc == RENDER_ERR_INTERVALS) {
        fprintf(stderr, "rayscad: error: %s (--max-intervals)\n", err);
        free(rgba);
        return EXIT_MODEL;
    }
    if (rc == 0) rc = io_image_write(o->output, o->width, o->height, 4, rgba, err, sizeof err);
    free(rgba);
    if (rc != 0) {
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

/* Cap the process's data memory at o->max_memory (its default when the
 * flag was not given), or keep a lower limit the caller already set;
 * records which in o->max_memory_enforced.  The top of this file says why
 * RLIMIT_DATA. */
static void apply_memory_limit(cli_options *o)
{
    if (!o->max_memory_given) o->max_memory = cli_default_max_memory(o);
#ifdef UNDER_ASAN
    if (o->max_memory_given)
        fprintf(stderr, "rayscad: warning: --max-memory is not enforced in an AddressSanitizer "
                        "build (its shadow memory would count)\n");
    return;
#else
    struct rlimit rl;
    if (getrlimit(RLIMIT_DATA, &rl) != 0) return;
    if (rl.rlim_cur != RLIM_INFINITY && rl.rlim_cur < o->max_memory) {
        o->max_memory = rl.rlim_cur;
        o->max_memory_enforced = 2;
        return;
    }
    rlim_t want = (rlim_t)o->max_memory;
    if (rl.rlim_max != RLIM_INFINITY && want > rl.rlim_max) want = rl.rlim_max;
    rl.rlim_cur = want;
    if (setrlimit(RLIMIT_DATA, &rl) != 0) return;
    o->max_memory = want;
    o->max_memory_enforced = 1;
#endif
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
    if (has_extension(path, ".pov") || io_image_format_supported(path)) return OUTPUT_IMAGE;
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
        printf("rayscad %s\n", RAYSCAD_VERSION);
        return 0;
    }
    output_kind kind = output_kind_of(o.output);
    if (kind == OUTPUT_UNKNOWN) {
        fprintf(stderr, "rayscad: cannot tell the output format from '%s' "
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
    apply_memory_limit(&o);
    int echo_out = kind == OUTPUT_ECHO, csg_out = kind == OUTPUT_CSG;

    messages msgs = {.to_buffer = echo_out, .o = &o};
    scad_options so = {
        .defines = o.defines,
        .define_count = o.define_count,
        .facets = o.facets,
        .max_recursion = o.max_recursion,
        .max_steps = o.max_steps,
        .max_list = o.max_list,
        .max_string = o.max_string,
        .services = cli_services(),
        .message = on_message,
        .ud = &msgs,
    };
    if (csg_out || echo_out) {
        /* OpenSCAD's evaluated tree, no geometry: as openscad, the .echo
         * holds what the evaluation says (what came before an error and
         * the error itself; the exit status still says the model failed),
         * and the .csg the tree, its messages on stderr. */
        char *text;
        size_t len;
        int failed = scad_dump_csg_file(o.input, &so, &text, &len) != 0;
        int rc = 0;
        if (echo_out)
            rc = atomic_file_write(o.output, msgs.buf ? msgs.buf : "", msgs.len, err, sizeof err);
        else if (!failed)
            rc = atomic_file_write(o.output, text, len, err, sizeof err);
        if (!failed) free(text);
        free(msgs.buf);
        if (rc != 0) {
            cli_print_error(&o, err);
            return EXIT_MODEL;
        }
        return failed ? EXIT_MODEL : 0;
    }
    scad_result res;
    int failed = scad_eval_file(o.input, &so, &res) != 0;
    if (failed) {
        free(msgs.buf);
        return EXIT_MODEL;
    }

    cli_settings_apply(&o, &res, stderr); /* the file's $rs_ scene settings */
    if (o.view.kind == RENDER_CAMERA_DEFAULT) { /* the file's $vp* camera */
        o.view.file_vp_set = res.vp_set;
        o.view.file_vp_auto_off = res.vp_auto_off;
        memcpy(o.view.vpr, res.vpr, sizeof o.view.vpr);
        memcpy(o.view.vpt, res.vpt, sizeof o.view.vpt);
        o.view.vpd = res.vpd;
        o.view.vpf = res.vpf;
    }
    csg_node *roots[3] = {res.model, res.highlight, res.background};
    res.model = res.highlight = res.background = NULL;
    scad_result_free(&res);
    csg_scene *scene = csg_scene_new(roots, 3, err, sizeof err);
    if (!scene) {
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
    csg_scene_free(scene);
    return rc;
}
