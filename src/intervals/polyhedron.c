/*
 * polyhedron.c — closed triangle meshes (polyhedron(), imported meshes,
 * twisted extrusions): a BVH over the triangles and a watertight ray test.
 *
 * Faces arrive as polygons wound clockwise seen from outside (OpenSCAD) and
 * are cut into triangles by diagonals (a non-planar one as OpenSCAD cuts it,
 * face_tess.c, for faces a user wrote; else a fan).  Faces a user wrote
 * (iv_shape_polyhedron) are read first as OpenSCAD reads them
 * (mesh_orient.c): turned where they wind inconsistently, and an open
 * surface becomes a sheet whose every crossing is a thin span.
 * Inside-ness along a line is the nonzero winding rule: every triangle the
 * line crosses adds +1 when the line enters through it and -1 when it
 * leaves, hits at equal t are summed before the state is read, and the
 * solid is where the running sum is positive.  The triangles of a concave
 * face have both orientations and their signed cover is exactly the face,
 * so no ear clipping is needed — provided all triangles of one face report
 * bitwise the same t, which is why t comes from the face's plane rather
 * than from each triangle.
 *
 * The ray–triangle test is Woop, Benthin and Wald (JCGT 2013): shear the
 * ray onto +z and evaluate three 2D edge functions.  Shared vertices map to
 * bitwise equal sheared coordinates and an edge's function in the two
 * triangles that share it are exact negatives, so there are no gaps.  To
 * also avoid double hits, an edge function that is exactly zero takes the
 * sign it would have for the ray moved by (ε, ε²) — one perturbation for all
 * edges, so every triangle around an edge or vertex agrees, and a line
 * through a vertex or along an edge counts exactly as a line beside it.
 *
 * The BVH's leaves hold references to triangles.  A long thin triangle
 * across the axes has a box far larger than itself, and a ray would test
 * every such triangle whose box it meets (a 90° twist of a 10^5-gon: tens
 * of thousands per ray), so before building, such triangles are clipped
 * into several references with smaller boxes (bvh_split.c).  A ray may then
 * meet one triangle through two references; its hits on one triangle have
 * bitwise the same t, and all but one are dropped after sorting.
 *
 * Ownership: the mesh is immutable after iv_shape_mesh and reference
 * counted (iv_shape_retain/release).  The triangles are stored in the order
 * of their first reference; a boundary's part is the triangle index modulo
 * 65536, and the normal picks among the few candidates the one whose plane
 * passes nearest the point.
 */
#include "shape_kinds.h"
#include "vec3.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

typedef struct bnode {
    double lo[3], hi[3];
    int start, count; /* leaf: triangles [start, start+count); inner: count 0 */
    int right;        /* inner: right child (left is this + 1) */
} bnode;

struct iv_mesh {
    atomic_int refs;
    int nv, nt, nf, nn;
    double (*v)[3];
    int (*tri)[3];   /* in the order of their first reference */
    int *face;       /* source face (plane) of each triangle */
    double (*pl)[4]; /* per face: outward unit normal, offset */
    int nr;          /* references: nt, or more when triangles were clipped */
    int *ref;        /* the triangle of each reference, in BVH order */
    bnode *node;
    double lo[3], hi[3];
    double volume;
    int sheet; /* open (iv_shape_polyhedron): each crossing is a thin span */
};

void iv_mesh_retain(iv_mesh *m)
{
    atomic_fetch_add(&m->refs, 1);
}

void iv_mesh_release(iv_mesh *m)
{
    if (atomic_fetch_sub(&m->refs, 1) != 1) return;
    free(m->v);
    free(m->tri);
    free(m->face);
    free(m->pl);
    free(m->ref);
    free(m->node);
    free(m);
}

/* ---- building ------------------------------------------------------------------ */

/* Node over items[start, start+count) (an item's id is its triangle), whose
 * box is box = {lo, hi}; returns its index.  Leaves of at most 4
 * references. */
