/*
 * test_api.c — the library through its one public header, as a program
 * that includes nothing else uses it: files served from memory through the
 * services (include and use never touch the disk), the status codes and
 * their messages, the .csg text against OpenSCAD 2021.01's own for the same
 * source, a render whose pixels are the colour scheme's, and volumes
 * measured on the rays against closed forms.
 */
#include <criterion/criterion.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../include/rayscad.h"
#include "scene_of.h"

/* ---- files from memory -------------------------------------------------------- */

typedef struct memfile {
    const char *path, *text;
} memfile;

static const memfile files[] = {
    {"/mem/main.scad", "include <lib/shapes.scad>\nuse <fns.scad>\necho(twice(size));\nbox();\n"},
    {"/mem/lib/shapes.scad", "size = 3;\nmodule box() cube(size);\n"},
    {"/mem/fns.scad", "function twice(x) = 2 * x;\n"},
};

static const memfile *find(const char *path)
{
    for (size_t i = 0; i < sizeof files / sizeof files[0]; i++)
        if (strcmp(files[i].path, path) == 0) return &files[i];
    return NULL;
}

static int reads; /* how often the library asked */

static int mem_read(void *ud, const char *path, size_t max, char **data, size_t *len, char *err,
                    size_t errlen)
{
    (void)ud;
    reads++;
    const memfile *f = find(path);
    if (!f || strlen(f->text) > max) {
        snprintf(err, errlen, "No such file or directory");
        return -1;
    }
    *len = strlen(f->text);
    *data = malloc(*len + 1);
    memcpy(*data, f->text, *len + 1);
    return 0;
}

static int mem_stat(void *ud, const char *path, long long *mtime)
{
    (void)ud;
    if (mtime) *mtime = 0;
    return find(path) != NULL;
}

typedef struct lines {
    char text[8192];
} lines;

static void collect(void *ud, rayscad_message_kind kind, const char *line)
{
    lines *l = ud;
    size_t n = strlen(l->text);
    snprintf(l->text + n, sizeof l->text - n, "%d %s\n", (int)kind, line);
}

/* include and use resolve relative to the including file and are read
 * through the caller's services alone: a model that exists nowhere on disk
 * evaluates, and its scene has the included module's cube. */
Test(api, files_come_through_the_services)
{
    lines m = {""};
    rayscad_services s = {.read_file = mem_read, .stat_file = mem_stat};
    rayscad_eval_options o = {.message = collect, .message_ud = &m, .services = &s};
    rayscad_model *model;
    reads = 0;
    cr_assert_eq(rayscad_model_load("/mem/main.scad", &o, &model), RAYSCAD_OK, "%s", m.text);
    cr_expect_str_eq(m.text, "0 ECHO: 6\n");
    cr_expect_geq(reads, 3);
    rayscad_scene *scene;
    char err[256];
    cr_assert_eq(rayscad_scene_new(model, &scene, err, sizeof err), RAYSCAD_OK, "%s", err);
    rayscad_model_free(model);
    double lo[3], hi[3];
    cr_assert_eq(rayscad_scene_bounds(scene, RAYSCAD_ROOT_MODEL, lo, hi), 0);
    for (int k = 0; k < 3; k++) { /* padded by a relative 1e-9 */
        cr_expect_float_eq(lo[k], 0, 1e-8);
        cr_expect_float_eq(hi[k], 3, 1e-8);
    }
    rayscad_scene_free(scene);
}

/* A file the services do not have is the language's own error, at the
 * include, worded as OpenSCAD's warning. */
