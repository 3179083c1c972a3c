/*
 * crease.c — a simplified mesh's chords across the edges and corners of
 * plane faces split on them, exactly (see dexels.h, mesh_split_creases).
 *
 * Where an edge between two plane faces runs obliquely through the grid,
 * a cell it passes through may see only one of the faces on its edges, put
 * its vertex on that face, and join it to a vertex on the other: a chord
 * that cuts the edge off (a chamfer up to a tenth of a cell deep); where
 * the third face of a corner meets no cell edge at all, the corner is cut
 * off likewise.  The simplifier keeps every such chord, and the vertices
 * about it: a box turned obliquely came out as 352 triangles where 12
 * describe it, and 8 tolerances off at its corners.
 *
 * Plane faces are known exactly: a ray through a triangle's centroid finds
 * the face under it, and a planar patch is one plane, read off that
 * crossing.  A vertex lies on those planes, of the faces under the
 * triangles around it, that pass within rounding of it.  A vertex whose
 * triangles lie over two or three planes, not all through it, moves onto
 * the line or point where they meet (a contour vertex a little off a
 * crease).  An edge whose ends share no plane, one end on A and the other
 * on B, crosses the line where A and B meet; it is split at the point of
 * that line nearest it.  A triangle whose corners still share no plane, and
 * lie on three, gets the point where the three meet as a new corner (a fan
 * of three).  Every such point must be one a ray along the planes' mean
 * normal finds on the surface (else the planes do not meet there: a face
 * lies between them), and every move or split must leave triangles with
 * area that face like the plane they lie on.  Passes repeat until one
 * changes nothing; the simplifier then runs again (mesh_dexels_simplify).
 * The contour's own mesh, before the simplifier, is crowded with slivers
 * along such edges, and most splits there would fold one.
 *
 * Measured (build/tools/meshdev, the mesh models at their default
 * tolerance): star_prism.scad 122 -> 36 triangles (openscad's), its tips 14
 * D off -> exact; pinched_cells 1,874 -> 1,510, 29 -> 14 D; twist_ties
 * 1,876 -> 1,402; minkowski_solids 732 -> 568; polygon_frustum 198 -> 142
 * (openscad 92); the box above 352 -> 262, seven of its corners found where
 * five were.  A contour vertex off a crease whose triangles a move would
 * fold, and the crowded triangles about it, are still left as they are.
 */
#include "../intervals/vec3.h"
#include "dexels.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PASSES 8
#define MAX_PLANES 8     /* candidates per edge or triangle */
#define COS_TURN 0.17    /* a snapped vertex's triangles turn less than 80° */
#define COS_APART 0.9998 /* planes whose normals part by less (about 1°) do not crease */

typedef struct plane {
    uint32_t patch; /* 0: empty slot */
    double n[3], d; /* n·x = d */
} plane;

typedef struct crease_mesh {
    mesh *m;
    mesh_snapper *sn;
    mesh_fmap pos; /* every vertex by its place */
    double h;
    plane *pl; /* open addressing by patch */
    size_t cap, npl;
    int32_t *tp;          /* each triangle's plane (index into pl), or -1 */
    int32_t *start, *fan; /* the triangles around each vertex */
    int32_t *opp;         /* each half-edge's twin */
    uint8_t *used;        /* triangles split this pass */
} crease_mesh;

/* The plane of the planar face under triangle t (a ray along its normal
 * through its centroid), as an index into c->pl; -1 when none (or out of
 * room: c->pl holds a few thousand planes at most, then stops adding). */
