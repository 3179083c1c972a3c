/*
 * mesh.c — the indexed triangle mesh: growing arrays of float vertices and
 * int32 triangles, and the whole-mesh sums (signed volume, area).
 *
 * Invariant: 0 <= nv <= capv, 0 <= nt <= capt, and every index in t[0 ..
 * 3·nt) is in [0, nv).  Arrays grow by doubling, so appending is amortised
 * O(1) and the mesh never holds more than twice what it uses.
 */
#include "dexels.h"
#include "../intervals/vec3.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>

static int grow(void **p, int *cap, int need, size_t elem)
{
    if (need <= *cap) return 0;
    long long c = *cap ? *cap : 1024;
    while (c < need)
        c *= 2;
    if (c > INT32_MAX) c = INT32_MAX;
    void *q = realloc(*p, (size_t)c * elem);
    if (!q) return -1;
    *p = q;
    *cap = (int)c;
    return 0;
}

int mesh_push_vertex(mesh *m, double x, double y, double z)
{
    if (m->nv == INT32_MAX || grow((void **)&m->v, &m->capv, m->nv + 1, 3 * sizeof(float)) != 0)
        return -1;
    float *p = m->v + 3 * (size_t)m->nv;
    p[0] = (float)x;
    p[1] = (float)y;
    p[2] = (float)z;
    return m->nv++;
}

void mesh_round_to_float(double x[3])
{
    for (int c = 0; c < 3; c++)
        x[c] = (float)x[c];
}

int mesh_vertex_fans(const mesh *m, int32_t t0, int32_t **start, int32_t **fan)
{
    int32_t *st = calloc((size_t)m->nv + 1, sizeof *st);
    int32_t *f = malloc(3 * (size_t)(m->nt > t0 ? m->nt - t0 : 1) * sizeof *f);
    int32_t *at = malloc(((size_t)m->nv + 1) * sizeof *at);
    if (!st || !f || !at) {
        free(st);
        free(f);
        free(at);
        return -1;
    }
    for (int32_t t = t0; t < m->nt; t++)
        for (int k = 0; k < 3; k++)
            st[m->t[3 * (size_t)t + k] + 1]++;
    for (int v = 0; v < m->nv; v++)
        st[v + 1] += st[v];
    memcpy(at, st, ((size_t)m->nv + 1) * sizeof *at);
    for (int32_t t = t0; t < m->nt; t++)
        for (int k = 0; k < 3; k++)
            f[at[m->t[3 * (size_t)t + k]]++] = t;
    free(at);
    *start = st;
    *fan = f;
    return 0;
}

/* The half-edges between a vertex a and its neighbours of higher index, one
 * entry each: the neighbour, the half-edge, whether it runs from a (2: a
 * side from a to a, of a triangle with a corner twice). */
typedef struct side {
    int32_t other, x;
    int out;
} side;

int mesh_half_twins(const mesh *m, int32_t t0, int32_t *opp)
{
    /* Half-edge x (a → b) pairs with the last earlier b → a that found no
     * twin when it came, if that is still unpaired: the twins of a manifold
     * mesh, and a fixed choice where more than two triangles share an edge.
     * Each edge's half-edges are gathered once, at its lower end, from that
     * vertex's fan (in the order the triangles were made), and taken in
     * their order there. */
    size_t nt = (size_t)(m->nt > t0 ? m->nt - t0 : 0);
    int32_t *start, *fan;
    uint8_t *waits = calloc(3 * nt + 1, 1);
    side *s = NULL;
    size_t cap = 0;
    if (!waits || mesh_vertex_fans(m, t0, &start, &fan) != 0) {
        free(waits);
        return -1;
    }
    int rc = 0;
    for (size_t x = 0; x < 3 * nt; x++)
        opp[x] = -1;
    for (int32_t a = 0; a < m->nv && rc == 0; a++) {
        size_t n = 0, need = 2 * (size_t)(start[a + 1] - start[a]);
        if (need > cap) {
            side *g = realloc(s, need * sizeof *g);
            if (!g) {
                rc = -1;
                break;
            }
            s = g;
            cap = need;
        }
        for (int32_t f = start[a]; f < start[a + 1]; f++) {
            if (f > start[a] && fan[f] == fan[f - 1]) continue; /* a corner twice */
            const int32_t *tv = &m->t[3 * (size_t)fan[f]];
            for (int k = 0; k < 3; k++) {
                int32_t p = tv[k], q = tv[(k + 1) % 3], x = 3 * (fan[f] - t0) + k;
                if (p == a && q == a)
                    s[n++] = (side){a, x, 2}; /* a degenerate side: its own twin's kind */
                else if (p == a && q > a)
                    s[n++] = (side){q, x, 1};
                else if (q == a && p > a)
                    s[n++] = (side){p, x, 0};
            }
        }
        /* by neighbour, then half-edge (insertion: a fan is a few) */
        for (size_t i = 1; i < n; i++) {
            side e = s[i];
            size_t j = i;
            for (; j > 0 &&
                   (s[j - 1].other > e.other || (s[j - 1].other == e.other && s[j - 1].x > e.x));
                 j--)
                s[j] = s[j - 1];
            s[j] = e;
        }
        for (size_t i = 0; i < n; i++) {
            int32_t best = -1;
            for (size_t j = i; j-- > 0 && s[j].other == s[i].other;)
                if ((s[j].out != s[i].out || s[i].out == 2) && waits[s[j].x]) {
                    best = s[j].x;
                    break;
                }
            int32_t x = s[i].x;
            if (best >= 0 && opp[best] < 0) {
                opp[x] = best;
                opp[best] = x;
            } else {
                waits[x] = 1;
            }
        }
    }
    free(s);
    free(start);
    free(fan);
    free(waits);
    return rc;
}

