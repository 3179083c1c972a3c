/*
 * test_csg.c — affine helpers, commit (dropping, bounds), csg_trace and the
 * normals, checked against hand-computed cases and against a point
 * classifier that evaluates the CSG expression directly, with transforms the
 * test builds and inverts itself.
 */
#include "../support.h"

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <string.h>

#include "../../src/csg/csg.h"
#include "../../src/csg/csg_internal.h"

/* ---- helpers ------------------------------------------------------------ */

static csg_material mat(float id)
{
    csg_material m = {.rgba = {id, 0, 0, 1}, .has_color = 1};
    return m;
}

/* world_from_object = translate(t) · scale(s) */
static void ts_affine(double tx, double ty, double tz, double sx, double sy, double sz,
                      csg_affine m)
{
    double v[12] = {sx, 0, 0, tx, 0, sy, 0, ty, 0, 0, sz, tz};
    memcpy(m, v, sizeof v);
}

static csg_node *leaf(iv_shape s, const csg_affine m, float id)
{
    csg_material mm = mat(id);
    csg_node *n = csg_node_shape(&s, m, &mm);
    cr_assert_not_null(n);
    return n;
}

static csg_node *op2(csg_op op, csg_node *a, csg_node *b)
{
    csg_node *n = csg_node_op(op);
    cr_assert_not_null(n);
    cr_assert_eq(csg_node_add(n, a), 0);
    cr_assert_eq(csg_node_add(n, b), 0);
    return n;
}

static csg_scene *commit1(csg_node *root)
{
    char err[128] = "";
    csg_scene *s = csg_scene_new(&root, 1, err, sizeof err);
    cr_assert_not_null(s, "%s", err);
    return s;
}

static iv_list trace(const csg_scene *s, double ox, double oy, double oz, double dx, double dy,
                     double dz, double tmin, double tmax)
{
    iv_list l;
    double o[3] = {ox, oy, oz}, d[3] = {dx, dy, dz};
    cr_assert_eq(csg_trace(s, 0, o, d, tmin, tmax, arena, &l), 0);
    return l;
}

/* ---- affine ------------------------------------------------------------- */

Test(csg_affine, mul_applies_right_first)
{
    csg_affine a, b, ab;
    ts_affine(1, 2, 3, 2, 2, 2, a);
    ts_affine(-1, 0, 5, 1, 3, 1, b);
    csg_affine_mul(a, b, ab);
    double p[3] = {0.5, -1, 2}, q[3], r[3], s[3];
    csg_affine_point(b, p, q);
    csg_affine_point(a, q, r);
    csg_affine_point(ab, p, s);
    for (int k = 0; k < 3; k++)
        near(s[k], r[k], 1e-14);
    csg_affine_mul(a, b, a); /* aliasing */
    for (int k = 0; k < 12; k++)
        near(a[k], ab[k], 0);
    double v[3];
    csg_affine_vector(ab, (double[3]){1, 1, 1}, v);
    near(v[0], 2, 0);
    near(v[1], 6, 0);
    near(v[2], 2, 0);
}

Test(csg_affine, invert_round_trips)
{
    rng_seed(42);
    for (int it = 0; it < 1000; it++) {
        csg_affine m, inv, id;
        for (int k = 0; k < 12; k++)
            m[k] = rng_uniform(-3, 3);
        if (csg_affine_invert(m, inv) != 0) continue;
        csg_affine_mul(m, inv, id);
        for (int k = 0; k < 12; k++)
            near(id[k], csg_affine_identity[k], 1e-8);
    }
    csg_affine m, inv;
    ts_affine(1, 2, 3, 1e-6, 1, 1e6, m); /* tiny but regular */
    cr_assert_eq(csg_affine_invert(m, inv), 0);
    near(inv[0], 1e6, 1e-4);
    near(inv[3], -1e6, 1e-4);
}

Test(csg_affine, invert_rejects_singular)
{
    csg_affine m, inv;
    ts_affine(1, 2, 3, 1, 1, 0, m);
    cr_assert_eq(csg_affine_invert(m, inv), -1);
    double dep[12] = {1, 2, 3, 0, 2, 4, 6, 0, 0, 0, 1, 0}; /* rows 0, 1 parallel */
    cr_assert_eq(csg_affine_invert(dep, inv), -1);
    double nan[12] = {1, 0, 0, NAN, 0, 1, 0, 0, 0, 0, 1, 0};
    cr_assert_eq(csg_affine_invert(nan, inv), -1);
}

/* ---- builder and commit --------------------------------------------------- */

TestSuite(csg_scene, .init = arena_setup, .fini = arena_teardown);

Test(csg_scene, builder_counts_and_frees)
{
    csg_node *u = csg_node_op(CSG_OP_UNION);
    cr_assert_eq(csg_node_child_count(u), 0);
    csg_node_add(u, leaf(sphere(1), csg_affine_identity, 0));
    csg_node_add(u, leaf(sphere(2), csg_affine_identity, 1));
    cr_assert_eq(csg_node_child_count(u), 2);
    csg_node *l = leaf(sphere(1), csg_affine_identity, 0);
    cr_assert_eq(csg_node_child_count(l), 0);
    /* A leaf cannot take children; the child is freed anyway. */
    cr_assert_eq(csg_node_add(l, leaf(sphere(1), csg_affine_identity, 0)), -1);
    csg_node_free(l);
    csg_node_free(u);
    csg_node_free(NULL);
}

Test(csg_scene, drops_degenerate_leaves)
{
    csg_affine flat;
    ts_affine(0, 0, 0, 1, 1, 0, flat);
    csg_node *u = csg_node_op(CSG_OP_UNION);
    csg_node_add(u, leaf(sphere(1), flat, 0));
    csg_node_add(u, leaf(sphere(0), csg_affine_identity, 1));
    csg_node_add(u, leaf(box(0, 0, 0, 1, 1, 1), csg_affine_identity, 2));
    csg_node_add(u, leaf(cone(0, 0, 1), csg_affine_identity, 3));
    csg_scene *s = commit1(u);
    cr_assert_eq(csg_scene_prim_count(s), 1);
    cr_assert_eq(csg_scene_material(s, 0)->rgba[0], 2);
    iv_list l = trace(s, -1, 0.5, 0.5, 1, 0, 0, -INFINITY, INFINITY);
    cr_assert_eq(l.n, 1);
    near(l.v[0].enter.t, 1, 0);
    near(l.v[0].exit.t, 2, 0);
    csg_scene_free(s);
}