static int build_node(iv_mesh *m, iv_bvh_item *items, int start, int count, int depth,
                      const double box[2][3])
{
    int ni = m->nn++;
    bnode *nd = &m->node[ni];
    memcpy(nd->lo, box[0], sizeof nd->lo);
    memcpy(nd->hi, box[1], sizeof nd->hi);
    nd->start = start;
    nd->count = count;
    nd->right = -1;
    if (count <= 4) return ni;
    double kids[2][2][3];
    int l = iv_bvh_split_boxes(items + start, count, depth, kids);
    m->node[ni].count = 0;
    build_node(m, items, start, l, depth + 1, (const double(*)[3])kids[0]);
    int r = build_node(m, items, start + l, count - l, depth + 1, (const double(*)[3])kids[1]);
    m->node[ni].right = r;
    return ni;
}

/* Triangles of the polygon F[a..b] closed by the edge F[b]F[a] (b - a >= 2),
 * appended at tri[*t]: the triangle (a, mid, b) and the two polygons it
 * leaves.  Any diagonal splits a polygon's winding number into the sum of
 * its two parts', so this covers a concave face as exactly as a fan; unlike
 * a fan, whose triangles of a many-sided face all reach across it from one
 * corner, its triangles are mostly small and near the boundary (those of a
 * circle's 10^5-gon have boxes of about their own area, a fan's up to 10^4
 * times theirs).  A quadrilateral gives the fan's two triangles. */
static void split_face(const int *F, int a, int b, int (*tri)[3], int *t)
{
    if (b - a < 2) return;
    int mid = a + (b - a + 1) / 2;
    split_face(F, a, mid, tri, t);
    tri[*t][0] = F[a];
    tri[*t][1] = F[mid];
    tri[*t][2] = F[b];
    (*t)++;
    split_face(F, mid, b, tri, t);
}

/* References that early split clipping may add, per triangle, and in all
 * (80 bytes each while building, about 50 after).  Each extra reference per
 * triangle costs about a microsecond of building on the twisted 10^5-gon,
 * and the second one still halves the tests a ray makes there. */
#define MESH_SPLIT_EXTRA 2.0
enum { MESH_REF_MAX = 1 << 22 };

/* How build reads the faces: as our own code makes them (closed), or as a
 * user wrote them (iv_shape_polyhedron), an open surface a sheet or, for a
 * mesh, a solid best effort. */
typedef enum faces_from { FROM_CODE, FROM_USER, FROM_USER_SOLID } faces_from;

static int build(iv_shape *s, const double (*verts)[3], int nverts, const int *faces,
                 const int *face_start, int nfaces, double extra_per_triangle, long *nref,
                 faces_from from);

int iv_shape_mesh(iv_shape *s, const double (*verts)[3], int nverts, const int *faces,
                  const int *face_start, int nfaces)
{
    return build(s, verts, nverts, faces, face_start, nfaces, MESH_SPLIT_EXTRA, NULL, FROM_CODE);
}

int iv_shape_mesh_budget(iv_shape *s, const double (*verts)[3], int nverts, const int *faces,
                         const int *face_start, int nfaces, double extra_per_triangle, long *nref)
{
    return build(s, verts, nverts, faces, face_start, nfaces, extra_per_triangle, nref, FROM_CODE);
}

int iv_shape_polyhedron(iv_shape *s, const double (*verts)[3], int nverts, const int *faces,
                        const int *face_start, int nfaces)
{
    return build(s, verts, nverts, faces, face_start, nfaces, MESH_SPLIT_EXTRA, NULL, FROM_USER);
}

int iv_shape_polyhedron_solid(iv_shape *s, const double (*verts)[3], int nverts, const int *faces,
                              const int *face_start, int nfaces)
{
    return build(s, verts, nverts, faces, face_start, nfaces, MESH_SPLIT_EXTRA, NULL,
                 FROM_USER_SOLID);
}

/* Turns the planes of the triangles flip[] marks (which read_edges turned).
 * Returns 0, or 1 when a plane's triangles do not all agree (a face the
 * turning would split: then nothing is turned back, and the caller reads
 * the mesh as open). */