Test(api, missing_files_are_reported_not_opened)
{
    lines m = {""};
    rayscad_services s = {.read_file = mem_read, .stat_file = mem_stat};
    rayscad_eval_options o = {.message = collect, .message_ud = &m, .services = &s};
    rayscad_model *model = NULL;
    cr_assert_eq(
        rayscad_model_load_string("/mem/x.scad", "include <nowhere.scad>\ncube(1);", &o, &model),
        RAYSCAD_OK);
    cr_expect_str_eq(m.text, "1 WARNING: Can't open include file 'nowhere.scad'.\n");
    rayscad_model_free(model);
    m.text[0] = 0;
    cr_expect_eq(rayscad_model_load("/mem/none.scad", &o, &model), RAYSCAD_ERROR);
    cr_expect_null(model);
    cr_expect_str_eq(m.text,
                     "2 /mem/none.scad:1:1: error: cannot read file: No such file or directory\n");
}

/* ---- status codes -------------------------------------------------------------- */

Test(api, status_codes_say_what_failed)
{
    lines m = {""};
    rayscad_eval_options o = {.message = collect, .message_ud = &m};
    rayscad_model *model;
    cr_expect_eq(rayscad_model_load_string("t.scad", "cube(;", &o, &model), RAYSCAD_ERROR);
    cr_expect(strstr(m.text, "2 t.scad:1:6: error: syntax error"), "%s", m.text);

    rayscad_colors c;
    cr_expect_eq(rayscad_colors_by_name("Plaid", &c), RAYSCAD_ERROR_ARGUMENT);
    cr_expect_eq(rayscad_colors_by_name("Cornfield", &c), RAYSCAD_OK);

    cr_assert_eq(
        rayscad_model_load_string("t.scad", "difference() { cube(10); sphere(6); }", &o, &model),
        RAYSCAD_OK);
    rayscad_scene *scene;
    cr_assert_eq(rayscad_scene_new(model, &scene, NULL, 0), RAYSCAD_OK);
    rayscad_model_free(model);
    char err[256] = "";
    rayscad_view v = {.kind = RAYSCAD_CAMERA_EYE, .v = {1, 2, 3, 1, 2, 3}};
    rayscad_camera cam;
    cr_expect_eq(rayscad_camera_frame(scene, &v, 64, 48, &cam, err, sizeof err),
                 RAYSCAD_ERROR_ARGUMENT);
    cr_expect_str_eq(err, "the camera's eye and centre coincide");

    rayscad_mesh_options mo;
    rayscad_mesh_options_default(&mo);
    mo.h = 0.01;
    mo.max_cells = 1000;
    rayscad_sampling *d;
    cr_expect_eq(rayscad_sampling_new(scene, &mo, &d, err, sizeof err), RAYSCAD_ERROR_CELLS);

    /* a difference needs the whole list: one interval is too few */
    rayscad_view def = {.kind = RAYSCAD_CAMERA_DEFAULT};
    cr_assert_eq(rayscad_camera_frame(scene, &def, 64, 48, &cam, NULL, 0), RAYSCAD_OK);
    rayscad_render_options ro;
    rayscad_render_options_default(&ro);
    ro.width = 64;
    ro.height = 48;
    ro.max_intervals = 1;
    float *rgba = malloc(64 * 48 * 4 * sizeof *rgba);
    cr_expect_eq(rayscad_render(scene, &cam, &ro, rgba, err, sizeof err), RAYSCAD_ERROR_INTERVALS);
    free(rgba);
    rayscad_scene_free(scene);
    cr_expect_str_eq(rayscad_version(), RAYSCAD_VERSION_STRING);
}

/* ---- the .csg text --------------------------------------------------------------- */

/* OpenSCAD 2021.01's `openscad -o x.csg` of this source, byte for byte
 * (the warnings are those of its .echo, which .csg now gives too). */