Test(csg_scene, empty_operands)
{
    csg_node *roots[5];
    /* difference with an empty first operand is empty */
    roots[0] = op2(CSG_OP_DIFFERENCE, NULL, leaf(sphere(1), csg_affine_identity, 0));
    /* intersection with an empty operand is empty */
    roots[1] = op2(CSG_OP_INTERSECTION, leaf(sphere(1), csg_affine_identity, 0),
                   leaf(sphere(0), csg_affine_identity, 1));
    /* an op with no children is empty */
    roots[2] = csg_node_op(CSG_OP_UNION);
    roots[3] = NULL;
    /* disjoint intersection: empty by bounds */
    csg_affine far;
    ts_affine(10, 0, 0, 1, 1, 1, far);
    roots[4] =
        op2(CSG_OP_INTERSECTION, leaf(sphere(1), csg_affine_identity, 0), leaf(sphere(1), far, 1));
    char err[64];
    csg_scene *s = csg_scene_new(roots, 5, err, sizeof err);
    cr_assert_not_null(s);
    cr_assert_eq(csg_scene_root_count(s), 5);
    cr_assert_eq(csg_scene_prim_count(s), 0);
    double lo[3], hi[3];
    for (int r = 0; r < 5; r++) {
        cr_assert_eq(csg_scene_bounds(s, r, lo, hi), -1, "root %d", r);
        iv_list l;
        cr_assert_eq(csg_trace(s, r, (double[3]){-5, 0, 0}, (double[3]){1, 0, 0}, -INFINITY,
                               INFINITY, arena, &l),
                     0);
        cr_assert_eq(l.n, 0);
    }
    csg_scene_free(s);
}

Test(csg_scene, bounds_per_operation)
{
    csg_affine a, b;
    ts_affine(1, 0, 0, 1, 1, 1, a);
    ts_affine(2, 0, 0, 1, 2, 1, b);
    csg_node *roots[4] = {
        op2(CSG_OP_UNION, leaf(sphere(1), a, 0), leaf(sphere(1), b, 1)),
        op2(CSG_OP_INTERSECTION, leaf(sphere(1), a, 0), leaf(sphere(1), b, 1)),
        op2(CSG_OP_DIFFERENCE, leaf(sphere(1), a, 0), leaf(sphere(1), b, 1)),
        op2(CSG_OP_INTERSECTION, leaf(halfspace(0, 0, 1, 3), csg_affine_identity, 0),
            leaf(halfspace(0, 0, -1, 1), csg_affine_identity, 1)),
    };
    csg_scene *s = csg_scene_new(roots, 4, NULL, 0);
    double lo[3], hi[3];
    const double e = 1e-6;
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    near(lo[0], 0, e);
    near(hi[0], 3, e);
    near(lo[1], -2, e);
    near(hi[1], 2, e);
    cr_assert_eq(csg_scene_bounds(s, 1, lo, hi), 0);
    near(lo[0], 1, e);
    near(hi[0], 2, e);
    near(lo[1], -1, e);
    near(hi[1], 1, e);
    cr_assert_eq(csg_scene_bounds(s, 2, lo, hi), 0);
    near(lo[0], 0, e);
    near(hi[0], 2, e);
    /* The slab -1 <= z <= 3: finite in z, infinite in x and y. */
    cr_assert_eq(csg_scene_bounds(s, 3, lo, hi), 0);
    near(lo[2], -1, e);
    near(hi[2], 3, e);
    cr_assert(isinf(lo[0]) && isinf(hi[1]));
    csg_scene_free(s);
}

Test(csg_scene, rotated_bounds_hold_the_corners)
{
    /* Unit cube rotated 45° about z: x and y reach ±√2/2 around the centre. */
    double c = sqrt(0.5);
    csg_affine m = {c, -c, 0, 0, c, c, 0, 0, 0, 0, 1, 0};
    csg_scene *s = commit1(leaf(box(-0.5, -0.5, -0.5, 0.5, 0.5, 0.5), m, 0));
    double lo[3], hi[3];
    cr_assert_eq(csg_scene_bounds(s, 0, lo, hi), 0);
    near(hi[0], c, 1e-6);
    near(lo[1], -c, 1e-6);
    near(hi[2], 0.5, 1e-6);
    cr_assert(hi[0] >= c && lo[1] <= -c, "bounds must be conservative");
    csg_scene_free(s);
}

/* ---- tracing by hand ------------------------------------------------------ */

TestSuite(csg_trace, .init = arena_setup, .fini = arena_teardown);

Test(csg_trace, ellipsoid_hits_and_normal)
{
    csg_affine m;
    ts_affine(10, 0, 0, 2, 1, 1, m); /* x²/4 + y² + z² <= 1 around (10,0,0) */
    csg_scene *s = commit1(leaf(sphere(1), m, 5));
    iv_list l = trace(s, 0, 0, 0, 1, 0, 0, -INFINITY, INFINITY);
    cr_assert_eq(l.n, 1);
    near(l.v[0].enter.t, 8, 1e-13);
    near(l.v[0].exit.t, 12, 1e-13);
    /* Unnormalised d: the same points at half the t. */
    l = trace(s, 0, 0, 0, 2, 0, 0, -INFINITY, INFINITY);
    near(l.v[0].enter.t, 4, 1e-13);
    double n[3];
    csg_scene_normal(s, &l.v[0].enter, (double[3]){0, 0, 0}, (double[3]){2, 0, 0}, n);
    near(n[0], -1, 1e-13);
    /* At (10 + 2cos45°, sin45°, 0) the gradient is ∝ (cos45°, 2 sin45°). */
    double c = sqrt(0.5);
    double o[3] = {10 + 2 * c, -5, 0}, d[3] = {0, 1, 0};
    cr_assert_eq(csg_trace(s, 0, o, d, -INFINITY, INFINITY, arena, &l), 0);
    cr_assert_eq(l.n, 1);
    near(l.v[0].exit.t, 5 + c, 1e-12);
    csg_scene_normal(s, &l.v[0].exit, o, d, n);
    near(n[0], 1 / sqrt(5), 1e-12);
    near(n[1], 2 / sqrt(5), 1e-12);
    near(n[2], 0, 1e-12);
    cr_assert_eq(csg_scene_material(s, l.v[0].exit.prim)->rgba[0], 5);
    csg_scene_free(s);
}

Test(csg_trace, difference_flips_normals_and_clips)
{
    csg_scene *s =
        commit1(op2(CSG_OP_DIFFERENCE, leaf(box(-1, -1, -1, 1, 1, 1), csg_affine_identity, 1),
                    leaf(sphere(0.5), csg_affine_identity, 2)));
    double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0}, n[3];
    iv_list l;
    cr_assert_eq(csg_trace(s, 0, o, d, 0, INFINITY, arena, &l), 0);
    cr_assert_eq(l.n, 2);
    near(l.v[0].enter.t, 4, 0);
    near(l.v[0].exit.t, 4.5, 1e-14);
    near(l.v[1].enter.t, 5.5, 1e-14);
    near(l.v[1].exit.t, 6, 0);
    cr_assert_eq(l.v[0].exit.flip, 1);
    cr_assert_eq(csg_scene_material(s, l.v[0].exit.prim)->rgba[0], 2);
    cr_assert_eq(csg_scene_material(s, l.v[0].enter.prim)->rgba[0], 1);
    csg_scene_normal(s, &l.v[0].exit, o, d, n);
    near(n[0], 1, 1e-14); /* the cavity's wall faces back into the hole */
    csg_scene_normal(s, &l.v[1].enter, o, d, n);
    near(n[0], -1, 1e-14);
    csg_scene_normal(s, &l.v[0].enter, o, d, n);
    near(n[0], -1, 0);
    /* Clip inside the box: the cut is a clip boundary facing the ray. */
    cr_assert_eq(csg_trace(s, 0, o, (double[3]){2, 0, 0}, 2.1, 2.9, arena, &l), 0);
    cr_assert_eq(l.n, 2);
    near(l.v[0].enter.t, 2.1, 0);
    cr_assert_eq(l.v[0].enter.prim, IV_PRIM_NONE);
    cr_assert_eq(l.v[1].exit.prim, IV_PRIM_NONE);
    near(l.v[1].exit.t, 2.9, 0);
    csg_scene_normal(s, &l.v[0].enter, o, (double[3]){2, 0, 0}, n);
    near(n[0], -1, 0);
    cr_assert_not_null(csg_scene_material(s, IV_PRIM_NONE));
    cr_assert_eq(csg_scene_material(s, IV_PRIM_NONE)->has_color, 0);
    csg_scene_free(s);
}