static int32_t face_under(crease_mesh *c, int32_t t)
{
    double p[3][3], g[3], n[3], hit[3], hn[3];
    for (int k = 0; k < 3; k++)
        mesh_vertex_at(c->m, c->m->t[3 * (size_t)t + k], p[k]);
    tri_normal3(p[0], p[1], p[2], n);
    double l = sqrt(dot3(n, n));
    if (!(l > 0)) return -1;
    for (int k = 0; k < 3; k++) {
        n[k] /= l;
        g[k] = (p[0][k] + p[1][k] + p[2][k]) / 3;
    }
    uint32_t patch = 0;
    if (!mesh_snap_probe_patch(c->sn, g, n, c->h, 0.5, 0, hit, hn, &patch) || !patch ||
        !(mesh_patch_flagged(c->sn->d, patch) & MESH_PATCH_PLANAR))
        return -1;
    size_t i = mesh_hash_mix(patch) & (c->cap - 1);
    while (c->pl[i].patch && c->pl[i].patch != patch)
        i = (i + 1) & (c->cap - 1);
    if (!c->pl[i].patch) {
        if (2 * (c->npl + 1) > c->cap || !((l = sqrt(dot3(hn, hn))) > 0)) return -1;
        c->pl[i].patch = patch;
        for (int k = 0; k < 3; k++)
            c->pl[i].n[k] = hn[k] / l;
        c->pl[i].d = dot3(c->pl[i].n, hit);
        c->npl++;
    }
    return (int32_t)i;
}

/* The planes under the triangles around vertices vs (nv of them),
 * distinct, into out (MAX_PLANES at most); their count. */
static int candidates(const crease_mesh *c, const int32_t *vs, int nv, const plane **out)
{
    int n = 0;
    for (int i = 0; i < nv; i++)
        for (int32_t f = c->start[vs[i]]; f < c->start[vs[i] + 1]; f++) {
            if (c->tp[c->fan[f]] < 0) continue;
            const plane *p = &c->pl[c->tp[c->fan[f]]];
            int seen = 0;
            for (int j = 0; j < n && !seen; j++)
                seen = out[j] == p;
            if (!seen && n < MAX_PLANES) out[n++] = p;
        }
    return n;
}

/* Which of the planes pl (np) vertex v lies on, as bits. */
static unsigned on_planes(const crease_mesh *c, int32_t v, const plane *const *pl, int np)
{
    double x[3];
    mesh_vertex_at(c->m, v, x);
    double big = fmax(fabs(x[0]), fmax(fabs(x[1]), fabs(x[2])));
    double eps = fmax(1e-4 * c->h, 5e-7 * big); /* vertices are floats */
    unsigned s = 0;
    for (int i = 0; i < np; i++)
        if (fabs(dot3(pl[i]->n, x) - pl[i]->d) < eps) s |= 1u << i;
    return s;
}

/* Whether x lies on the surface: a ray through it along n (not unit) finds
 * the surface there. */
static int on_surface(crease_mesh *c, const double x[3], const double n[3])
{
    double u[3], hit[3], hn[3], d[3], l = sqrt(dot3(n, n));
    if (!(l > 1e-9)) return 0;
    for (int k = 0; k < 3; k++)
        u[k] = n[k] / l;
    if (!mesh_snap_probe(c->sn, x, u, c->h, -1, hit, hn)) return 0;
    sub3(hit, x, d);
    return dot3(d, d) < 1e-8 * c->h * c->h;
}

/* Whether the triangle p, q, r has area and faces like the first of the
 * planes of bits `shared` of pl, which its corners share (like n where
 * they share none: it still crosses a crease). */
static int half_ok(const plane *const *pl, unsigned shared, const double p[3], const double q[3],
                   const double r[3], const double n[3], double min2)
{
    double t[3];
    tri_normal3(p, q, r, t);
    for (int i = 0; i < MAX_PLANES; i++)
        if (shared >> i & 1) {
            n = pl[i]->n;
            break;
        }
    return dot3(t, t) > min2 && dot3(t, n) > 0;
}

/* A vertex at x (float), not where one is; its number, -1 when one is
 * there, -2 when out of memory. */
static int32_t add_vertex(crease_mesh *c, const double x[3])
{
    if (mesh_fmap_has(&c->pos, mesh_pos_key(x))) return -1;
    int fresh;
    int32_t v = mesh_push_vertex(c->m, x[0], x[1], x[2]);
    int32_t *slot = v < 0 ? NULL : mesh_fmap_slot(&c->pos, mesh_pos_key(x), &fresh);
    if (!slot) return -2;
    *slot = v;
    return v;
}

/* A point of the line where planes a and b meet into p0, its direction
 * (not unit) into e; 0 when they are parallel. */