Test(api, csg_text_is_openscads)
{
    lines m = {""};
    rayscad_eval_options o = {.message = collect, .message_ud = &m};
    char *text = NULL;
    size_t len = 0;
    cr_assert_eq(rayscad_csg_text_string("t.scad",
                                         "translate([1, 0, 0]) cube([1, 2]);\n"
                                         "linear_extrude(center = true, 5) square(1);\n",
                                         &o, &text, &len),
                 RAYSCAD_OK);
    cr_expect_str_eq(text,
                     "multmatrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]) {\n"
                     "\tcube(size = [1, 1, 1], center = false);\n"
                     "}\n"
                     "linear_extrude(height = 100, center = true, convexity = 1, "
                     "scale = [1, 1], $fn = 0, $fa = 12, $fs = 2) {\n"
                     "\tsquare(size = [1, 1], center = false);\n"
                     "}\n\n");
    cr_expect_eq(len, strlen(text));
    cr_expect_str_eq(m.text, "1 WARNING: Unable to convert cube(size=[1, 2], ...) parameter to a "
                             "number or a vec3 of numbers in file t.scad, line 1\n");
    free(text);
}

/* The .ast and .term of OpenSCAD 2021.01 for this source: the parse
 * printed back, and the empty term it writes for any file that parses. */
Test(api, ast_and_term_texts_are_openscads)
{
    lines m = {""};
    rayscad_eval_options o = {.message = collect, .message_ud = &m};
    const char *src = "size = 3; // [1:10]\n"
                      "module box(s) cube(s);\n"
                      "translate([1, 0, 0]) box(size);\n";
    char *text = NULL;
    size_t len = 0;
    cr_assert_eq(rayscad_ast_text_string("t.scad", src, &o, &text, &len), RAYSCAD_OK);
    cr_expect_str_eq(text, "module box(s) {\n"
                           "\tcube(s);\n"
                           "}\n"
                           "//Parameter([1 : 10])\n"
                           "size = 3;\n"
                           "translate([1, 0, 0]) box(size);\n");
    cr_expect_eq(len, strlen(text));
    free(text);
    cr_assert_eq(rayscad_term_text_string("t.scad", src, &o, &text, &len), RAYSCAD_OK);
    cr_expect_str_eq(text, "No top-level CSG object\n");
    cr_expect_eq(len, strlen(text));
    free(text);
    cr_expect_str_eq(m.text, "");
    cr_expect_eq(rayscad_term_text_string("t.scad", "cube(", &o, &text, &len), RAYSCAD_ERROR);
    cr_expect_null(text);
}

/* ---- rendering and measuring ------------------------------------------------------ */

/* Cornfield's background (#ffffe5) in a corner, and no background at the
 * centre, where the default view looks at the cube. */
Test(api, render_draws_the_model_over_the_scheme)
{
    rayscad_view v = {.kind = RAYSCAD_CAMERA_DEFAULT};
    rayscad_scene *scene = scene_of("cube(10, center = true);", &v.file);
    rayscad_render_options ro;
    rayscad_render_options_default(&ro);
    ro.width = 80;
    ro.height = 60;
    rayscad_camera cam;
    cr_assert_eq(rayscad_camera_frame(scene, &v, ro.width, ro.height, &cam, NULL, 0), RAYSCAD_OK);
    float *px = malloc((size_t)ro.width * ro.height * 4 * sizeof *px);
    cr_assert_eq(rayscad_render(scene, &cam, &ro, px, NULL, 0), RAYSCAD_OK);
    const float bg[3] = {1, 1, 229 / 255.0f};
    for (int k = 0; k < 3; k++)
        cr_expect_float_eq(px[k], bg[k], 1e-6, "corner channel %d", k);
    const float *mid = px + ((size_t)30 * ro.width + 40) * 4;
    cr_expect(fabsf(mid[0] - bg[0]) + fabsf(mid[1] - bg[1]) + fabsf(mid[2] - bg[2]) > 0.1f);
    free(px);
    rayscad_scene_free(scene);
}

/* The cancel hook: asked between tiles, it stops the render after the
 * tiles it allowed; a hook that never asks to stop changes nothing. */
static int stop_after(void *ud)
{
    int *left = ud;
    return __atomic_sub_fetch(left, 1, __ATOMIC_SEQ_CST) < 0;
}