Test(csg_trace, rotated_nonuniform_box_normal)
{
    /* A box scaled (1, 4, 1) then rotated 30° about z.  Its +x face normal
     * is the rotated x axis: scaling does not tilt it, but a wrong normal
     * matrix (the plain linear part) would. */
    const double c = sqrt(3) / 2, sn = 0.5; /* 30° */
    csg_affine m = {c * 1, -sn * 4, 0, 0, sn * 1, c * 4, 0, 0, 0, 0, 1, 0};
    csg_scene *s = commit1(leaf(box(-1, -1, -1, 1, 1, 1), m, 0));
    double o[3] = {10 * c, 10 * sn, 0.1}, d[3] = {-c, -sn, 0}, n[3];
    iv_list l;
    cr_assert_eq(csg_trace(s, 0, o, d, -INFINITY, INFINITY, arena, &l), 0);
    cr_assert_eq(l.n, 1);
    near(l.v[0].enter.t, 9, 1e-12);
    csg_scene_normal(s, &l.v[0].enter, o, d, n);
    near(n[0], c, 1e-12);
    near(n[1], sn, 1e-12);
    /* A ray at an angle onto the long face: normal is the rotated y axis. */
    double o2[3] = {-sn * 10 + 0.3, c * 10, 0}, d2[3] = {sn, -c, 0.05};
    cr_assert_eq(csg_trace(s, 0, o2, d2, -INFINITY, INFINITY, arena, &l), 0);
    cr_assert_eq(l.n, 1);
    csg_scene_normal(s, &l.v[0].enter, o2, d2, n);
    near(n[0], -sn, 1e-12);
    near(n[1], c, 1e-12);
    near(n[2], 0, 1e-12);
    csg_scene_free(s);
}

Test(csg_trace, mirrored_leaf_normals_point_out)
{
    csg_affine m;
    ts_affine(0, 0, 0, -1, 1, 1, m); /* mirror x: det < 0 */
    csg_scene *s = commit1(leaf(cone(1, 1, 2), m, 0));
    double o[3] = {-5, 0, 1}, d[3] = {1, 0, 0}, n[3];
    iv_list l;
    cr_assert_eq(csg_trace(s, 0, o, d, -INFINITY, INFINITY, arena, &l), 0);
    cr_assert_eq(l.n, 1);
    csg_scene_normal(s, &l.v[0].enter, o, d, n);
    near(n[0], -1, 1e-14);
    csg_scene_normal(s, &l.v[0].exit, o, d, n);
    near(n[0], 1, 1e-14);
    csg_scene_free(s);
}

Test(csg_trace, roots_are_independent)
{
    csg_affine m;
    ts_affine(5, 0, 0, 1, 1, 1, m);
    csg_node *roots[2] = {leaf(sphere(1), csg_affine_identity, 0), leaf(sphere(1), m, 1)};
    csg_scene *s = csg_scene_new(roots, 2, NULL, 0);
    cr_assert_eq(csg_scene_prim_count(s), 2);
    iv_list l;
    double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0};
    cr_assert_eq(csg_trace(s, 1, o, d, -INFINITY, INFINITY, arena, &l), 0);
    cr_assert_eq(l.n, 1);
    near(l.v[0].enter.t, 9, 1e-14);
    cr_assert_eq(csg_scene_material(s, l.v[0].enter.prim)->rgba[0], 1);
    cr_assert_eq(csg_trace(s, 0, o, d, 0, 3, arena, &l), 0);
    cr_assert_eq(l.n, 0);
    csg_scene_free(s);
}

/* ---- property test: random trees against a point classifier ------------- */

enum { MAXK = 12 }; /* > 4 so that commit's grouping of wide operations is exercised */

typedef struct tnode {
    int leaf;
    csg_op op;
    iv_shape shape;
    double world_from_object[12], object_from_world[12];
    int empty; /* a degenerate leaf the scene must drop */
    int nk;
    struct tnode *k[MAXK];
} tnode;

static tnode pool[4096];
static int npool;
static tnode *leaves_by_id[4096];

static void apply(const double m[12], const double p[3], double q[3])
{
    for (int i = 0; i < 3; i++)
        q[i] = m[4 * i] * p[0] + m[4 * i + 1] * p[1] + m[4 * i + 2] * p[2] + m[4 * i + 3];
}

/* Classify world point p: 1 inside, 0 outside; *close is set when some leaf
 * surface is within 1e-6 (object units), where rounding may decide. */
static int classify(const tnode *n, const double p[3], int *close)
{
    if (n->leaf) {
        if (n->empty) return 0;
        double q[3];
        apply(n->object_from_world, p, q);
        double f = shape_sdf(&n->shape, q);
        if (fabs(f) < 1e-6) *close = 1;
        return f < 0;
    }
    if (n->nk == 0) return 0;
    int r = classify(n->k[0], p, close);
    for (int i = 1; i < n->nk; i++) {
        int c = classify(n->k[i], p, close);
        if (n->op == CSG_OP_UNION)
            r = r || c;
        else if (n->op == CSG_OP_INTERSECTION)
            r = r && c;
        else
            r = r && !c;
    }
    return r;
}

static iv_shape random_shape(void)
{
    switch (rng_int(9)) {
    case 0: {
        double n[3] = {rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1)};
        if (rng_int(2)) n[0] = n[1] = 0, n[2] = 1;
        return halfspace(n[0], n[1], n[2], rng_uniform(-0.5, 1));
    }
    case 1:
    case 2:
        return sphere(rng_uniform(0.3, 1.5));
    case 3:
    case 4:
    case 5: {
        double a[3], b[3];
        for (int k = 0; k < 3; k++) {
            a[k] = rng_uniform(-1.5, 0.5);
            b[k] = a[k] + rng_uniform(0.2, 2);
        }
        return box(a[0], a[1], a[2], b[0], b[1], b[2]);
    }
    default: {
        double r1 = rng_uniform(0, 1.5), r2 = rng_uniform(0, 1.5);
        int z = rng_int(4);
        if (z == 0)
            r1 = 0;
        else if (z == 1)
            r2 = 0;
        else if (z == 2)
            r2 = r1;
        return cone(r1, r2, rng_uniform(0.3, 2.5));
    }
    }
}

