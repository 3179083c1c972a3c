/*
 * trace.c — one ray through a committed scene: csg_trace, its first boundary
 * alone (csg_trace_first, below) and the normals.
 *
 * Evaluation is a post-order walk of the flat pre-order node array driven by
 * an explicit stack of frames (one per open operation), so its depth is
 * limited by arena memory, never by the C stack: there is no depth limit.
 * Lists live on a second stack, an array of spans from the arena: a frame's
 * accumulated list sits at `base`, the child being evaluated is written right
 * after it, and a merge writes past both and is copied back to `base`.  A
 * merge's output is at most as long as its inputs together, so the array
 * holds at most twice the spans the leaves along the ray produce (one per
 * convex primitive); it grows by doubling, so the waste stays bounded too.
 *
 * The arena's list limit (iv_arena_list_limit, M) caps every list made
 * along the way: a leaf's (whose scratch may take up to M spans' room) and
 * each merge's.  The inputs of a merge are then at most M each, so one ray
 * holds at most M spans per open frame plus 4M for the merge at hand,
 * whatever the model; a list that would pass M ends the trace with
 * IV_ARENA_LIST_TOO_LONG recorded in the arena.  The test is one compare
 * per leaf and per merge.
 *
 * Invariant: a subtree evaluated for the range [t0, t1] yields exactly its
 * true interval list clipped to [t0, t1].  That is what lets a node whose
 * bounds the segment misses return the empty list, and lets the operands of
 * an intersection or difference after the first be evaluated only over the
 * extent of the list accumulated so far (nothing outside it can matter).
 * Clip boundaries (prim = IV_PRIM_NONE) made at such a narrowed range fall
 * on a boundary of the accumulated list, which the merges prefer at equal t,
 * so only the root range [tmin, tmax] ever shows up as a clip in a result.
 */
#include "csg_internal.h"

#include <math.h>
#include <string.h>

typedef struct frame {
    int32_t node;   /* the op node */
    int32_t cursor; /* the child being evaluated */
    int32_t base;   /* span-stack index of the accumulated list */
    int32_t nacc;   /* its length; -1 before the first child is done */
    double t0, t1;  /* the range this op was asked for */
} frame;

typedef struct ray {
    const csg_scene *s;
    double o[3], d[3], inv[3];
    int cull;       /* the scene's: box tests on */
    uint8_t neg[3]; /* d[k] < 0: a box's near plane on axis k is hi, not lo */
    uint8_t flat;   /* some d[k] is 0: the slab test needs box_entry_flat */
    iv_arena *a;
    iv_span *sp; /* the span stack */
    int cap;
    int max;   /* spans one list may hold: the arena's list limit */
    frame *fr; /* s->max_depth frames */
} ray;

/* A list would hold more than r->max spans: record why, and fail. */
static int too_long(ray *r)
{
    iv_arena_record_failure(r->a, IV_ARENA_LIST_TOO_LONG);
    return -1;
}

/* Make room for `need` spans, keeping the first `live`. */
static int reserve(ray *r, long need, int live)
{
    if (need <= r->cap) return 0;
    long cap = 2L * r->cap;
    if (cap < need) cap = need;
    if (cap > INT32_MAX) return -1;
    iv_span *v = iv_arena_alloc(r->a, (size_t)cap * sizeof *v);
    if (!v) return -1;
    if (live > 0) memcpy(v, r->sp, (size_t)live * sizeof *v);
    r->sp = v;
    r->cap = (int)cap;
    return 0;
}

/* box_entry for a ray parallel to some axis: on that axis the ray is
 * inside the slab or never meets it. */
static int box_entry_flat(const ray *r, const double lo[3], const double hi[3], double t0,
                          double t1, double *te)
{
    for (int k = 0; k < 3; k++) {
        if (r->d[k] == 0) {
            if (r->o[k] < lo[k] || r->o[k] > hi[k]) return 0;
            continue;
        }
        double ta = ((r->neg[k] ? hi[k] : lo[k]) - r->o[k]) * r->inv[k];
        double tb = ((r->neg[k] ? lo[k] : hi[k]) - r->o[k]) * r->inv[k];
        if (ta > t0) t0 = ta;
        if (tb < t1) t1 = tb;
    }
    *te = t0;
    return t0 <= t1;
}