Test(api, render_stops_when_cancelled)
{
    rayscad_view v = {.kind = RAYSCAD_CAMERA_DEFAULT};
    rayscad_scene *scene = scene_of("sphere(10);", NULL);
    rayscad_render_options ro;
    rayscad_render_options_default(&ro);
    ro.width = 256;
    ro.height = 256; /* 64 tiles of 32 × 32 */
    ro.threads = 1;
    rayscad_camera cam;
    cr_assert_eq(rayscad_camera_frame(scene, &v, ro.width, ro.height, &cam, NULL, 0), RAYSCAD_OK);
    size_t n = (size_t)ro.width * ro.height * 4;
    float *plain = malloc(n * sizeof *plain), *hooked = malloc(n * sizeof *hooked);
    cr_assert_eq(rayscad_render(scene, &cam, &ro, plain, NULL, 0), RAYSCAD_OK);
    int left = 1 << 20;
    ro.cancelled = stop_after;
    ro.cancel_ud = &left;
    cr_assert_eq(rayscad_render(scene, &cam, &ro, hooked, NULL, 0), RAYSCAD_OK);
    cr_expect_eq(memcmp(plain, hooked, n * sizeof *plain), 0, "a hook that never stops");
    left = 3;
    for (size_t i = 0; i < n; i++)
        hooked[i] = -1;
    char err[128];
    cr_assert_eq(rayscad_render(scene, &cam, &ro, hooked, err, sizeof err), RAYSCAD_CANCELLED);
    size_t drawn = 0;
    for (size_t i = 0; i < n; i += 4)
        drawn += hooked[i] >= 0;
    cr_expect_eq(drawn, (size_t)3 * 32 * 32, "three tiles drawn, then stopped");
    free(plain);
    free(hooked);
    rayscad_scene_free(scene);
}

/* A hollow box seen from the front (orthographic, 1 unit = 4 pixels) and
 * cut at y = 0: inside |x| < 5 the cavity's far wall shows (a subtracted
 * surface: the scheme's back colour, green); for 5 < |x| < 10 the cut face
 * (the box's own colour, yellow); uncut, the front face (yellow) there. */
Test(api, section_cuts_the_model_open)
{
    rayscad_scene *scene =
        scene_of("difference() { cube(20, center = true); cube(10, center = true); }", NULL);
    rayscad_render_options ro;
    rayscad_render_options_default(&ro);
    ro.width = ro.height = 160;
    rayscad_view v = {.kind = RAYSCAD_CAMERA_GIMBAL, .v = {0, 0, 0, 90, 0, 0, 0}, .ortho = 1};
    v.v[6] = 20 / tan(22.5 / 2 * 3.14159265358979323846 / 180); /* half height 20 */
    rayscad_camera cam;
    cr_assert_eq(rayscad_camera_frame(scene, &v, ro.width, ro.height, &cam, NULL, 0), RAYSCAD_OK);
    float *px = malloc((size_t)ro.width * ro.height * 4 * sizeof *px);
    const float *mid = px + ((size_t)80 * ro.width + 80) * 4;   /* x = 0 */
    const float *wall = px + ((size_t)80 * ro.width + 110) * 4; /* x = 7.5 */
    cr_assert_eq(rayscad_render(scene, &cam, &ro, px, NULL, 0), RAYSCAD_OK);
    cr_expect(mid[0] > mid[2] + 0.3f && mid[0] > 0.5f, "uncut: the yellow front face");
    ro.section[1] = -1; /* -y > 0 taken away: the front half */
    cr_assert_eq(rayscad_render(scene, &cam, &ro, px, NULL, 0), RAYSCAD_OK);
    cr_expect(mid[1] > mid[0] && mid[1] > mid[2],
              "cut: the green far wall of the cavity (%g %g %g)", mid[0], mid[1], mid[2]);
    cr_expect(wall[0] > wall[2] + 0.3f && wall[0] > 0.5f, "cut: the yellow cut face (%g %g %g)",
              wall[0], wall[1], wall[2]);
    free(px);
    rayscad_scene_free(scene);
}