/* world_from_object = T·R·S with R from a random unit quaternion and S a
 * non-uniform scale (sometimes a mirror); its inverse S⁻¹·Rᵀ·T⁻¹ is written
 * out here, independently of csg_affine_invert. */
static void random_transform(tnode *n)
{
    double q[4], ql = 0;
    for (int i = 0; i < 4; i++) {
        q[i] = rng_uniform(-1, 1);
        ql += q[i] * q[i];
    }
    ql = sqrt(ql);
    for (int i = 0; i < 4; i++)
        q[i] /= ql;
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    if (rng_int(4) == 0) { /* axis-aligned now and then: exact zeros in d */
        memset(R, 0, sizeof R);
        R[0][0] = R[1][1] = R[2][2] = 1;
    }
    double s[3], t[3];
    for (int i = 0; i < 3; i++) {
        s[i] = rng_uniform(0.4, 2.5) * (rng_int(6) == 0 ? -1 : 1);
        t[i] = rng_uniform(-1.5, 1.5);
    }
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
            n->world_from_object[4 * i + j] = R[i][j] * s[j];
            n->object_from_world[4 * i + j] = R[j][i] / s[i];
        }
        n->world_from_object[4 * i + 3] = t[i];
    }
    for (int i = 0; i < 3; i++)
        n->object_from_world[4 * i + 3] =
            -(n->object_from_world[4 * i] * t[0] + n->object_from_world[4 * i + 1] * t[1] +
              n->object_from_world[4 * i + 2] * t[2]);
    if (rng_int(25) == 0) { /* singular: flattened to a plane */
        for (int i = 0; i < 3; i++)
            n->world_from_object[4 * i + 2] = 0;
        n->empty = 1;
    }
}

static tnode *random_tree(int depth)
{
    tnode *n = &pool[npool++];
    memset(n, 0, sizeof *n);
    if (depth >= 5 || npool > 80 || rng_int(3) == 0) {
        n->leaf = 1;
        n->shape = random_shape();
        random_transform(n);
        return n;
    }
    n->op = (csg_op)rng_int(3);
    int r = rng_int(8);
    n->nk = r == 0 ? rng_int(2) : r < 3 ? 5 + rng_int(MAXK - 4) : 2 + rng_int(3);
    for (int i = 0; i < n->nk; i++)
        n->k[i] = random_tree(depth + 1);
    return n;
}

static csg_node *build(const tnode *n, int *nleaves)
{
    if (n->leaf) {
        int id = (*nleaves)++;
        leaves_by_id[id] = (tnode *)n;
        csg_material m = mat((float)id);
        csg_node *c = csg_node_shape(&n->shape, n->world_from_object, &m);
        cr_assert_not_null(c);
        return c;
    }
    csg_node *c = csg_node_op(n->op);
    for (int i = 0; i < n->nk; i++)
        cr_assert_eq(csg_node_add(c, build(n->k[i], nleaves)), 0);
    return c;
}

static int same_bound(const iv_bound *a, const iv_bound *b)
{
    return a->t == b->t && a->prim == b->prim && a->part == b->part && a->flip == b->flip;
}