/* Whether the segment t in [t0, t1] of the ray meets the box [lo, hi], and
 * where it enters it (*te; t0 itself when the scene does not cull).  The
 * slab products may be NaN (a bound plane through o with a subnormal d,
 * giving 0·inf); every comparison with NaN is false, so such a slab narrows
 * nothing and the test errs on the side of "hit".  The near and far planes
 * are picked by the ray's signs (precomputed), so the common case has no
 * data-dependent branch: this test is most of a big union's traversal. */
static inline int box_entry(const ray *r, const double lo[3], const double hi[3], double t0,
                            double t1, double *te)
{
    if (!r->cull) {
        *te = t0;
        return t0 <= t1;
    }
    if (r->flat) return box_entry_flat(r, lo, hi, t0, t1, te);
    for (int k = 0; k < 3; k++) {
        double ta = ((r->neg[k] ? hi[k] : lo[k]) - r->o[k]) * r->inv[k];
        double tb = ((r->neg[k] ? lo[k] : hi[k]) - r->o[k]) * r->inv[k];
        t0 = ta > t0 ? ta : t0;
        t1 = tb < t1 ? tb : t1;
    }
    *te = t0;
    return t0 <= t1;
}

/* A leaf's list, clipped to [t0, t1], written at span index `at`; its
 * length, or -1 when the arena is out of memory or the list is too long.
 * Convex shapes append one span, but the shape gets all the room left on
 * the span stack (at least 16) and, should it report that is not enough,
 * twice as much again, so shapes with more spans need no size query here.
 * The room stops growing past r->max spans: a mesh keeps its crossings
 * there, two to a span, before pairing them, so a shape that cannot make do
 * with that crosses the ray more than 2·max times. */
static int trace_leaf(ray *r, int32_t prim, double t0, double t1, int at)
{
    const csg_prim *p = &r->s->prims[prim];
    double o[3], d[3];
    /* Map the ray, not the shape, and do not normalise d: t then means the
     * same point in both spaces. */
    csg_affine_point(p->object_from_world, r->o, o);
    csg_affine_vector(p->object_from_world, r->d, d);
    if (reserve(r, at + 16L, at) != 0) return -1;
    for (;;) {
        iv_list l = {r->sp + at, 0, r->cap - at};
        if (iv_shape_intersect(&p->shape, o, d, prim, &l) >= 0) {
            iv_list_clip(&l, t0, t1);
            return l.n <= r->max ? l.n : too_long(r);
        }
        if (r->cap - at > r->max) return too_long(r);
        if (reserve(r, at + 2L * (r->cap - at), at) != 0) return -1;
    }
}

/* Set up r for one ray: its inverse direction and signs; the frame array
 * and the span stack come from the arena when first needed. */
static void ray_init(ray *r, const csg_scene *s, const double o[3], const double d[3], iv_arena *a)
{
    /* Field by field: a compound literal would zero the whole struct first
     * (a rep stos, a tenth of a simple scene's ray). */
    r->s = s;
    r->a = a;
    r->sp = NULL;
    r->cap = 0;
    r->fr = NULL;
    r->max = iv_arena_list_limit(a);
    r->cull = s->cull;
    r->flat = 0;
    for (int k = 0; k < 3; k++) {
        r->o[k] = o[k];
        r->d[k] = d[k];
        r->inv[k] = 1 / d[k]; /* ±inf when d[k] = ±0; the box tests never use it then */
        r->neg[k] = d[k] < 0;
        r->flat |= d[k] == 0;
    }
}

/* The frame array, made on the first operation a ray opens (most rays of a
 * big union meet leaves alone); NULL when the arena is out of memory. */
static frame *frames(ray *r)
{
    if (!r->fr)
        r->fr = iv_arena_alloc(r->a,
                               (size_t)(r->s->max_depth > 0 ? r->s->max_depth : 1) * sizeof *r->fr);
    return r->fr;
}

/* The list of the subtree at node `node`, clipped to [tmin, tmax], written at
 * span index `at` (read it from r->sp after the call: the stack may move).
 * Returns its length, or -1 when the arena is out of memory or a list would
 * pass r->max (the arena records which). */