/* Scene src rendered 96×96 from (30°, 0°, 35°), orthographic, with plane
 * cut as section, options as ro gives them; a malloc'd image. */
static float *render_cut(const char *src, rayscad_render_options ro, const double cut[4])
{
    rayscad_scene *scene = scene_of(src, NULL);
    ro.width = ro.height = 96;
    memcpy(ro.section, cut, sizeof ro.section);
    rayscad_view v = {.kind = RAYSCAD_CAMERA_GIMBAL, .v = {0, 0, 4, 30, 0, 35, 90}, .ortho = 1};
    rayscad_camera cam;
    cr_assert_eq(rayscad_camera_frame(scene, &v, ro.width, ro.height, &cam, NULL, 0), RAYSCAD_OK);
    float *px = malloc((size_t)ro.width * ro.height * 4 * sizeof *px);
    char err[256];
    cr_assert_eq(rayscad_render(scene, &cam, &ro, px, err, sizeof err), RAYSCAD_OK, "%s", err);
    rayscad_scene_free(scene);
    return px;
}

/* Pixels of two 96×96 images whose channels differ by more than 2/255. */
static int pixels_apart(const float *a, const float *b)
{
    int n = 0;
    for (int i = 0; i < 96 * 96; i++)
        for (int k = 0; k < 3; k++)
            if (fabsf(a[4 * i + k] - b[4 * i + k]) > 2.0f / 255) {
                n++;
                break;
            }
    return n;
}

/* A part the section takes away wholly is gone for every ray: the picture
 * equals that of the model without it (rendered with no section at all),
 * whose shadows, mirror images and light paths never saw it.  The part
 * here is a roof that shadows the floor and shows in its mirror; left in
 * for the secondary rays, it changes most of the floor's pixels. */
static void cut_equals_removed(rayscad_render_options ro, const char *floor)
{
    char whole[512];
    snprintf(whole, sizeof whole, "%s translate([-14, -14, 9]) cube([28, 28, 2]);", floor);
    const double none[4] = {0, 0, 0, 0}, roof[4] = {0, 0, 1, 6}; /* z > 6 taken away */
    float *cut = render_cut(whole, ro, roof);
    float *removed = render_cut(floor, ro, none);
    float *uncut = render_cut(whole, ro, none);
    int apart = pixels_apart(cut, removed);
    cr_expect(apart <= 96 * 96 / 200, "%d pixels differ from the model without the roof", apart);
    cr_expect(pixels_apart(uncut, removed) > 96 * 96 / 10,
              "the roof, uncut, changes the picture (else the test shows nothing)");
    free(cut);
    free(removed);
    free(uncut);
}

Test(api, section_cuts_shadow_rays)
{
    rayscad_render_options ro;
    rayscad_render_options_default(&ro);
    ro.shadows = 1;
    ro.lights[0] = (rayscad_light){.pos = {5, -8, 60}, .intensity = 1};
    ro.nlights = 1;
    cut_equals_removed(ro, "translate([-20, -20, 0]) cube([40, 40, 1]);");
}

Test(api, section_cuts_mirror_rays)
{
    rayscad_render_options ro;
    rayscad_render_options_default(&ro);
    cut_equals_removed(ro, "translate([-20, -20, 0]) cube([40, 40, 1], $rs_reflect = 0.8);");
}

Test(api, section_cuts_the_path_tracer)
{
    rayscad_render_options ro;
    rayscad_render_options_default(&ro);
    ro.path_trace = 2; /* under the key light: a point light's strength follows
                          the model's bounds, which the roof moves */
    cut_equals_removed(ro, "translate([-20, -20, 0]) cube([40, 40, 1], $rs_reflect = 0.5);");
}

/* Progressive passes converge to the exact pixel: a slab's edge runs down
 * the middle of a pixel column, 0.7 of it covered.  One pass samples the
 * pixel's centre and shows all or nothing; the mean of 64 passes shows
 * 0.7 of the slab's colour over 0.3 of the background, as the area rule
 * says, within 3/64 of the step (the R2 sequence's discrepancy). */
