/*
 * scene.c — commit: turn builder trees into the read-only flat scene.
 *
 * Commit runs in two non-recursive passes over each root.  The first is a
 * post-order walk (parents found through `link`, progress kept in `visit`)
 * that simplifies bottom-up: leaves with a singular transform or an empty
 * shape vanish; empty operands are removed by the rules of each operation
 * (an empty operand empties an intersection, and a difference whose first
 * operand is empty); nested unions and intersections are spliced into their
 * parent, as are a difference's leading difference and subtracted unions
 * (a − (b ∪ c) = a − b − c); subtracted operands whose bounds miss the first
 * operand's are dropped; an operation left with one operand becomes that
 * operand.  Every surviving node then holds its world bounds, subtree size
 * and depth.  The second pass lays the nodes out in pre-order in one array
 * (csg_internal.h) and moves leaves into the primitive arrays.
 *
 * The invariant the scene keeps for csg_trace: every point of a node's solid
 * lies inside that node's bounds, which are padded outward so that rounding
 * in the ray–box test can never reject a ray that the exact shape test
 * would hit.
 */
#include "csg_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Relative padding of bounds.  Object-space hits and world-space box tests
 * round differently; their disagreement is a few ulps of the coordinates
 * (~1e-16 relative), so 1e-9 is far outside it and far below anything
 * visible. */
#define BOUNDS_PAD 1e-9

static void pad_bounds(double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        double m = fmax(fabs(lo[k]), fabs(hi[k]));
        if (!isfinite(m)) m = isfinite(lo[k]) ? fabs(lo[k]) : isfinite(hi[k]) ? fabs(hi[k]) : 0;
        double e = BOUNDS_PAD * m + 1e-300;
        lo[k] -= e; /* ±inf stays ±inf */
        hi[k] += e;
    }
}

void csg_box_transform(const csg_affine m, const double lo[3], const double hi[3], double wlo[3],
                       double whi[3])
{
    for (int i = 0; i < 3; i++) {
        double a = m[4 * i + 3], b = m[4 * i + 3];
        for (int j = 0; j < 3; j++) {
            double c = m[4 * i + j];
            if (c == 0) continue;
            double x = c * lo[j], y = c * hi[j];
            a += fmin(x, y);
            b += fmax(x, y);
        }
        wlo[i] = a;
        whi[i] = b;
    }
}

static void free_shell(csg_node *n)
{
    free(n->kids);
    free(n);
}

static int overlaps(const csg_node *a, const csg_node *b)
{
    for (int k = 0; k < 3; k++)
        if (a->hi[k] < b->lo[k] || b->hi[k] < a->lo[k]) return 0;
    return 1;
}

/* Whether kid's own children can replace it in an `op` node at position i. */
static int splices(csg_op op, int i, const csg_node *kid)
{
    if (kid->is_leaf || kid->whole) return 0;
    switch (op) {
    case CSG_OP_UNION:
        return kid->op == CSG_OP_UNION;
    case CSG_OP_INTERSECTION:
        return kid->op == CSG_OP_INTERSECTION;
    case CSG_OP_DIFFERENCE:
        return i == 0 ? kid->op == CSG_OP_DIFFERENCE : kid->op == CSG_OP_UNION;
    }
    return 0;
}

/* Simplify op node x whose children are already simplified (NULL = empty).
 * Returns what replaces x (x itself, one of its children, or NULL) and frees
 * whatever is no longer used. */
