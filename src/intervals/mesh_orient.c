/*
 * mesh_orient.c — what a triangle mesh's edges say about it: closed, closed
 * once its faces are turned consistently, cracked only at T-junctions, or
 * open; and the turning itself.
 *
 * OpenSCAD's preview draws a polyhedron's faces whatever their winding, and
 * CGAL (its render and export) reads a closed surface as a solid whatever
 * the winding of its faces.  A mesh whose every edge joins exactly two
 * triangles is turned face by face until each edge is used once each way
 * (a parity union–find over the triangles), then each connected piece is
 * turned so that an outermost piece encloses positive volume and a piece
 * nested inside k others has the sign of (-1)^k — a cavity stays a cavity.
 *
 * A mesh with edges that only one triangle uses is closed all the same when
 * those edges are T-junctions (the long edge of one triangle covered by the
 * short edges of its neighbours, as exporters that do not split edges
 * write), and open — a surface without an inside — when they are holes.
 */
#include "shape_kinds.h"
#include "vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int cmp_ull(const void *a, const void *b)
{
    const unsigned long long *x = a, *y = b;
    return (*x > *y) - (*x < *y);
}

/* Sorts e[0..n) with the help of tmp[0..n): least significant digit first,
 * 11 bits a pass, as many passes as the largest key needs (4 for the edges
 * of 2·10^5 vertices) — a qsort of a million edges spends its time in
 * comparator calls. */
static void sort_keys(unsigned long long *e, unsigned long long *tmp, size_t n)
{
    unsigned long long max = 0, *src = e, *dst = tmp;
    for (size_t i = 0; i < n; i++)
        max = e[i] > max ? e[i] : max;
    for (int shift = 0; shift < 64 && (max >> shift) != 0; shift += 11) {
        size_t at[2048] = {0};
        for (size_t i = 0; i < n; i++)
            at[(src[i] >> shift) & 2047]++;
        size_t sum = 0;
        for (int b = 0; b < 2048; b++) {
            size_t c = at[b];
            at[b] = sum;
            sum += c;
        }
        for (size_t i = 0; i < n; i++)
            dst[at[(src[i] >> shift) & 2047]++] = src[i];
        unsigned long long *x = src;
        src = dst;
        dst = x;
    }
    if (src != e) memcpy(e, src, n * sizeof *e);
}

/* The edges of the triangles as sorted keys: the unordered vertex pair, then
 * with `with_tri` the triangle (32 bits), then the direction in the low bit
 * (1: from the lower index to the higher).  nv < 2^31 keeps a pair below
 * 2^62, so `with_tri` needs nv·nv·nt < 2^63 — the caller checks.  Returns
 * the malloc'd array and *ne, or NULL when out of memory. */
static unsigned long long *edge_keys(const int (*tri)[3], int nt, int nv, int with_tri, size_t *ne)
{
    unsigned long long *e = malloc((size_t)nt * 3 * sizeof *e);
    if (!e) return NULL;
    size_t n = 0;
    for (int i = 0; i < nt; i++)
        for (int j = 0; j < 3; j++) {
            unsigned long long a = (unsigned)tri[i][j], b = (unsigned)tri[i][(j + 1) % 3];
            if (a == b) continue;
            unsigned long long lo = a < b ? a : b, hi = a < b ? b : a;
            unsigned long long k = lo * (unsigned long long)nv + hi;
            if (with_tri) k = k * (unsigned long long)nt + (unsigned)i;
            e[n++] = (k << 1) | (a < b);
        }
    unsigned long long *tmp = malloc(n * sizeof *tmp);
    if (tmp)
        sort_keys(e, tmp, n);
    else
        qsort(e, n, sizeof *e, cmp_ull);
    free(tmp);
    *ne = n;
    return e;
}