static int turn_planes(double (*pl)[4], int np, const int *face, const unsigned char *flip, int nt)
{
    signed char *st = calloc((size_t)np, 1);
    if (!st) return 1;
    int bad = 0;
    for (int i = 0; i < nt && !bad; i++) {
        signed char want = flip[i] ? 1 : -1;
        if (st[face[i]] == 0) st[face[i]] = want;
        bad = st[face[i]] != want;
    }
    if (!bad)
        for (int p = 0; p < np; p++)
            if (st[p] == 1)
                for (int k = 0; k < 4; k++)
                    pl[p][k] = -pl[p][k];
    free(st);
    return bad;
}

/* Keeps in m->v (a copy of the input's m->nv points) only the points the
 * triangles use, in their order, and renumbers tri to match: a point no
 * face uses is no part of the shape, nor of hull() of it, as in OpenSCAD.
 * Returns 0, or -1 when out of memory. */
static int keep_used_points(iv_mesh *m, int (*tri)[3])
{
    int *to = malloc((size_t)m->nv * sizeof *to);
    if (!to) return -1;
    for (int i = 0; i < m->nv; i++)
        to[i] = -1;
    for (int i = 0; i < m->nt; i++)
        for (int j = 0; j < 3; j++)
            to[tri[i][j]] = 0;
    int n = 0;
    for (int i = 0; i < m->nv; i++)
        if (to[i] == 0) {
            memmove(m->v[n], m->v[i], sizeof *m->v);
            to[i] = n++;
        }
    for (int i = 0; i < m->nt; i++)
        for (int j = 0; j < 3; j++)
            tri[i][j] = to[tri[i][j]];
    m->nv = n;
    free(to);
    return 0;
}

/* The signed volume of the triangles, positive when they wind as OpenSCAD's
 * faces: clockwise from outside, so the right-handed triple product is
 * negative for a proper solid; negate it. */
static double signed_volume(const double (*v)[3], const int (*tri)[3], int nt)
{
    double vol = 0;
    for (int i = 0; i < nt; i++)
        vol -= triple3(v[tri[i][0]], v[tri[i][1]], v[tri[i][2]]) / 6;
    return vol;
}

