/*
 * bvh_split.c — binned SAH (Wald, "On fast construction of SAH-based
 * bounding volume hierarchies", 2007): one pass bins the centres, two
 * sweeps over the bins give every plane's cost, one pass partitions.
 * Linear in m per split, so a build is O(m log m) while the splits stay
 * balanced and the median fallback keeps it so when they are not.
 *
 * Then early split clipping for meshes: long thin triangles become several
 * references whose boxes together cover the triangle (Ernst and Greiner,
 * 2007).  A box needs only contain its piece: a ray that meets a triangle
 * meets at least one of its references' boxes, and maybe more.
 */

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "intervals.h"

enum { BINS = 16 };

static double half_area(const double lo[3], const double hi[3])
{
    double x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
    return x * y + y * z + z * x;
}

/* Conditional expressions rather than fmin/fmax, which are library calls
 * at -O2: they compile to minsd/maxsd, without branches to mispredict, and
 * skip a NaN in blo/bhi as fmin/fmax do. */
static inline void grow(double lo[3], double hi[3], const double blo[3], const double bhi[3])
{
    /* written out: -O2 keeps a loop of three, at twice the instructions */
    lo[0] = blo[0] < lo[0] ? blo[0] : lo[0];
    lo[1] = blo[1] < lo[1] ? blo[1] : lo[1];
    lo[2] = blo[2] < lo[2] ? blo[2] : lo[2];
    hi[0] = bhi[0] > hi[0] ? bhi[0] : hi[0];
    hi[1] = bhi[1] > hi[1] ? bhi[1] : hi[1];
    hi[2] = bhi[2] > hi[2] ? bhi[2] : hi[2];
}

static void empty_box(double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
}

static int bin_of(double c, double lo, double ext)
{
    int b = (int)((c - lo) / ext * BINS);
    return b < 0 ? 0 : b >= BINS ? BINS - 1 : b;
}

static int cmp_x(const void *a, const void *b)
{
    double x = ((const iv_bvh_item *)a)->c[0], y = ((const iv_bvh_item *)b)->c[0];
    return (x > y) - (x < y);
}
static int cmp_y(const void *a, const void *b)
{
    double x = ((const iv_bvh_item *)a)->c[1], y = ((const iv_bvh_item *)b)->c[1];
    return (x > y) - (x < y);
}
static int cmp_z(const void *a, const void *b)
{
    double x = ((const iv_bvh_item *)a)->c[2], y = ((const iv_bvh_item *)b)->c[2];
    return (x > y) - (x < y);
}

static int median_split(iv_bvh_item *items, int m, const double clo[3], const double chi[3])
{
    int axis = 0;
    for (int k = 1; k < 3; k++)
        if (chi[k] - clo[k] > chi[axis] - clo[axis]) axis = k;
    qsort(items, (size_t)m, sizeof *items, axis == 0 ? cmp_x : axis == 1 ? cmp_y : cmp_z);
    return m / 2;
}

/* The boxes of items[0..l) and items[l..m), into box[0] and box[1]. */
static void part_boxes(const iv_bvh_item *items, int m, int l, double box[2][2][3])
{
    for (int s = 0; s < 2; s++) {
        empty_box(box[s][0], box[s][1]);
        for (int i = s ? l : 0; i < (s ? m : l); i++)
            grow(box[s][0], box[s][1], items[i].lo, items[i].hi);
    }
}

int iv_bvh_split(iv_bvh_item *items, int m, int depth)
{
    return iv_bvh_split_boxes(items, m, depth, NULL);
}