int iv_mesh_edges_closed(const int (*tri)[3], int nt, int nv)
{
    size_t ne;
    unsigned long long *e = edge_keys(tri, nt, nv, 0, &ne);
    if (!e) return -1;
    int closed = 1;
    for (size_t i = 0; i < ne && closed;) {
        size_t j = i;
        int fw = 0, bw = 0;
        for (; j < ne && (e[j] >> 1) == (e[i] >> 1); j++)
            (e[j] & 1) ? fw++ : bw++;
        /* Fan diagonals are used once each way inside one face, like any
         * manifold edge. */
        if (fw != bw) closed = 0;
        i = j;
    }
    free(e);
    return closed;
}

/* ---- turning faces ------------------------------------------------------ */

/* Union–find with parity: par[i] is the parity of i relative to up[i]. */
static int find(int *up, unsigned char *par, int i)
{
    int root = i, p = 0;
    while (up[root] != root) {
        p ^= par[root];
        root = up[root];
    }
    /* compress: each node on the path points at the root with its parity */
    while (up[i] != root) {
        int next = up[i];
        unsigned char pi = par[i];
        up[i] = root;
        par[i] = (unsigned char)p;
        p ^= pi;
        i = next;
    }
    return root;
}

/* Parity of i relative to its root (after find). */
static int parity(const int *up, const unsigned char *par, int i)
{
    int p = 0;
    while (up[i] != i) {
        p ^= par[i];
        i = up[i];
    }
    return p;
}

/* Joins a and b with flip(a) ^ flip(b) == want; 0, or 1 on a contradiction
 * (a one-sided surface). */
static int join(int *up, unsigned char *par, int a, int b, int want)
{
    int ra = find(up, par, a), rb = find(up, par, b);
    int pa = parity(up, par, a), pb = parity(up, par, b);
    if (ra == rb) return (pa ^ pb) != want;
    up[rb] = ra;
    par[rb] = (unsigned char)(pa ^ pb ^ want);
    return 0;
}

/* The parity of the crossings of the ray from p along a fixed direction
 * with each piece's triangles (Möller–Trumbore), into odd[piece]: one pass
 * over the triangles for all pieces. */
static void crossings(const double (*v)[3], const int (*tri)[3], int nt, const int *piece_of,
                      const double p[3], unsigned char *odd)
{
    /* an irrational-looking direction: no edge or vertex of real data lies
     * on the ray but by a coincidence of about 1e-16 */
    static const double d[3] = {0.5773502691896258, 0.5345224838248488, 0.6172133998483676};
    for (int i = 0; i < nt; i++) {
        const double *a = v[tri[i][0]];
        double e1[3], e2[3], s[3], h[3], q[3];
        sub3(v[tri[i][1]], a, e1);
        sub3(v[tri[i][2]], a, e2);
        sub3(p, a, s);
        cross3(d, e2, h);
        double det = dot3(e1, h);
        if (det == 0) continue;
        double u = dot3(s, h) / det;
        if (u < 0 || u > 1) continue;
        cross3(s, e1, q);
        double w = dot3(d, q) / det;
        if (w < 0 || u + w > 1) continue;
        if (dot3(e2, q) / det > 0) odd[piece_of[i]] ^= 1;
    }
}

/* Nested pieces are told apart only up to this many pieces (each piece's
 * test walks every triangle); beyond, every piece is made positive. */
enum { NEST_MAX_PIECES = 64 };

/* Turns the triangles of a mesh whose every edge joins two triangles so that
 * each edge is used once each way, and each piece as the file comment says.
 * flip[t] gets 1 for each triangle turned.  Returns 0, 1 when the surface
 * is one-sided or an edge has other than two triangles, or -1 when out of
 * memory. */
