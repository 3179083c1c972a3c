/*
 * fuzz_pipeline.c — libFuzzer harness for the whole pipeline: any bytes, as
 * a NUL-terminated source, are evaluated (recursion limit 200, 10^5 steps, the 2D
 * operations and the mesh service wired to src/io and src/mesh as the
 * command wires them, no files: include/use open files relative to the
 * current folder, import/surface/text are not available), committed into a
 * csg_scene, rendered as a 16×16 image from the default view, and meshed on
 * a coarse grid (8 cells along the longest side).  Everything runs on one
 * thread.  Checked besides the sanitizers: every pixel the renderer writes
 * is a finite number in [0, 1], and a mesh's indices lie within its
 * vertices.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/io/polygon.h"
#include "../../src/mesh/mesh.h"
#include "../../src/render/render.h"
#include "../../src/scad/scad.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

enum { W = 16, H = 16, CELLS = 8 };

static io_paths to_io(const scad_paths *p)
{
    io_paths q = {p->pts, p->start, p->npaths};
    return q;
}

static void from_io(const io_paths *q, scad_paths *p)
{
    p->pts = q->pts;
    p->start = q->start;
    p->npaths = q->npaths;
}

static int clip(void *ud, int op, const scad_paths *a, int a_evenodd, const scad_paths *b,
                int b_evenodd, scad_paths *out, char *err, size_t errlen)
{
    (void)ud;
    io_paths ia = to_io(a), ib = to_io(b), r = {0};
    int rc = io_polygon_clip((io_clip_op)op, &ia, a_evenodd, &ib, b_evenodd, &r, err, errlen);
    from_io(&r, out);
    return rc;
}

static int offset(void *ud, const scad_paths *a, double delta, int join, double miter_limit,
                  double arc_tolerance, scad_paths *out, char *err, size_t errlen)
{
    (void)ud;
    io_paths ia = to_io(a), r = {0};
    int rc =
        io_polygon_offset(&ia, delta, (io_join)join, miter_limit, arc_tolerance, &r, err, errlen);
    from_io(&r, out);
    return rc;
}

static int minkowski(void *ud, const scad_paths *a, const scad_paths *b, scad_paths *out, char *err,
                     size_t errlen)
{
    (void)ud;
    io_paths ia = to_io(a), ib = to_io(b), r = {0};
    int rc = io_polygon_minkowski(&ia, &ib, &r, err, errlen);
    from_io(&r, out);
    return rc;
}

static int mesh_tree(void *ud, csg_node *root, double h, float **v, int *nv, int32_t **t, int *nt,
                     char *err, size_t errlen)
{
    (void)ud;
    *v = NULL;
    *t = NULL;
    *nv = *nt = 0;
    csg_scene *s = csg_scene_new(&root, 1, err, errlen);
    if (!s) return -1;
    mesh_options mo;
    mesh_options_default(&mo);
    mo.h = h;
    mo.cells_per_side = CELLS;
    mo.threads = 1;
    mesh *m = NULL;
    int rc = mesh_from_scene(s, &mo, &m, NULL, err, errlen);
    csg_scene_free(s);
    if (rc != 0) return -1;
    *nv = mesh_vertex_count(m);
    *nt = mesh_triangle_count(m);
    *v = malloc(sizeof **v * 3 * (size_t)(*nv ? *nv : 1));
    *t = malloc(sizeof **t * 3 * (size_t)(*nt ? *nt : 1));
    if (!*v || !*t) {
        free(*v);
        free(*t);
        *v = NULL;
        *t = NULL;
        mesh_free(m);
        return -1;
    }
    if (*nv) memcpy(*v, mesh_vertices(m), sizeof **v * 3 * (size_t)*nv);
    if (*nt) memcpy(*t, mesh_triangles(m), sizeof **t * 3 * (size_t)*nt);
    mesh_free(m);
    return 0;
}

static const scad_services services = {
    .paths_clip = clip,
    .paths_offset = offset,
    .paths_minkowski = minkowski,
    .mesh_tree = mesh_tree,
};

static void render_scene(const csg_scene *s)
{
    double lo[3] = {0}, hi[3] = {0};
    int have = 0;
    for (int r = 0; r < csg_scene_root_count(s); r++) {
        double l[3], h[3];
        if (csg_scene_view_bounds(s, r, l, h) != 0) continue;
        for (int k = 0; k < 3; k++) {
            lo[k] = have && lo[k] < l[k] ? lo[k] : l[k];
            hi[k] = have && hi[k] > h[k] ? hi[k] : h[k];
        }
        have = 1;
    }
    render_view view = {.kind = RAYSCAD_CAMERA_DEFAULT, .viewall = 1, .autocenter = 1};
    render_camera cam;
    if (render_camera_resolve(&view, lo, hi, have, W, H, &cam) != 0) return;
    render_options ro = {.width = W, .height = H, .samples = 1, .threads = 1};
    render_colors_by_name("Cornfield", &ro.colors);
    static float rgba[W * H * 4];
    char err[512];
    if (render_image(s, &cam, &ro, rgba, err, sizeof err) != 0) return;
    for (int i = 0; i < W * H * 4; i++)
        if (!(rgba[i] >= 0 && rgba[i] <= 1)) abort(); /* NaN or out of range */
}

static void mesh_scene(const csg_scene *s)
{
    mesh_options mo;
    mesh_options_default(&mo);
    mo.cells_per_side = CELLS;
    mo.threads = 1;
    mesh *m = NULL;
    mesh_measure mm;
    char err[512];
    if (mesh_from_scene(s, &mo, &m, &mm, err, sizeof err) != 0) return;
    int nv = mesh_vertex_count(m), nt = mesh_triangle_count(m);
    const int32_t *t = mesh_triangles(m);
    for (int i = 0; i < 3 * nt; i++)
        if (t[i] < 0 || t[i] >= nv) abort();
    mesh_free(m);
}

static void quiet(void *ud, scad_msg_kind kind, const char *line)
{
    (void)ud;
    (void)kind;
    (void)line;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *src = malloc(size + 1);
    if (!src) return 0;
    memcpy(src, data, size);
    src[size] = 0;
    scad_options opt = {
        .message = quiet, .max_recursion = 200, .max_steps = 100000, .services = &services};
    scad_result r;
    int rc = scad_eval_string("fuzz.scad", src, &opt, &r);
    free(src);
    if (rc != 0) return 0;
    csg_node *roots[3] = {r.model, r.highlight, r.background};
    char err[512];
    csg_scene *s = csg_scene_new(roots, 3, err, sizeof err);
    if (!s) return 0;
    render_scene(s);
    mesh_scene(s);
    csg_scene_free(s);
    return 0;
}