int iv_bvh_split_boxes(iv_bvh_item *items, int m, int depth, double box[2][2][3])
{
    double clo[3], chi[3];
    empty_box(clo, chi);
    for (int i = 0; i < m; i++)
        grow(clo, chi, items[i].c, items[i].c);
    if (depth >= IV_BVH_SAH_DEPTH) {
        int l = median_split(items, m, clo, chi);
        if (box) part_boxes(items, m, l, box);
        return l;
    }
    double best = INFINITY, best_box[2][2][3];
    int best_axis = -1, best_plane = 0;
    /* One pass bins the items on all three axes. */
    double ext[3];
    int cnt[3][BINS] = {{0}};
    double blo[3][BINS][3], bhi[3][BINS][3];
    for (int k = 0; k < 3; k++) {
        ext[k] = chi[k] - clo[k];
        for (int b = 0; b < BINS; b++)
            empty_box(blo[k][b], bhi[k][b]);
    }
    for (int i = 0; i < m; i++) {
        const iv_bvh_item *it = &items[i];
        for (int k = 0; k < 3; k++) {
            if (!(ext[k] > 0)) continue;
            int b = bin_of(it->c[k], clo[k], ext[k]);
            cnt[k][b]++;
            grow(blo[k][b], bhi[k][b], it->lo, it->hi);
        }
    }
    for (int k = 0; k < 3; k++) {
        if (!(ext[k] > 0)) continue;
        /* Only the planes just below a nonempty bin: the planes between two
         * nonempty bins part the items alike, cost the same, and of them
         * the sweep downwards would keep the first, the one just below the
         * upper bin.  full[0..nb): the nonempty bins, upwards. */
        int full[BINS], nb = 0;
        for (int b = 0; b < BINS; b++)
            if (cnt[k][b]) full[nb++] = b;
        /* left_cost[i]: bins full[0..i], left of the plane below full[i + 1],
         * whose box is left[i]. */
        double left_cost[BINS], left[BINS][2][3], lo[3], hi[3];
        int n = 0;
        empty_box(lo, hi);
        for (int i = 0; i + 1 < nb; i++) {
            n += cnt[k][full[i]];
            grow(lo, hi, blo[k][full[i]], bhi[k][full[i]]);
            left_cost[i] = half_area(lo, hi) * n;
            for (int j = 0; j < 3; j++) {
                left[i][0][j] = lo[j];
                left[i][1][j] = hi[j];
            }
        }
        n = 0;
        empty_box(lo, hi);
        for (int i = nb - 2; i >= 0; i--) {
            n += cnt[k][full[i + 1]];
            grow(lo, hi, blo[k][full[i + 1]], bhi[k][full[i + 1]]);
            double cost = left_cost[i] + half_area(lo, hi) * n;
            if (cost < best) {
                best = cost;
                best_axis = k;
                best_plane = full[i + 1] - 1;
                for (int j = 0; j < 3; j++) {
                    best_box[0][0][j] = left[i][0][j];
                    best_box[0][1][j] = left[i][1][j];
                    best_box[1][0][j] = lo[j];
                    best_box[1][1][j] = hi[j];
                }
            }
        }
    }
    if (best_axis < 0) {
        int l = median_split(items, m, clo, chi);
        if (box) part_boxes(items, m, l, box);
        return l;
    }
    double lo = clo[best_axis], e = ext[best_axis];
    int i = 0, j = m - 1;
    for (;;) {
        while (i <= j && bin_of(items[i].c[best_axis], lo, e) <= best_plane)
            i++;
        while (i <= j && bin_of(items[j].c[best_axis], lo, e) > best_plane)
            j--;
        if (i >= j) break;
        iv_bvh_item t = items[i];
        items[i] = items[j];
        items[j] = t;
    }
    if (box) memcpy(box, best_box, sizeof best_box);
    return i; /* both sides hold items: the plane's cost was finite */
}

/* ---- early split clipping -------------------------------------------------------- */

/* A piece of a triangle: a convex polygon of at most 3 + 6 + 1 vertices
 * (three corners, one more per clipping plane) — more room for what
 * rounding may add to a piece that is convex only up to rounding. */
enum { PIECE_MAX = 24 };

/* The part of poly[0..n) with p[k] <= s (below) or p[k] >= s, into out
 * (PIECE_MAX vertices); returns its vertex count, 0 when out of room.  A
 * vertex made on the plane gets p[k] = s exactly. */
static int clip_axis(const double (*poly)[3], int n, double (*out)[3], int k, double s, int below)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        if (m + 2 > PIECE_MAX) return 0;
        const double *a = poly[i], *b = poly[(i + 1) % n];
        int ina = below ? a[k] <= s : a[k] >= s, inb = below ? b[k] <= s : b[k] >= s;
        if (ina) {
            for (int j = 0; j < 3; j++)
                out[m][j] = a[j];
            m++;
        }
        if (ina != inb) {
            /* one end inside or on the plane, the other strictly
             * outside, so b[k] != a[k] and u is in [0, 1) */
            double u = (s - a[k]) / (b[k] - a[k]);
            for (int j = 0; j < 3; j++)
                out[m][j] = a[j] + u * (b[j] - a[j]);
            out[m][k] = s;
            m++;
        }
    }
    return m;
}