static csg_node *finish_op(csg_node *x)
{
    const csg_op op = x->op;
    if (x->nkids == 0 || (op == CSG_OP_DIFFERENCE && !x->kids[0])) {
        csg_node_free(x);
        return NULL;
    }
    if (op == CSG_OP_INTERSECTION) {
        for (int i = 0; i < x->nkids; i++) {
            if (!x->kids[i]) {
                csg_node_free(x);
                return NULL;
            }
        }
    }
    /* Splice into a fresh array when memory allows; otherwise keep the
     * nesting (correct, just deeper) and only squeeze out the NULLs. */
    int total = 0;
    for (int i = 0; i < x->nkids; i++)
        if (x->kids[i]) total += splices(op, i, x->kids[i]) ? x->kids[i]->nkids : 1;
    csg_node **flat = total > 0 ? malloc((size_t)total * sizeof *flat) : NULL;
    int n = 0;
    if (flat) {
        for (int i = 0; i < x->nkids; i++) {
            csg_node *k = x->kids[i];
            if (!k) continue;
            if (splices(op, i, k)) {
                memcpy(flat + n, k->kids, (size_t)k->nkids * sizeof *flat);
                n += k->nkids;
                free_shell(k);
            } else {
                flat[n++] = k;
            }
        }
        free(x->kids);
        x->kids = flat;
        x->cap = total;
    } else {
        for (int i = 0; i < x->nkids; i++)
            if (x->kids[i]) x->kids[n++] = x->kids[i];
    }
    x->nkids = n;
    if (n == 0) {
        csg_node_free(x);
        return NULL;
    }
    /* Bounds, and operands that bounds prove irrelevant. */
    csg_node *first = x->kids[0];
    memcpy(x->lo, first->lo, sizeof x->lo);
    memcpy(x->hi, first->hi, sizeof x->hi);
    if (op == CSG_OP_DIFFERENCE) {
        int m = 1;
        for (int i = 1; i < n; i++) {
            if (overlaps(first, x->kids[i]))
                x->kids[m++] = x->kids[i];
            else
                csg_node_free(x->kids[i]);
        }
        n = x->nkids = m;
    } else {
        for (int i = 1; i < n; i++) {
            const csg_node *k = x->kids[i];
            for (int a = 0; a < 3; a++) {
                if (op == CSG_OP_UNION) {
                    x->lo[a] = fmin(x->lo[a], k->lo[a]);
                    x->hi[a] = fmax(x->hi[a], k->hi[a]);
                } else {
                    x->lo[a] = fmax(x->lo[a], k->lo[a]);
                    x->hi[a] = fmin(x->hi[a], k->hi[a]);
                }
            }
        }
        if (op == CSG_OP_INTERSECTION) {
            for (int a = 0; a < 3; a++) {
                if (x->lo[a] > x->hi[a]) { /* disjoint operands */
                    csg_node_free(x);
                    return NULL;
                }
            }
        }
    }
    if (n == 1) {
        x->nkids = 0;
        if (!first->is_leaf) first->whole |= x->whole;
        free_shell(x);
        return first;
    }
    x->size = 1;
    x->leaves = 0;
    x->depth = 0;
    for (int i = 0; i < n; i++) {
        x->size += x->kids[i]->size;
        x->leaves += x->kids[i]->leaves;
        if (x->kids[i]->depth > x->depth) x->depth = x->kids[i]->depth;
    }
    x->depth += 1;
    return x;
}

static csg_node *finish_leaf(csg_node *x)
{
    double lo[3], hi[3];
    if (csg_affine_invert(x->world_from_object, x->object_from_world) != 0 ||
        iv_shape_bounds(&x->shape, lo, hi) != 0) {
        csg_node_free(x);
        return NULL;
    }
    csg_box_transform(x->world_from_object, lo, hi, x->lo, x->hi);
    pad_bounds(x->lo, x->hi);
    x->size = x->leaves = x->depth = 1;
    return x;
}

/* Post-order without recursion: descend through unvisited children (a NULL
 * one is passed over), setting each child's `link` to its parent; when a
 * node's children are done, finish it and store what finish returns in the
 * parent's slot.  Returns what finish made of the root. */
static csg_node *post_order(csg_node *root, csg_node *(*finish)(csg_node *x))
{
    if (!root) return NULL;
    root->link = NULL;
    root->visit = 0;
    csg_node *x = root;
    for (;;) {
        if (!x->is_leaf && x->visit < x->nkids) {
            csg_node *c = x->kids[x->visit];
            if (c) {
                c->link = x;
                c->visit = 0;
                x = c;
            } else {
                x->visit++;
            }
            continue;
        }
        csg_node *parent = x->link;
        csg_node *r = finish(x);
        if (!parent) return r;
        parent->kids[parent->visit++] = r;
        x = parent;
    }
}

static csg_node *finish_node(csg_node *x)
{
    return x->is_leaf ? finish_leaf(x) : finish_op(x);
}

/* ---- grouping: a bounding hierarchy inside wide unions ------------------- */

/* Most operands per group.  A group costs one box test per ray; 4 keeps the
 * hierarchy shallow while letting most rays reject a group of 4 at once. */
#define GROUP_MAX 4

/* A build: the operands (items' ids index `ops`) and the group nodes made
 * so far (at most 2m - 1 for m operands), so that a failed build can free
 * them. */
