/*
 * contour.c — a closed 2-manifold triangle mesh from tri-dexel Hermite data.
 *
 * Method: the cell topology of Manifold Dual Contouring (Schaefer, Ju &
 * Warren 2007) — one vertex per connected component of the surface inside a
 * cell, as Marching Cubes would draw it, placed by minimising that
 * component's QEF — but the vertices are joined through the primal patch
 * instead of by dual quads, with the face feature points of Cubical
 * Marching Squares (Ho et al. 2005).  Why not plain dual quads: on a uniform
 * grid without MDC's octree clustering, a face whose four corners alternate
 * in sign can put both of its surface segments into one component on each
 * side (a small tunnel through the face), and the two cells' vertices are
 * then joined by an edge of four quads.  Joining through the patch cannot do
 * that, and the mesh is manifold by construction:
 *
 *   - Node signs come from the z rays only (a node is inside when an odd
 *     number of z crossings lie at or below it), so all cells agree on them.
 *   - On each cell face, walking the corners counter-clockwise seen from
 *     outside the cell, every crossing where the walk enters the solid is
 *     joined to the next crossing: the segments cut off the inside corners.
 *     An ambiguous face (inside corners on a diagonal) keeps them apart
 *     unless the solid holds the face's middle (a ray asks the scene, as the
 *     asymptotic decider asks the bilinear saddle): then they are joined
 *     and the segments cut off the outside corners.  This depends on the
 *     face alone, so both cells sharing a face draw the same segments, in
 *     opposite directions.
 *   - Each crossing starts one segment and ends another within a cell, so the
 *     segments chain into loops (the MC components); each loop is a disc,
 *     triangulated alone.  Every segment is shared by exactly two cells, and
 *     every loop vertex's triangles form one fan: closed, 2-manifold, and
 *     consistently oriented (inside is on the right of a segment seen from
 *     outside, which makes the triangles counter-clockwise seen from outside).
 *
 * Vertices: one per sign-changing grid edge at the exact ray crossing (the
 * first crossing of the right direction on the edge's ray, moved at most
 * EPS·h away from the nodes so no two vertices meet); one per face segment
 * whose two normals meet at more than the feature angle, or whose two ends
 * lie on two plane patches at any angle over 1° (the facets of a polygon,
 * hull or polyhedron: mesh_patch_of), at the crossing of their tangent
 * lines within the face (where a sharp edge passes through the face),
 * shrunk into the face by EPS·h; one per loop that holds a feature, at its
 * QEF minimiser clamped to the cell shrunk by EPS·h.  The tangent planes
 * pass through the exact crossings, not the vertices moved off the nodes.  A loop without
 * a feature is triangulated among its own vertices when every added diagonal
 * joins two grid edges on no common face (so no other cell can draw it) and
 * no triangle is degenerate or folded; otherwise it is fanned around its QEF
 * vertex.  Since consecutive loop vertices lie on one cell face and the fan
 * centre lies at least EPS·h off every face, no fan triangle has zero area.
 * A fan that would turn a triangle over (against the normals at its loop
 * corners) is replaced: by one about the sharp edge's point within the
 * cell, or the loop triangulated alone (fan_free), or about the QEF vertex
 * unsnapped or the loop's centre.  Such fans were where a crease clips a
 * corner of its cell, and they lasted through every later stage: 48
 * triangles turned over on the bench part, 153 on pinched_cells.scad.
 *
 * The sweep goes up the z slabs and keeps two layers of node signs and of
 * edge-vertex indices, so its memory beyond the output is O(n²) plus the z
 * crossings bucketed by layer (each layer's signs are the previous layer's
 * with the columns that cross in between flipped).
 */
#include "dexels.h"
#include "../intervals/vec3.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EPS MESH_CONTOUR_EPS

/* Corner c of a cell is at offset (c & 1, c >> 1 & 1, c >> 2 & 1).  Edge e
 * runs along axis e / 4; its other two offsets are the bits of e % 4 (the
 * lower axis first).  Faces: 2·axis + side, corners listed counter-clockwise
 * seen from outside the cell. */
static const int face_corner[6][4] = {
    {0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6},
};

static int edge_of(int ca, int cb)
{
    int x = ca ^ cb;
    int axis = x == 1 ? 0 : x == 2 ? 1 : 2;
    int lo = ca & cb;
    int b0, b1;
    if (axis == 0) {
        b0 = lo >> 1 & 1;
        b1 = lo >> 2 & 1;
    } else if (axis == 1) {
        b0 = lo & 1;
        b1 = lo >> 2 & 1;
    } else {
        b0 = lo & 1;
        b1 = lo >> 1 & 1;
    }
    return axis * 4 + b0 + 2 * b1;
}

static int edge_corner(int e, int which)
{
    int axis = e / 4, b0 = e & 1, b1 = e >> 1 & 1, c;
    if (axis == 0)
        c = 2 * b0 + 4 * b1;
    else if (axis == 1)
        c = b0 + 4 * b1;
    else
        c = b0 + 2 * b1;
    return which ? c | 1 << axis : c;
}

typedef struct tables {
    int face_edge[6][4]; /* edge between corner m and m+1 of the face */
    int edge_faces[12];  /* bit mask of the two faces holding the edge */
} tables;

static void tables_init(tables *tb)
{
    memset(tb, 0, sizeof *tb);
    for (int f = 0; f < 6; f++)
        for (int m = 0; m < 4; m++) {
            int e = edge_of(face_corner[f][m], face_corner[f][(m + 1) & 3]);
            tb->face_edge[f][m] = e;
            tb->edge_faces[e] |= 1 << f;
        }
}

/* ---- a small open-addressing map (dexels.h) ------------------------------ */

int32_t *mesh_fmap_slot(mesh_fmap *m, uint64_t key, int *fresh)
{
    if (2 * (m->n + 1) > m->cap) {
        size_t cap = m->cap ? 2 * m->cap : 256;
        uint64_t *k = calloc(cap, sizeof *k);
        int32_t *v = malloc(cap * sizeof *v);
        if (!k || !v) {
            free(k);
            free(v);
            return NULL;
        }
        for (size_t i = 0; i < m->cap; i++) {
            if (!m->key[i]) continue;
            size_t p = mesh_hash_mix(m->key[i]) & (cap - 1);
            while (k[p])
                p = (p + 1) & (cap - 1);
            k[p] = m->key[i];
            v[p] = m->val[i];
        }
        free(m->key);
        free(m->val);
        m->key = k;
        m->val = v;
        m->cap = cap;
    }
    size_t p = mesh_hash_mix(key) & (m->cap - 1);
    while (m->key[p] && m->key[p] != key)
        p = (p + 1) & (m->cap - 1);
    *fresh = !m->key[p];
    if (*fresh) {
        m->key[p] = key;
        m->n++;
    }
    return &m->val[p];
}

int mesh_fmap_has(const mesh_fmap *m, uint64_t key)
{
    if (!m->cap) return 0;
    size_t p = mesh_hash_mix(key) & (m->cap - 1);
    while (m->key[p] && m->key[p] != key)
        p = (p + 1) & (m->cap - 1);
    return m->key[p] != 0;
}

uint64_t mesh_pos_key(const double p[3])
{
    uint64_t k = 0x9e3779b97f4a7c15ULL;
    for (int c = 0; c < 3; c++) {
        float f = (float)p[c];
        if (f == 0) f = 0;
        uint32_t b;
        memcpy(&b, &f, sizeof b);
        k = mesh_hash_mix(k ^ b);
    }
    return k | 1;
}