/* The triangle's part inside the box [lo, hi], into out; returns its
 * vertex count (0 when the box misses it).  A plane that no corner of the
 * triangle lies beyond would cut nothing (up to the rounding of earlier
 * cuts, which piece_box's clamp to the cell takes back), and is skipped. */
static int clip_to_box(const double (*v)[3], const int tri[3], const double lo[3],
                       const double hi[3], double (*out)[3])
{
    double a[PIECE_MAX][3], b[PIECE_MAX][3];
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 3; k++)
            a[j][k] = v[tri[j]][k];
    int n = 3;
    for (int k = 0; k < 3 && n >= 3; k++) {
        const double x = v[tri[0]][k], y = v[tri[1]][k], z = v[tri[2]][k];
        if (x < lo[k] || y < lo[k] || z < lo[k]) {
            n = clip_axis((const double(*)[3])a, n, b, k, lo[k], 0);
            for (int j = 0; j < n; j++)
                for (int c = 0; c < 3; c++)
                    a[j][c] = b[j][c];
        }
        if (n >= 3 && (x > hi[k] || y > hi[k] || z > hi[k])) {
            n = clip_axis((const double(*)[3])a, n, b, k, hi[k], 1);
            for (int j = 0; j < n; j++)
                for (int c = 0; c < 3; c++)
                    a[j][c] = b[j][c];
        }
    }
    for (int j = 0; j < n; j++)
        for (int k = 0; k < 3; k++)
            out[j][k] = a[j][k];
    return n;
}

static double poly_area(const double (*p)[3], int n)
{
    double s[3] = {0, 0, 0};
    for (int i = 1; i + 1 < n; i++) {
        double u[3], w[3];
        for (int k = 0; k < 3; k++) {
            u[k] = p[i][k] - p[0][k];
            w[k] = p[i + 1][k] - p[0][k];
        }
        s[0] += u[1] * w[2] - u[2] * w[1];
        s[1] += u[2] * w[0] - u[0] * w[2];
        s[2] += u[0] * w[1] - u[1] * w[0];
    }
    return 0.5 * sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
}

/* The box of p[0..n), widened by pad and then cut back to [lo, hi]: the
 * vertices made by clipping are rounded, and the box must hold the exact
 * piece; the cell's own walls are exact. */
static void piece_box(const double (*p)[3], int n, double pad, const double lo[3],
                      const double hi[3], iv_bvh_item *it)
{
    empty_box(it->lo, it->hi);
    for (int i = 0; i < n; i++)
        grow(it->lo, it->hi, p[i], p[i]);
    for (int k = 0; k < 3; k++) {
        it->lo[k] -= pad;
        it->hi[k] += pad;
        if (it->lo[k] < lo[k]) it->lo[k] = lo[k];
        if (it->hi[k] > hi[k]) it->hi[k] = hi[k];
        it->c[k] = 0.5 * (it->lo[k] + it->hi[k]);
    }
}

/* A piece is worth cutting while its box's area is this many times its
 * own: at most about 3.5 for a well-shaped triangle at any slant, 2 for
 * one in an axis plane; a long thin one across the axes reaches 10^4. */
#define SPLIT_RATIO 8.0

/* The items waiting to be cut, by the area of their box: a list per half
 * octave of area (a bucket queue), so the order is largest first to within
 * a factor of √2 at constant cost per item — a binary heap over millions of
 * items spends its time in cache misses.  A piece's box lies in its
 * parent's, so no item enters above the bucket being taken from. */
enum { QUEUE_BUCKETS = 2 * 2200 };

typedef struct queue {
    int head[QUEUE_BUCKETS];
    int *next; /* per item */
    int top;   /* no bucket above holds anything */
} queue;

static int bucket_of(double a)
{
    int e;
    double f = frexp(a, &e); /* a = f·2^e, f in [0.5, 1), e in [-1073, 1024] */
    int b = 2 * (e + 1100) + (f >= 0.70710678118654752);
    return b < 0 ? 0 : b >= QUEUE_BUCKETS ? QUEUE_BUCKETS - 1 : b;
}