typedef struct builder {
    csg_node **ops;
    csg_node **made;
    int nmade;
} builder;

static void op_totals(csg_node *x)
{
    x->size = 1;
    x->leaves = 0;
    x->depth = 0;
    for (int i = 0; i < x->nkids; i++) {
        x->size += x->kids[i]->size;
        x->leaves += x->kids[i]->leaves;
        if (x->kids[i]->depth > x->depth) x->depth = x->kids[i]->depth;
    }
    x->depth += 1;
}

static csg_node *group_node(builder *b)
{
    csg_node *g = calloc(1, sizeof *g);
    if (!g) return NULL;
    g->kids = malloc(GROUP_MAX * sizeof *g->kids);
    if (!g->kids) {
        free(g);
        return NULL;
    }
    g->op = CSG_OP_UNION;
    g->cap = GROUP_MAX;
    b->made[b->nmade++] = g;
    return g;
}

/* A union hierarchy over items[0..m); NULL when out of memory (the nodes
 * made are in b->made). */
static csg_node *group_build(builder *b, iv_bvh_item *items, int m, int depth)
{
    csg_node *g = group_node(b);
    if (!g) return NULL;
    if (m <= GROUP_MAX) {
        for (int i = 0; i < m; i++)
            g->kids[i] = b->ops[items[i].id];
        g->nkids = m;
    } else {
        /* Two levels of binary splits at once: up to four subgroups, so a
         * ray pops half as many groups on its way down. */
        int l = iv_bvh_split(items, m, depth);
        int part[5] = {0, l, l, m, m}, n = 0;
        for (int h = 0; h < 2; h++) {
            int a = part[2 * h], z = part[2 * h + 2], c = z - a;
            part[2 * h + 1] = c > GROUP_MAX ? a + iv_bvh_split(items + a, c, depth + 1) : z;
        }
        for (int i = 0; i < 4; i++) {
            int a = part[i], z = part[i + 1];
            if (z - a == 1) /* no group of one */
                g->kids[n++] = b->ops[items[a].id];
            else if (z > a && !(g->kids[n++] = group_build(b, items + a, z - a, depth + 2)))
                return NULL;
        }
        g->nkids = n;
    }
    memcpy(g->lo, g->kids[0]->lo, sizeof g->lo);
    memcpy(g->hi, g->kids[0]->hi, sizeof g->hi);
    for (int i = 1; i < g->nkids; i++)
        for (int k = 0; k < 3; k++) {
            g->lo[k] = fmin(g->lo[k], g->kids[i]->lo[k]);
            g->hi[k] = fmax(g->hi[k], g->kids[i]->hi[k]);
        }
    op_totals(g);
    return g;
}

/* Replace x's operands from index `from` on (all of a union's, or a
 * difference's subtracted ones, since a − b − c = a − (b ∪ c)) by a union
 * hierarchy over those with finite bounds; unbounded ones stay as they are.
 * Out of memory leaves x unchanged, which is only slower. */
static void group_op(csg_node *x, int from)
{
    int m = x->nkids - from, nf = 0;
    iv_bvh_item *items = malloc((size_t)m * sizeof *items);
    if (!items) return;
    for (int i = 0; i < m; i++) {
        csg_node *k = x->kids[from + i];
        int finite = 1;
        for (int a = 0; a < 3; a++)
            finite &= isfinite(k->lo[a]) && isfinite(k->hi[a]);
        if (!finite) continue;
        for (int a = 0; a < 3; a++) {
            items[nf].lo[a] = k->lo[a];
            items[nf].hi[a] = k->hi[a];
            items[nf].c[a] = 0.5 * (k->lo[a] + k->hi[a]);
        }
        items[nf].id = from + i;
        nf++;
    }
    if (nf <= GROUP_MAX) {
        free(items);
        return;
    }
    builder b = {x->kids, malloc(2 * (size_t)nf * sizeof *b.made), 0};
    csg_node *h = b.made ? group_build(&b, items, nf, 0) : NULL;
    free(items);
    if (!h) {
        for (int i = 0; i < b.nmade; i++)
            free_shell(b.made[i]);
        free(b.made);
        return;
    }
    free(b.made);
    /* Unbounded operands first, in their order, then the hierarchy. */
    int n = from;
    for (int i = from; i < x->nkids; i++) {
        csg_node *k = x->kids[i];
        int finite = 1;
        for (int a = 0; a < 3; a++)
            finite &= isfinite(k->lo[a]) && isfinite(k->hi[a]);
        if (!finite) x->kids[n++] = k;
    }
    if (x->op == CSG_OP_UNION && n == 0) {
        /* x itself becomes the root of the hierarchy. */
        memcpy(x->kids, h->kids, (size_t)h->nkids * sizeof *h->kids);
        n = h->nkids;
        free_shell(h);
    } else {
        x->kids[n++] = h;
    }
    x->nkids = n;
}