/* ---- the sweep state ---------------------------------------------------- */

typedef struct sample {
    double p[3];
    double x[3]; /* the exact crossing (p is kept EPS·h from the nodes) */
    double n[3];
    int32_t vid;
    uint32_t patch; /* the crossing's (mesh_hit.patch); 0: none */
    uint16_t color; /* the crossing's (mesh_hit.color) */
} sample;

typedef struct sweep {
    const mesh_dexels *d;
    mesh *m;
    tables tb;
    double cos_feature;
    int nx, ny, nz;   /* cells */
    int k;            /* current slab */
    uint8_t *sign[2]; /* node signs of layers k, k+1: i + (nx+1) j */
    /* z crossings bucketed by the first node layer at or above them: the
     * columns flip[flip_at[k] .. flip_at[k + 1]) change sign at layer k. */
    uint32_t *flip;
    size_t *flip_at;
    int32_t *xv[2]; /* x-edge vertices of layers k, k+1: i + nx j */
    int32_t *yv[2]; /* y-edge vertices: i + (nx+1) j */
    int32_t *zv;    /* z-edge vertices of slab k: i + (nx+1) j */
    mesh_fmap faces;
    mesh_fmap pos; /* every vertex by its float position (mesh_pos_key) */
    mesh_snapper snap;
    mesh_vnormals vn; /* the edge samples' normals, for refine.c */
    int oom;
} sweep;

/* Push a vertex at p, or where a vertex is at p's float position already
 * (two cells' vertices snapped to one point of a sharp edge, which a reader
 * welding by position would join into one vertex of two fans) at fallback
 * (copied into p; NULL: at p all the same), and where that is taken too, a
 * little way from it towards `toward` (its cell's middle): the first of
 * four steps of 1e-4 h to a place of its own; its index, or -1 when out of
 * memory. */
static int32_t push_unique(sweep *s, double p[3], const double *fallback, const double *toward)
{
    int fresh;
    int32_t *slot = mesh_fmap_slot(&s->pos, mesh_pos_key(p), &fresh);
    if (slot && !fresh && fallback) {
        memcpy(p, fallback, 3 * sizeof *p);
        slot = mesh_fmap_slot(&s->pos, mesh_pos_key(p), &fresh);
        double from[3] = {p[0], p[1], p[2]}, d[3];
        sub3(toward, from, d);
        double l = sqrt(dot3(d, d));
        for (int k = 1; slot && !fresh && l > 0 && k <= 4; k++) {
            for (int c = 0; c < 3; c++)
                p[c] = from[c] + d[c] / l * fmin(k * 1e-4 * s->d->h, l);
            slot = mesh_fmap_slot(&s->pos, mesh_pos_key(p), &fresh);
        }
    }
    if (!slot) return -1;
    int32_t v = mesh_push_vertex(s->m, p[0], p[1], p[2]);
    if (v >= 0 && fresh) *slot = v;
    return v;
}

/* Push a vertex mesh_snap placed at p (on: on a sharp edge) in the cell
 * with corner lo by push_unique, at unsnapped where p is taken (then not on
 * the edge), with its entry in s->vn; its index, or -1 when out of memory. */
static int32_t push_snapped(sweep *s, double p[3], const double unsnapped[3], int on,
                            const double lo[3])
{
    static const double none[3] = {0, 0, 0};
    double snapped[3] = {p[0], p[1], p[2]}, mid[3];
    for (int c = 0; c < 3; c++)
        mid[c] = lo[c] + 0.5 * s->d->h;
    int32_t v = push_unique(s, p, unsnapped, mid);
    if (v < 0 ||
        mesh_vnormal_set(&s->vn, v, none, on && !memcmp(p, snapped, sizeof snapped), 0) != 0)
        return -1;
    return v;
}

/* The first layer k with t <= k·h, decided by the same comparison the
 * edge search makes (t <= seg·h), not by a rounded quotient alone. */
static int layer_of(double t, double h)
{
    double q = ceil(t / h);
    int k = q < 0 ? 0 : q > INT32_MAX - 2 ? INT32_MAX - 2 : (int)q;
    while (k > 0 && t <= (k - 1) * h)
        k--;
    while (t > k * h)
        k++;
    return k;
}

/* Bucket the z crossings by layer (a counting sort): O(crossings + nz). */
static int flips_init(sweep *s)
{
    const mesh_dexels *d = s->d;
    size_t nl = (size_t)s->nz + 2, nr = (size_t)(s->nx + 1) * (s->ny + 1);
    s->flip_at = calloc(nl + 1, sizeof *s->flip_at);
    s->flip = malloc((d->nhit[2] ? d->nhit[2] : 1) * sizeof *s->flip);
    if (!s->flip_at || !s->flip) return -1;
    for (size_t q = 0; q < d->nhit[2]; q++) {
        int k = layer_of(d->hit[2][q].t, d->h);
        s->flip_at[(size_t)(k < (int)nl ? k : (int)nl - 1) + 1]++;
    }
    for (size_t k = 0; k < nl; k++)
        s->flip_at[k + 1] += s->flip_at[k];
    size_t *fill = malloc(nl * sizeof *fill);
    if (!fill) return -1;
    memcpy(fill, s->flip_at, nl * sizeof *fill);
    for (size_t r = 0; r < nr; r++)
        for (size_t q = d->off[2][r]; q < d->off[2][r + 1]; q++) {
            int k = layer_of(d->hit[2][q].t, d->h);
            s->flip[fill[k < (int)nl ? k : (int)nl - 1]++] = (uint32_t)r;
        }
    free(fill);
    return 0;
}

/* Node signs of layer k from those of layer k - 1 (prev; NULL for k = 0):
 * a node is inside when an odd number of its column's crossings lie at or
 * below it. */
static void layer_signs(const sweep *s, int k, const uint8_t *prev, uint8_t *out)
{
    size_t nr = (size_t)(s->nx + 1) * (s->ny + 1);
    if (prev)
        memcpy(out, prev, nr);
    else
        memset(out, 0, nr);
    for (size_t q = s->flip_at[k]; q < s->flip_at[k + 1]; q++)
        out[s->flip[q]] ^= 1;
}

/* The crossing on grid edge `seg` (from node seg to seg+1 along axis a) of
 * ray r of family a, going the right way (enter when the lower node is
 * outside).  Node signs come from the z rays; an x or y ray that disagrees
 * near a grazing contact may have no such crossing on the edge, and then the
 * nearest one within a cell is clamped onto it, or failing that the midpoint
 * with the axis as normal is used: the topology never depends on it. */
