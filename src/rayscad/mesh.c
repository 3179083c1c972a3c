/*
 * mesh.c — sampling a scene by the three ray families, measuring and
 * contouring and simplifying it (src/mesh), and writing meshes (src/io's
 * OpenMesh adapter; AMF and 3MF through io_amf_write and io_3mf_write, by
 * extension).
 */
#include <stdlib.h>
#include <string.h>

#include "../io/io.h"
#include "rayscad_internal.h"

void rayscad_mesh_options_default(rayscad_mesh_options *o)
{
    mesh_options_default(o);
}

rayscad_status rayscad_sampling_new(const rayscad_scene *s, const rayscad_mesh_options *o,
                                    rayscad_sampling **out, char *err, size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    *out = NULL;
    rayscad_sampling *d = calloc(1, sizeof *d);
    if (!d) {
        rayscad_say(err, errlen, "out of memory");
        return RAYSCAD_ERROR_MEMORY;
    }
    int rc = mesh_dexels_new(s->s, o, &d->d, err, errlen);
    if (rc != 0) {
        free(d);
        return rc == RAYSCAD_ERROR_CELLS || rc == RAYSCAD_ERROR_INTERVALS ? (rayscad_status)rc
                                                                          : RAYSCAD_ERROR;
    }
    *out = d;
    return RAYSCAD_OK;
}

void rayscad_sampling_free(rayscad_sampling *d)
{
    if (!d) return;
    mesh_dexels_free(d->d);
    free(d);
}

void rayscad_sampling_grid(const rayscad_sampling *d, double *h, double origin[3], int n[3])
{
    mesh_dexels_grid(d->d, h, origin, n);
}

void rayscad_sampling_measure(const rayscad_sampling *d, rayscad_measurement *out)
{
    mesh_dexels_measure(d->d, out);
}

void rayscad_measure_options_default(rayscad_measure_options *o)
{
    memset(o, 0, sizeof *o);
    o->root = RAYSCAD_ROOT_MODEL;
    o->tolerance = RAYSCAD_MEASURE_TOLERANCE;
}

rayscad_status rayscad_scene_measure(const rayscad_scene *s, const rayscad_measure_options *o,
                                     rayscad_measurement *out, char *err, size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    rayscad_measure_options def;
    if (!o) {
        rayscad_measure_options_default(&def);
        o = &def;
    }
    mesh_exact_limits lim = {o->max_rays, o->max_intervals, o->cancelled, o->cancel_ud};
    int rc = mesh_measure_exact(s->s, o->root,
                                o->tolerance > 0 ? o->tolerance : RAYSCAD_MEASURE_TOLERANCE, &lim,
                                out, err, errlen);
    return rc == 0 || rc == RAYSCAD_ERROR_RAYS || rc == RAYSCAD_ERROR_INTERVALS ||
                   rc == RAYSCAD_CANCELLED
               ? (rayscad_status)rc
               : RAYSCAD_ERROR;
}

void rayscad_sampling_thin(const rayscad_sampling *d, double thickness, rayscad_thin *out)
{
    mesh_dexels_thin(d->d, thickness, out);
}

/* A handle around m (taken); NULL (m freed) when out of memory. */
static rayscad_mesh *wrap(mesh *m)
{
    rayscad_mesh *r = m ? malloc(sizeof *r) : NULL;
    if (!r) {
        mesh_free(m);
        return NULL;
    }
    r->m = m;
    r->tolerance = 0;
    return r;
}

rayscad_status rayscad_sampling_mesh(const rayscad_sampling *d, const rayscad_mesh_options *o,
                                     rayscad_mesh **out, char *err, size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    mesh *m;
    if (mesh_dexels_contour(d->d, o, &m, err, errlen) != 0) return RAYSCAD_ERROR;
    int simplify = o && o->tolerance > 0;
    long long n = mesh_triangle_count(m);
    if (simplify && o->simplify_max_triangles > 0 && n > o->simplify_max_triangles) {
        double share = o->simplify_max_triangles_smooth > 0 && n <= o->simplify_max_triangles_smooth
                           ? mesh_corner_share(m)
                           : 1;
        simplify = share >= 0 && share < 0.01;
    }
    if (simplify && mesh_dexels_simplify(d->d, m, o->tolerance, o, err, errlen) != 0) {
        mesh_free(m);
        return RAYSCAD_ERROR_MEMORY;
    }
    *out = wrap(m);
    if (*out) {
        (*out)->tolerance = simplify ? o->tolerance : 0;
        return RAYSCAD_OK;
    }
    rayscad_say(err, errlen, "out of memory");
    return RAYSCAD_ERROR_MEMORY;
}

void rayscad_mesh_free(rayscad_mesh *m)
{
    if (!m) return;
    mesh_free(m->m);
    free(m);
}

int rayscad_mesh_vertex_count(const rayscad_mesh *m)
{
    return mesh_vertex_count(m->m);
}

int rayscad_mesh_triangle_count(const rayscad_mesh *m)
{
    return mesh_triangle_count(m->m);
}

const float *rayscad_mesh_vertices(const rayscad_mesh *m)
{
    return mesh_vertices(m->m);
}

const int32_t *rayscad_mesh_triangles(const rayscad_mesh *m)
{
    return mesh_triangles(m->m);
}

double rayscad_mesh_volume(const rayscad_mesh *m)
{
    return mesh_signed_volume(m->m);
}

double rayscad_mesh_tolerance(const rayscad_mesh *m)
{
    return m->tolerance;
}

int rayscad_mesh_color_count(const rayscad_mesh *m)
{
    return mesh_color_count(m->m);
}

const float *rayscad_mesh_colors(const rayscad_mesh *m)
{
    return mesh_colors(m->m);
}

const uint16_t *rayscad_mesh_triangle_colors(const rayscad_mesh *m)
{
    return mesh_triangle_colors(m->m);
}

int rayscad_mesh_format_supported(const char *path)
{
    if (!path) return 0;
    return io_path_has_extension(path, "amf") || io_path_has_extension(path, "3mf") ||
           io_mesh_format_supported(path);
}

rayscad_status rayscad_mesh_write(const rayscad_mesh *m, const char *path, int flags, char *err,
                                  size_t errlen)
{
    char local[1];
    if (!err) err = local, errlen = sizeof local;
    const float *v = mesh_vertices(m->m);
    const int32_t *t = mesh_triangles(m->m);
    int nv = mesh_vertex_count(m->m), nt = mesh_triangle_count(m->m), rc;
    if (!rayscad_mesh_format_supported(path)) {
        rayscad_say(err, errlen,
                    "%s: unknown mesh format (use .stl, .off, .obj, .ply, .amf or .3mf)", path);
        return RAYSCAD_ERROR;
    }
    io_colors colors = {(const float(*)[4])mesh_colors(m->m), mesh_color_count(m->m),
                        mesh_triangle_colors(m->m)};
    const io_colors *c = colors.n && !(flags & RAYSCAD_WRITE_NO_COLORS) ? &colors : NULL;
    if (io_path_has_extension(path, "amf"))
        rc = io_amf_write(path, v, nv, t, nt, err, errlen);
    else if (io_path_has_extension(path, "3mf"))
        rc = io_3mf_write(path, v, nv, t, nt, c, err, errlen);
    else
        rc = io_mesh_write(path, v, nv, t, nt, flags & RAYSCAD_WRITE_ASCII, c, err, errlen);
    return rc == 0 ? RAYSCAD_OK : RAYSCAD_ERROR;
}