static int crease_line(const plane *a, const plane *b, double p0[3], double e[3])
{
    cross3(a->n, b->n, e);
    double ee = dot3(e, e), t1[3], t2[3];
    if (!(ee > 1 - COS_APART * COS_APART)) return 0;
    /* (d_a (n_b × e) + d_b (e × n_a)) / |e|² */
    cross3(b->n, e, t1);
    cross3(e, a->n, t2);
    for (int k = 0; k < 3; k++)
        p0[k] = (a->d * t1[k] + b->d * t2[k]) / ee;
    return 1;
}

/* Where planes a, b and c meet, into x; 0 when they nearly share a line. */
static int corner_point(const plane *a, const plane *b, const plane *c, double x[3])
{
    double bc[3], ca[3], ab[3];
    cross3(b->n, c->n, bc);
    cross3(c->n, a->n, ca);
    cross3(a->n, b->n, ab);
    double det = dot3(a->n, bc);
    if (!(fabs(det) > 0.05)) return 0;
    for (int i = 0; i < 3; i++)
        x[i] = (a->d * bc[i] + b->d * ca[i] + c->d * ab[i]) / det;
    return 1;
}

/* The point of the line where planes a and b meet nearest the segment
 * from u to w, well inside it and within a cell of it, into x; 0 when
 * there is none. */
static int crease_point(const plane *a, const plane *b, const double u[3], const double w[3],
                        double h, double x[3])
{
    double e[3], p0[3], s[3], r[3];
    if (!crease_line(a, b, p0, e)) return 0;
    double ee = dot3(e, e);
    /* the nearest points of the line p0 + t e and the segment u + s (w − u) */
    sub3(w, u, s);
    sub3(u, p0, r);
    double A = ee, B = dot3(e, s), C = dot3(s, s), D = dot3(e, r), E = dot3(s, r);
    double den = A * C - B * B;
    if (!(den > 1e-12 * A * C)) return 0;
    double sg = (B * D - A * E) / den, tl = (B * sg + D) / A, gap[3];
    if (!(sg > 0.02 && sg < 0.98)) return 0;
    for (int k = 0; k < 3; k++) {
        x[k] = p0[k] + tl * e[k];
        gap[k] = u[k] + sg * s[k] - x[k];
    }
    return dot3(gap, gap) < h * h;
}

/* Move vertex v, whose triangles lie over two or three plane faces, not
 * all through v, onto the line or point where those meet, where a ray
 * finds it on the surface within half a cell (a contour vertex off a
 * crease, whose chords cut it off), unless that turns one of its triangles
 * over; 1 when moved. */
static int snap_vertex(crease_mesh *c, int32_t v)
{
    const plane *pl[MAX_PLANES];
    int np = candidates(c, &v, 1, pl);
    if (np < 2 || np > 3 || on_planes(c, v, pl, np) == (1u << np) - 1) return 0;
    double x[3], to[3], mean[3], d[3];
    mesh_vertex_at(c->m, v, x);
    if (np == 3) {
        if (!corner_point(pl[0], pl[1], pl[2], to)) return 0;
    } else {
        double p0[3], e[3];
        if (!crease_line(pl[0], pl[1], p0, e)) return 0;
        sub3(x, p0, d);
        double t = dot3(d, e) / dot3(e, e);
        for (int k = 0; k < 3; k++)
            to[k] = p0[k] + t * e[k];
    }
    for (int k = 0; k < 3; k++)
        mean[k] = pl[0]->n[k] + pl[1]->n[k] + (np == 3 ? pl[2]->n[k] : 0);
    sub3(to, x, d);
    if (!(dot3(d, d) < 0.25 * c->h * c->h) || !on_surface(c, to, mean)) return 0;
    for (int k = 0; k < 3; k++)
        to[k] = (float)to[k];
    int fresh;
    if (mesh_fmap_has(&c->pos, mesh_pos_key(to))) return 0;
    double min2 = 1e-10 * c->h * c->h * c->h * c->h;
    if (!mesh_vertex_move(c->m, v, &c->fan[c->start[v]], c->start[v + 1] - c->start[v], to,
                          COS_TURN, min2))
        return 0;
    int32_t *slot = mesh_fmap_slot(&c->pos, mesh_pos_key(to), &fresh);
    if (slot) *slot = v;
    return slot ? 1 : -1;
}