static int eval(ray *r, int32_t node, double tmin, double tmax, int at)
{
    const csg_fnode *nodes = r->s->nodes;
    frame *fr = NULL;
    int depth = 0; /* open frames */
    int32_t cur = node;
    double t0 = tmin, t1 = tmax;
    int nres; /* length of the list just finished, at `at` */
    for (;;) {
        /* Descend from cur until a list is known. */
        const csg_fnode *n = &nodes[cur];
        double te;
        if (!box_entry(r, n->lo, n->hi, t0, t1, &te)) {
            nres = 0;
        } else if (n->op == FNODE_LEAF) {
            nres = trace_leaf(r, n->prim, t0, t1, at);
            if (nres < 0) return -1;
        } else {
            if (!fr && !(fr = frames(r))) return -1;
            fr[depth++] = (frame){cur, cur + 1, at, -1, t0, t1};
            cur = cur + 1;
            continue;
        }
        /* Ascend: hand nres to the open frames until one wants another
         * child. */
        for (;;) {
            if (depth == 0) return nres;
            frame *f = &fr[depth - 1];
            const csg_fnode *op = &nodes[f->node];
            if (f->nacc <= 0) {
                /* First operand, or a union whose operands so far were
                 * empty: the child's list already sits at base. */
                f->nacc = nres;
            } else if (nres == 0) {
                if (op->op == CSG_OP_INTERSECTION) f->nacc = 0;
            } else {
                const int base = f->base, na = f->nacc;
                if (reserve(r, (long)base + 2L * (na + nres), base + na + nres) != 0) return -1;
                iv_list la = {r->sp + base, na, na};
                iv_list lb = {r->sp + base + na, nres, nres};
                iv_list lo = {r->sp + base + na + nres, 0, na + nres};
                switch (op->op) {
                case CSG_OP_UNION:
                    iv_list_union(&la, &lb, &lo);
                    break;
                case CSG_OP_INTERSECTION:
                    iv_list_intersection(&la, &lb, &lo);
                    break;
                default:
                    iv_list_difference(&la, &lb, &lo);
                    break;
                }
                if (lo.n > r->max) return too_long(r);
                memcpy(r->sp + base, lo.v, (size_t)lo.n * sizeof *lo.v);
                f->nacc = lo.n;
            }
            int32_t next = nodes[f->cursor].next;
            /* Roth: once an intersection or difference is empty, the
             * remaining operands cannot change it. */
            if (next >= op->next || (f->nacc == 0 && op->op != CSG_OP_UNION)) {
                nres = f->nacc;
                at = f->base;
                depth--;
                continue;
            }
            f->cursor = next;
            cur = next;
            at = f->base + f->nacc;
            t0 = f->t0;
            t1 = f->t1;
            if (op->op != CSG_OP_UNION) {
                /* The accumulated list is clipped to [f->t0, f->t1], so its
                 * extent lies inside that range. */
                t0 = r->sp[f->base].enter.t;
                t1 = r->sp[f->base + f->nacc - 1].exit.t;
            }
            break;
        }
    }
}

int csg_trace(const csg_scene *s, int root, const double o[3], const double d[3], double tmin,
              double tmax, iv_arena *a, iv_list *out)
{
    out->v = NULL;
    out->n = out->cap = 0;
    if (root < 0 || root >= s->nroots || s->roots[root] < 0 || !(tmin < tmax)) return 0;
    ray r;
    ray_init(&r, s, o, d, a);
    int n = eval(&r, s->roots[root], tmin, tmax, 0);
    if (n < 0) return -1;
    out->v = r.sp;
    out->n = n;
    out->cap = r.cap;
    return 0;
}