static void edge_sample(const sweep *s, int a, size_t r, int seg, int enter, const double base[3],
                        sample *out)
{
    const mesh_dexels *d = s->d;
    const mesh_hit *hp = d->hit[a] + d->off[a][r];
    size_t nh = d->off[a][r + 1] - d->off[a][r];
    double h = d->h, t0 = seg * h, t1 = t0 + h;
    /* First crossing with t > t0 (binary search). */
    size_t lo = 0, hi = nh;
    while (lo < hi) {
        size_t mid = (lo + hi) / 2;
        if (hp[mid].t <= t0)
            lo = mid + 1;
        else
            hi = mid;
    }
    const mesh_hit *best = NULL;
    for (size_t q = lo; q < nh && hp[q].t <= t1; q++)
        if (hp[q].enter == enter) {
            best = &hp[q];
            break;
        }
    if (!best) {
        double bd = h;
        for (size_t q = lo > 2 ? lo - 2 : 0; q < nh && q < lo + 3; q++) {
            if (hp[q].enter != enter) continue;
            double dist = hp[q].t < t0 ? t0 - hp[q].t : hp[q].t - t1;
            if (dist <= bd) {
                bd = dist;
                best = &hp[q];
            }
        }
    }
    double t;
    for (int c = 0; c < 3; c++)
        out->p[c] = base[c];
    if (best) {
        t = best->t;
        for (int c = 0; c < 3; c++)
            out->n[c] = best->n[c];
        out->color = best->color;
        out->patch = best->patch;
    } else {
        out->color = 0;
        out->patch = 0;
        t = 0.5 * (t0 + t1);
        for (int c = 0; c < 3; c++)
            out->n[c] = 0;
        out->n[a] = enter ? -1 : 1;
    }
    memcpy(out->x, out->p, sizeof out->x);
    out->x[a] = d->org[a] + t;
    double exact = t;
    if (t < t0 + EPS * h) t = t0 + EPS * h;
    if (t > t1 - EPS * h) t = t1 - EPS * h;
    out->p[a] = d->org[a] + t;
    /* A crossing at (or within EPS·h of) a node moves along the edge, off
     * the surface where the edge is not in it: it goes back onto its
     * tangent plane (a plane facet through a row of nodes, as a frustum's
     * through the nodes every other layer, was left rippled by EPS·h, and
     * the simplifier kept five times the triangles). */
    double dt = t - exact, nn = dot3(out->n, out->n);
    if (best && dt != 0 && fabs(dt) <= EPS * h && nn > 0.5 && nn < 2) /* (a unit normal) */
        for (int c = 0; c < 3; c++)
            out->p[c] -= dt * out->n[a] * out->n[c];
}

/* Fill sample e of cell (i, j, k): position, normal, vertex index. */
static int cell_edge(sweep *s, int i, int j, int e, int enter, sample *out)
{
    const mesh_dexels *d = s->d;
    int a = e / 4, b0 = e & 1, b1 = e >> 1 & 1;
    int k = s->k;
    double h = d->h;
    double base[3] = {d->org[0] + i * h, d->org[1] + j * h, d->org[2] + k * h};
    int32_t *slot;
    size_t r;
    int seg;
    if (a == 0) {
        base[1] += b0 * h;
        base[2] += b1 * h;
        slot = &s->xv[b1][i + (size_t)s->nx * (j + b0)];
        r = (size_t)(j + b0) + (size_t)(s->ny + 1) * (k + b1);
        seg = i;
    } else if (a == 1) {
        base[0] += b0 * h;
        base[2] += b1 * h;
        slot = &s->yv[b1][(i + b0) + (size_t)(s->nx + 1) * j];
        r = (size_t)(i + b0) + (size_t)(s->nx + 1) * (k + b1);
        seg = j;
    } else {
        base[0] += b0 * h;
        base[1] += b1 * h;
        slot = &s->zv[(i + b0) + (size_t)(s->nx + 1) * (j + b1)];
        r = (size_t)(i + b0) + (size_t)(s->nx + 1) * (j + b1);
        seg = k;
    }
    edge_sample(s, a, r, seg, enter, base, out);
    if (*slot < 0) {
        *slot = push_unique(s, out->p, NULL, NULL);
        if (*slot < 0 || mesh_vnormal_set(&s->vn, *slot, out->n, 0, out->patch) != 0) return -1;
    }
    out->vid = *slot;
    return 0;
}

/* Whether samples a and b lie either side of a sharp edge: their normals
 * part by more than the feature angle, or they lie on two plane patches
 * whose normals part by more than 1° (a polygon's facets, at any angle;
 * see mesh_patch_of). */
static int creased(const sweep *s, const sample *a, const sample *b)
{
    double c = dot3(a->n, b->n);
    return c < s->cos_feature || mesh_planes_crease(a->patch, b->patch, c);
}

/* The point where the tangent lines of samples a and b (through their exact
 * crossings) cross within face f of the cell at lo (side h), or 0 when they
 * lie on one side of no sharp edge (creased), are nearly parallel in the
 * face, or cross outside it, or at one of the two crossings (then *through,
 * else NULL).  The inputs are put in a canonical order first
 * so both cells compute the same bits. */
static int face_point(const sweep *s, const sample *a, const sample *b, int f, const double lo[3],
                      double out[3], const sample **through)
{
    *through = NULL;
    if (a->vid > b->vid) {
        const sample *t = a;
        a = b;
        b = t;
    }
    if (!creased(s, a, b)) return 0;
    int fa = f / 2, u, v;
    mesh_axes_other(fa, &u, &v);
    double h = s->d->h;
    double au = a->n[u], av = a->n[v], bu = b->n[u], bv = b->n[v];
    double det = au * bv - av * bu;
    double la = hypot(au, av), lb = hypot(bu, bv);
    /* lines within ~11.5° of parallel meet far off the surface where it
     * curves; the lines of two planes at a slight angle meet on their edge */
    int slight = dot3(a->n, b->n) >= s->cos_feature;
    if (!(fabs(det) > (slight ? 0.005 : 0.2) * la * lb)) return 0;
    double ca = au * a->x[u] + av * a->x[v], cb = bu * b->x[u] + bv * b->x[v];
    double x = (ca * bv - av * cb) / det, y = (au * cb - ca * bu) / det;
    double tol = EPS * h;
    if (!(x >= lo[u] - tol && x <= lo[u] + h + tol && y >= lo[v] - tol && y <= lo[v] + h + tol))
        return 0;
    /* A sharp edge through (or within 2·EPS·h of) a crossing on the face's
     * rim goes through the crossing's own vertex: a point beside it, held
     * EPS·h into the face, would leave a cluster of vertices off the edge
     * and slivers between them at any angle (a frustum's 15° facets, through
     * the grid edges every other layer, were so left five times the
     * triangles). */
    for (int k = 0; k < 2; k++) {
        const sample *e = k ? b : a;
        if (hypot(x - e->x[u], y - e->x[v]) <= 2 * tol) {
            *through = e;
            return 0;
        }
    }
    double mn = EPS * h, mx = (1 - EPS) * h;
    x = fmin(fmax(x, lo[u] + mn), lo[u] + mx);
    y = fmin(fmax(y, lo[v] + mn), lo[v] + mx);
    out[fa] = lo[fa] + (f & 1) * h;
    out[u] = x;
    out[v] = y;
    return 1;
}

/* Eigen-decomposition of the symmetric 3×3 matrix a (cyclic Jacobi), then
 * the minimum-norm least-squares solution of a x = b, dropping eigenvalues
 * below cut times the largest (those directions are left at the mass point:
 * a flat patch keeps its vertex at the patch centre, an edge keeps it on the
 * edge nearest the centre; see planes_meet). */
void mesh_qef_solve(double a[3][3], const double b[3], double cut, double x[3])
{
    double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int sweep_i = 0; sweep_i < 12; sweep_i++) {
        double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        if (off < 1e-24) break;
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                if (fabs(a[p][q]) < 1e-30) continue;
                double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                double t = (theta >= 0 ? 1 : -1) / (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), sn = t * c;
                for (int k = 0; k < 3; k++) {
                    double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - sn * akq;
                    a[k][q] = sn * akp + c * akq;
                }
                for (int k = 0; k < 3; k++) {
                    double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - sn * aqk;
                    a[q][k] = sn * apk + c * aqk;
                }
                for (int k = 0; k < 3; k++) {
                    double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - sn * vkq;
                    v[k][q] = sn * vkp + c * vkq;
                }
            }
    }
    double lmax = fmax(fabs(a[0][0]), fmax(fabs(a[1][1]), fabs(a[2][2])));
    x[0] = x[1] = x[2] = 0;
    for (int e = 0; e < 3; e++) {
        double l = a[e][e];
        if (!(fabs(l) > cut * lmax) || lmax == 0) continue;
        double proj = (v[0][e] * b[0] + v[1][e] * b[1] + v[2][e] * b[2]) / l;
        for (int k = 0; k < 3; k++)
            x[k] += proj * v[k][e];
    }
}