Test(csg_trace, random_trees_match_point_classifier)
{
    const uint64_t seed = 0xc5c5;
    rng_seed(seed);
    long samples = 0, inside = 0, hits = 0;
    for (int tree = 0; tree < 400; tree++) {
        npool = 0;
        tnode *root = random_tree(0);
        int nleaves = 0;
        csg_node *croot = build(root, &nleaves);
        char err[128];
        csg_scene *s = csg_scene_new(&croot, 1, err, sizeof err);
        cr_assert_not_null(s, "%s", err);
        double blo[3], bhi[3];
        int has_bounds = csg_scene_bounds(s, 0, blo, bhi) == 0;
        for (int ray = 0; ray < 100; ray++) {
            iv_arena_reset(arena);
            double o[3], d[3];
            for (int k = 0; k < 3; k++) {
                o[k] = rng_uniform(-4, 4);
                d[k] = rng_uniform(-1, 1);
            }
            if (rng_int(5) == 0) d[rng_int(3)] = 0;
            double tmin = rng_uniform(-4, 0), tmax = rng_int(4) ? rng_uniform(1, 8) : INFINITY;
            if (rng_int(6) == 0) tmin = -INFINITY;
            iv_list l, lc;
            cr_assert_eq(csg_trace(s, 0, o, d, tmin, tmax, arena, &l), 0);
            /* Culling must not change a single boundary. */
            csg_scene_set_cull(s, 0);
            cr_assert_eq(csg_trace(s, 0, o, d, tmin, tmax, arena, &lc), 0);
            csg_scene_set_cull(s, 1);
            cr_assert_eq(l.n, lc.n, "seed %#llx tree %d ray %d: culling changed the span count",
                         (unsigned long long)seed, tree, ray);
            for (int i = 0; i < l.n; i++)
                cr_assert(same_bound(&l.v[i].enter, &lc.v[i].enter) &&
                              same_bound(&l.v[i].exit, &lc.v[i].exit),
                          "seed %#llx tree %d ray %d: culling changed span %d",
                          (unsigned long long)seed, tree, ray, i);
            const double dl = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            for (int i = 0; i < l.n; i++) {
                const iv_bound *bs[2] = {&l.v[i].enter, &l.v[i].exit};
                cr_assert(l.v[i].enter.t < l.v[i].exit.t);
                cr_assert(i == 0 || l.v[i - 1].exit.t < l.v[i].enter.t);
                for (int e = 0; e < 2; e++) {
                    const iv_bound *b = bs[e];
                    cr_assert(b->t >= tmin && b->t <= tmax, "seed %#llx tree %d ray %d",
                              (unsigned long long)seed, tree, ray);
                    if (b->prim == IV_PRIM_NONE) {
                        cr_assert(b->t == tmin || b->t == tmax,
                                  "seed %#llx tree %d ray %d: clip inside the range",
                                  (unsigned long long)seed, tree, ray);
                        continue;
                    }
                    if (isinf(b->t)) { /* a halfspace reaching an infinite tmin/tmax */
                        cr_assert(b->t == tmin || b->t == tmax);
                        continue;
                    }
                    hits++;
                    cr_assert(b->prim >= 0 && b->prim < csg_scene_prim_count(s));
                    /* The boundary lies on the surface of the leaf it names. */
                    int id = (int)csg_scene_material(s, b->prim)->rgba[0];
                    const tnode *lf = leaves_by_id[id];
                    double p[3], q[3];
                    for (int k = 0; k < 3; k++)
                        p[k] = o[k] + b->t * d[k];
                    apply(lf->object_from_world, p, q);
                    double f = shape_sdf(&lf->shape, q);
                    cr_assert(fabs(f) < 1e-9 * (1 + fabs(b->t) * dl),
                              "seed %#llx tree %d ray %d: boundary off its leaf (%g)",
                              (unsigned long long)seed, tree, ray, f);
                    /* Inside the root's bounds. */
                    cr_assert(has_bounds);
                    for (int k = 0; k < 3; k++)
                        cr_assert(p[k] >= blo[k] && p[k] <= bhi[k],
                                  "seed %#llx tree %d ray %d: hit outside bounds",
                                  (unsigned long long)seed, tree, ray);
                    /* The normal faces against the ray on entry, with it on
                     * exit. */
                    double n[3];
                    csg_scene_normal(s, b, o, d, n);
                    double nd = (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / dl;
                    near(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, 1e-12);
                    cr_assert(e == 0 ? nd <= 1e-9 : nd >= -1e-9,
                              "seed %#llx tree %d ray %d: %s normal·d = %g",
                              (unsigned long long)seed, tree, ray, e ? "exit" : "enter", nd);
                }
            }
            /* Membership at sample points. */
            double hi = isinf(tmax) ? 12 : tmax + 1, lo = isinf(tmin) ? -12 : tmin - 1;
            for (int k = 0; k < 40; k++) {
                double t = rng_uniform(lo, hi);
                int close = 0;
                for (int i = 0; i < l.n; i++)
                    if (fabs(t - l.v[i].enter.t) * dl < 1e-7 || fabs(t - l.v[i].exit.t) * dl < 1e-7)
                        close = 1;
                if (fabs(t - tmin) * dl < 1e-7 || fabs(t - tmax) * dl < 1e-7) close = 1;
                double p[3] = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
                int want = classify(root, p, &close) && t >= tmin && t <= tmax;
                if (close) continue;
                samples++;
                inside += want;
                cr_assert_eq(iv_list_contains(&l, t), want,
                             "seed %#llx tree %d ray %d t %.17g: traced %d, classifier %d",
                             (unsigned long long)seed, tree, ray, t, !want, want);
                if (want) {
                    for (int c = 0; c < 3; c++)
                        cr_assert(p[c] >= blo[c] && p[c] <= bhi[c],
                                  "seed %#llx tree %d ray %d: inside point outside bounds",
                                  (unsigned long long)seed, tree, ray);
                }
            }
        }
        csg_scene_free(s);
    }
    /* The test means something only if both answers occur often. */
    cr_assert(inside > samples / 20 && inside < samples - samples / 20, "inside %ld of %ld samples",
              inside, samples);
    cr_assert(hits > 4000, "only %ld surface hits", hits);
}

/* A union of 5 … 60 operands — leaves, a third of them exact copies of an
 * earlier leaf (equal t: the tie rule), and random subtrees — wide enough
 * that commit builds its bounding hierarchy. */
static tnode *random_wide_union(void)
{
    tnode *u = &pool[npool++];
    memset(u, 0, sizeof *u);
    u->op = CSG_OP_UNION;
    int n = 5 + rng_int(56);
    tnode *kids[64];
    int nleaf = 0;
    tnode *leaves[64];
    for (int i = 0; i < n; i++) {
        int r = rng_int(6);
        if (r < 2 && nleaf > 0) {
            tnode *c = &pool[npool++];
            *c = *leaves[rng_int(nleaf)];
            kids[i] = c;
        } else if (r < 4) {
            tnode *c = &pool[npool++];
            memset(c, 0, sizeof *c);
            c->leaf = 1;
            c->shape = random_shape();
            random_transform(c);
            kids[i] = leaves[nleaf++] = c;
        } else {
            kids[i] = random_tree(2);
        }
    }
    /* Nest the operands MAXK at a time (commit splices nested unions). */
    tnode *cur = u;
    for (int i = 0; i < n; i++) {
        if (cur->nk == MAXK - 1 && i < n - 1) {
            tnode *v = &pool[npool++];
            memset(v, 0, sizeof *v);
            v->op = CSG_OP_UNION;
            cur->k[cur->nk++] = v;
            cur = v;
        }
        cur->k[cur->nk++] = kids[i];
    }
    return u;
}

/* csg_trace_first's boundary of root 0 along o + t·d over [tmin, tmax] is the
 * full trace's first, culling with csg_wide's AVX box tests (where the CPU
 * has them), with its scalar ones, and not culling.  Returns whether the ray
 * meets the root; leaves culling and AVX on. */
static int first_boundary_agrees(csg_scene *s, const double o[3], const double d[3], double tmin,
                                 double tmax, unsigned long long seed, int tree, int ray)
{
    int met = 0;
    for (int mode = 2; mode >= 0; mode--) {
        csg_scene_set_cull(s, mode > 0);
        csg_scene_set_avx(s, mode == 2);
        iv_arena_reset(arena);
        iv_list l;
        iv_bound b = {-1, -7, 7, 7};
        cr_assert_eq(csg_trace(s, 0, o, d, tmin, tmax, arena, &l), 0);
        int rc = csg_trace_first(s, 0, o, d, tmin, tmax, arena, &b);
        cr_assert_eq(rc, l.n > 0, "seed %#llx tree %d ray %d mode %d: found %d, %d spans", seed,
                     tree, ray, mode, rc, l.n);
        met = l.n > 0;
        if (!met) continue;
        const iv_bound *w = &l.v[0].enter;
        cr_assert(same_bound(&b, w),
                  "seed %#llx tree %d ray %d mode %d: first (%.17g, prim %d, part %d, flip %d), "
                  "full trace (%.17g, prim %d, part %d, flip %d)",
                  seed, tree, ray, mode, b.t, b.prim, b.part, b.flip, w->t, w->prim, w->part,
                  w->flip);
    }
    csg_scene_set_cull(s, 1);
    csg_scene_set_avx(s, 1);
    return met;
}

Test(csg_trace, first_boundary_matches_full_trace)
{
    const uint64_t seed = 0xf1257;
    rng_seed(seed);
    long hits = 0;
    for (int tree = 0; tree < 600; tree++) {
        npool = 0;
        tnode *root = tree % 3 == 0 ? random_tree(0) : random_wide_union();
        if (tree % 3 == 2) { /* a wide union inside a difference or intersection */
            tnode *x = &pool[npool++];
            memset(x, 0, sizeof *x);
            x->op = rng_int(2) ? CSG_OP_DIFFERENCE : CSG_OP_INTERSECTION;
            x->nk = 2;
            x->k[rng_int(2)] = root;
            tnode *o = random_tree(3);
            x->k[x->k[0] ? 1 : 0] = o;
            root = x;
        }
        int nleaves = 0;
        csg_node *croot = build(root, &nleaves);
        char err[128];
        csg_scene *s = csg_scene_new(&croot, 1, err, sizeof err);
        cr_assert_not_null(s, "%s", err);
        for (int ray = 0; ray < 200; ray++) {
            double o[3], d[3];
            for (int k = 0; k < 3; k++) {
                o[k] = rng_uniform(-4, 4);
                d[k] = rng_uniform(-1, 1);
            }
            if (rng_int(5) == 0) d[rng_int(3)] = 0;
            double tmin = rng_int(3) ? 0 : rng_uniform(-4, 2);
            double tmax = rng_int(4) ? rng_uniform(1, 8) : INFINITY;
            if (rng_int(6) == 0) tmin = -INFINITY;
            hits += first_boundary_agrees(s, o, d, tmin, tmax, seed, tree, ray);
        }
        csg_scene_free(s);
    }
    cr_assert(hits > 10000, "only %ld rays hit", hits);
}

/* The slab test as trace.c documents it, written out here for one box:
 * the entry into [lo, hi] of the segment [t0, t1], comparisons with a NaN
 * slab product being false. */
static int ref_box_entry(const double lo[3], const double hi[3], const double o[3],
                         const double d[3], double t0, double t1, double *te)
{
    for (int k = 0; k < 3; k++) {
        if (d[k] == 0) {
            if (o[k] < lo[k] || o[k] > hi[k]) return 0;
            continue;
        }
        double inv = 1 / d[k];
        double ta = ((d[k] < 0 ? hi[k] : lo[k]) - o[k]) * inv;
        double tb = ((d[k] < 0 ? lo[k] : hi[k]) - o[k]) * inv;
        if (ta > t0) t0 = ta;
        if (tb < t1) t1 = tb;
    }
    *te = t0;
    return t0 <= t1;
}

/* Every operand record of a wide union (some operands unbounded), tested
 * with AVX and with scalar code against ref_box_entry on the operands'
 * node bounds: the same hits, and bit for bit the same entries.  Origins
 * often lie on a bound plane and direction components are often ±0 or
 * subnormal, so NaN slab products (0·inf) are common. */
Test(csg_trace, wide_entry_matches_box_test)
{
    const uint64_t seed = 0x51ab;
    rng_seed(seed);
    csg_node *u = csg_node_op(CSG_OP_UNION);
    for (int i = 0; i < 300; i++) {
        csg_affine m;
        ts_affine(rng_uniform(-5, 5), rng_uniform(-5, 5), rng_uniform(-5, 5), rng_uniform(0.1, 2),
                  rng_uniform(0.1, 2), rng_uniform(0.1, 2), m);
        iv_shape sh = i % 50 == 7  ? halfspace(0, 0, 1, rng_uniform(-1, 1))
                      : rng_int(2) ? box(-1, -1, -1, 1, 1, 1)
                                   : sphere(1);
        cr_assert_eq(csg_node_add(u, leaf(sh, m, (float)i)), 0);
    }
    csg_scene *s = commit1(u);
    cr_assert(s->nwide > 75);
    const int avx = csg_cpu_has_avx();
    const double tiny[4] = {0.0, -0.0, 5e-324, -1e-310};
    long hits = 0, nan_slabs = 0;
    for (int ray = 0; ray < 20000; ray++) {
        const csg_wide *w = &s->wide[rng_int(s->nwide)];
        double o[3], d[3];
        for (int k = 0; k < 3; k++) {
            o[k] = rng_uniform(-8, 8);
            d[k] = rng_int(4) ? rng_uniform(-1, 1) : tiny[rng_int(4)];
            if (rng_int(3) == 0) { /* on a plane of some lane's box */
                int i = rng_int(w->n);
                o[k] = w->box[rng_int(2)][k][i];
                if (isinf(o[k])) o[k] = 0;
            }
        }
        double t0 = rng_int(4) ? rng_uniform(-10, 10) : -INFINITY;
        double t1 = rng_int(4) ? t0 + rng_uniform(0, 20) : INFINITY;
        int cull = rng_int(8) != 0;
        csg_scene_set_cull(s, cull);
        double te[3][WIDE];
        unsigned m[3] = {0, 0, 0};
        csg_scene_set_avx(s, 0);
        m[0] = csg_scene_wide_entry(s, (int32_t)(w - s->wide), o, d, t0, t1, arena, te[0]);
        if (avx) {
            cr_assert_eq(csg_scene_set_avx(s, 1), 1);
            m[1] = csg_scene_wide_entry(s, (int32_t)(w - s->wide), o, d, t0, t1, arena, te[1]);
        }
        for (int i = 0; i < w->n; i++) {
            csg_scene_node_info info;
            csg_scene_node_get(s, w->node[i], &info);
            for (int k = 0; k < 3; k++) {
                cr_assert(w->box[0][k][i] == info.lo[k] && w->box[1][k][i] == info.hi[k]);
                if (o[k] == info.lo[k] || o[k] == info.hi[k])
                    nan_slabs += d[k] != 0 && !isnormal(d[k]);
            }
            te[2][i] = t0;
            int want = cull ? ref_box_entry(info.lo, info.hi, o, d, t0, t1, &te[2][i]) : t0 <= t1;
            hits += want;
            for (int v = 0; v < 1 + avx; v++) {
                cr_assert_eq(m[v] >> i & 1, (unsigned)want,
                             "seed %#llx ray %d lane %d %s: hit %u, box test %d",
                             (unsigned long long)seed, ray, i, v ? "avx" : "scalar", m[v] >> i & 1,
                             want);
                if (want)
                    cr_assert(memcmp(&te[v][i], &te[2][i], sizeof(double)) == 0,
                              "seed %#llx ray %d lane %d %s: entry %.17g, box test %.17g",
                              (unsigned long long)seed, ray, i, v ? "avx" : "scalar", te[v][i],
                              te[2][i]);
            }
        }
        for (int v = 0; v < 1 + avx; v++)
            cr_assert_eq(m[v] >> w->n, 0u, "seed %#llx ray %d: an unused lane hit",
                         (unsigned long long)seed, ray);
    }
    csg_scene_free(s);
    cr_assert(hits > 5000 && nan_slabs > 500, "%ld hits, %ld NaN slabs", hits, nan_slabs);
}

/* A coordinate for first_boundary_of_big_unions: on the unit grid the boxes
 * and spheres sit on, so that rays run along box faces and start on them,
 * or anywhere. */
static double grid_or_not(double lo, double hi)
{
    double x = rng_uniform(lo, hi);
    return rng_int(3) == 0 ? floor(x) : x;
}

/* Unions of hundreds of leaves on a grid (boxes and spheres, some of them
 * copies: ties), traced by csg_trace_first with the AVX and the scalar box
 * tests of the unions' operand records and without culling, against the
 * first boundary of the full trace.  The rays graze faces, run parallel to
 * axes, and some have a subnormal direction component, whose slab product
 * at a plane through the origin is 0·inf = NaN. */
Test(csg_trace, first_boundary_of_big_unions)
{
    const uint64_t seed = 0xb16a;
    rng_seed(seed);
    long hits = 0, rays = 0;
    for (int tree = 0; tree < 12; tree++) {
        csg_node *u = csg_node_op(CSG_OP_UNION);
        int n = 100 + rng_int(1400);
        for (int i = 0; i < n; i++) {
            csg_affine m;
            double c[3];
            for (int k = 0; k < 3; k++)
                c[k] = floor(rng_uniform(0, 12));
            double sz = rng_int(2) ? 1 : rng_uniform(0.2, 1.5);
            ts_affine(c[0], c[1], c[2], sz, sz, sz, m);
            iv_shape sh = rng_int(2) ? box(0, 0, 0, 1, 1, 1) : sphere(0.5);
            cr_assert_eq(csg_node_add(u, leaf(sh, m, (float)i)), 0);
            if (rng_int(8) == 0) cr_assert_eq(csg_node_add(u, leaf(sh, m, (float)i)), 0);
        }
        char err[128];
        csg_scene *s = csg_scene_new(&u, 1, err, sizeof err);
        cr_assert_not_null(s, "%s", err);
        for (int ray = 0; ray < 400; ray++) {
            double o[3], d[3];
            for (int k = 0; k < 3; k++) {
                o[k] = grid_or_not(-3, 15);
                d[k] = rng_uniform(-1, 1);
            }
            int z = rng_int(4);
            if (z == 1) d[rng_int(3)] = 0;
            if (z == 2) d[rng_int(3)] = d[rng_int(3)] = 0;
            if (z == 3) d[rng_int(3)] = rng_int(2) ? 1e-310 : -1e-310;
            if (!(d[0] || d[1] || d[2])) d[rng_int(3)] = 1;
            double tmin = rng_int(3) ? 0 : -INFINITY;
            double tmax = rng_int(2) ? INFINITY : rng_uniform(1, 30);
            hits += first_boundary_agrees(s, o, d, tmin, tmax, seed, tree, ray);
            rays++;
        }
        csg_scene_free(s);
    }
    cr_assert(hits > rays / 4, "only %ld of %ld rays hit", hits, rays);
}

/* ---- deep trees, memory, threads ------------------------------------------ */

/* U_k = union(sphere at x = k, I_k), I_k = intersection(halfspace, U_k+1):
 * nothing can be spliced, so the committed depth is about 2n. */
static csg_node *deep_tree(int n)
{
    csg_node *tail = NULL;
    for (int k = n - 1; k >= 0; k--) {
        csg_affine m;
        ts_affine(k, 0, 0, 1, 1, 1, m);
        csg_node *u = csg_node_op(CSG_OP_UNION);
        csg_node_add(u, leaf(sphere(0.25), m, (float)k));
        if (tail) {
            csg_node *i = csg_node_op(CSG_OP_INTERSECTION);
            csg_node_add(i, leaf(halfspace(1, 0, 0, 1e6), csg_affine_identity, -1));
            csg_node_add(i, tail);
            csg_node_add(u, i);
        }
        tail = u;
    }
    return tail;
}

Test(csg_trace, deep_tree_has_no_depth_limit)
{
    const int n = 3000;
    csg_scene *s = commit1(deep_tree(n));
    cr_assert_eq(csg_scene_prim_count(s), 2 * n - 1);
    iv_list l = trace(s, -1, 0, 0, 1, 0, 0, -INFINITY, INFINITY);
    cr_assert_eq(l.n, n);
    for (int k = 0; k < n; k++) {
        near(l.v[k].enter.t, k + 0.75, 1e-12);
        near(l.v[k].exit.t, k + 1.25, 1e-12);
    }
    csg_scene_free(s);
}

Test(csg_scene, deep_chains_free_and_commit_without_recursion)
{
    /* 200000 nested single-child unions: freeing and committing must not
     * recurse (the commit also collapses the chain). */
    csg_node *t = leaf(sphere(1), csg_affine_identity, 0);
    for (int i = 0; i < 200000; i++) {
        csg_node *u = csg_node_op(i % 2 ? CSG_OP_UNION : CSG_OP_INTERSECTION);
        cr_assert_eq(csg_node_add(u, t), 0);
        t = u;
    }
    csg_scene *s = commit1(t);
    cr_assert_eq(csg_scene_prim_count(s), 1);
    csg_scene_free(s);
    t = leaf(sphere(1), csg_affine_identity, 0);
    for (int i = 0; i < 200000; i++) {
        csg_node *u = csg_node_op(CSG_OP_DIFFERENCE);
        csg_node_add(u, t);
        csg_node_add(u, leaf(sphere(0.1), csg_affine_identity, 1));
        t = u;
    }
    csg_node_free(t);
}

Test(csg_trace, steady_state_needs_no_new_memory)
{
    csg_scene *s = commit1(deep_tree(200));
    rng_seed(7);
    double rays[100][6];
    for (int i = 0; i < 100; i++)
        for (int k = 0; k < 6; k++)
            rays[i][k] = rng_uniform(-1, 1) + (k == 3 ? 2 : 0);
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < 100; i++) {
            iv_arena_reset(arena);
            iv_list l;
            cr_assert_eq(csg_trace(s, 0, rays[i], rays[i] + 3, 0, INFINITY, arena, &l), 0,
                         "pass %d ray %d", pass, i);
        }
        iv_arena_set_limit(arena, 1); /* no chunk can be added from now on */
    }
    csg_scene_free(s);
}

