/*
 * exact_faces.c — a part of a model that is one polyhedral primitive alone
 * (far from every other part: pieces.c) written as its own faces rather
 * than contoured from its samples.
 *
 * A hull(), an OpenSCAD-faceted sphere or cylinder, a minkowski of
 * polytopes: the ray queries answer them exactly, but a contour meets
 * their many small facets only as closely as its grid allows, and the
 * simplifier then bends them within the tolerance (hull_revolve.scad's
 * hull of a 64 × 32 torus came out 1.44 tolerances off in places, at
 * 10,452 triangles).  Its own triangles are exact and fewer: the hull's,
 * as the hull made them (closed, wound outward: iv_polytope_set_faces
 * checks that every edge is used once each way), a box's twelve, and a
 * polyhedron's or an imported mesh's as written (turned where OpenSCAD
 * turns them) where they are the boundary of the solid the rays see — no
 * two crossing, no shell inside another wound alike (geom_mesh_is_boundary;
 * a file of overlapping shells is contoured: its union).
 * Only where the part is alone — no other operand of the top-level unions
 * near it — is it the model's surface there; anything near, and the part
 * is contoured with the rest.
 */
#include "../geom/earcut.h"
#include "../geom/mesh_boundary.h"
#include "../intervals/vec3.h"
#include "dexels.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A box's corners (bit k of i: the high side along axis k) and its twelve
 * triangles, wound outward. */
static const int BOX_TRI[12][3] = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5},  /* -x, +x */
                                   {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},  /* -y, +y */
                                   {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}}; /* -z, +z */

int mesh_faces_of(const iv_shape *sh, mesh_faces *f)
{
    memset(f, 0, sizeof *f);
    switch (sh->kind) {
    case IV_SHAPE_MESH:
        f->cw = 1;
        f->t = (const int32_t(*)[3])iv_mesh_triangles(sh, &f->nt);
        f->v = iv_mesh_vertices(sh, &f->nv);
        break;
    case IV_SHAPE_BOX:
        for (int i = 0; i < 8; i++)
            for (int k = 0; k < 3; k++)
                f->box[i][k] = i >> k & 1 ? sh->u.box.hi[k] : sh->u.box.lo[k];
        f->v = (const double(*)[3])f->box;
        f->nv = 8;
        f->t = (const int32_t(*)[3])BOX_TRI;
        f->nt = 12;
        break;
    case IV_SHAPE_PRISM: {
        if (!sh->u.prism.g) return 0; /* a disc's: curved */
        int n, np;
        const double(*P)[2] = iv_region_points(sh->u.prism.g, &n);
        const int *ps = iv_region_paths(sh->u.prism.g, &np);
        f->nt = geom_prism_mesh(P, ps, np, sh->u.prism.z0, sh->u.prism.z1, &f->own_v, &f->own_t);
        f->nv = 2 * ps[np];
        f->v = (const double(*)[3])f->own_v;
        f->t = (const int32_t(*)[3])f->own_t;
        break;
    }
    default:
        f->t = iv_polytope_triangles(sh, &f->nt);
        f->v = iv_polytope_vertices(sh, &f->nv);
    }
    return f->t && f->v && f->nt > 0;
}

void mesh_faces_free(mesh_faces *f)
{
    free(f->own_v);
    free(f->own_t);
}

static int cmp_point(const void *a, const void *b)
{
    const double *p = a, *q = b;
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
    return 0;
}

int mesh_faces_bound(const mesh_faces *f)
{
    int(*ccw)[3] = malloc((size_t)f->nt * sizeof *ccw);
    if (!ccw) return 0;
    for (int i = 0; i < f->nt; i++) {
        ccw[i][0] = f->t[i][0];
        ccw[i][1] = f->t[i][f->cw ? 2 : 1];
        ccw[i][2] = f->t[i][f->cw ? 1 : 2];
    }
    int ok = geom_mesh_is_boundary(f->v, f->nv, (const int(*)[3])ccw, f->nt) == 1;
    free(ccw);
    return ok;
}

int mesh_floats_apart(const double (*v)[3], int nv, const int32_t (*t)[3], int nt)
{
    double(*q)[3] = malloc((size_t)(nv ? nv : 1) * sizeof *q);
    int ok = q != NULL;
    for (int i = 0; ok && i < nv; i++) {
        memcpy(q[i], v[i], sizeof q[i]);
        mesh_round_to_float(q[i]);
        ok = isfinite(q[i][0]) && isfinite(q[i][1]) && isfinite(q[i][2]);
    }
    for (int i = 0; ok && i < nt; i++) {
        double n[3];
        tri_normal3(q[t[i][0]], q[t[i][1]], q[t[i][2]], n);
        ok = dot3(n, n) > 0;
    }
    if (ok) qsort(q, (size_t)nv, sizeof *q, cmp_point);
    for (int i = 1; ok && i < nv; i++)
        ok = cmp_point(q[i - 1], q[i]) != 0;
    free(q);
    return ok;
}