static int build(iv_shape *s, const double (*verts)[3], int nverts, const int *faces,
                 const int *face_start, int nfaces, double extra_per_triangle, long *nref,
                 faces_from from)
{
    const int as_written = from != FROM_CODE;
    if (nverts <= 0 || nfaces <= 0) return -1;
    for (int i = 0; i < nverts; i++)
        for (int k = 0; k < 3; k++)
            if (!isfinite(verts[i][k])) return -1;
    long nt = 0;
    for (int f = 0; f < nfaces; f++) {
        int len = face_start[f + 1] - face_start[f];
        if (len < 0) return -1;
        for (int j = face_start[f]; j < face_start[f + 1]; j++)
            if (faces[j] < 0 || faces[j] >= nverts) return -1;
        if (len >= 3) nt += len - 2;
    }
    if (nt == 0 || nt > (1L << 28)) return -1;
    iv_mesh *m = calloc(1, sizeof *m);
    if (!m) return -1;
    int rc = -1;
    iv_bvh_item *items = NULL;
    int *first = NULL;
    int(*tri)[3] = malloc((size_t)nt * sizeof *tri);
    int *face = malloc((size_t)nt * sizeof *face);
    m->v = malloc((size_t)nverts * sizeof *m->v);
    /* A non-planar face is split into its fan triangles, each its own
     * plane, so at most nt planes. */
    m->pl = malloc((size_t)nt * sizeof *m->pl);
    m->tri = malloc((size_t)nt * sizeof *m->tri);
    m->face = malloc((size_t)nt * sizeof *m->face);
    if (!tri || !face || !m->v || !m->pl || !m->tri || !m->face) goto done;
    memcpy(m->v, verts, (size_t)nverts * sizeof *m->v);
    m->nv = nverts;
    for (int k = 0; k < 3; k++) {
        m->lo[k] = INFINITY;
        m->hi[k] = -INFINITY;
    }
    /* the box of the points the faces use: a point no face uses is not
     * part of the shape (nor of OpenSCAD's box, which frames the view) */
    for (int f = 0; f < nfaces; f++) {
        if (face_start[f + 1] - face_start[f] < 3) continue;
        for (int j = face_start[f]; j < face_start[f + 1]; j++)
            for (int k = 0; k < 3; k++) {
                m->lo[k] = fmin(m->lo[k], verts[faces[j]][k]);
                m->hi[k] = fmax(m->hi[k], verts[faces[j]][k]);
            }
    }
    int t = 0, np = 0;
    for (int f = 0; f < nfaces; f++) {
        const int *F = faces + face_start[f];
        int len = face_start[f + 1] - face_start[f];
        if (len < 3) continue;
        /* Newell's normal: right-handed, so it points inward for
         * OpenSCAD's clockwise-from-outside winding. */
        double n[3] = {0, 0, 0}, c[3] = {0, 0, 0};
        for (int j = 0; j < len; j++) {
            const double *p = verts[F[j]], *q = verts[F[(j + 1) % len]];
            n[0] += (p[1] - q[1]) * (p[2] + q[2]);
            n[1] += (p[2] - q[2]) * (p[0] + q[0]);
            n[2] += (p[0] - q[0]) * (p[1] + q[1]);
            for (int k = 0; k < 3; k++)
                c[k] += p[k] / len;
        }
        double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        int planar = l > 0;
        if (planar && len > 3) {
            double ext = 0;
            for (int k = 0; k < 3; k++)
                ext = fmax(ext, m->hi[k] - m->lo[k]);
            for (int j = 0; j < len; j++) {
                const double *p = verts[F[j]];
                double dist =
                    ((p[0] - c[0]) * n[0] + (p[1] - c[1]) * n[1] + (p[2] - c[2]) * n[2]) / l;
                if (fabs(dist) > 1e-9 * ext) planar = 0;
            }
        }
        int t0 = t;
        if (planar) {
            split_face(F, 0, len - 1, tri, &t);
        } else if (as_written && iv_face_tessellate(verts, F, len, tri + t) == 0) {
            /* as OpenSCAD's tessellation cuts it (face_tess.c) */
            t += len - 2;
        } else {
            /* each fan triangle its own plane, as OpenSCAD triangulates */
            for (int j = 1; j + 1 < len; j++, t++) {
                tri[t][0] = F[0];
                tri[t][1] = F[j];
                tri[t][2] = F[j + 1];
            }
        }
        for (t = t0; t < t0 + len - 2; t++) {
            const double *a = verts[tri[t][0]], *p = verts[tri[t][1]], *q = verts[tri[t][2]];
            if (!planar) {
                double u[3], w[3], tn[3];
                for (int k = 0; k < 3; k++) {
                    u[k] = p[k] - a[k];
                    w[k] = q[k] - a[k];
                }
                tn[0] = u[1] * w[2] - u[2] * w[1];
                tn[1] = u[2] * w[0] - u[0] * w[2];
                tn[2] = u[0] * w[1] - u[1] * w[0];
                double tl = sqrt(tn[0] * tn[0] + tn[1] * tn[1] + tn[2] * tn[2]);
                if (!(tl > 0)) tl = 1;
                for (int k = 0; k < 3; k++)
                    m->pl[np][k] = -tn[k] / tl;
                m->pl[np][3] = m->pl[np][0] * a[0] + m->pl[np][1] * a[1] + m->pl[np][2] * a[2];
                face[t] = np++;
            } else {
                face[t] = np;
            }
        }
        if (planar) {
            for (int k = 0; k < 3; k++)
                m->pl[np][k] = -n[k] / l;
            m->pl[np][3] = m->pl[np][0] * c[0] + m->pl[np][1] * c[1] + m->pl[np][2] * c[2];
            np++;
        }
    }
    m->nt = t;
    m->nf = np;
    if (keep_used_points(m, tri) != 0) goto done;
    const double(*V)[3] = (const double(*)[3])m->v;
    iv_mesh_reading reading = IV_MESH_CLOSED;
    if (as_written) {
        unsigned char *flip = malloc((size_t)t);
        if (!flip) goto done;
        reading = iv_mesh_read_edges(V, m->nv, tri, t, flip);
        if (reading == IV_MESH_TURNED && turn_planes(m->pl, np, face, flip, t))
            reading = IV_MESH_OPEN;
        free(flip);
        if (reading == IV_MESH_READ_FAILED) goto done;
        m->sheet = reading == IV_MESH_OPEN && from == FROM_USER;
    }
    double vol = m->sheet ? 0 : signed_volume(V, (const int(*)[3])tri, t);
    if (vol < 0) {
        /* Wound the other way round as a whole: turn it inside out rather
         * than render an inverted solid (OpenSCAD's preview shows it
         * solid). */
        for (int i = 0; i < t; i++) {
            int x = tri[i][1];
            tri[i][1] = tri[i][2];
            tri[i][2] = x;
        }
        for (int i = 0; i < np; i++)
            for (int k = 0; k < 4; k++)
                m->pl[i][k] = -m->pl[i][k];
        vol = -vol;
    }
    m->volume = vol;
    long extra = 0;
    if (extra_per_triangle > 0 && t < MESH_REF_MAX)
        extra = (long)fmin(extra_per_triangle * t, (double)(MESH_REF_MAX - t));
    long nr = 0;
    for (;;) {
        items = iv_bvh_clip_triangles(V, (const int(*)[3])tri, t, extra, &nr);
        m->node = malloc((size_t)(2 * nr) * sizeof *m->node);
        m->ref = malloc((size_t)nr * sizeof *m->ref);
        if ((items && m->node && m->ref) || extra == 0) break;
        /* short of memory (a data limit): the plain hierarchy, slower for
         * long thin triangles but no larger than the mesh itself */
        free(items);
        free(m->node);
        free(m->ref);
        items = NULL;
        m->node = NULL;
        m->ref = NULL;
        extra = 0;
    }
    first = malloc((size_t)t * sizeof *first);
    if (!items || !m->node || !m->ref || !first) goto done;
    m->nr = (int)nr;
    double box[2][3];
    for (int k = 0; k < 3; k++) {
        box[0][k] = INFINITY;
        box[1][k] = -INFINITY;
    }
    for (int j = 0; j < m->nr; j++)
        for (int k = 0; k < 3; k++) {
            box[0][k] = items[j].lo[k] < box[0][k] ? items[j].lo[k] : box[0][k];
            box[1][k] = items[j].hi[k] > box[1][k] ? items[j].hi[k] : box[1][k];
        }
    build_node(m, items, 0, m->nr, 0, (const double(*)[3])box);
    bnode *shrunk = realloc(m->node, (size_t)m->nn * sizeof *m->node);
    if (shrunk) m->node = shrunk;
    /* Triangles in the order of their first reference: a leaf's are then
     * near each other in memory, and with one reference each the
     * references are 0, 1, 2, ... */
    for (int i = 0; i < t; i++)
        first[i] = -1;
    int nt_seen = 0;
    for (int j = 0; j < m->nr; j++) {
        int id = items[j].id;
        if (first[id] < 0) {
            first[id] = nt_seen;
            memcpy(m->tri[nt_seen], tri[id], sizeof *tri);
            m->face[nt_seen] = face[id];
            nt_seen++;
        }
        m->ref[j] = first[id];
    }
    if (nref) *nref = nr;
    atomic_init(&m->refs, 1);
    memset(s, 0, sizeof *s);
    s->kind = IV_SHAPE_MESH;
    s->u.mesh.m = m;
    if (as_written)
        rc = reading == IV_MESH_CLOSED    ? 0
             : reading == IV_MESH_TURNED  ? 1
             : reading == IV_MESH_CRACKED ? 2
                                          : 3;
    else
        rc = iv_mesh_edges_closed((const int(*)[3])m->tri, m->nt, m->nv) == 0 ? 1 : 0;
done:
    free(tri);
    free(face);
    free(items);
    free(first);
    if (rc < 0) {
        m->refs = 1;
        iv_mesh_release(m);
    }
    return rc;
}