/* The centre of a loop's samples (which lie on the cell's edges). */
static void loop_mass(const sample *smp, const int *loop, int nl, double mass[3])
{
    mass[0] = mass[1] = mass[2] = 0;
    for (int q = 0; q < nl; q++)
        for (int c = 0; c < 3; c++)
            mass[c] += smp[loop[q]].p[c] / nl;
}

/* Whether the samples of a loop (QEF a, b about mass) lie on planes (see
 * mesh_patch_of) that meet in one line or point: then that is where the
 * vertex goes, however slight their angles, and the QEF is solved without
 * dropping any direction.  Elsewhere eigenvalues under 5 % of the largest
 * are dropped: a curved surface's normals spread a little over the cell,
 * and planes that do not meet in one point (more features in the cell than
 * one vertex can stand for) have only a compromise, kept near the mass. */
static int planes_meet(const sample *smp, const int *loop, int nl, double a[3][3],
                       const double b[3], const double mass[3], const double lo[3], double h)
{
    for (int q = 0; q < nl; q++)
        if (!(smp[loop[q]].patch & MESH_PATCH_PLANAR)) return 0;
    double ac[3][3], x[3];
    memcpy(ac, a, sizeof ac);
    mesh_qef_solve(ac, b, 1e-6, x);
    /* (planes that meet far away, the thin facets fanning out of a hull's
     * corner, meet nowhere in the cell) */
    for (int c = 0; c < 3; c++)
        if (!(mass[c] + x[c] >= lo[c] - h && mass[c] + x[c] <= lo[c] + 2 * h)) return 0;
    for (int q = 0; q < nl; q++) {
        const sample *e = &smp[loop[q]];
        double rel[3] = {mass[0] + x[0] - e->x[0], mass[1] + x[1] - e->x[1],
                         mass[2] + x[2] - e->x[2]};
        if (!(fabs(dot3(e->n, rel)) <= 1e-4 * h)) return 0;
    }
    return 1;
}

/* The QEF vertex of a loop's samples (their tangent planes through their
 * exact crossings), clamped to the cell shrunk by EPS·h. */
static void loop_vertex(const sweep *s, const sample *smp, const int *loop, int nl,
                        const double lo[3], double out[3])
{
    double mass[3];
    loop_mass(smp, loop, nl, mass);
    double a[3][3] = {{0}}, b[3] = {0, 0, 0};
    for (int q = 0; q < nl; q++) {
        const sample *e = &smp[loop[q]];
        double rel[3] = {e->x[0] - mass[0], e->x[1] - mass[1], e->x[2] - mass[2]};
        double nd = dot3(e->n, rel);
        for (int r = 0; r < 3; r++) {
            b[r] += e->n[r] * nd;
            for (int c = 0; c < 3; c++)
                a[r][c] += e->n[r] * e->n[c];
        }
    }
    /* Minimise within the shrunk cell by a small active-set loop: solve,
     * pin every coordinate that leaves the cell to the wall it crossed,
     * re-solve for the others.  Plain clamping would leave a vertex whose
     * feature passes just outside the cell off both of its planes; pinned,
     * it slides along the wall to the best point there. */
    double h = s->d->h, blo[3], bhi[3], x[3] = {0, 0, 0};
    double cut = planes_meet(smp, loop, nl, a, b, mass, lo, h) ? 1e-6 : 0.05;
    for (int c = 0; c < 3; c++) {
        blo[c] = lo[c] + EPS * h - mass[c];
        bhi[c] = lo[c] + (1 - EPS) * h - mass[c];
    }
    int fixed = 0;
    for (int it = 0; it < 3; it++) {
        double ar[3][3], br[3], y[3];
        for (int r = 0; r < 3; r++) {
            br[r] = b[r];
            for (int c = 0; c < 3; c++) {
                if (fixed >> c & 1) br[r] -= a[r][c] * x[c];
                ar[r][c] = (fixed >> r & 1) || (fixed >> c & 1) ? 0 : a[r][c];
            }
            if (fixed >> r & 1) br[r] = 0;
        }
        mesh_qef_solve(ar, br, cut, y);
        int moved = 0;
        for (int c = 0; c < 3; c++) {
            if (fixed >> c & 1) continue;
            x[c] = y[c];
            if (!(x[c] >= blo[c]) || !(x[c] <= bhi[c])) {
                x[c] = x[c] > bhi[c] ? bhi[c] : blo[c];
                fixed |= 1 << c;
                moved = 1;
            }
        }
        if (!moved) break;
    }
    for (int c = 0; c < 3; c++)
        out[c] = fmin(fmax(mass[c] + x[c], lo[c] + EPS * h), lo[c] + (1 - EPS) * h);
}

/* A face point moved onto its sharp edge's exact position in face f; 1
 * when it is on it (not held in the face short of it). */
static int snap_face_point(sweep *s, const sample *a, const sample *b, int f, const double lo[3],
                           double fp[3])
{
    double h = s->d->h, sp[2][3], nrm[2][3], blo[3], bhi[3];
    uint32_t patch[2] = {a->patch, b->patch};
    for (int c = 0; c < 3; c++) {
        sp[0][c] = a->x[c];
        sp[1][c] = b->x[c];
        nrm[0][c] = a->n[c];
        nrm[1][c] = b->n[c];
        blo[c] = lo[c] + EPS * h;
        bhi[c] = lo[c] + (1 - EPS) * h;
    }
    blo[f / 2] = bhi[f / 2] = fp[f / 2];
    double want[3] = {fp[0], fp[1], fp[2]};
    int surfaces = mesh_snap(&s->snap, (const double(*)[3])sp, (const double(*)[3])nrm, patch, 2,
                             f / 2, blo, bhi, want);
    int inside = 1;
    for (int c = 0; c < 3; c++)
        inside &= (want[c] > blo[c] && want[c] < bhi[c]) || c == f / 2;
    memcpy(fp, want, sizeof want);
    return surfaces == 2 && inside;
}

/* A loop vertex.  Its colour is its sample's, for a face point the next
 * sample's: the triangles from a vertex to the next take its colour, so a
 * sharp edge through the face separates the colours of its two sides. */
typedef struct lvert {
    int32_t vid;
    int edge; /* cell edge, or -1 for a face point */
    double p[3];
    uint16_t color;
    uint8_t crease; /* a sample the cell's sharp edge runs through (see face_point) */
    int8_t face;    /* a face point's cell face; -1 for a crossing */
} lvert;

/* Twice the smallest area a fan triangle around a QEF vertex can have
 * (see the file comment), squared: below it, a triangle has none. */
static double fan_min2(double h)
{
    double a = EPS * EPS * h * h;
    return a * a;
}

/* 1 when moving the centre of the fan around the loop lv from x to y turns
 * none of its triangles over or leaves one without area. */