Test(api, passes_converge_to_the_covered_fraction)
{
    rayscad_scene *scene = scene_of("translate([0.3, -15, -1]) cube([30, 30, 1]);", NULL);
    rayscad_render_options ro;
    rayscad_render_options_default(&ro);
    ro.width = ro.height = 20;
    /* seen from above, orthographic, 1 unit a pixel, pixel edges on whole x */
    rayscad_view v = {.kind = RAYSCAD_CAMERA_GIMBAL, .ortho = 1};
    v.v[6] = 10 / tan(22.5 / 2 * 3.14159265358979323846 / 180);
    rayscad_camera cam;
    cr_assert_eq(rayscad_camera_frame(scene, &v, ro.width, ro.height, &cam, NULL, 0), RAYSCAD_OK);
    size_t n = (size_t)ro.width * ro.height * 4;
    float *px = malloc(n * sizeof *px);
    double *mean = calloc(n, sizeof *mean);
    const int passes = 64;
    for (int k = 0; k < passes; k++) {
        ro.pass = k;
        cr_assert_eq(rayscad_render(scene, &cam, &ro, px, NULL, 0), RAYSCAD_OK);
        for (size_t i = 0; i < n; i++)
            mean[i] += px[i] / passes;
    }
    /* the row's middle: slab and background at either end, the edge between */
    const double *row = mean + (size_t)10 * ro.width * 4;
    int slab_left = fabs(row[4 * 19] - ro.colors.background[0]) < 1e-6;
    double bg = row[4 * (slab_left ? 19 : 0)], fg = row[4 * (slab_left ? 0 : 19)];
    cr_assert(fabs(bg - ro.colors.background[0]) < 1e-6, "one end shows the background");
    cr_assert(fabs(fg - bg) > 0.1, "slab %g, background %g", fg, bg);
    int edge = -1;
    for (int x = 0; x < 20; x++)
        if (fabs(row[4 * x] - fg) > 1e-6 && fabs(row[4 * x] - bg) > 1e-6) {
            cr_expect_eq(edge, -1, "one column on the edge (%d and %d)", edge, x);
            edge = x;
        }
    cr_assert_geq(edge, 0, "a column on the edge");
    double covered = (row[4 * edge] - bg) / (fg - bg);
    cr_expect(fabs(covered - 0.7) < 3.0 / passes, "the edge column shows %g of the slab", covered);
    ro.pass = -1;
    cr_expect_eq(rayscad_render(scene, &cam, &ro, px, NULL, 0), RAYSCAD_ERROR, "a negative pass");
    free(px);
    free(mean);
    rayscad_scene_free(scene);
}

/* A light model's pass k draws its own random numbers: two passes of soft
 * shadows differ, and the same pass twice does not. */
Test(api, passes_draw_their_own_random_numbers)
{
    rayscad_render_options ro;
    rayscad_render_options_default(&ro);
    ro.lights[0] = (rayscad_light){.pos = {5, -8, 30}, .radius = 6, .intensity = 1};
    ro.nlights = 1;
    ro.light_samples = 1;
    const char *src = "translate([-20, -20, 0]) cube([40, 40, 1]); translate([0, 0, 8]) cube(6);";
    const double none[4] = {0};
    float *a = render_cut(src, ro, none);
    ro.pass = 1;
    float *b = render_cut(src, ro, none), *c = render_cut(src, ro, none);
    cr_expect_gt(pixels_apart(a, b), 50, "pass 1 samples the light elsewhere");
    cr_expect_eq(pixels_apart(b, c), 0, "pass 1 is the same picture each time");
    free(a);
    free(b);
    free(c);
}