/* ---- the first boundary ------------------------------------------------------
 * The first boundary of a union is the earliest first boundary of its
 * operands, and at equal t the merge keeps the earlier operand's (list.c
 * emits a's boundary when both change).  Unions nest, so over the "union
 * frontier" of the root — the nodes that are not unions, reached from the
 * root through unions only — the answer is the least (t, node index) of
 * their first boundaries: pre-order is exactly the merge's precedence.
 *
 * So the search walks the unions with a stack, nearest box entry on top, and
 * evaluates each frontier node (a leaf, an intersection or a difference) in
 * full but only over [tmin, hi]: with a best (t*, k*) found, a node with
 * index above k* can only win below t* (hi = t*: the clip drops spans that
 * enter at t* or later), and one below k* also at t* itself (hi = the next
 * double above t*, so a span entering at t* survives).  A clip only changes
 * what lies at or beyond hi, and eval's invariant makes each result the
 * node's true list clipped, so the first boundary found is exactly the full
 * trace's.  A node whose box entry lies beyond that window is skipped.
 *
 * A union's operands come from its csg_wide records (scene.c), four boxes
 * tested at once, with AVX where the CPU has it; both tests do box_entry's
 * operations in box_entry's order, so every entry is its bit for bit, and a
 * stack entry carries what its node's evaluation needs (`ref`) without
 * reading the node. */

typedef struct pending {
    double te; /* where the ray enters the node's box (tmin when not culling) */
    int32_t node;
    int32_t ref; /* as csg_wide's */
} pending;

/* Which operands of record w the segment [t0, t1] meets (bit i for lane i),
 * and where each enters its box (te[i], defined for the lanes met):
 * box_entry on each lane's bounds. */
static unsigned wide_entry(const void *ray_, const csg_wide *w, double t0, double t1,
                           double te[WIDE])
{
    const ray *r = ray_;
    unsigned hit = 0;
    for (int i = 0; i < w->n; i++) {
        double lo[3], hi[3];
        for (int k = 0; k < 3; k++) {
            lo[k] = w->box[0][k][i];
            hi[k] = w->box[1][k][i];
        }
        hit |= (unsigned)box_entry(r, lo, hi, t0, t1, &te[i]) << i;
    }
    return hit;
}

/* Whether entry x comes off the stack after y: a farther box entry, or the
 * same and a later node.  Entries are never NaN (box_entry's t0 starts at
 * tmin and a NaN slab leaves it), and no two hold one node, so this is a
 * strict total order and any correct sort gives the one result. */
static inline int later(const pending *x, const pending *y)
{
    return x->te > y->te || (x->te == y->te && x->node > y->node);
}

/* Put the later of v[i], v[j] (i < j) at i. */
static inline void order2(pending *v, int i, int j)
{
    pending x = v[i], y = v[j];
    int sw = later(&y, &x);
    v[i] = sw ? y : x;
    v[j] = sw ? x : y;
}

/* Children sorted in place with the nearest box entry last (it is popped
 * first), the lower index last among equal entries.  Sorting networks for
 * a grouped union's 2 to 4 operands, insertion sort up to 32; past that (an
 * ungrouped union, only when grouping ran out of memory) the order is left
 * as pushed, reversed so that pre-order comes off first — any order is
 * correct, only slower. */
static inline void sort_pending(pending *v, int n)
{
    switch (n) {
    case 0:
    case 1:
        return;
    case 2:
        order2(v, 0, 1);
        return;
    case 3:
        order2(v, 0, 1);
        order2(v, 1, 2);
        order2(v, 0, 1);
        return;
    case 4:
        order2(v, 0, 1);
        order2(v, 2, 3);
        order2(v, 0, 2);
        order2(v, 1, 3);
        order2(v, 1, 2);
        return;
    }
    if (n > 32) {
        for (int i = 0, j = n - 1; i < j; i++, j--) {
            pending t = v[i];
            v[i] = v[j];
            v[j] = t;
        }
        return;
    }
    for (int i = 1; i < n; i++) {
        pending x = v[i];
        int j = i;
        while (j > 0 && later(&x, &v[j - 1])) {
            v[j] = v[j - 1];
            j--;
        }
        v[j] = x;
    }
}

/* The stack st (sn entries, capacity *cap) moved to twice the room in the
 * arena; NULL when the arena is out of memory. */
static pending *grow(iv_arena *a, const pending *st, int sn, int *cap)
{
    pending *v = iv_arena_alloc(a, 2 * (size_t)*cap * sizeof *v);
    if (!v) return NULL;
    memcpy(v, st, (size_t)sn * sizeof *v);
    *cap *= 2;
    return v;
}

#if defined(__GNUC__) || defined(__clang__)
#define ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define ALWAYS_INLINE inline
#endif

/* A record's box test: wide_entry, or one of the AVX ones with their
 * per-ray constants in ctx. */