Test(csg_trace, arena_exhaustion_is_an_error)
{
    iv_arena *a = iv_arena_new(256);
    iv_arena_set_limit(a, 256);
    csg_scene *s = commit1(deep_tree(100));
    iv_list l;
    cr_assert_eq(csg_trace(s, 0, (double[3]){-1, 0, 0}, (double[3]){1, 0, 0}, 0, INFINITY, a, &l),
                 -1);
    csg_scene_free(s);
    iv_arena_free(a);
}

typedef struct job {
    const csg_scene *s;
    uint64_t seed;
    double sum;
    int fail;
} job;

static void *trace_many(void *arg)
{
    job *j = arg;
    iv_arena *a = iv_arena_new(0);
    uint64_t st = j->seed;
    for (int i = 0; i < 2000; i++) {
        iv_arena_reset(a);
        double od[6];
        for (int k = 0; k < 6; k++) {
            st = st * 6364136223846793005ull + 1442695040888963407ull;
            od[k] = (double)(st >> 11) / 9007199254740992.0 * 2 - 1;
        }
        od[0] -= 1;
        od[3] += 2;
        iv_list l;
        if (csg_trace(j->s, 0, od, od + 3, 0, INFINITY, a, &l) != 0) j->fail = 1;
        for (int k = 0; k < l.n; k++)
            j->sum += l.v[k].enter.t + 3 * l.v[k].exit.t;
    }
    iv_arena_free(a);
    return NULL;
}