int mesh_exact_faces(const csg_scene *s, int32_t prim)
{
    mesh_faces f;
    csg_affine w;
    const iv_shape *sh = csg_scene_prim_shape(s, prim);
    int ok = mesh_faces_of(sh, &f);
    csg_scene_prim_transform(s, prim, w);
    double d = csg_affine_det(w);
    ok = ok && isfinite(d) && d != 0;
    /* a mesh as written, a prism as cut here: the boundary of their solid? */
    if (ok && (sh->kind == IV_SHAPE_MESH || sh->kind == IV_SHAPE_PRISM)) ok = mesh_faces_bound(&f);
    /* the corners where the mesh will hold them */
    double(*p)[3] = ok ? malloc((size_t)f.nv * sizeof *p) : NULL;
    ok = ok && p;
    for (int i = 0; ok && i < f.nv; i++)
        csg_affine_point(w, f.v[i], p[i]);
    ok = ok && mesh_floats_apart((const double(*)[3])p, f.nv, f.t, f.nt);
    free(p);
    mesh_faces_free(&f);
    return ok;
}

/* Append the faces of grid d's primitive to m; 0 or -1 when out of memory. */
static int append(const mesh_dexels *d, mesh *m)
{
    mesh_faces f;
    csg_affine w;
    /* (mesh_exact_faces found faces: none now is out of memory) */
    int rc = mesh_faces_of(csg_scene_prim_shape(d->scene, d->exact), &f) ? 0 : -1;
    csg_scene_prim_transform(d->scene, d->exact, w);
    int turn = (csg_affine_det(w) < 0) != f.cw; /* a mirror winds them the other way */
    uint16_t color = mesh_palette_of(&d->pal, d->exact);
    int32_t base = m->nv;
    for (int i = 0; rc == 0 && i < f.nv; i++) {
        double p[3];
        csg_affine_point(w, f.v[i], p);
        rc = mesh_push_vertex(m, p[0], p[1], p[2]) < 0 ? -1 : 0;
    }
    for (int i = 0; rc == 0 && i < f.nt; i++)
        rc = mesh_push_triangle(m, base + f.t[i][0], base + f.t[i][turn ? 2 : 1],
                                base + f.t[i][turn ? 1 : 2], color) < 0
                 ? -1
                 : 0;
    mesh_faces_free(&f);
    return rc;
}

int mesh_exact_append(const mesh_dexels *d, mesh *m)
{
    int32_t nv = m->nv, nt = m->nt;
    for (; d; d = d->next) {
        if (d->exact >= 0 && append(d, m) != 0) return -1;
        if (d->exact == MESH_POLYHEDRAL) {
            int32_t base = m->nv;
            for (int i = 0; i < d->poly.nv; i++)
                if (mesh_push_vertex(m, d->poly.v[i][0], d->poly.v[i][1], d->poly.v[i][2]) < 0)
                    return -1;
            for (int i = 0; i < d->poly.nt; i++)
                if (mesh_push_triangle(m, base + d->poly.t[i][0], base + d->poly.t[i][1],
                                       base + d->poly.t[i][2], d->poly.color[i]) < 0)
                    return -1;
        }
    }
    m->exact_nv += m->nv - nv;
    m->exact_nt += m->nt - nt;
    return 0;
}

int mesh_exact_detach(mesh *m, mesh_exact_tail *x)
{
    memset(x, 0, sizeof *x);
    if (!m->exact_nt) return 0;
    int32_t v0 = m->nv - m->exact_nv, t0 = m->nt - m->exact_nt;
    x->v = malloc(3 * (size_t)m->exact_nv * sizeof *x->v);
    x->t = malloc(3 * (size_t)m->exact_nt * sizeof *x->t);
    x->tc = m->npal ? malloc((size_t)m->exact_nt * sizeof *x->tc) : NULL;
    if (!x->v || !x->t || (m->npal && !x->tc)) {
        mesh_exact_tail_free(x);
        return -1;
    }
    memcpy(x->v, m->v + 3 * (size_t)v0, 3 * (size_t)m->exact_nv * sizeof *x->v);
    for (size_t i = 0; i < 3 * (size_t)m->exact_nt; i++)
        x->t[i] = m->t[3 * (size_t)t0 + i] - v0;
    if (x->tc) memcpy(x->tc, m->tc + t0, (size_t)m->exact_nt * sizeof *x->tc);
    x->nv = m->exact_nv;
    x->nt = m->exact_nt;
    m->nv = v0;
    m->nt = t0;
    m->exact_nv = m->exact_nt = 0;
    return 0;
}

int mesh_exact_attach(mesh *m, mesh_exact_tail *x)
{
    int32_t base = m->nv, rc = 0;
    for (int i = 0; i < x->nv && rc == 0; i++)
        rc = mesh_push_vertex(m, x->v[3 * i], x->v[3 * i + 1], x->v[3 * i + 2]) < 0 ? -1 : 0;
    for (int i = 0; i < x->nt && rc == 0; i++)
        rc = mesh_push_triangle(m, base + x->t[3 * i], base + x->t[3 * i + 1],
                                base + x->t[3 * i + 2], x->tc ? x->tc[i] : 0) < 0
                 ? -1
                 : 0;
    if (rc == 0) {
        m->exact_nv += x->nv;
        m->exact_nt += x->nt;
    }
    mesh_exact_tail_free(x);
    return rc;
}

void mesh_exact_tail_free(mesh_exact_tail *x)
{
    free(x->v);
    free(x->t);
    free(x->tc);
    memset(x, 0, sizeof *x);
}