/* Groups a wide union or difference and refreshes its size and depth (a
 * post_order finish). */
static csg_node *group_wide(csg_node *x)
{
    if (!x->is_leaf) {
        if (x->op == CSG_OP_UNION && x->nkids > GROUP_MAX)
            group_op(x, 0);
        else if (x->op == CSG_OP_DIFFERENCE && x->nkids - 1 > GROUP_MAX)
            group_op(x, 1);
        op_totals(x);
    }
    return x;
}

/* Lay out a simplified tree in pre-order from node index `at` and primitive
 * index `*prim`, freeing the builder nodes.  Uses `link` as the stack. */
static void flatten(csg_scene *s, csg_node *root, int at, int *prim)
{
    root->link = NULL;
    csg_node *stack = root;
    while (stack) {
        csg_node *x = stack;
        stack = x->link;
        csg_fnode *f = &s->nodes[at];
        memcpy(f->lo, x->lo, sizeof f->lo);
        memcpy(f->hi, x->hi, sizeof f->hi);
        f->next = at + x->size;
        f->wide = -1;
        if (x->is_leaf) {
            int p = (*prim)++;
            f->op = FNODE_LEAF;
            f->prim = p;
            csg_prim *hot = &s->prims[p];
            csg_prim_cold *cold = &s->cold[p];
            memcpy(hot->object_from_world, x->object_from_world, sizeof(csg_affine));
            hot->shape = x->shape;
            /* Normals map by the inverse transpose of world_from_object's
             * linear part, which is the transpose of object_from_world's. */
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    cold->normal_from_object[3 * i + j] = x->object_from_world[4 * j + i];
            cold->material = x->material;
        } else {
            f->op = (uint8_t)x->op;
            f->whole = (uint8_t)x->whole;
            f->prim = -1;
            /* Push in reverse so the first child is laid out next. */
            for (int i = x->nkids - 1; i >= 0; i--) {
                x->kids[i]->link = stack;
                stack = x->kids[i];
            }
        }
        at++;
        free_shell(x);
    }
}

/* The unions' operand records (csg_internal.h), from the flat nodes: a
 * first pass numbers each union's records, so that the second can name a
 * union operand's.  Returns 0, or -1 when out of memory. */
static int build_wide(csg_scene *s)
{
    csg_fnode *nodes = s->nodes;
    int nw = 0;
    for (int i = 0; i < s->nnodes; i++) {
        if (nodes[i].op != CSG_OP_UNION) continue;
        int n = 0;
        for (int32_t c = i + 1; c < nodes[i].next; c = nodes[c].next)
            n++;
        nodes[i].wide = nw;
        nw += (n + WIDE - 1) / WIDE;
    }
    s->wide = malloc((size_t)(nw ? nw : 1) * sizeof *s->wide);
    if (!s->wide) return -1;
    s->nwide = nw;
    for (int i = 0; i < s->nnodes; i++) {
        if (nodes[i].op != CSG_OP_UNION) continue;
        csg_wide *w = NULL;
        int32_t at = nodes[i].wide;
        for (int32_t c = i + 1; c < nodes[i].next; c = nodes[c].next) {
            if (!w || w->n == WIDE) {
                if (w) w->more = at;
                w = &s->wide[at++];
                for (int k = 0; k < 3; k++)
                    for (int j = 0; j < WIDE; j++) { /* an empty box in unused lanes */
                        w->box[0][k][j] = INFINITY;
                        w->box[1][k][j] = -INFINITY;
                    }
                memset(w->node, 0, sizeof w->node);
                memset(w->ref, 0, sizeof w->ref);
                w->n = 0;
                w->more = -1;
            }
            const csg_fnode *f = &nodes[c];
            int lane = w->n++;
            for (int k = 0; k < 3; k++) {
                w->box[0][k][lane] = f->lo[k];
                w->box[1][k][lane] = f->hi[k];
            }
            w->node[lane] = c;
            w->ref[lane] = f->op == FNODE_LEAF     ? -2 - f->prim
                           : f->op == CSG_OP_UNION ? f->wide
                                                   : -1;
        }
    }
    return 0;
}