/* Split the edge of half-edge x (triangle t = (u, w, c), its twin in o =
 * (w, u, d)) on the crease its ends' planes meet at; 1 when split, 0 when
 * not, -1 when out of memory. */
static int split_edge(crease_mesh *c, int32_t x)
{
    int32_t y = c->opp[x], t = x / 3, o = y / 3;
    if (y < 0 || t == o || c->used[t] || c->used[o]) return 0;
    int k = x % 3, j = y % 3;
    mesh *m = c->m;
    int32_t vs[4] = {m->t[3 * (size_t)t + k], m->t[3 * (size_t)t + (k + 1) % 3],
                     m->t[3 * (size_t)t + (k + 2) % 3], m->t[3 * (size_t)o + (j + 2) % 3]};
    const plane *pl[MAX_PLANES];
    int np = candidates(c, vs, 2, pl);
    if (np < 2) return 0;
    unsigned su = on_planes(c, vs[0], pl, np), sw = on_planes(c, vs[1], pl, np);
    if (!su || !sw || (su & sw)) return 0;
    unsigned sc = on_planes(c, vs[2], pl, np), sd = on_planes(c, vs[3], pl, np);
    double u[3], w[3], pc[3], pd[3], tn[3], on[3];
    mesh_vertex_at(m, vs[0], u);
    mesh_vertex_at(m, vs[1], w);
    mesh_vertex_at(m, vs[2], pc);
    mesh_vertex_at(m, vs[3], pd);
    tri_normal3(u, w, pc, tn);
    tri_normal3(w, u, pd, on);
    double min2 = 1e-10 * c->h * c->h * c->h * c->h;
    for (int a = 0; a < np; a++)
        for (int b = 0; b < np; b++) {
            double xp[3], mean[3];
            if (!(su >> a & 1) || !(sw >> b & 1) || !crease_point(pl[a], pl[b], u, w, c->h, xp))
                continue;
            for (int i = 0; i < 3; i++)
                mean[i] = pl[a]->n[i] + pl[b]->n[i];
            if (!on_surface(c, xp, mean)) continue;
            for (int i = 0; i < 3; i++)
                xp[i] = (float)xp[i]; /* as the mesh will hold it */
            unsigned sx = 1u << a | 1u << b;
            if (!half_ok(pl, su & sx & sc, u, xp, pc, tn, min2) ||
                !half_ok(pl, sx & sw & sc, xp, w, pc, tn, min2) ||
                !half_ok(pl, sw & sx & sd, w, xp, pd, on, min2) ||
                !half_ok(pl, sx & su & sd, xp, u, pd, on, min2))
                continue;
            int32_t v = add_vertex(c, xp);
            if (v == -2) return -1;
            if (v < 0) continue;
            uint16_t ct = m->tc && m->npal ? m->tc[t] : 0, co = m->tc && m->npal ? m->tc[o] : 0;
            m->t[3 * (size_t)t + (k + 1) % 3] = v; /* (u, v, c) */
            m->t[3 * (size_t)o + (j + 1) % 3] = v; /* (w, v, d) */
            if (mesh_push_triangle(m, v, vs[1], vs[2], ct) < 0 ||
                mesh_push_triangle(m, v, vs[0], vs[3], co) < 0)
                return -1;
            c->used[t] = c->used[o] = 1;
            return 1;
        }
    return 0;
}

/* Give triangle t, whose corners share no plane and lie on three, the
 * point where those meet as a new corner; 1 when split, 0 when not, -1
 * when out of memory. */