static int fan_keeps(const lvert *lv, int nv, const double x[3], const double y[3], double h)
{
    double min2 = fan_min2(h);
    for (int q = 0; q < nv; q++) {
        double n0[3], n1[3];
        tri_normal3(x, lv[q].p, lv[(q + 1) % nv].p, n0);
        tri_normal3(y, lv[q].p, lv[(q + 1) % nv].p, n1);
        if (!(dot3(n0, n1) > 0 && dot3(n1, n1) > min2)) return 0;
    }
    return 1;
}

/* x moved onto the surfaces of loop's samples (mesh_snap) within the box
 * blo..bhi; the number of surfaces it is on. */
static int snap_within(sweep *s, const sample *smp, const int *loop, int nl, const double blo[3],
                       const double bhi[3], double x[3])
{
    double sp[12][3], nrm[12][3];
    uint32_t patch[12];
    for (int q = 0; q < nl; q++) {
        patch[q] = smp[loop[q]].patch;
        for (int c = 0; c < 3; c++) {
            sp[q][c] = smp[loop[q]].x[c];
            nrm[q][c] = smp[loop[q]].n[c];
        }
    }
    return mesh_snap(&s->snap, (const double(*)[3])sp, (const double(*)[3])nrm, patch, nl, -1, blo,
                     bhi, x);
}

/* A loop vertex moved onto the exact surface, sharp edge or corner of its
 * samples.  On a sharp edge it may leave its cell by up to a cell: where a
 * concave crease runs just beyond a face of the cell (the groove between
 * two nodes the node signs do not see), or an acute ridge ends beyond the
 * last node inside it (half a cell left a revolved triangle's apex ring
 * jagged), the edge is where the vertex belongs.  Anywhere else it must
 * stay in the cell shrunk by EPS·h, where no fan triangle folds (and no
 * other cell's vertex is: a corner is one point, which only the cell
 * holding it may take); where the snapped point is outside it, or would
 * fold its fan (the loop lv), the QEF vertex x stays as it is (clamping the
 * snapped point into the cell coordinate by coordinate slid it off both of
 * its surfaces: 1.4 tolerances at rounded_cube.scad's edges, 2.9 so). */
static int snap_loop_vertex(sweep *s, const sample *smp, const int *loop, int nl, const lvert *lv,
                            int nv, const double lo[3], double x[3])
{
    double h = s->d->h, blo[3], bhi[3], y[3];
    for (int c = 0; c < 3; c++) {
        blo[c] = lo[c] - h;
        bhi[c] = lo[c] + 2 * h;
        y[c] = x[c];
    }
    int surfaces = snap_within(s, smp, loop, nl, blo, bhi, y);
    int kept = surfaces == 2 && fan_keeps(lv, nv, x, y, h), inside = 1;
    for (int c = 0; c < 3; c++)
        inside &= y[c] >= lo[c] + EPS * h && y[c] <= lo[c] + (1 - EPS) * h;
    if (!kept && !inside) return 0;
    memcpy(x, y, sizeof y);
    return surfaces >= 2;
}

/* Triangulate a featureless loop among its own vertices, as a fan from some
 * start vertex, if that is safe (see the file comment); 1 when done. */
static int fan_plain(sweep *s, const lvert *lv, int nl, const double navg[3])
{
    double min2 = fan_min2(s->d->h); /* below it, prefer the fan */
    for (int st = 0; st < nl; st++) {
        int ok = 1;
        for (int q = 2; q < nl - 1 && ok; q++) {
            int e0 = lv[st].edge, e1 = lv[(st + q) % nl].edge;
            if (e0 < 0 || e1 < 0 || (s->tb.edge_faces[e0] & s->tb.edge_faces[e1])) ok = 0;
        }
        for (int q = 1; q + 1 < nl && ok; q++) {
            double n[3];
            tri_normal3(lv[st].p, lv[(st + q) % nl].p, lv[(st + q + 1) % nl].p, n);
            if (!(dot3(n, n) > min2) || !(dot3(n, navg) > 0)) ok = 0;
        }
        if (!ok) continue;
        for (int q = 1; q + 1 < nl; q++)
            if (mesh_push_triangle(s->m, lv[st].vid, lv[(st + q) % nl].vid,
                                   lv[(st + q + 1) % nl].vid, lv[(st + q) % nl].color) < 0)
                s->oom = 1;
        return 1;
    }
    return 0;
}

/* How far triangle (a, b, c) of loop lv turns from the surface at its
 * corners: the cosine of its normal with the nearest of the crossings'
 * normals there (a face point has none; with none at all, navg's); -2
 * when it has no area (twice it, squared, at most min2).  Across a sharp
 * edge a triangle may lean more than 90° from the sum of two surfaces'
 * normals, not from both. */
static double facing(const sample *smp, const lvert *lv, int a, int b, int c, const double navg[3],
                     double min2)
{
    double n[3];
    tri_normal3(lv[a].p, lv[b].p, lv[c].p, n);
    double l2 = dot3(n, n), best = -2;
    if (!(l2 > min2)) return -2;
    int idx[3] = {a, b, c}, any = 0;
    for (int k = 0; k < 3; k++) {
        if (lv[idx[k]].edge < 0) continue;
        any = 1;
        const double *r = smp[lv[idx[k]].edge].n;
        best = fmax(best, dot3(n, r) / sqrt(l2 * dot3(r, r)));
    }
    double rl = sqrt(dot3(navg, navg));
    if (!any && rl > 0) best = dot3(n, navg) / (sqrt(l2) * rl);
    return best;
}

/* The cell faces vertex v of a loop lies on, as a bit mask. */
static int faces_of(const sweep *s, const lvert *v)
{
    return v->edge >= 0 ? s->tb.edge_faces[v->edge] : 1 << v->face;
}

/* Triangulate loop lv (nv vertices) among its own vertices where no centre
 * can be fanned from without turning a triangle over: of the
 * triangulations whose added diagonals each join two vertices on no
 * common cell face (no other cell can draw them), whose triangles have
 * area, the one whose worst triangle turns least from the normals at its
 * corners (dynamic programming over the polygon), if that turns less than
 * 90°.  A crease that clips a corner of the cell leaves a loop of two
 * surfaces, both of whose pieces lie along the cell's faces: no point
 * sees all of it the right way round (the bench part's bores, where they
 * meet the cube's faces a thousandth of a cell off a node: 48 folded
 * triangles).  1 when done. */
static int fan_free(sweep *s, const sample *smp, const lvert *lv, int nv, const double navg[3])
{
    enum { MAXV = 24 };
    double h = s->d->h, min2 = fan_min2(h);
    double best[MAXV][MAXV];
    int8_t pick[MAXV][MAXV];
    if (nv > MAXV || nv < 3) return 0;
    for (int len = 1; len < nv; len++)
        for (int i = 0; i + len < nv; i++) {
            int j = i + len;
            best[i][j] = len == 1 ? 2 : -3;
            pick[i][j] = -1;
            if (len == 1) continue;
            /* (i, j) a diagonal unless it is the closing side */
            if (!(i == 0 && j == nv - 1) && (faces_of(s, &lv[i]) & faces_of(s, &lv[j]))) continue;
            for (int k = i + 1; k < j; k++) {
                double f = facing(smp, lv, i, k, j, navg, min2);
                double w = fmin(f, fmin(best[i][k], best[k][j]));
                if (w > best[i][j]) {
                    best[i][j] = w;
                    pick[i][j] = (int8_t)k;
                }
            }
        }
    if (!(best[0][nv - 1] > 0)) return 0;
    int stack[2 * MAXV][2], n = 0;
    stack[n][0] = 0;
    stack[n++][1] = nv - 1;
    while (n) {
        n--;
        int i = stack[n][0], j = stack[n][1], k = pick[i][j];
        if (k < 0) continue;
        if (mesh_push_triangle(s->m, lv[i].vid, lv[k].vid, lv[j].vid, lv[k].color) < 0) s->oom = 1;
        stack[n][0] = i;
        stack[n++][1] = k;
        stack[n][0] = k;
        stack[n++][1] = j;
    }
    return 1;
}