Test(csg_trace, concurrent_traces_agree)
{
    csg_scene *s = commit1(deep_tree(50));
    job js[4] = {{s, 1, 0, 0}, {s, 1, 0, 0}, {s, 1, 0, 0}, {s, 1, 0, 0}};
    pthread_t th[4];
    for (int i = 0; i < 4; i++)
        cr_assert_eq(pthread_create(&th[i], NULL, trace_many, &js[i]), 0);
    for (int i = 0; i < 4; i++)
        pthread_join(th[i], NULL);
    for (int i = 0; i < 4; i++) {
        cr_assert_eq(js[i].fail, 0);
        cr_assert_eq(js[i].sum, js[0].sum);
    }
    cr_assert(js[0].sum != 0);
    csg_scene_free(s);
}

Test(csg_trace, culling_keeps_grazing_hits)
{
    /* An axis-aligned box's bounds are the box itself (plus padding), so
     * rays that clip an edge or corner by a hair test the box test where it
     * is tightest: every hit the shape reports must survive culling. */
    const uint64_t seed = 0x9a2e;
    rng_seed(seed);
    csg_scene *s = commit1(leaf(box(0, 0, 0, 1, 1, 1), csg_affine_identity, 0));
    int kept = 0;
    for (int it = 0; it < 20000; it++) {
        iv_arena_reset(arena);
        /* A point just inside an edge or a corner. */
        double p[3];
        for (int k = 0; k < 3; k++) {
            double e = pow(10, -rng_uniform(2, 12));
            p[k] = rng_int(3) == 0 ? rng_uniform(0.1, 0.9) : (rng_int(2) ? e : 1 - e);
        }
        double d[3] = {rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1)};
        double o[3] = {p[0] - 3 * d[0], p[1] - 3 * d[1], p[2] - 3 * d[2]};
        iv_list l, lc;
        cr_assert_eq(csg_trace(s, 0, o, d, -INFINITY, INFINITY, arena, &l), 0);
        csg_scene_set_cull(s, 0);
        cr_assert_eq(csg_trace(s, 0, o, d, -INFINITY, INFINITY, arena, &lc), 0);
        csg_scene_set_cull(s, 1);
        cr_assert_eq(l.n, lc.n, "seed %#llx iter %d", (unsigned long long)seed, it);
        cr_assert_eq(l.n, 1, "seed %#llx iter %d: the ray passes through (%g,%g,%g)",
                     (unsigned long long)seed, it, p[0], p[1], p[2]);
        cr_assert(same_bound(&l.v[0].enter, &lc.v[0].enter) &&
                  same_bound(&l.v[0].exit, &lc.v[0].exit));
        kept++;
    }
    cr_assert_eq(kept, 20000);
    csg_scene_free(s);
}