const double (*iv_mesh_vertices(const iv_shape *s, int *n))[3]
{
    if (s->kind != IV_SHAPE_MESH) return NULL;
    *n = s->u.mesh.m->nv;
    return (const double(*)[3])s->u.mesh.m->v;
}

const int (*iv_mesh_triangles(const iv_shape *s, int *n))[3]
{
    if (s->kind != IV_SHAPE_MESH) return NULL;
    *n = s->u.mesh.m->nt;
    return (const int(*)[3])s->u.mesh.m->tri;
}

double iv_mesh_volume(const iv_shape *s)
{
    return s->kind == IV_SHAPE_MESH ? s->u.mesh.m->volume : 0;
}

int iv_mesh_max_spans(const iv_mesh *m)
{
    return m->sheet ? m->nt + 1 : m->nt / 2 + 1;
}

int iv_mesh_bounds(const iv_mesh *m, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        if (!(m->lo[k] <= m->hi[k])) return -1;
        lo[k] = m->lo[k];
        hi[k] = m->hi[k];
    }
    /* a flat mesh has no volume, but keep it (best effort) */
    return 0;
}

/* ---- queries ------------------------------------------------------------------- */

/* The sign of an edge function, with zero resolved by moving the ray by
 * (ε, ε²) in the sheared plane: e(δ) = e + δx·gx + δy·gy. */