typedef unsigned entry_fn(const void *ctx, const csg_wide *w, double t0, double t1,
                          double te[WIDE]);

/* csg_trace_first's walk from the root union's entry `top`, with the box
 * test `entry` (a constant at each call, so that it is inlined). */
static ALWAYS_INLINE int walk(ray *r, pending top, double tmin, double tmax, iv_bound *hit,
                              entry_fn *entry, const void *ctx)
{
    const csg_wide *wide = r->s->wide;
    pending local[64], *st = local; /* to the arena past 64 */
    int cap = 64, sn = 0;
    st[sn++] = top;
    int found = 0;
    double bt = 0;  /* the best boundary's t … */
    int32_t bk = 0; /* … and the frontier node it came from */
    while (sn > 0) {
        pending p = st[--sn];
        double hi = tmax;
        if (found) {
            if (later(&p, &(pending){bt, bk, 0})) continue;
            /* bt < tmax (a clipped list's first entry), so hi <= tmax. */
            hi = p.node < bk ? nextafter(bt, INFINITY) : bt;
        }
        if (p.ref < 0) {
            int m =
                p.ref == -1 ? eval(r, p.node, tmin, hi, 0) : trace_leaf(r, -2 - p.ref, tmin, hi, 0);
            if (m < 0) return -1;
            if (m > 0) { /* inside the window, so it beats the best */
                *hit = r->sp[0].enter;
                bt = hit->t;
                bk = p.node;
                found = 1;
            }
            continue;
        }
        int from = sn;
        for (int32_t k = p.ref; k >= 0; k = wide[k].more) {
            const csg_wide *w = &wide[k];
            double t[WIDE];
            unsigned m = entry(ctx, w, tmin, hi, t);
            if (sn + WIDE > cap && !(st = grow(r->a, st, sn, &cap))) return -1;
            for (int i = 0; i < w->n; i++)
                if (m >> i & 1) st[sn++] = (pending){t[i], w->node[i], w->ref[i]};
        }
        sort_pending(st + from, sn - from);
    }
    return found;
}

static int walk_scalar(ray *r, pending top, double tmin, double tmax, iv_bound *hit)
{
    return walk(r, top, tmin, tmax, hit, wide_entry, r);
}

#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define HAVE_AVX_PATH 1

/* A ray as entry_avx reads it: with the near and far planes of each axis
 * as indices into a record's box viewed as six rows (3j + k for box[j][k]),
 * so that picking them costs no arithmetic per record. */
typedef struct avx_ray {
    const ray *r;
    int near[3], far[3];
} avx_ray;

static void avx_ray_init(avx_ray *q, const ray *r)
{
    q->r = r;
    for (int k = 0; k < 3; k++) {
        q->near[k] = 3 * r->neg[k] + k;
        q->far[k] = 3 * (r->neg[k] ^ 1) + k;
    }
}

/* wide_entry with the four lanes at once, for a ray with no zero d[k]
 * (culling on).  maxpd(x, y) is x > y ? x : y and minpd(x, y) is
 * x < y ? x : y, NaN operands included, so with the slab product first
 * they are box_entry's ternaries exactly.  Not inlined: the walk stays
 * SSE code, and the function's exit clears the upper halves (vzeroupper),
 * which legacy SSE code after 256-bit AVX code would otherwise pay for. */
__attribute__((target("avx"), noinline)) static unsigned
entry_avx(const void *ctx, const csg_wide *w, double t0, double t1, double te[WIDE])
{
    const avx_ray *q = ctx;
    const ray *r = q->r;
    const double(*plane)[WIDE] = w->box[0]; /* box[j][k] is plane[3j + k] */
    __m256d a = _mm256_set1_pd(t0), b = _mm256_set1_pd(t1);
    for (int k = 0; k < 3; k++) {
        __m256d o = _mm256_set1_pd(r->o[k]), inv = _mm256_set1_pd(r->inv[k]);
        __m256d n = _mm256_loadu_pd(plane[q->near[k]]);
        __m256d f = _mm256_loadu_pd(plane[q->far[k]]);
        a = _mm256_max_pd(_mm256_mul_pd(_mm256_sub_pd(n, o), inv), a);
        b = _mm256_min_pd(_mm256_mul_pd(_mm256_sub_pd(f, o), inv), b);
    }
    _mm256_storeu_pd(te, a);
    return (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(a, b, _CMP_LE_OQ)) & ((1u << w->n) - 1);
}

