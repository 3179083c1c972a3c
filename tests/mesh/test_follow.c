/*
 * test_follow.c — boundaries followed along a line of rays (src/mesh/follow.c)
 * against the rays themselves (a boundary's t, the length of solid and its
 * area weight on moved rays, cast by csg_trace) and against closed forms
 * (where a ray leaves a sphere's silhouette, where a sphere meets a box's
 * face).
 */
#include "../support.h"

#include <string.h>

#include "../../src/csg/csg.h"
#include "../../src/mesh/follow.h"

static const csg_material plain = {.rgba = {1, 1, 1, 1}};

static csg_node *node(iv_shape s, double tx, double ty, double tz)
{
    const csg_affine m = {1, 0, 0, tx, 0, 1, 0, ty, 0, 0, 1, tz};
    csg_node *n = csg_node_shape(&s, m, &plain);
    cr_assert_not_null(n);
    return n;
}

static csg_scene *difference(csg_node *a, csg_node *b)
{
    csg_node *n = csg_node_op(CSG_OP_DIFFERENCE);
    cr_assert_not_null(n);
    cr_assert_eq(csg_node_add(n, a), 0);
    cr_assert_eq(csg_node_add(n, b), 0);
    char err[128] = "";
    csg_scene *s = csg_scene_new(&n, 1, err, sizeof err);
    cr_assert_not_null(s, "%s", err);
    return s;
}

/* The ray u of line F traced into l, its boundaries followed into f
 * (at most cap); their number. */
static int trace_forms(const csg_scene *s, const mesh_line_frame *F, double u, iv_list *l,
                       mesh_form *f, int cap)
{
    double o[3];
    for (int k = 0; k < 3; k++)
        o[k] = F->p0[k] + u * F->e1[k];
    cr_assert_eq(csg_trace(s, 0, o, F->d, 0, INFINITY, arena, l), 0);
    cr_assert_leq(2 * l->n, cap);
    for (int i = 0; i < 2 * l->n; i++) {
        const iv_bound *b = i & 1 ? &l->v[i / 2].exit : &l->v[i / 2].enter;
        iv_quadric q;
        cr_assert_eq(csg_scene_quadric(s, b, o, F->d, &q), 0);
        uint64_t face = (uint64_t)(uint32_t)b->prim << 32 | (uint64_t)b->part << 1 | b->flip;
        double x[3] = {o[0] + b->t * F->d[0], o[1] + b->t * F->d[1], o[2] + b->t * F->d[2]};
        mesh_form_init(&f[i], &q, F, x, i & 1 ? 1 : -1, face);
    }
    return 2 * l->n;
}

static void unit(double v[3])
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int k = 0; k < 3; k++)
        v[k] /= l;
}

/* A random line: an oblique direction, two across it, an origin. */
static void random_frame(mesh_line_frame *F)
{
    double a[3] = {rng_uniform(-1, 1), rng_uniform(-1, 1), rng_uniform(-1, 1)};
    for (int k = 0; k < 3; k++)
        F->d[k] = rng_uniform(-1, 1);
    unit(F->d);
    /* e1 = a less its part along d; e2 = d × e1 */
    double ad = a[0] * F->d[0] + a[1] * F->d[1] + a[2] * F->d[2];
    for (int k = 0; k < 3; k++)
        F->e1[k] = a[k] - ad * F->d[k];
    unit(F->e1);
    F->e2[0] = F->d[1] * F->e1[2] - F->d[2] * F->e1[1];
    F->e2[1] = F->d[2] * F->e1[0] - F->d[0] * F->e1[2];
    F->e2[2] = F->d[0] * F->e1[1] - F->d[1] * F->e1[0];
    double v = rng_uniform(-2.5, 2.5);
    for (int k = 0; k < 3; k++)
        F->p0[k] = v * F->e2[k] - 10 * F->d[k];
}

TestSuite(follow, .init = arena_setup, .fini = arena_teardown);

Test(follow, moved_rays_cross_what_the_forms_say)
{
    /* A sphere less a cone along a tilted axis: planes, a sphere and a
     * cone's side, entered and left, some flipped. */
    const double r = 3;
    iv_shape sph = {.kind = IV_SHAPE_SPHERE, .u.sphere.r = r};
    iv_shape cone = {.kind = IV_SHAPE_CONE, .u.cone = {0.6, 1.4, 8}};
    csg_scene *s = difference(node(sph, 0, 0, 0), node(cone, 0.3, -0.2, -4));
    rng_seed(0xf011);
    int same = 0;
    for (int it = 0; it < 300; it++) {
        mesh_line_frame F;
        random_frame(&F);
        double u0 = rng_uniform(-3, 3), u1 = u0 + rng_uniform(-0.05, 0.05);
        iv_arena_reset(arena);
        iv_list l0, l1;
        mesh_form f[16], g[16];
        int n0 = trace_forms(s, &F, u0, &l0, f, 16);
        int n1 = trace_forms(s, &F, u1, &l1, g, 16);
        if (n0 == 0 || n0 != n1) continue;
        int alike = 1;
        for (int i = 0; i < n0; i++)
            alike &= f[i].face == g[i].face;
        if (!alike) continue;
        same++;
        double len = 0, area = 0;
        for (int i = 0; i < n0; i++) {
            const iv_bound *b = i & 1 ? &l1.v[i / 2].exit : &l1.v[i / 2].enter;
            double t, o[3], n[3];
            cr_assert_eq(mesh_form_t(&f[i], u1, &t), 0);
            cr_expect(fabs(t - b->t) < 1e-11, "line %d boundary %d: followed %.15g, cast %.15g", it,
                      i, t, b->t);
            len += (i & 1 ? 1 : -1) * b->t;
            for (int k = 0; k < 3; k++)
                o[k] = F.p0[k] + u1 * F.e1[k];
            csg_scene_normal(s, b, o, F.d, n);
            area += fabs(n[0] * F.d[0] + n[1] * F.d[1] + n[2] * F.d[2]);
        }
        mesh_follow_sums m;
        cr_assert_eq(mesh_forms_sums(f, n0, &F, u1, &m), 0);
        cr_expect(fabs(m.len - len) < 1e-11, "line %d: length %.15g, cast %.15g", it, m.len, len);
        cr_expect(fabs(m.area - area) < 1e-11, "line %d: area %.15g, cast %.15g", it, m.area, area);
    }
    cr_expect_gt(same, 150, "%d lines whose moved ray crossed the same faces", same);
    csg_scene_free(s);
}