static int edge_sign(double e, double gx, double gy)
{
    if (e > 0) return 1;
    if (e < 0) return -1;
    if (gx != 0) return gx > 0 ? 1 : -1;
    if (gy != 0) return gy > 0 ? 1 : -1;
    return 0; /* the edge projects to a point: it has no side */
}

static int cmp_bound(const void *a, const void *b)
{
    double x = ((const iv_bound *)a)->t, y = ((const iv_bound *)b)->t;
    return (x > y) - (x < y);
}

/* By t, then by prim (the triangle, while hits hold it). */
static int cmp_bound_prim(const void *a, const void *b)
{
    const iv_bound *x = a, *y = b;
    if (x->t != y->t) return (x->t > y->t) - (x->t < y->t);
    return (x->prim > y->prim) - (x->prim < y->prim);
}

static int before(const iv_bound *x, const iv_bound *y, int by_prim)
{
    return x->t < y->t || (by_prim && x->t == y->t && x->prim < y->prim);
}

/* Sorts hit[0..nh) by t; with `dedup`, also by the triangle in prim, and
 * drops all but one of the hits on the same triangle — they have bitwise
 * the same t, which comes from the face's plane.  Returns the count. */
static long sort_hits(iv_bound *hit, long nh, int dedup)
{
    if (nh < 24) {
        for (long i = 1; i < nh; i++) {
            iv_bound x = hit[i];
            long j = i;
            while (j > 0 && before(&x, &hit[j - 1], dedup)) {
                hit[j] = hit[j - 1];
                j--;
            }
            hit[j] = x;
        }
    } else {
        qsort(hit, (size_t)nh, sizeof *hit, dedup ? cmp_bound_prim : cmp_bound);
    }
    if (!dedup) return nh;
    long w = nh ? 1 : 0;
    for (long i = 1; i < nh; i++)
        if (hit[i].t != hit[w - 1].t || hit[i].prim != hit[w - 1].prim) hit[w++] = hit[i];
    return w;
}

