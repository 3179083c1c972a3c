/*
 * bvh_split.c — binned SAH (Wald, "On fast construction of SAH-based
 * bounding volume hierarchies", 2007): one pass bins the centres, two
 * sweeps over the bins give every plane's cost, one pass partitions.
 * Linear in m per split, so a build is O(m log m) while the splits stay
 * balanced and the median fallback keeps it so when they are not.
 */
#include "bvh_split.h"

#include <math.h>
#include <stdlib.h>

enum { BINS = 16 };

static double half_area(const double lo[3], const double hi[3])
{
    double x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
    return x * y + y * z + z * x;
}

static void grow(double lo[3], double hi[3], const double blo[3], const double bhi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = fmin(lo[k], blo[k]);
        hi[k] = fmax(hi[k], bhi[k]);
    }
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

int iv_bvh_split(iv_bvh_item *items, int m, int depth)
{
    double clo[3], chi[3];
    empty_box(clo, chi);
    for (int i = 0; i < m; i++)
        grow(clo, chi, items[i].c, items[i].c);
    if (depth >= IV_BVH_SAH_DEPTH) return median_split(items, m, clo, chi);
    double best = INFINITY;
    int best_axis = -1, best_plane = 0;
    for (int k = 0; k < 3; k++) {
        double ext = chi[k] - clo[k];
        if (!(ext > 0)) continue;
        int cnt[BINS] = {0};
        double blo[BINS][3], bhi[BINS][3];
        for (int b = 0; b < BINS; b++)
            empty_box(blo[b], bhi[b]);
        for (int i = 0; i < m; i++) {
            int b = bin_of(items[i].c[k], clo[k], ext);
            cnt[b]++;
            grow(blo[b], bhi[b], items[i].lo, items[i].hi);
        }
        /* left_cost[p]: bins 0..p, left of the plane after bin p. */
        double left_cost[BINS], lo[3], hi[3];
        int n = 0;
        empty_box(lo, hi);
        for (int p = 0; p < BINS - 1; p++) {
            n += cnt[p];
            if (cnt[p]) grow(lo, hi, blo[p], bhi[p]);
            left_cost[p] = n ? half_area(lo, hi) * n : INFINITY;
        }
        n = 0;
        empty_box(lo, hi);
        for (int p = BINS - 2; p >= 0; p--) {
            n += cnt[p + 1];
            if (cnt[p + 1]) grow(lo, hi, blo[p + 1], bhi[p + 1]);
            double cost = n ? left_cost[p] + half_area(lo, hi) * n : INFINITY;
            if (cost < best) {
                best = cost;
                best_axis = k;
                best_plane = p;
            }
        }
    }
    if (best_axis < 0) return median_split(items, m, clo, chi);
    double lo = clo[best_axis], ext = chi[best_axis] - lo;
    int i = 0, j = m - 1;
    for (;;) {
        while (i <= j && bin_of(items[i].c[best_axis], lo, ext) <= best_plane)
            i++;
        while (i <= j && bin_of(items[j].c[best_axis], lo, ext) > best_plane)
            j--;
        if (i >= j) break;
        iv_bvh_item t = items[i];
        items[i] = items[j];
        items[j] = t;
    }
    return i; /* both sides hold items: the plane's cost was finite */
}