/* Whether the fan around c of loop lv faces the way the surface does:
 * each triangle with area and turned less than 90° from the normals at
 * its loop corners (see facing). */
static int fan_faces(const sample *smp, const lvert *lv, int nv, const double c[3],
                     const double navg[3], double h)
{
    double min2 = fan_min2(h);
    lvert t[3];
    memcpy(t[0].p, c, sizeof t[0].p);
    t[0].edge = -1;
    for (int q = 0; q < nv; q++) {
        t[1] = lv[q];
        t[2] = lv[(q + 1) % nv];
        if (!(facing(smp, t, 0, 1, 2, navg, min2) > 0)) return 0;
    }
    return 1;
}

/* Whether face f of cell (i, j, s->k), its corners' signs in[] (in
 * face_corner's order), is ambiguous — inside corners on a diagonal — with
 * its middle inside the solid: then the inside corners are joined across
 * the face and its segments cut off the outside corners.  (A convex sharp
 * edge that passes beside the face, near its middle, leaves the solid's
 * section through the face one convex piece holding both inside corners;
 * cut apart, the cell's two plane pieces made one loop, whose vertex
 * belonged on the edge in the next cell, and its fan chamfered the edge.)
 * The middle is computed from the face's own node indices, so both cells
 * that share the face decide alike. */
static int ambiguous_face(sweep *s, int i, int j, int f, const int in[4])
{
    if (in[0] == in[1] || in[1] == in[2] || in[2] == in[3]) return 0;
    const mesh_dexels *d = s->d;
    int fa = f / 2, idx[3] = {i, j, s->k};
    double mid[3];
    for (int c = 0; c < 3; c++)
        mid[c] = d->org[c] + (c == fa ? idx[c] + (f & 1) : idx[c] + 0.5) * d->h;
    return mesh_snap_inside(&s->snap, mid, fa) == 1;
}

/* Whether vertex v was put on a sharp edge (push_snapped). */
static int vertex_on_edge(const sweep *s, int32_t v)
{
    return (size_t)v < s->vn.cap && s->vn.edge[v];
}

/* Whether the samples of the n vertices of loop lv (nv in all) from a on,
 * less those on its sharp edge, lie on one surface. */
static int one_surface(const sweep *s, const sample *smp, const lvert *lv, int nv, int a, int n)
{
    for (int q = 0; q < n; q++)
        for (int r = q + 1; r < n; r++) {
            const lvert *u = &lv[(a + q) % nv], *w = &lv[(a + r) % nv];
            if (u->edge >= 0 && !u->crease && w->edge >= 0 && !w->crease &&
                creased(s, &smp[u->edge], &smp[w->edge]))
                return 0;
        }
    return 1;
}

/* A loop whose sharp edge runs in and out through two of its vertices —
 * face points put on the edge, or crossings the edge passes through (see
 * face_point) — while the cell's vertex could not be put on it (the edge
 * leaves the cell within a corner, and the vertex belongs beyond it, where
 * the loop's fan would fold): the loop is cut along the chord between the
 * two, and each side, one surface's samples, fanned from a vertex of its
 * own on that surface (a side of the two alone, a segment of the loop
 * along the edge, has nothing to fan; with one such vertex the edge only
 * touches the loop, which is triangulated whole on its other surface).
 * Not along a chord in a cell face, which the cell across could draw too
 * (an edge of four triangles).  Fanned from the vertex held in the
 * cell instead, off both surfaces, the loop cut the edge off
 * (rotated_box_pin.scad's pin, where it leaves the box: 21 such cells).
 * 1 when done; 0 leaves the loop to the fan. */
static int split_loop(sweep *s, const sample *smp, const lvert *lv, int nv, const double lo[3])
{
    int fp[2], nfp = 0;
    for (int q = 0; q < nv; q++) {
        if (lv[q].edge < 0 && !lv[q].crease) return 0; /* a face point off the edge */
        if (!lv[q].crease) continue;
        if (nfp == 2) return 0;
        fp[nfp++] = q;
    }
    if (nfp == 0) return 0;
    if (nfp == 2 && fp[1] - fp[0] != 1 && fp[1] - fp[0] != nv - 1) {
        int mask[2]; /* the cell faces each end lies on */
        for (int k = 0; k < 2; k++) {
            const lvert *v = &lv[fp[k]];
            mask[k] = v->edge >= 0 ? s->tb.edge_faces[v->edge] : 1 << v->face;
        }
        if (mask[0] & mask[1]) return 0;
    }
    if (nfp == 1) { /* the edge touches the loop at one vertex: one side */
        double navg[3] = {0, 0, 0};
        for (int q = 0; q < nv; q++)
            if (lv[q].edge >= 0 && !lv[q].crease)
                for (int c = 0; c < 3; c++)
                    navg[c] += smp[lv[q].edge].n[c];
        if (one_surface(s, smp, lv, nv, 0, nv) && fan_plain(s, lv, nv, navg)) return 1;
        fp[1] = (fp[0] + nv - 1) % nv;
    }
    double h = s->d->h, centre[2][3];
    double min2 = fan_min2(h);
    int count[2];
    for (int side = 0; side < 2; side++) {
        /* lv[fp[side]] .. lv[fp[1 - side]], around the loop */
        int a = fp[side], b = fp[1 - side], n = (b - a + nv) % nv + 1;
        count[side] = n == 2 || (nfp == 1 && side == 1) ? 0 : n; /* 0: nothing to fan */
        if (!count[side]) continue;
        if (!one_surface(s, smp, lv, nv, a, n)) return 0; /* two surfaces on one side: a corner */
        double sp[12][3], nrm[12][3], navg[3] = {0, 0, 0}, mass[3] = {0, 0, 0};
        uint32_t patch[12];
        int ns = 0;
        for (int k = 0; k < n; k++) {
            const lvert *v = &lv[(a + k) % nv];
            for (int c = 0; c < 3; c++)
                mass[c] += v->p[c] / n;
            if (v->edge < 0 || v->crease) continue;
            const sample *e = &smp[v->edge];
            memcpy(sp[ns], e->x, sizeof sp[ns]);
            memcpy(nrm[ns], e->n, sizeof nrm[ns]);
            patch[ns++] = e->patch;
            for (int c = 0; c < 3; c++)
                navg[c] += e->n[c];
        }
        if (ns == 0) return 0;
        /* the side's middle, onto its surface (its first sample's plane,
         * then the exact surface), in the shrunk cell */
        double rel[3];
        sub3(mass, sp[0], rel);
        double off = dot3(rel, nrm[0]);
        for (int c = 0; c < 3; c++)
            centre[side][c] = mass[c] - off * nrm[0][c];
        double blo[3], bhi[3];
        for (int c = 0; c < 3; c++) {
            blo[c] = lo[c] + EPS * h;
            bhi[c] = lo[c] + (1 - EPS) * h;
        }
        mesh_snap(&s->snap, (const double(*)[3])sp, (const double(*)[3])nrm, patch, ns, -1, blo,
                  bhi, centre[side]);
        for (int c = 0; c < 3; c++)
            if (!(centre[side][c] >= blo[c] && centre[side][c] <= bhi[c])) return 0;
        /* its fan, the chord closing it, neither folded nor flat */
        for (int k = 0; k < n; k++) {
            const double *p0 = lv[(a + k) % nv].p, *p1 = lv[(a + (k + 1) % n) % nv].p;
            if (k == n - 1) p1 = lv[a].p; /* the chord back */
            double tn[3];
            tri_normal3(centre[side], p0, p1, tn);
            if (!(dot3(tn, tn) > min2) || !(dot3(tn, navg) > 0)) return 0;
        }
    }
    for (int side = 0; side < 2; side++) {
        if (!count[side]) continue;
        int32_t cv = push_snapped(s, centre[side], centre[side], 0, lo);
        if (cv < 0) {
            s->oom = 1;
            return 1;
        }
        int a = fp[side], n = count[side];
        for (int k = 0; k < n; k++) {
            const lvert *v0 = &lv[(a + k) % nv];
            const lvert *v1 = k == n - 1 ? &lv[a] : &lv[(a + k + 1) % nv];
            if (mesh_push_triangle(s->m, cv, v0->vid, v1->vid, v0->color) < 0) s->oom = 1;
        }
    }
    return 1;
}