/* The spans of an open mesh (a surface without an inside) from its sorted
 * crossings hit[0..nh): each crossing is a span a billionth of the mesh's
 * size thick — the face itself in a picture, and thick enough that merges
 * keep it — and crossings closer than that are one span.  The hits move
 * to the back of the room (nh <= triangles < room / 2, as
 * iv_mesh_max_spans leaves room for a span per triangle) so that the spans
 * written from the front never overtake them. */
static int sheet_spans(const iv_mesh *m, const double d[3], iv_bound *hit, long nh, long room,
                       iv_list *out)
{
    double ext = 0;
    for (int k = 0; k < 3; k++)
        ext = fmax(ext, m->hi[k] - m->lo[k]);
    double thin = 1e-9 * ext / sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    iv_bound *src = hit + room - nh;
    memmove(src, hit, (size_t)nh * sizeof *hit);
    iv_span *sp = out->v + out->n;
    int ns = 0;
    for (long i = 0; i < nh; i++) {
        iv_bound b = src[i];
        b.flip = 0;
        double end = b.t + fmax(thin, 1e-12 * fabs(b.t));
        if (!(end > b.t)) end = nextafter(b.t, INFINITY);
        if (ns > 0 && b.t <= sp[ns - 1].exit.t) {
            if (end > sp[ns - 1].exit.t) sp[ns - 1].exit.t = end;
            continue;
        }
        sp[ns].enter = b;
        sp[ns].exit = b;
        sp[ns].exit.t = end;
        ns++;
    }
    out->n += ns;
    return ns;
}