/* q(x) over |∇q(x)|: x's distance from the surface, to first order. */
static double quadric_distance(const iv_quadric *q, const double x[3], double g[3])
{
    double v = q->c;
    for (int i = 0; i < 3; i++) {
        g[i] = q->b[i];
        for (int j = 0; j < 3; j++)
            g[i] += 2 * q->A[i][j] * x[j];
        v += x[i] * (q->b[i] + q->A[i][0] * x[0] + q->A[i][1] * x[1] + q->A[i][2] * x[2]);
    }
    return v / sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
}

Test(csg_trace, boundary_quadrics_follow_the_surface)
{
    /* Each kind of curved part, and flat ones, under a sheared, scaled,
     * rotated and moved transform, subtracted from a box so that half the
     * boundaries are flipped.  The quadric of a boundary must hold its hit,
     * have the normal as its gradient's direction, and hold the hits of the
     * same part on a ray moved by 0.01: a tangent plane would miss those by
     * about 1e-4 times the curvature. */
    iv_region *ring = iv_region_new((const double[][2]){{1, 0}, {3, 0}, {1, 2}}, (int[]){0, 3}, 1);
    cr_assert_not_null(ring);
    iv_shape shapes[6] = {sphere(1.5),
                          cone(0.5, 1.5, 2),
                          cone(1, 1, 2),
                          {.kind = IV_SHAPE_PRISM},
                          box(-1, -1, -1, 1, 1, 1)};
    shapes[3].u.prism.r = 1.2;
    shapes[3].u.prism.z0 = -1;
    shapes[3].u.prism.z1 = 1;
    iv_shape_revolve(&shapes[5], ring, 270);
    const csg_affine m = {0.9, 0.3, -0.2, 0.1, -0.25, 1.1, 0.4, -0.3, 0.35, -0.1, 0.7, 0.2};
    rng_seed(0x51ab);
    for (int k = 0; k < 6; k++) {
        csg_scene *s = commit1(
            op2(CSG_OP_DIFFERENCE, leaf(box(-5, -5, -5, 5, 5, 5), m, 1), leaf(shapes[k], m, 2)));
        int checked = 0, moved = 0;
        for (int it = 0; it < 400; it++) {
            iv_arena_reset(arena);
            double o[3], d[3], e[3], l2[3];
            for (int c = 0; c < 3; c++) {
                o[c] = rng_uniform(-1.5, 1.5) - 8 * (c == it % 3);
                d[c] = rng_uniform(-0.3, 0.3) + (c == it % 3);
                e[c] = rng_uniform(-1, 1);
            }
            iv_list l;
            cr_assert_eq(csg_trace(s, 0, o, d, -INFINITY, INFINITY, arena, &l), 0);
            double o2[3] = {o[0] + 0.01 * e[0], o[1] + 0.01 * e[1], o[2] + 0.01 * e[2]};
            iv_list l2l;
            cr_assert_eq(csg_trace(s, 0, o2, d, -INFINITY, INFINITY, arena, &l2l), 0);
            for (int i = 0; i < l.n; i++)
                for (int end = 0; end < 2; end++) {
                    const iv_bound *b = end ? &l.v[i].exit : &l.v[i].enter;
                    if (b->prim != 1) continue;
                    iv_quadric q;
                    cr_assert_eq(csg_scene_quadric(s, b, o, d, &q), 0);
                    double x[3], g[3], n[3];
                    for (int c = 0; c < 3; c++)
                        x[c] = o[c] + b->t * d[c];
                    cr_expect_lt(fabs(quadric_distance(&q, x, g)), 1e-12, "shape %d", k);
                    csg_scene_normal(s, b, o, d, n);
                    double gl = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
                    cr_expect_gt((g[0] * n[0] + g[1] * n[1] + g[2] * n[2]) / gl, 1 - 1e-12,
                                 "shape %d: the gradient against the normal", k);
                    checked++;
                    for (int j = 0; j < l2l.n; j++)
                        for (int end2 = 0; end2 < 2; end2++) {
                            const iv_bound *b2 = end2 ? &l2l.v[j].exit : &l2l.v[j].enter;
                            if (b2->prim != 1 || b2->part != b->part || end2 != end) continue;
                            for (int c = 0; c < 3; c++)
                                l2[c] = o2[c] + b2->t * d[c];
                            cr_expect_lt(fabs(quadric_distance(&q, l2, g)), 1e-12,
                                         "shape %d part %d: the moved ray's hit", k, b->part);
                            moved++;
                        }
                }
        }
        cr_expect_gt(checked, 100, "shape %d: %d boundaries", k, checked);
        cr_expect_gt(moved, 80, "shape %d: %d moved", k, moved);
        csg_scene_free(s);
    }
    iv_region_release(ring);
}