static double measured_volume(const char *src, rayscad_facets facets, double h)
{
    rayscad_eval_options o = {.facets = facets};
    rayscad_model *model;
    cr_assert_eq(rayscad_model_load_string("t.scad", src, &o, &model), RAYSCAD_OK);
    rayscad_scene *scene;
    cr_assert_eq(rayscad_scene_new(model, &scene, NULL, 0), RAYSCAD_OK);
    rayscad_model_free(model);
    rayscad_mesh_options mo;
    rayscad_mesh_options_default(&mo);
    mo.h = h;
    rayscad_sampling *d;
    char err[256];
    cr_assert_eq(rayscad_sampling_new(scene, &mo, &d, err, sizeof err), RAYSCAD_OK, "%s", err);
    rayscad_measurement m;
    rayscad_sampling_measure(d, &m);
    rayscad_mesh *mesh;
    cr_assert_eq(rayscad_sampling_mesh(d, &mo, &mesh, err, sizeof err), RAYSCAD_OK, "%s", err);
    cr_expect(fabs(rayscad_mesh_volume(mesh) - m.volume) < 0.02 * m.volume, "mesh %g, rays %g",
              rayscad_mesh_volume(mesh), m.volume);
    rayscad_mesh_free(mesh);
    rayscad_sampling_free(d);
    rayscad_scene_free(scene);
    return m.volume;
}

/* A box's volume is exact along every ray; OpenSCAD's own tessellation of
 * a cylinder with $fn = inf is 3 fragments (get_fragments_from_r), a
 * triangular prism of area 3√3/4 · r². */
Test(api, volumes_against_closed_forms)
{
    double v = measured_volume("cube([2, 3, 4]);", RAYSCAD_FACETS_AUTO, 0.05);
    cr_expect(fabs(v - 24) < 1e-9, "box %.12g", v);
    v = measured_volume("cylinder(r = 10, h = 1, $fn = 1/0);", RAYSCAD_FACETS_OPENSCAD, 0.05);
    double prism = 3 * sqrt(3) / 4 * 100;
    cr_expect(fabs(v - prism) < 0.005 * prism, "prism %g, closed form %g", v, prism);
}

/* OpenSCAD 2021.01's get_fragments_from_r, restated. */
static int fragments(double r, double fn, double fs, double fa)
{
    if (fn > 0) return fn >= 3 ? (int)fn : 3;
    return (int)ceil(fmax(fmin(360.0 / fa, r * 2 * 3.14159265358979323846 / fs), 5));
}

static double sag(double r, int n)
{
    return r * (1 - cos(3.14159265358979323846 / n));
}

/* The facet deviation: the least chord sag of the model's round primitives
 * at their own $fn/$fa/$fs, in world units; 0 with none (a sphere whose
 * user asked for 8 fragments is built as OpenSCAD's polytope: flat).  The
 * default $fa/$fs give sphere(1) 5 fragments, and it stays round. */
Test(api, facet_deviation_is_openscads_chord_sag)
{
    static const char *const src[8] = {
        "sphere(10);",
        "sphere(10); translate([30, 0, 0]) cylinder(r = 5, h = 3, $fn = 40);",
        "scale([3, 1, 1]) sphere(10, $fn = 64);",
        "$fa = 5; $fs = 0.5; cylinder(r1 = 4, r2 = 2, h = 10);",
        "rotate_extrude($fn = 48) translate([10, 0]) square(2);",
        "cube(5);",
        "sphere(1);",
        "sphere(1, $fn = 8);",
    };
    double want[8] = {
        sag(10, fragments(10, 0, 2, 12)),
        fmin(sag(10, fragments(10, 0, 2, 12)), sag(5, 40)),
        sag(30, 64),
        sag(4, fragments(4, 0, 0.5, 5)),
        sag(12, 48),
        0,
        sag(1, 5),
        0,
    };
    for (int i = 0; i < 8; i++) {
        rayscad_scene *scene = scene_of(src[i], NULL);
        double got = rayscad_scene_facet_deviation(scene);
        cr_expect(fabs(got - want[i]) <= 1e-12 * (1 + want[i]), "%s: %.15g, want %.15g", src[i],
                  got, want[i]);
        rayscad_scene_free(scene);
    }
}

