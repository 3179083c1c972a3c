/*
 * geometry_services.c — the 2D geometry services (geometry_services.h):
 * thin adapters from the language's scad_paths to src/io's io_paths (the
 * same three members, so a view, nothing copied, and results handed over
 * as they are malloc'ed) and from a csg tree to a mesh's flat arrays.
 */
#include "geometry_services.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../io/polygon.h"
#include "../io/text.h"
#include "../mesh/mesh.h"

static io_paths io_view(const scad_paths *p)
{
    io_paths q = {NULL, NULL, 0};
    if (p) {
        q.pts = p->pts;
        q.start = p->start;
        q.npaths = p->npaths;
    }
    return q;
}

static void from_io(const io_paths *q, scad_paths *out)
{
    out->pts = q->pts;
    out->start = q->start;
    out->npaths = q->npaths;
}

int cli_paths_clip(void *ud, int op, const scad_paths *a, int a_evenodd, const scad_paths *b,
                   int b_evenodd, scad_paths *out, char *err, size_t errlen)
{
    (void)ud;
    io_clip_op o = op == CSG_OP_INTERSECTION ? IO_CLIP_INTERSECTION
                   : op == CSG_OP_DIFFERENCE ? IO_CLIP_DIFFERENCE
                                             : IO_CLIP_UNION;
    io_paths x = io_view(a), y = io_view(b), r;
    if (io_polygon_clip(o, &x, a_evenodd, &y, b_evenodd, &r, err, errlen) != 0) return -1;
    from_io(&r, out);
    return 0;
}

int cli_paths_offset(void *ud, const scad_paths *a, double delta, int join, double miter_limit,
                     double arc_tolerance, scad_paths *out, char *err, size_t errlen)
{
    (void)ud;
    io_join j = join == SCAD_JOIN_MITER    ? IO_JOIN_MITER
                : join == SCAD_JOIN_SQUARE ? IO_JOIN_SQUARE
                                           : IO_JOIN_ROUND;
    io_paths x = io_view(a), r;
    if (io_polygon_offset(&x, delta, j, miter_limit, arc_tolerance, &r, err, errlen) != 0)
        return -1;
    from_io(&r, out);
    return 0;
}

int cli_paths_minkowski(void *ud, const scad_paths *a, const scad_paths *b, scad_paths *out,
                        char *err, size_t errlen)
{
    (void)ud;
    io_paths x = io_view(a), y = io_view(b), r;
    if (io_polygon_minkowski(&x, &y, &r, err, errlen) != 0) return -1;
    from_io(&r, out);
    return 0;
}

int cli_mesh_tree(void *ud, csg_node *root, double h, float **v, int *nv, int32_t **t, int *nt,
                  char *err, size_t errlen)
{
    (void)ud;
    *v = NULL;
    *t = NULL;
    *nv = *nt = 0;
    csg_scene *s = csg_scene_new(&root, 1, err, errlen);
    if (!s) return -1;
    mesh_options o;
    mesh_options_default(&o);
    o.h = h;
    o.cells_per_side = 256;
    mesh *m = NULL;
    int rc = mesh_from_scene(s, &o, &m, NULL, err, errlen);
    csg_scene_free(s);
    if (rc != 0) return -1;
    int n = mesh_vertex_count(m), k = mesh_triangle_count(m);
    *v = malloc((size_t)(n ? n : 1) * 3 * sizeof **v);
    *t = malloc((size_t)(k ? k : 1) * 3 * sizeof **t);
    if (!*v || !*t) {
        free(*v);
        free(*t);
        *v = NULL;
        *t = NULL;
        mesh_free(m);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    memcpy(*v, mesh_vertices(m), (size_t)n * 3 * sizeof **v);
    memcpy(*t, mesh_triangles(m), (size_t)k * 3 * sizeof **t);
    *nv = n;
    *nt = k;
    mesh_free(m);
    return 0;
}

int cli_text(void *ud, const scad_text_params *p, scad_paths *out, char *err, size_t errlen)
{
    (void)ud;
    io_text_params q = {p->text,    p->size,      p->font,     p->halign, p->valign,
                        p->spacing, p->direction, p->language, p->script, p->segments};
    io_paths r;
    if (io_text_render(&q, &r, err, errlen) != 0) return -1;
    from_io(&r, out);
    return 0;
}