static int orient(const double (*v)[3], const int (*tri)[3], int nt, int nv, unsigned char *flip)
{
    if ((double)nv * nv * nt * 2 >= 9.2e18) return 1;
    size_t ne;
    unsigned long long *e = edge_keys(tri, nt, nv, 1, &ne);
    int *up = malloc((size_t)nt * sizeof *up);
    unsigned char *par = calloc((size_t)nt, 1);
    int *piece_of = NULL;
    double *vol = NULL;
    int rc = -1;
    if (!e || !up || !par) goto done;
    for (int i = 0; i < nt; i++)
        up[i] = i;
    rc = 1;
    for (size_t i = 0; i < ne;) {
        size_t j = i;
        unsigned long long pair = (e[i] >> 1) / (unsigned)nt;
        while (j < ne && (e[j] >> 1) / (unsigned)nt == pair)
            j++;
        if (j - i != 2) goto done;
        int a = (int)((e[i] >> 1) % (unsigned)nt), b = (int)((e[i + 1] >> 1) % (unsigned)nt);
        /* the same direction in both: one of the two must turn */
        if (join(up, par, a, b, (e[i] & 1) == (e[i + 1] & 1))) goto done;
        i = j;
    }
    rc = -1;
    piece_of = malloc((size_t)nt * sizeof *piece_of);
    vol = calloc((size_t)nt, sizeof *vol);
    if (!piece_of || !vol) goto done;
    int npieces = 0;
    for (int i = 0; i < nt; i++) {
        int r = find(up, par, i);
        flip[i] = (unsigned char)parity(up, par, i);
        if (r == i) piece_of[i] = npieces++;
    }
    for (int i = 0; i < nt; i++)
        piece_of[i] = piece_of[find(up, par, i)];
    /* vol[piece]: six times its signed volume as turned, positive for
     * OpenSCAD's winding (clockwise from outside) */
    for (int i = 0; i < nt; i++) {
        const double *p = v[tri[i][1]], *q = v[tri[i][2]];
        vol[piece_of[i]] -= flip[i] ? triple3(v[tri[i][0]], q, p) : triple3(v[tri[i][0]], p, q);
    }
    unsigned char *turn = calloc((size_t)npieces, 1), *odd = calloc((size_t)npieces, 1);
    if (!turn || !odd) {
        free(turn);
        free(odd);
        goto done;
    }
    for (int k = 0; k < npieces; k++) {
        int depth = 0;
        if (npieces > 1 && npieces <= NEST_MAX_PIECES) {
            int t = 0;
            while (piece_of[t] != k)
                t++;
            double c[3];
            for (int j = 0; j < 3; j++)
                c[j] = (v[tri[t][0]][j] + v[tri[t][1]][j] + v[tri[t][2]][j]) / 3;
            memset(odd, 0, (size_t)npieces);
            crossings(v, tri, nt, piece_of, c, odd);
            for (int other = 0; other < npieces; other++)
                if (other != k) depth += odd[other];
        }
        int want_positive = depth % 2 == 0;
        turn[k] = (unsigned char)((vol[k] > 0) != want_positive);
    }
    for (int i = 0; i < nt; i++)
        flip[i] ^= turn[piece_of[i]];
    free(turn);
    free(odd);
    rc = 0;
done:
    free(e);
    free(up);
    free(par);
    free(piece_of);
    free(vol);
    return rc;
}

/* ---- cracks ------------------------------------------------------------- */

/* Unmatched edges are told apart as cracks only up to this many (each is
 * compared with every other); beyond, the mesh is taken as cracked. */
enum { CRACK_MAX_EDGES = 8192 };

/* 1 when the parts of the segments (a[i], b[i]), i != k, that run along
 * segment k the other way cover it, within 1e-9 of its length. */