/* The same for a ray with some zero d[k]: on those axes the ray is inside
 * the slab or misses the box, !(o < lo) && !(o > hi) with unordered
 * compares, as box_entry_flat rejects o < lo || o > hi. */
__attribute__((target("avx"), noinline)) static unsigned
entry_avx_flat(const void *ray_, const csg_wide *w, double t0, double t1, double te[WIDE])
{
    const ray *r = ray_;
    __m256d a = _mm256_set1_pd(t0), b = _mm256_set1_pd(t1);
    __m256d in = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    for (int k = 0; k < 3; k++) {
        __m256d o = _mm256_set1_pd(r->o[k]);
        __m256d lo = _mm256_loadu_pd(w->box[0][k]), hi = _mm256_loadu_pd(w->box[1][k]);
        if (r->d[k] == 0) {
            in = _mm256_and_pd(in, _mm256_and_pd(_mm256_cmp_pd(o, lo, _CMP_NLT_UQ),
                                                 _mm256_cmp_pd(o, hi, _CMP_NGT_UQ)));
            continue;
        }
        __m256d inv = _mm256_set1_pd(r->inv[k]);
        __m256d n = r->neg[k] ? hi : lo, f = r->neg[k] ? lo : hi;
        a = _mm256_max_pd(_mm256_mul_pd(_mm256_sub_pd(n, o), inv), a);
        b = _mm256_min_pd(_mm256_mul_pd(_mm256_sub_pd(f, o), inv), b);
    }
    _mm256_storeu_pd(te, a);
    in = _mm256_and_pd(in, _mm256_cmp_pd(a, b, _CMP_LE_OQ));
    return (unsigned)_mm256_movemask_pd(in) & ((1u << w->n) - 1);
}

static int walk_avx(ray *r, pending top, double tmin, double tmax, iv_bound *hit)
{
    if (r->flat) return walk(r, top, tmin, tmax, hit, entry_avx_flat, r);
    avx_ray q;
    avx_ray_init(&q, r);
    return walk(r, top, tmin, tmax, hit, entry_avx, &q);
}

static unsigned wide_entry_avx(const ray *r, const csg_wide *w, double t0, double t1,
                               double te[WIDE])
{
    avx_ray q;
    avx_ray_init(&q, r);
    return r->flat ? entry_avx_flat(r, w, t0, t1, te) : entry_avx(&q, w, t0, t1, te);
}
#endif

unsigned csg_scene_wide_entry(const csg_scene *s, int32_t w, const double o[3], const double d[3],
                              double t0, double t1, iv_arena *a, double te[WIDE])
{
    ray r;
    ray_init(&r, s, o, d, a);
#ifdef HAVE_AVX_PATH
    if (s->avx && r.cull) return wide_entry_avx(&r, &s->wide[w], t0, t1, te);
#endif
    return wide_entry(&r, &s->wide[w], t0, t1, te);
}

int csg_trace_first(const csg_scene *s, int root, const double o[3], const double d[3], double tmin,
                    double tmax, iv_arena *a, iv_bound *hit)
{
    if (root < 0 || root >= s->nroots || s->roots[root] < 0 || !(tmin < tmax)) return 0;
    ray r;
    ray_init(&r, s, o, d, a);
    const csg_fnode *rn = &s->nodes[s->roots[root]];
    if (rn->op != CSG_OP_UNION) { /* the frontier is the root alone */
        int m = eval(&r, s->roots[root], tmin, tmax, 0);
        if (m > 0) *hit = r.sp[0].enter;
        return m < 0 ? -1 : m > 0;
    }
    double te;
    if (!box_entry(&r, rn->lo, rn->hi, tmin, tmax, &te)) return 0;
    /* The leaves' lists start on the C stack (reserve moves them to the
     * arena should they outgrow it): most rays meet a leaf or two, and then
     * need no arena allocation at all. */
    iv_span sp[16];
    r.sp = sp;
    r.cap = 16;
    pending top = {te, s->roots[root], rn->wide};
#ifdef HAVE_AVX_PATH
    if (s->avx && r.cull) return walk_avx(&r, top, tmin, tmax, hit);
#endif
    return walk_scalar(&r, top, tmin, tmax, hit);
}