void mesh_triangle_normal(const mesh *m, int32_t t, double n[3])
{
    double p[3][3];
    for (int k = 0; k < 3; k++)
        mesh_vertex_at(m, m->t[3 * (size_t)t + k], p[k]);
    tri_normal3(p[0], p[1], p[2], n);
}

int mesh_vertex_move(mesh *m, int32_t v, const int32_t *fan, int nf, const double to[3],
                     double min_cos, double min2)
{
    if (nf > 64) return 0;
    double before[64][3], old[3];
    for (int f = 0; f < nf; f++)
        mesh_triangle_normal(m, fan[f], before[f]);
    mesh_vertex_at(m, v, old);
    float *pv = &m->v[3 * (size_t)v];
    for (int c = 0; c < 3; c++)
        pv[c] = (float)to[c];
    for (int f = 0; f < nf; f++) {
        double n[3];
        mesh_triangle_normal(m, fan[f], n);
        double l0 = sqrt(dot3(before[f], before[f])), l1 = sqrt(dot3(n, n));
        if (!(dot3(n, before[f]) > min_cos * l0 * l1 && dot3(n, n) > min2)) {
            for (int c = 0; c < 3; c++)
                pv[c] = (float)old[c];
            return 0;
        }
    }
    return 1;
}

int mesh_push_triangle(mesh *m, int32_t a, int32_t b, int32_t c, uint16_t color)
{
    if (m->nt == INT32_MAX || grow((void **)&m->t, &m->capt, m->nt + 1, 3 * sizeof(int32_t)) != 0 ||
        (m->npal && grow((void **)&m->tc, &m->captc, m->nt + 1, sizeof *m->tc) != 0))
        return -1;
    int32_t *p = m->t + 3 * (size_t)m->nt;
    p[0] = a;
    p[1] = b;
    p[2] = c;
    if (m->npal) m->tc[m->nt] = color;
    return m->nt++;
}

int mesh_set_palette(mesh *m, const mesh_palette *p)
{
    if (!p->n) return 0;
    m->pal = malloc((size_t)p->n * sizeof *m->pal);
    if (!m->pal || grow((void **)&m->tc, &m->captc, m->nt + 1, sizeof *m->tc) != 0) {
        free(m->pal);
        m->pal = NULL;
        return -1;
    }
    memcpy(m->pal, p->rgba, (size_t)p->n * sizeof *m->pal);
    m->npal = p->n;
    return 0;
}

void mesh_free(mesh *m)
{
    if (!m) return;
    free(m->v);
    free(m->t);
    free(m->tc);
    free(m->pal);
    free(m);
}

int mesh_vertex_count(const mesh *m)
{
    return m->nv;
}
int mesh_triangle_count(const mesh *m)
{
    return m->nt;
}
const float *mesh_vertices(const mesh *m)
{
    return m->v;
}
const int32_t *mesh_triangles(const mesh *m)
{
    return m->t;
}

int mesh_color_count(const mesh *m)
{
    return m->npal;
}
const float *mesh_colors(const mesh *m)
{
    return m->npal ? m->pal[0] : NULL;
}
const uint16_t *mesh_triangle_colors(const mesh *m)
{
    return m->npal ? m->tc : NULL;
}