int csg_cpu_has_avx(void)
{
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
    return __builtin_cpu_supports("avx") != 0;
#else
    return 0;
#endif
}

/* csg_scene_new giving up: the trees not yet flattened (roots[r] is NULL
 * once one is) and the scene so far are freed, and err says why. */
static csg_scene *commit_failed(csg_scene *s, csg_node **roots, int n, char *err, size_t errlen,
                                const char *why)
{
    for (int r = 0; r < n; r++)
        csg_node_free(roots[r]);
    csg_scene_free(s);
    if (err && errlen) snprintf(err, errlen, "%s", why);
    return NULL;
}

csg_scene *csg_scene_new(csg_node **roots, int n, char *err, size_t errlen)
{
    static const char oom[] = "out of memory committing the scene";
    csg_scene *s = calloc(1, sizeof *s);
    if (s && n > 0) s->roots = malloc((size_t)n * sizeof *s->roots);
    if (!s || (n > 0 && !s->roots)) return commit_failed(s, roots, n, err, errlen, oom);
    s->nroots = n;
    s->cull = 1;
    s->avx = csg_cpu_has_avx();
    long nodes = 0, prims = 0;
    for (int r = 0; r < n; r++) {
        roots[r] = post_order(roots[r], finish_node);
        post_order(roots[r], group_wide); /* group wide unions and differences */
        if (roots[r]) {
            nodes += roots[r]->size;
            prims += roots[r]->leaves;
            if (roots[r]->depth > s->max_depth) s->max_depth = roots[r]->depth;
        }
    }
    if (nodes > INT32_MAX) {
        char why[64];
        snprintf(why, sizeof why, "scene has more than %ld nodes", (long)INT32_MAX);
        return commit_failed(s, roots, n, err, errlen, why);
    }
    s->nodes = malloc((size_t)(nodes ? nodes : 1) * sizeof *s->nodes);
    s->prims = malloc((size_t)(prims ? prims : 1) * sizeof *s->prims);
    s->cold = malloc((size_t)(prims ? prims : 1) * sizeof *s->cold);
    if (!s->nodes || !s->prims || !s->cold) return commit_failed(s, roots, n, err, errlen, oom);
    int at = 0, prim = 0;
    for (int r = 0; r < n; r++) {
        if (!roots[r]) {
            s->roots[r] = -1;
            continue;
        }
        s->roots[r] = at;
        int size = roots[r]->size;
        flatten(s, roots[r], at, &prim);
        roots[r] = NULL;
        at += size;
    }
    s->nnodes = at;
    s->nprims = prim;
    if (build_wide(s) != 0) return commit_failed(s, roots, n, err, errlen, oom);
    return s;
}

void csg_scene_free(csg_scene *s)
{
    if (!s) return;
    for (int i = 0; i < s->nprims; i++) /* each prim holds its leaf's reference */
        iv_shape_release(&s->prims[i].shape);
    free(s->nodes);
    free(s->prims);
    free(s->cold);
    free(s->wide);
    free(s->roots);
    free(s);
}

void csg_scene_set_cull(csg_scene *s, int on)
{
    s->cull = on;
}

int csg_scene_set_avx(csg_scene *s, int on)
{
    s->avx = on && csg_cpu_has_avx();
    return s->avx;
}

int csg_scene_root_count(const csg_scene *s)
{
    return s->nroots;
}

int csg_scene_prim_count(const csg_scene *s)
{
    return s->nprims;
}

int csg_scene_bounds(const csg_scene *s, int r, double lo[3], double hi[3])
{
    if (r < 0 || r >= s->nroots || s->roots[r] < 0) return -1;
    const csg_fnode *f = &s->nodes[s->roots[r]];
    memcpy(lo, f->lo, sizeof f->lo);
    memcpy(hi, f->hi, sizeof f->hi);
    return 0;
}

static const csg_material default_material = {.rgba = {1, 1, 1, 1}};

const csg_material *csg_scene_material(const csg_scene *s, int32_t prim)
{
    /* A clip boundary (IV_PRIM_NONE) has no primitive; it gets the
     * uncoloured default rather than a NULL the caller would trip on. */
    if (prim < 0 || prim >= s->nprims) return &default_material;
    return &s->cold[prim].material;
}