/* The number of triangles rayscad_sampling_mesh makes of src at tolerance
 * tol with at most max contour triangles simplified (smooth: at most that
 * many where few vertices are on sharp edges), negative when it left the
 * contour as it is. */
static int mesh_triangles_of2(const char *src, double tol, long long max, long long smooth)
{
    rayscad_scene *scene = scene_of(src, NULL);
    rayscad_mesh_options mo;
    rayscad_mesh_options_default(&mo);
    mo.h = 0.25;
    mo.tolerance = tol;
    mo.simplify_max_triangles = max;
    mo.simplify_max_triangles_smooth = smooth;
    mo.contour_all = 1; /* a box's contour, not its own faces */
    rayscad_sampling *d;
    char err[256];
    cr_assert_eq(rayscad_sampling_new(scene, &mo, &d, err, sizeof err), RAYSCAD_OK, "%s", err);
    rayscad_mesh *mesh;
    cr_assert_eq(rayscad_sampling_mesh(d, &mo, &mesh, err, sizeof err), RAYSCAD_OK, "%s", err);
    int n = rayscad_mesh_triangle_count(mesh);
    double got = rayscad_mesh_tolerance(mesh);
    cr_expect(got == 0 || got == tol, "simplified to %g, asked %g", got, tol);
    rayscad_mesh_free(mesh);
    rayscad_sampling_free(d);
    rayscad_scene_free(scene);
    return got > 0 ? n : -n;
}

/* As mesh_triangles_of2 with no smooth limit: the count. */
static int mesh_triangles_of(const char *src, double tol, long long max)
{
    return abs(mesh_triangles_of2(src, tol, max, 0));
}

/* A box simplifies to its 12 triangles; over simplify_max_triangles its
 * contour is kept, as with no tolerance. */
Test(api, simplification_has_a_size_limit)
{
    const char *box = "cube([10, 20, 30]);";
    int raw = mesh_triangles_of(box, 0, 0);
    cr_expect_gt(raw, 1000);
    cr_expect_eq(mesh_triangles_of(box, 0.01, 0), 12);
    cr_expect_eq(mesh_triangles_of(box, 0.01, raw), 12);
    cr_expect_eq(mesh_triangles_of(box, 0.01, raw - 1), raw);
}

/* Past simplify_max_triangles, a contour of few corners of three sharp
 * edges (a box: its 8) is simplified all the same within
 * simplify_max_triangles_smooth; a surface of facets finer than the grid
 * (a saw of 0.1 teeth on a grid of 0.25, whose contour vertices lie on
 * the teeth's edges) is not, nor anything past the smooth limit. */
Test(api, smooth_contours_are_simplified_past_the_limit)
{
    const char *box = "cube([10, 20, 30]);";
    int raw = mesh_triangles_of(box, 0, 0);
    cr_expect_eq(mesh_triangles_of2(box, 0.01, raw - 1, raw), 12);
    cr_expect_eq(mesh_triangles_of2(box, 0.01, raw - 1, raw - 1), -raw);
    char saw[8192];
    int n = snprintf(saw, sizeof saw, "linear_extrude(5) polygon([[0, -2]");
    for (int i = 0; i <= 100; i++)
        n += snprintf(saw + n, sizeof saw - (size_t)n, ", [%g, %g]", 0.1 * i, i % 2 ? 0.3 : 0.0);
    snprintf(saw + n, sizeof saw - (size_t)n, ", [10, -2]]);");
    int teeth = mesh_triangles_of(saw, 0, 0);
    cr_expect_eq(mesh_triangles_of2(saw, 0.01, teeth - 1, teeth), -teeth);
    cr_expect_lt(mesh_triangles_of(saw, 0.01, 0), teeth); /* (it does simplify, asked) */
}