static int split_corner(crease_mesh *c, int32_t t)
{
    if (c->used[t]) return 0;
    mesh *m = c->m;
    int32_t vs[3];
    memcpy(vs, &m->t[3 * (size_t)t], sizeof vs);
    const plane *pl[MAX_PLANES];
    int np = candidates(c, vs, 3, pl);
    unsigned s0 = on_planes(c, vs[0], pl, np), s1 = on_planes(c, vs[1], pl, np),
             s2 = on_planes(c, vs[2], pl, np), all = s0 | s1 | s2;
    if (!s0 || !s1 || !s2 || (s0 & s1 & s2)) return 0;
    const plane *three[3];
    int n3 = 0;
    for (int i = 0; i < np; i++)
        if (all >> i & 1) {
            if (n3 == 3) return 0;
            three[n3++] = pl[i];
        }
    if (n3 != 3) return 0;
    double x[3], mean[3], p[3][3], g[3];
    if (!corner_point(three[0], three[1], three[2], x)) return 0;
    for (int i = 0; i < 3; i++)
        mean[i] = three[0]->n[i] + three[1]->n[i] + three[2]->n[i];
    for (int q = 0; q < 3; q++)
        mesh_vertex_at(m, vs[q], p[q]);
    for (int i = 0; i < 3; i++)
        g[i] = (p[0][i] + p[1][i] + p[2][i]) / 3 - x[i];
    if (!(dot3(g, g) < 4 * c->h * c->h) || !on_surface(c, x, mean)) return 0;
    for (int i = 0; i < 3; i++)
        x[i] = (float)x[i];
    double min2 = 1e-10 * c->h * c->h * c->h * c->h;
    unsigned sv[3] = {s0, s1, s2};
    for (int q = 0; q < 3; q++)
        if (!half_ok(pl, sv[q] & sv[(q + 1) % 3], p[q], p[(q + 1) % 3], x, mean, min2)) return 0;
    int32_t v = add_vertex(c, x);
    if (v == -2) return -1;
    if (v < 0) return 0;
    uint16_t ct = m->tc && m->npal ? m->tc[t] : 0;
    m->t[3 * (size_t)t + 2] = v; /* (a, b, x) */
    if (mesh_push_triangle(m, vs[1], vs[2], v, ct) < 0 ||
        mesh_push_triangle(m, vs[2], vs[0], v, ct) < 0)
        return -1;
    c->used[t] = 1;
    return 1;
}

/* One pass: the planes under the triangles, then edges, then corners;
 * *split counts the splits.  0 or -1. */
static int pass_once(crease_mesh *c, int *split)
{
    mesh *m = c->m;
    size_t nt = (size_t)m->nt;
    c->tp = malloc(nt * sizeof *c->tp);
    c->opp = malloc(3 * nt * sizeof *c->opp);
    c->used = calloc(nt, 1);
    c->start = c->fan = NULL;
    int rc = -1;
    if (!c->tp || !c->opp || !c->used || mesh_half_twins(m, 0, c->opp) != 0 ||
        mesh_vertex_fans(m, 0, &c->start, &c->fan) != 0)
        goto done;
    for (size_t t = 0; t < nt; t++)
        c->tp[t] = face_under(c, (int32_t)t);
    for (int32_t v = 0; v < m->nv; v++) {
        int r = snap_vertex(c, v);
        if (r < 0) goto done;
        *split += r;
    }
    for (size_t x = 0; x < 3 * nt; x++) {
        int r = split_edge(c, (int32_t)x);
        if (r < 0) goto done;
        *split += r;
    }
    for (size_t t = 0; t < nt; t++) {
        int r = split_corner(c, (int32_t)t);
        if (r < 0) goto done;
        *split += r;
    }
    rc = 0;
done:
    free(c->tp);
    free(c->opp);
    free(c->used);
    free(c->start);
    free(c->fan);
    return rc;
}

int mesh_split_creases(mesh *m, mesh_snapper *sn, int *splits)
{
    *splits = 0;
    if (!sn->arena || m->nt == 0) return 0;
    crease_mesh c;
    memset(&c, 0, sizeof c);
    c.m = m;
    c.sn = sn;
    c.h = sn->d->h;
    c.cap = 8192;
    c.pl = calloc(c.cap, sizeof *c.pl);
    int rc = c.pl ? 0 : -1, fresh;
    for (int32_t v = 0; v < m->nv && rc == 0; v++) {
        double p[3];
        mesh_vertex_at(m, v, p);
        int32_t *slot = mesh_fmap_slot(&c.pos, mesh_pos_key(p), &fresh);
        if (!slot)
            rc = -1;
        else if (fresh)
            *slot = v;
    }
    for (int pass = 0; pass < PASSES && rc == 0; pass++) {
        int split = 0;
        rc = pass_once(&c, &split);
        *splits += split;
        if (!split) break;
    }
    free(c.pl);
    free(c.pos.key);
    free(c.pos.val);
    return rc;
}