static void cell(sweep *s, int i, int j, int mask)
{
    const mesh_dexels *d = s->d;
    const tables *tb = &s->tb;
    double h = d->h;
    double lo[3] = {d->org[0] + i * h, d->org[1] + j * h, d->org[2] + s->k * h};
    sample smp[12];
    int next[12], segface[12], has[12] = {0};
    for (int e = 0; e < 12; e++) {
        int c0 = edge_corner(e, 0), c1 = edge_corner(e, 1);
        int s0 = mask >> c0 & 1, s1 = mask >> c1 & 1;
        if (s0 == s1) continue;
        has[e] = 1;
        if (cell_edge(s, i, j, e, s1, &smp[e]) != 0) {
            s->oom = 1;
            return;
        }
    }
    for (int f = 0; f < 6; f++) {
        int in[4];
        for (int m = 0; m < 4; m++)
            in[m] = mask >> face_corner[f][m] & 1;
        int joined = ambiguous_face(s, i, j, f, in);
        for (int m = 0; m < 4; m++) {
            if (in[m] || !in[(m + 1) & 3]) continue; /* not an outside-to-inside crossing */
            if (joined) { /* around the outside corner m, to the crossing before */
                next[tb->face_edge[f][m]] = tb->face_edge[f][(m + 3) & 3];
                segface[tb->face_edge[f][m]] = f;
                continue;
            }
            for (int q = 1; q < 4; q++) {
                int mm = (m + q) & 3;
                if (in[mm] != in[(mm + 1) & 3]) {
                    int e = tb->face_edge[f][m];
                    next[e] = tb->face_edge[f][mm];
                    segface[e] = f;
                    break;
                }
            }
        }
    }
    int done[12] = {0};
    /* this cell's loop vertices so far: two loops whose QEF vertices are
     * pinned to the same corner of the shrunk cell would share a point, and
     * a reader that welds by position (every STL reader) would see one
     * vertex with two fans */
    double placed[6][3];
    int nplaced = 0;
    for (int e0 = 0; e0 < 12; e0++) {
        if (!has[e0] || done[e0]) continue;
        int loop[12], nl = 0;
        for (int e = e0; !done[e]; e = next[e]) {
            done[e] = 1;
            loop[nl++] = e;
        }
        /* Loop vertices: edge crossings with feature points between. */
        lvert lv[24];
        int nv = 0, feature = 0;
        double navg[3] = {0, 0, 0};
        uint8_t through[12] = {0}; /* by cell edge: its sample is on the sharp edge */
        for (int q = 0; q < nl; q++) {
            const sample *a = &smp[loop[q]], *b = &smp[loop[(q + 1) % nl]];
            lv[nv].vid = a->vid;
            lv[nv].edge = loop[q];
            lv[nv].color = a->color;
            lv[nv].crease = 0;
            lv[nv].face = -1;
            memcpy(lv[nv].p, a->p, sizeof a->p);
            nv++;
            for (int c = 0; c < 3; c++)
                navg[c] += a->n[c];
            for (int r = q + 1; r < nl; r++)
                if (creased(s, a, &smp[loop[r]])) feature = 1;
            double fp[3];
            const sample *on_it;
            int got = face_point(s, a, b, segface[loop[q]], lo, fp, &on_it);
            if (on_it) through[on_it == a ? loop[q] : loop[(q + 1) % nl]] = 1;
            if (got) {
                int32_t lo_id = a->vid < b->vid ? a->vid : b->vid;
                int32_t hi_id = a->vid < b->vid ? b->vid : a->vid;
                uint64_t key = (uint64_t)(lo_id + 1) << 32 | (uint64_t)(hi_id + 1);
                int fresh;
                int32_t *slot = mesh_fmap_slot(&s->faces, key, &fresh);
                if (!slot) {
                    s->oom = 1;
                    return;
                }
                if (fresh) {
                    double unsnapped[3] = {fp[0], fp[1], fp[2]};
                    int on = snap_face_point(s, a, b, segface[loop[q]], lo, fp);
                    if ((*slot = push_snapped(s, fp, unsnapped, on, lo)) < 0) {
                        s->oom = 1;
                        return;
                    }
                } else {
                    for (int c = 0; c < 3; c++) /* where the first cell put it */
                        fp[c] = s->m->v[3 * (size_t)*slot + c];
                }
                lv[nv].vid = *slot;
                lv[nv].edge = -1;
                lv[nv].face = (int8_t)segface[loop[q]];
                lv[nv].color = b->color;
                lv[nv].crease = (uint8_t)vertex_on_edge(s, *slot);
                memcpy(lv[nv].p, fp, sizeof fp);
                nv++;
                feature = 1;
            }
        }
        for (int q = 0; q < nv; q++)
            if (lv[q].edge >= 0) lv[q].crease = through[lv[q].edge];
        if (!feature && fan_plain(s, lv, nv, navg)) continue;
        double c[3];
        loop_vertex(s, smp, loop, nl, lo, c);
        double unsnapped[3] = {c[0], c[1], c[2]};
        int on = snap_loop_vertex(s, smp, loop, nl, lv, nv, lo, c);
        if (!on && split_loop(s, smp, lv, nv, lo)) continue;
        for (int q = 0; q < nplaced; q++) {
            double dd[3];
            sub3(c, placed[q], dd);
            if (dot3(dd, dd) < EPS * EPS * h * h) {
                /* the loop's own centre instead: in the cell, and its own */
                loop_mass(smp, loop, nl, c);
                for (int k = 0; k < 3; k++)
                    c[k] = fmin(fmax(c[k], lo[k] + EPS * h), lo[k] + (1 - EPS) * h);
                on = 0;
                break;
            }
        }
        /* A fan turned over about c: the sharp edge's point nearest the
         * QEF vertex within the cell, or the loop alone, if either faces it
         * — not where c was put on the sharp edge beyond the cell, which
         * stands for a sliver of solid whose grid edges cross the surface
         * twice, held by no cell's loop (bored_cone.scad's cross hole under
         * the cone: cut off there, its rim's samples lay 1.5 tolerances off
         * the mesh) — else the QEF vertex or the loop's centre, if one does. */
        if (!fan_faces(smp, lv, nv, c, navg, h)) {
            int beyond = 0;
            double in[3], blo[3], bhi[3];
            for (int k = 0; k < 3; k++) {
                beyond |= c[k] < lo[k] || c[k] > lo[k] + h;
                in[k] = unsnapped[k];
                blo[k] = lo[k] + EPS * h;
                bhi[k] = lo[k] + (1 - EPS) * h;
            }
            if (!beyond && snap_within(s, smp, loop, nl, blo, bhi, in) == 2 &&
                fan_faces(smp, lv, nv, in, navg, h)) {
                memcpy(c, in, sizeof c);
                on = 1;
            } else if (!beyond && fan_free(s, smp, lv, nv, navg)) {
                continue;
            } else {
                double mc[3];
                loop_mass(smp, loop, nl, mc);
                for (int k = 0; k < 3; k++)
                    mc[k] = fmin(fmax(mc[k], blo[k]), bhi[k]);
                const double *alt = fan_faces(smp, lv, nv, unsnapped, navg, h) ? unsnapped
                                    : fan_faces(smp, lv, nv, mc, navg, h)      ? mc
                                                                               : NULL;
                if (alt) {
                    memmove(c, alt, sizeof c);
                    on = 0;
                }
            }
        }
        int32_t cv = push_snapped(s, c, unsnapped, on, lo);
        if (nplaced < 6) memcpy(placed[nplaced++], c, sizeof c);
        if (cv < 0) {
            s->oom = 1;
            return;
        }
        for (int q = 0; q < nv; q++)
            if (mesh_push_triangle(s->m, cv, lv[q].vid, lv[(q + 1) % nv].vid, lv[q].color) < 0)
                s->oom = 1;
    }
}