/* Queue item i when its piece p[0..n) is worth cutting. */
static void consider(queue *q, const iv_bvh_item *items, int i, const double (*p)[3], int n)
{
    double a = half_area(items[i].lo, items[i].hi), area = poly_area(p, n);
    if (!(area > 0 && a > SPLIT_RATIO * area)) return;
    int b = bucket_of(a);
    q->next[i] = q->head[b];
    q->head[b] = i;
    if (b > q->top) q->top = b;
}

/* The item taken next; -1 when none is left. */
static int take(queue *q)
{
    while (q->top >= 0 && q->head[q->top] < 0)
        q->top--;
    if (q->top < 0) return -1;
    int i = q->head[q->top];
    q->head[q->top] = q->next[i];
    return i;
}

iv_bvh_item *iv_bvh_clip_triangles(const double (*v)[3], const int (*tri)[3], int nt, long extra,
                                   long *nref)
{
    if (extra < 0) extra = 0;
    iv_bvh_item *items = malloc((size_t)(nt + extra) * sizeof *items);
    if (!items) return NULL;
    for (int i = 0; i < nt; i++) {
        iv_bvh_item *it = &items[i];
        for (int k = 0; k < 3; k++) {
            const double a = v[tri[i][0]][k], b = v[tri[i][1]][k], c = v[tri[i][2]][k];
            it->lo[k] = a < b ? (a < c ? a : c) : (b < c ? b : c);
            it->hi[k] = a > b ? (a > c ? a : c) : (b > c ? b : c);
            it->c[k] = (a + b + c) / 3;
        }
        it->id = i;
    }
    long n = nt;
    queue *q = extra > 0 ? malloc(sizeof *q) : NULL;
    int *next = q ? malloc((size_t)(nt + extra) * sizeof *next) : NULL;
    if (q && next) {
        q->next = next;
        q->top = -1;
        for (int b = 0; b < QUEUE_BUCKETS; b++)
            q->head[b] = -1;
        for (int i = 0; i < nt; i++) {
            double p[3][3];
            for (int j = 0; j < 3; j++)
                for (int k = 0; k < 3; k++)
                    p[j][k] = v[tri[i][j]][k];
            consider(q, items, i, (const double(*)[3])p, 3);
        }
        /* Largest box first: the chance that a ray meets a box goes with
         * its area.  Each cut turns one reference into two. */
        int i;
        while (n < nt + extra && (i = take(q)) >= 0) {
            iv_bvh_item cell = items[i];
            double p[PIECE_MAX][3], lp[PIECE_MAX][3], rp[PIECE_MAX][3];
            int np = clip_to_box(v, tri[cell.id], cell.lo, cell.hi, p);
            int ax = 0;
            for (int k = 1; k < 3; k++)
                if (cell.hi[k] - cell.lo[k] > cell.hi[ax] - cell.lo[ax]) ax = k;
            double s = 0.5 * (cell.lo[ax] + cell.hi[ax]);
            int nl = clip_axis((const double(*)[3])p, np, lp, ax, s, 1);
            int nr = clip_axis((const double(*)[3])p, np, rp, ax, s, 0);
            if (nl < 3 || nr < 3) continue; /* stays one reference */
            /* The rounding of a clipped vertex is a few ulps of the
             * coordinates; 2^-40 of the largest keeps far clear of it. */
            double big = 0;
            for (int k = 0; k < 3; k++)
                big = fmax(big, fmax(fabs(cell.lo[k]), fabs(cell.hi[k])));
            double pad = big * 0x1p-40;
            double lo[3], hi[3];
            for (int k = 0; k < 3; k++) {
                lo[k] = cell.lo[k];
                hi[k] = cell.hi[k];
            }
            hi[ax] = s;
            piece_box((const double(*)[3])lp, nl, pad, lo, hi, &items[i]);
            hi[ax] = cell.hi[ax];
            lo[ax] = s;
            piece_box((const double(*)[3])rp, nr, pad, lo, hi, &items[n]);
            items[n].id = cell.id;
            consider(q, items, i, (const double(*)[3])lp, nl);
            consider(q, items, (int)n, (const double(*)[3])rp, nr);
            n++;
        }
    }
    free(q);
    free(next);
    *nref = n;
    return items;
}