Test(follow, foresees_a_silhouette_and_a_meeting)
{
    /* Rays along z at y = 0.5 through a sphere of radius 3: the ray u
     * misses past u² + 0.25 = 9. */
    mesh_line_frame F = {{0, 0.5, -10}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    iv_shape sph = {.kind = IV_SHAPE_SPHERE, .u.sphere.r = 3};
    iv_shape box = {.kind = IV_SHAPE_BOX, .u.box = {{-2, -2, -2}, {2, 2, 2}}};
    csg_node *lone = node(sph, 0, 0, 0);
    char err[128];
    csg_scene *s = csg_scene_new(&lone, 1, err, sizeof err);
    cr_assert_not_null(s);
    iv_list l;
    mesh_form a[8], b[8];
    int na = trace_forms(s, &F, 2.5, &l, a, 8), nb = trace_forms(s, &F, 3.5, &l, b, 8);
    cr_assert_eq(na, 2);
    cr_assert_eq(nb, 0);
    double x[8];
    int n = mesh_forms_events(a, na, b, nb, 2.5, 3.5, x, 8);
    cr_assert_eq(n, 1);
    cr_expect(fabs(x[0] - sqrt(8.75)) < 1e-14, "silhouette at %.17g", x[0]);
    /* Rays along z at y = 0 through a box of 4 less a sphere of 2.5: the
     * sphere holds the whole ray inside the box up to u = 1.5, where it
     * meets the box's faces z = ±2 (1.5² + 2² = 2.5²). */
    csg_scene_free(s);
    s = difference(node(box, 0, 0, 0),
                   node((iv_shape){.kind = IV_SHAPE_SPHERE, .u.sphere.r = 2.5}, 0, 0, 0));
    F.p0[1] = 0;
    na = trace_forms(s, &F, 1.3, &l, a, 8);
    nb = trace_forms(s, &F, 1.7, &l, b, 8);
    cr_assert_eq(na, 0);
    cr_assert_eq(nb, 4);
    n = mesh_forms_events(a, na, b, nb, 1.3, 1.7, x, 8);
    int found = 0;
    for (int i = 0; i < n; i++)
        found |= fabs(x[i] - 1.5) < 1e-13;
    cr_expect(found, "%d events foreseen, none at 1.5 (first %.17g)", n, n ? x[0] : NAN);
    csg_scene_free(s);
}

/* Two curved faces that meet twice close together, foreseen over a window
 * far wider than the gap between the meetings (as where a piece of a line
 * is followed to another line, and two events close in on each other): a
 * sphere of radius 3 and a cylinder of radius ρ = 2.999 along z, united,
 * along rays along x at y = 0.5 — the sphere bulges past the cylinder
 * where z² < 9 − ρ², and the rays enter and leave through it there. */
Test(follow, foresees_meetings_close_together)
{
    const double rho = 2.999, zm = sqrt(9 - rho * rho);
    mesh_line_frame F = {{-10, 0.5, 0}, {0, 0, 1}, {0, 1, 0}, {1, 0, 0}};
    csg_node *u = csg_node_op(CSG_OP_UNION);
    cr_assert_not_null(u);
    cr_assert_eq(
        csg_node_add(u, node((iv_shape){.kind = IV_SHAPE_SPHERE, .u.sphere.r = 3}, 0, 0, 0)), 0);
    cr_assert_eq(csg_node_add(u, node((iv_shape){.kind = IV_SHAPE_CONE, .u.cone = {rho, rho, 20}},
                                      0, 0, -10)),
                 0);
    char err[128] = "";
    csg_scene *s = csg_scene_new(&u, 1, err, sizeof err);
    cr_assert_not_null(s, "%s", err);
    iv_list l;
    mesh_form a[8], b[8];
    int na = trace_forms(s, &F, 0, &l, a, 8), nb = trace_forms(s, &F, 0.5, &l, b, 8);
    cr_assert_eq(na, 2);
    cr_assert_eq(nb, 2);
    cr_assert_neq(a[0].face, b[0].face, "the sphere at z = 0, the cylinder at 0.5");
    double x[16];
    int n = mesh_forms_events(a, na, b, nb, -20, 20, x, 16), near[2] = {0, 0};
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 2; k++)
            near[k] |= fabs(x[i] - (k ? zm : -zm)) < 1e-12;
    cr_expect(near[0] && near[1], "%d events foreseen, not both at ±%.17g", n, zm);
    csg_scene_free(s);
}