int iv_mesh_intersect(const iv_mesh *m, const double o[3], const double d[3], int32_t prim,
                      iv_list *out)
{
    int kz = 0;
    for (int k = 1; k < 3; k++)
        if (fabs(d[k]) > fabs(d[kz])) kz = k;
    if (d[kz] == 0) return 0;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0) {
        int x = kx;
        kx = ky;
        ky = x;
    }
    const double Sx = d[kx] / d[kz], Sy = d[ky] / d[kz];
    double inv[3];
    for (int k = 0; k < 3; k++)
        inv[k] = 1 / d[k];
    /* Hits go to the list's spare room, read as an array of bounds; the
     * flip field holds the crossing's sign (+1 enter: 1, -1 exit: 0) until
     * the sweep below rewrites them as spans. */
    iv_bound *hit = &out->v[out->n].enter;
    const long room = 2L * (out->cap - out->n);
    long nh = 0;
    /* Several references of a clipped triangle may report it: hits then
     * carry the triangle in prim until they are sorted and deduplicated. */
    const int clipped = m->nr > m->nt;
    int stack[96], sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
        const bnode *nd = &m->node[stack[--sp]];
        double t0 = -INFINITY, t1 = INFINITY;
        int miss = 0;
        for (int k = 0; k < 3 && !miss; k++) {
            if (d[k] == 0) {
                if (o[k] < nd->lo[k] || o[k] > nd->hi[k]) miss = 1;
                continue;
            }
            double ta = (nd->lo[k] - o[k]) * inv[k], tb = (nd->hi[k] - o[k]) * inv[k];
            if (ta > tb) {
                double x = ta;
                ta = tb;
                tb = x;
            }
            /* 1e-9 relative slack: the box test must never reject a
             * triangle the exact test below would accept. */
            double slack = 1e-9 * (fabs(ta) + fabs(tb)) + 1e-300;
            /* comparisons, not fmax/fmin (library calls): a NaN (0·∞
             * for a subnormal direction) is skipped all the same */
            t0 = ta - slack > t0 ? ta - slack : t0;
            t1 = tb + slack < t1 ? tb + slack : t1;
        }
        if (miss || t0 > t1) continue;
        if (nd->count == 0) {
            /* depth <= IV_BVH_SAH_DEPTH + log2(references): cannot happen */
            if (sp + 2 > 96) return -1;
            stack[sp++] = nd->right;
            stack[sp++] = (int)(nd - m->node) + 1;
            continue;
        }
        for (int r = nd->start; r < nd->start + nd->count; r++) {
            const int i = m->ref[r];
            if (clipped && r > nd->start && i == m->ref[r - 1]) continue;
            const int *tv = m->tri[i];
            double X[3], Y[3];
            for (int j = 0; j < 3; j++) {
                const double *p = m->v[tv[j]];
                double az = p[kz] - o[kz];
                X[j] = (p[kx] - o[kx]) - Sx * az;
                Y[j] = (p[ky] - o[ky]) - Sy * az;
            }
            /* A = 0, B = 1, C = 2 */
            double U = X[2] * Y[1] - Y[2] * X[1];
            double V = X[0] * Y[2] - Y[0] * X[2];
            double W = X[1] * Y[0] - Y[1] * X[0];
            int su = edge_sign(U, Y[2] - Y[1], X[1] - X[2]);
            int sv = edge_sign(V, Y[0] - Y[2], X[2] - X[0]);
            int sw = edge_sign(W, Y[1] - Y[0], X[0] - X[1]);
            int pos = (su > 0) + (sv > 0) + (sw > 0), neg = (su < 0) + (sv < 0) + (sw < 0);
            if ((pos && neg) || (!pos && !neg)) continue;
            const double *q = m->pl[m->face[i]];
            double a = q[0] * d[0] + q[1] * d[1] + q[2] * d[2];
            if (a == 0) continue;
            double t = (q[3] - (q[0] * o[0] + q[1] * o[1] + q[2] * o[2])) / a;
            if (!isfinite(t)) continue;
            if (nh >= room && clipped) nh = sort_hits(hit, nh, 1);
            if (nh >= room) return -1;
            /* pos: det > 0, the triangle turns its outward side away
             * from the ray (see the file comment): an exit. */
            hit[nh++] =
                (iv_bound){t, clipped ? i : prim, (uint16_t)(i & 0xffff), (uint16_t)(neg ? 1 : 0)};
        }
    }
    if (nh == 0) return 0;
    nh = sort_hits(hit, nh, clipped);
    if (clipped)
        for (long i = 0; i < nh; i++)
            hit[i].prim = prim;
    if (m->sheet) return sheet_spans(m, d, hit, nh, room, out);
    /* Sweep: sum the signs at each distinct t, emit on state changes.  The
     * write index never passes the read index. */
    long w = 0;
    int count = 0, inside = 0;
    iv_bound last = hit[nh - 1];
    for (long i = 0; i < nh;) {
        long j = i;
        int delta = 0;
        iv_bound first_in = hit[i], first_out = hit[i];
        int have_in = 0, have_out = 0;
        while (j < nh && hit[j].t == hit[i].t) {
            if (hit[j].flip) {
                delta++;
                if (!have_in) first_in = hit[j], have_in = 1;
            } else {
                delta--;
                if (!have_out) first_out = hit[j], have_out = 1;
            }
            j++;
        }
        count += delta;
        int now = count > 0;
        if (now != inside) {
            iv_bound bnd = now ? first_in : first_out;
            bnd.flip = 0;
            hit[w++] = bnd;
            inside = now;
        }
        i = j;
    }
    if (inside) {
        /* Not closed along this line (best effort for open meshes): end at
         * the last hit. */
        if (hit[w - 1].t < last.t) {
            last.flip = 0;
            hit[w++] = last;
        } else {
            w--;
        }
    }
    int ns = (int)(w / 2);
    out->n += ns;
    return ns;
}

void iv_mesh_normal(const iv_mesh *m, const double p[3], int part, double n[3])
{
    int best = -1;
    double bd = INFINITY;
    for (int i = part; i < m->nt; i += 65536) {
        const double *q = m->pl[m->face[i]];
        double dist = fabs(q[0] * p[0] + q[1] * p[1] + q[2] * p[2] - q[3]);
        if (dist < bd) {
            bd = dist;
            best = i;
        }
    }
    if (best < 0) {
        n[0] = n[1] = 0;
        n[2] = 1;
        return;
    }
    const double *q = m->pl[m->face[best]];
    n[0] = q[0];
    n[1] = q[1];
    n[2] = q[2];
}
