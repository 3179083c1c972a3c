/*
 * fuzz_pipeline.c — libFuzzer harness for the whole pipeline through the
 * public header: any bytes, as a NUL-terminated source, are evaluated
 * (recursion limit 200, 10^5 steps, the library's own 2D operations,
 * meshing and fonts, no files: the file, mesh and image services refuse
 * everything), committed into a scene, rendered as a 16×16 image from
 * OpenSCAD's default view, and meshed on a coarse grid (8 cells along the
 * longest side).  Everything runs on one thread.  Checked besides the
 * sanitizers: every pixel the renderer writes is a finite number in [0, 1],
 * and a mesh's indices lie within its vertices.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../include/rayscad.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

enum { W = 16, H = 16, CELLS = 8 };

static int no_file(void *ud, const char *path, size_t max, char **data, size_t *len, char *err,
                   size_t errlen)
{
    (void)ud, (void)path, (void)max, (void)data, (void)len;
    snprintf(err, errlen, "no files here");
    return -1;
}

static int no_stat(void *ud, const char *path, long long *mtime)
{
    (void)ud, (void)path;
    if (mtime) *mtime = 0;
    return 0;
}

static int no_mesh(void *ud, const char *path, float **v, int *nv, int32_t **t, int *nt, char *err,
                   size_t errlen)
{
    (void)ud, (void)path, (void)v, (void)nv, (void)t, (void)nt;
    snprintf(err, errlen, "no files here");
    return -1;
}

static int no_image(void *ud, const char *path, int *width, int *height, int *channels,
                    float **pixels, char *err, size_t errlen)
{
    (void)ud, (void)path, (void)width, (void)height, (void)channels, (void)pixels;
    snprintf(err, errlen, "no files here");
    return -1;
}

static const rayscad_services no_files = {
    .read_file = no_file, .stat_file = no_stat, .read_mesh = no_mesh, .read_image = no_image};

static void render_scene(const rayscad_scene *s)
{
    rayscad_view view = {.kind = RAYSCAD_CAMERA_DEFAULT, .viewall = 1, .autocenter = 1};
    rayscad_render_options ro;
    rayscad_render_options_default(&ro);
    ro.width = W;
    ro.height = H;
    ro.threads = 1;
    rayscad_camera cam;
    if (rayscad_camera_frame(s, &view, W, H, &cam, NULL, 0) != RAYSCAD_OK) return;
    static float rgba[W * H * 4];
    if (rayscad_render(s, &cam, &ro, rgba, NULL, 0) != RAYSCAD_OK) return;
    for (int i = 0; i < W * H * 4; i++)
        if (!(rgba[i] >= 0 && rgba[i] <= 1)) abort(); /* NaN or out of range */
}

static void mesh_scene(const rayscad_scene *s)
{
    rayscad_mesh_options mo;
    rayscad_mesh_options_default(&mo);
    mo.cells_per_side = CELLS;
    mo.threads = 1;
    rayscad_sampling *d;
    if (rayscad_sampling_new(s, &mo, &d, NULL, 0) != RAYSCAD_OK) return;
    rayscad_mesh *m;
    if (rayscad_sampling_mesh(d, &mo, &m, NULL, 0) == RAYSCAD_OK) {
        int nv = rayscad_mesh_vertex_count(m), nt = rayscad_mesh_triangle_count(m);
        const int32_t *t = rayscad_mesh_triangles(m);
        for (int i = 0; i < 3 * nt; i++)
            if (t[i] < 0 || t[i] >= nv) abort();
        rayscad_mesh_free(m);
    }
    rayscad_sampling_free(d);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *src = malloc(size + 1);
    if (!src) return 0;
    memcpy(src, data, size);
    src[size] = 0;
    rayscad_eval_options o = {.max_recursion = 200, .max_steps = 100000, .services = &no_files};
    rayscad_model *model;
    rayscad_status rc = rayscad_model_load_string("fuzz.scad", src, &o, &model);
    free(src);
    if (rc != RAYSCAD_OK) return 0;
    rayscad_scene *s;
    rc = rayscad_scene_new(model, &s, NULL, 0);
    rayscad_model_free(model);
    if (rc != RAYSCAD_OK) return 0;
    render_scene(s);
    mesh_scene(s);
    rayscad_scene_free(s);
    return 0;
}