void csg_scene_normal(const csg_scene *s, const iv_bound *b, const double o[3], const double d[3],
                      double n[3])
{
    double v[3];
    int ok = 0;
    if (b->prim >= 0 && b->prim < s->nprims) {
        const csg_prim *p = &s->prims[b->prim];
        const double *N = s->cold[b->prim].normal_from_object;
        /* An infinite t only comes from a flat face the line runs into at
         * infinity (halfspace), whose normal does not depend on the point;
         * use the origin rather than an infinite point. */
        double pw[3] = {0, 0, 0}, po[3] = {0, 0, 0}, no[3];
        if (isfinite(b->t)) {
            for (int k = 0; k < 3; k++)
                pw[k] = o[k] + b->t * d[k];
            csg_affine_point(p->object_from_world, pw, po);
        }
        iv_shape_normal(&p->shape, po, b->part, no);
        for (int i = 0; i < 3; i++)
            v[i] = N[3 * i] * no[0] + N[3 * i + 1] * no[1] + N[3 * i + 2] * no[2];
        double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (l > 0 && isfinite(l)) {
            double sgn = b->flip ? -1 : 1;
            for (int k = 0; k < 3; k++)
                n[k] = sgn * v[k] / l;
            ok = 1;
        }
    }
    if (ok) return;
    /* A clip: the surface faces the viewer. */
    double l = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (l > 0 && isfinite(l)) {
        for (int k = 0; k < 3; k++)
            n[k] = -d[k] / l;
    } else {
        n[0] = n[1] = 0;
        n[2] = 1;
    }
}

int csg_scene_quadric(const csg_scene *s, const iv_bound *b, const double o[3], const double d[3],
                      iv_quadric *q)
{
    if (b->prim < 0 || b->prim >= s->nprims || !isfinite(b->t)) return -1;
    const csg_prim *p = &s->prims[b->prim];
    double pw[3], po[3], n[3];
    for (int k = 0; k < 3; k++)
        pw[k] = o[k] + b->t * d[k];
    csg_affine_point(p->object_from_world, pw, po);
    csg_scene_normal(s, b, o, d, n);
    iv_quadric qo;
    if (!iv_shape_quadric(&p->shape, po, b->part, &qo)) {
        memset(q, 0, sizeof *q);
        for (int k = 0; k < 3; k++)
            q->b[k] = n[k];
        q->c = -(n[0] * pw[0] + n[1] * pw[1] + n[2] * pw[2]);
        return 0;
    }
    /* y = M x + m: yᵀAy + b·y + c = xᵀ(MᵀAM)x + (2MᵀAm + Mᵀb)·x + (mᵀAm + b·m + c) */
    const double *F = p->object_from_world;
    double M[3][3], m[3], AM[3][3], Am[3];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            M[i][j] = F[4 * i + j];
        m[i] = F[4 * i + 3];
    }
    for (int i = 0; i < 3; i++) {
        Am[i] = 0;
        for (int j = 0; j < 3; j++) {
            AM[i][j] = 0;
            for (int k = 0; k < 3; k++)
                AM[i][j] += qo.A[i][k] * M[k][j];
            Am[i] += qo.A[i][j] * m[j];
        }
    }
    q->c = qo.c;
    for (int i = 0; i < 3; i++) {
        q->c += m[i] * Am[i] + qo.b[i] * m[i];
        q->b[i] = 0;
        for (int j = 0; j < 3; j++) {
            q->A[i][j] = 0;
            for (int k = 0; k < 3; k++)
                q->A[i][j] += M[k][i] * AM[k][j];
            q->b[i] += M[j][i] * (2 * Am[j] + qo.b[j]);
        }
    }
    double g = 0; /* the gradient 2Ax + b along the normal */
    for (int i = 0; i < 3; i++)
        g += n[i] * (2 * (q->A[i][0] * pw[0] + q->A[i][1] * pw[1] + q->A[i][2] * pw[2]) + q->b[i]);
    if (g < 0) {
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++)
                q->A[i][j] = -q->A[i][j];
            q->b[i] = -q->b[i];
        }
        q->c = -q->c;
    }
    return 0;
}