/* Contour one grid of a sampling, appending to m; 0 or -1 (message). */
static int contour_grid(const mesh_dexels *d, const mesh_options *o, mesh *m, char *err,
                        size_t errlen)
{
    if (!d->off[0]) return 0;
    int first_tri = m->nt;
    sweep s;
    memset(&s, 0, sizeof s);
    s.d = d;
    s.m = m;
    tables_init(&s.tb);
    double fdeg = o && o->feature_angle_deg > 0 ? o->feature_angle_deg : 30;
    s.cos_feature = cos(fdeg * 3.14159265358979323846 / 180);
    s.nx = d->n[0];
    s.ny = d->n[1];
    s.nz = d->n[2];
    size_t nodes = (size_t)(s.nx + 1) * (s.ny + 1);
    size_t nxe = (size_t)s.nx * (s.ny + 1), nye = (size_t)(s.nx + 1) * s.ny;
    s.zv = malloc(nodes * sizeof *s.zv);
    for (int l = 0; l < 2; l++) {
        s.sign[l] = malloc(nodes);
        s.xv[l] = malloc(nxe * sizeof *s.xv[l]);
        s.yv[l] = malloc(nye * sizeof *s.yv[l]);
    }
    int rc = -1;
    if (mesh_snapper_init(&s.snap, d, s.cos_feature) != 0 || flips_init(&s) != 0 || !s.zv ||
        !s.sign[0] || !s.sign[1] || !s.xv[0] || !s.xv[1] || !s.yv[0] || !s.yv[1]) {
        snprintf(err, errlen, "out of memory contouring");
        goto done;
    }
    layer_signs(&s, 0, NULL, s.sign[1]);
    memset(s.xv[1], 0xff, nxe * sizeof *s.xv[1]);
    memset(s.yv[1], 0xff, nye * sizeof *s.yv[1]);
    for (int k = 0; k < s.nz && !s.oom; k++) {
        if (o && o->progress) o->progress(o->progress_ud, "contouring", (double)k / s.nz);
        s.k = k;
        /* Roll: the top layer of slab k-1 is the bottom of slab k. */
        uint8_t *ts = s.sign[0];
        s.sign[0] = s.sign[1];
        s.sign[1] = ts;
        int32_t *tx = s.xv[0], *ty = s.yv[0];
        s.xv[0] = s.xv[1];
        s.xv[1] = tx;
        s.yv[0] = s.yv[1];
        s.yv[1] = ty;
        layer_signs(&s, k + 1, s.sign[0], s.sign[1]);
        memset(s.xv[1], 0xff, nxe * sizeof *s.xv[1]);
        memset(s.yv[1], 0xff, nye * sizeof *s.yv[1]);
        memset(s.zv, 0xff, nodes * sizeof *s.zv);
        const uint8_t *b = s.sign[0], *t = s.sign[1];
        size_t w = (size_t)s.nx + 1;
        for (int j = 0; j < s.ny && !s.oom; j++) {
            const uint8_t *b0 = b + w * j, *b1 = b0 + w, *t0 = t + w * j, *t1 = t0 + w;
            for (int i = 0; i < s.nx; i++) {
                /* Skip 8 cells at a time where their 4 × 9 nodes agree. */
                if (i + 9 <= s.nx) {
                    uint64_t word[8];
                    memcpy(&word[0], b0 + i, 8);
                    memcpy(&word[1], b0 + i + 1, 8);
                    memcpy(&word[2], b1 + i, 8);
                    memcpy(&word[3], b1 + i + 1, 8);
                    memcpy(&word[4], t0 + i, 8);
                    memcpy(&word[5], t0 + i + 1, 8);
                    memcpy(&word[6], t1 + i, 8);
                    memcpy(&word[7], t1 + i + 1, 8);
                    uint64_t diff = 0;
                    for (int q = 1; q < 8; q++)
                        diff |= word[q] ^ word[0];
                    if (!diff && (word[0] == 0 || word[0] == 0x0101010101010101ULL)) {
                        i += 7;
                        continue;
                    }
                }
                int mask = b0[i] | b0[i + 1] << 1 | b1[i] << 2 | b1[i + 1] << 3 | t0[i] << 4 |
                           t0[i + 1] << 5 | t1[i] << 6 | t1[i + 1] << 7;
                if (mask != 0 && mask != 255) cell(&s, i, j, mask);
            }
        }
    }
    if (o && o->progress && !s.oom) o->progress(o->progress_ud, "contouring", 1);
    if (s.oom || mesh_unbend(m, first_tri, d->h, &s.vn) != 0 ||
        mesh_refine_edges(m, first_tri, o ? o->tolerance : 0, &s.snap, &s.vn, &s.pos) != 0 ||
        mesh_unfold(m, first_tri, d->h) != 0) {
        snprintf(err, errlen, "out of memory contouring (or more than 2^31 vertices)");
        goto done;
    }
    rc = 0;
done:
    mesh_snapper_free(&s.snap);
    mesh_vnormals_free(&s.vn);
    free(s.flip);
    free(s.flip_at);
    free(s.zv);
    for (int l = 0; l < 2; l++) {
        free(s.sign[l]);
        free(s.xv[l]);
        free(s.yv[l]);
    }
    free(s.faces.key);
    free(s.faces.val);
    free(s.pos.key);
    free(s.pos.val);
    return rc;
}

int mesh_dexels_contour(const mesh_dexels *d, const mesh_options *o, mesh **out, char *err,
                        size_t errlen)
{
    *out = NULL;
    mesh *m = calloc(1, sizeof *m);
    if (!m) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    if (mesh_set_palette(m, &d->pal) != 0) {
        mesh_free(m);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    /* The grids cover disjoint boxes: their meshes are disjoint too.  They
     * sample one root, so they share its palette. */
    for (const mesh_dexels *g = d; g; g = g->next)
        if (g->exact == -1 && contour_grid(g, o, m, err, errlen) != 0) {
            mesh_free(m);
            return -1;
        }
    if (mesh_exact_append(d, m) != 0) {
        mesh_free(m);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    *out = m;
    return 0;
}