mesh *mesh_new_from_arrays(const float *v, int nv, const int32_t *t, int nt)
{
    if (nv < 0 || nt < 0) return NULL;
    for (long long q = 0; q < 3LL * nt; q++)
        if (t[q] < 0 || t[q] >= nv) return NULL;
    mesh *m = calloc(1, sizeof *m);
    if (!m) return NULL;
    if (grow((void **)&m->v, &m->capv, nv, 3 * sizeof(float)) != 0 ||
        grow((void **)&m->t, &m->capt, nt, 3 * sizeof(int32_t)) != 0) {
        mesh_free(m);
        return NULL;
    }
    if (nv) memcpy(m->v, v, 3 * (size_t)nv * sizeof(float));
    if (nt) memcpy(m->t, t, 3 * (size_t)nt * sizeof(int32_t));
    m->nv = nv;
    m->nt = nt;
    return m;
}

/* Each triangle, taken from the first vertex's position (which keeps the
 * products small and the sums accurate far from the origin). */
static void sums(const mesh *m, double *vol, double *area)
{
    double sv = 0, sa = 0;
    const float *o = m->nv ? m->v : NULL;
    for (int q = 0; q < m->nt; q++) {
        const int32_t *t = m->t + 3 * (size_t)q;
        double p[3][3];
        for (int k = 0; k < 3; k++)
            for (int c = 0; c < 3; c++)
                p[k][c] = (double)m->v[3 * (size_t)t[k] + c] - o[c];
        double e1[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
        double e2[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0]};
        sa += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        /* det(p0, p1, p2) / 6 = p0 · (p1 × p2) / 6 */
        sv += (p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
               p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
               p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0])) /
              6;
    }
    *vol = sv;
    *area = sa;
}

double mesh_signed_volume(const mesh *m)
{
    double v, a;
    sums(m, &v, &a);
    return v;
}

double mesh_area(const mesh *m)
{
    double v, a;
    sums(m, &v, &a);
    return a;
}

int mesh_from_scene(const csg_scene *s, const mesh_options *o, mesh **out, mesh_measure *m,
                    char *err, size_t errlen)
{
    mesh_dexels *d;
    *out = NULL;
    int rc = mesh_dexels_new(s, o, &d, err, errlen);
    if (rc != 0) return rc;
    if (m) mesh_dexels_measure(d, m);
    rc = mesh_dexels_contour(d, o, out, err, errlen);
    if (rc == 0 && o && o->tolerance > 0 &&
        (rc = mesh_dexels_simplify(d, *out, o->tolerance, o, err, errlen)) != 0) {
        mesh_free(*out);
        *out = NULL;
    }
    mesh_dexels_free(d);
    return rc;
}

int mesh_measure_scene(const csg_scene *s, const mesh_options *o, mesh_measure *out, char *err,
                       size_t errlen)
{
    mesh_dexels *d;
    int rc = mesh_dexels_new(s, o, &d, err, errlen);
    if (rc != 0) return rc;
    mesh_dexels_measure(d, out);
    mesh_dexels_free(d);
    return 0;
}

double mesh_corner_share(const mesh *m)
{
    size_t nt = (size_t)m->nt, nv = (size_t)m->nv;
    int32_t *opp = malloc(3 * nt * sizeof *opp + 1);
    uint8_t *deg = calloc(nv + 1, 1); /* sharp edges at each vertex, up to 255 */
    uint8_t *used = calloc(nv + 1, 1);
    double(*tn)[3] = malloc(nt * sizeof *tn + 1);
    if (!opp || !deg || !used || !tn || mesh_half_twins(m, 0, opp) != 0) {
        free(opp);
        free(deg);
        free(used);
        free(tn);
        return -1;
    }
    for (size_t t = 0; t < nt; t++)
        mesh_triangle_normal(m, (int32_t)t, tn[t]);
    for (size_t x = 0; x < 3 * nt; x++) {
        int32_t p = m->t[x], q = m->t[3 * (x / 3) + (x % 3 + 1) % 3];
        used[p] = 1;
        if (opp[x] >= 0 && (size_t)opp[x] < x) continue; /* each edge once */
        const double *a = tn[x / 3], *b = opp[x] >= 0 ? tn[opp[x] / 3] : NULL;
        if (b && dot3(a, b) >= 0.94 * sqrt(dot3(a, a) * dot3(b, b))) continue; /* cos 20° */
        if (deg[p] < 255) deg[p]++;
        if (deg[q] < 255) deg[q]++;
    }
    size_t n = 0, corners = 0;
    for (size_t v = 0; v < nv; v++) {
        n += used[v];
        corners += deg[v] >= 3;
    }
    free(opp);
    free(deg);
    free(used);
    free(tn);
    return n ? (double)corners / (double)n : 0;
}