static int covered(const double (*v)[3], const int *ea, const int *eb, int n, int k)
{
    const double *a = v[ea[k]], *b = v[eb[k]];
    double ab[3], len2 = 0;
    for (int j = 0; j < 3; j++) {
        ab[j] = b[j] - a[j];
        len2 += ab[j] * ab[j];
    }
    if (!(len2 > 0)) return 1;
    /* the covering pieces as parameters along ab, at most n */
    double lo[64], hi[64];
    int m = 0;
    for (int i = 0; i < n; i++) {
        if (i == k) continue;
        double u[2], off = 0;
        for (int e = 0; e < 2; e++) {
            const double *p = v[e == 0 ? ea[i] : eb[i]];
            double ap[3], dot = 0;
            for (int j = 0; j < 3; j++) {
                ap[j] = p[j] - a[j];
                dot += ap[j] * ab[j];
            }
            u[e] = dot / len2;
            for (int j = 0; j < 3; j++) {
                double r = ap[j] - u[e] * ab[j];
                off += r * r;
            }
        }
        if (off > 1e-18 * len2 || !(u[1] < u[0])) continue; /* off the line, or the same way */
        if (u[0] <= 0 || u[1] >= 1) continue;               /* beside k */
        if (m == 64) return 0;
        lo[m] = u[1];
        hi[m] = u[0];
        m++;
    }
    /* sweep from 0: extend the covered prefix while a piece starts in it */
    double reach = 0;
    for (int grown = 1; grown && reach < 1 - 1e-9;) {
        grown = 0;
        for (int i = 0; i < m; i++)
            if (lo[i] <= reach + 1e-9 && hi[i] > reach) {
                reach = hi[i];
                grown = 1;
            }
    }
    return reach >= 1 - 1e-9;
}

/* 1 when every edge left unmatched is a T-junction crack, 0 when one is a
 * hole's, -1 when out of memory. */
static int only_cracks(const double (*v)[3], const int (*tri)[3], int nt, int nv)
{
    size_t ne;
    unsigned long long *e = edge_keys(tri, nt, nv, 0, &ne);
    if (!e) return -1;
    int *ea = malloc(CRACK_MAX_EDGES * sizeof *ea), *eb = malloc(CRACK_MAX_EDGES * sizeof *eb);
    int n = 0, rc = -1;
    if (!ea || !eb) goto done;
    rc = 1;
    for (size_t i = 0; i < ne;) {
        size_t j = i;
        int fw = 0, bw = 0;
        for (; j < ne && (e[j] >> 1) == (e[i] >> 1); j++)
            (e[j] & 1) ? fw++ : bw++;
        int lo = (int)((e[i] >> 1) / (unsigned)nv), hi = (int)((e[i] >> 1) % (unsigned)nv);
        for (int x = fw; x < bw || x > bw;) {
            if (n == CRACK_MAX_EDGES) goto done;
            ea[n] = x > bw ? lo : hi;
            eb[n] = x > bw ? hi : lo;
            n++;
            x += x > bw ? -1 : 1;
        }
        i = j;
    }
    for (int k = 0; k < n && rc == 1; k++)
        if (!covered(v, ea, eb, n, k)) rc = 0;
done:
    free(e);
    free(ea);
    free(eb);
    return rc;
}

iv_mesh_reading iv_mesh_read_edges(const double (*v)[3], int nv, int (*tri)[3], int nt,
                                   unsigned char *flip)
{
    memset(flip, 0, (size_t)nt);
    int closed = iv_mesh_edges_closed((const int(*)[3])tri, nt, nv);
    if (closed < 0) return IV_MESH_READ_FAILED;
    if (closed) return IV_MESH_CLOSED;
    int rc = orient(v, (const int(*)[3])tri, nt, nv, flip);
    if (rc < 0) return IV_MESH_READ_FAILED;
    if (rc == 0) {
        for (int i = 0; i < nt; i++)
            if (flip[i]) {
                int x = tri[i][1];
                tri[i][1] = tri[i][2];
                tri[i][2] = x;
            }
        return IV_MESH_TURNED;
    }
    memset(flip, 0, (size_t)nt);
    rc = only_cracks(v, (const int(*)[3])tri, nt, nv);
    if (rc < 0) return IV_MESH_READ_FAILED;
    return rc ? IV_MESH_CRACKED : IV_MESH_OPEN;
}
