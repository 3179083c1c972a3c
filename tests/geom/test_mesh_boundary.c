/*
 * test_mesh_boundary.c — geom_mesh_is_boundary (src/geom/mesh_boundary.c)
 * on meshes built to be, or not to be, the boundary of their nonzero-rule
 * solid: cubes apart, nested, overlapping, touching, sharing a corner, a
 * void and an island in it, a face pushed through the one opposite, a
 * crack, a flipped triangle, and a subdivided octahedron on a sphere.
 */
#include <criterion/criterion.h>

#include <math.h>
#include <string.h>

#include "../../src/geom/mesh_boundary.h"

#define MAXV 4096
#define MAXT 8192

typedef struct soup {
    double v[MAXV][3];
    int t[MAXT][3];
    int nv, nt;
} soup;

/* A cube's corners (bit k of i: the high side along axis k) and its
 * triangles, counter-clockwise from outside. */
static const int CUBE[12][3] = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                                {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};

/* Append the cube at lo of side a, wound inward when inward. */
static void cube(soup *s, double x, double y, double z, double a, int inward)
{
    int base = s->nv;
    for (int i = 0; i < 8; i++) {
        s->v[s->nv][0] = x + (i & 1 ? a : 0);
        s->v[s->nv][1] = y + (i & 2 ? a : 0);
        s->v[s->nv][2] = z + (i & 4 ? a : 0);
        s->nv++;
    }
    for (int i = 0; i < 12; i++) {
        s->t[s->nt][0] = base + CUBE[i][0];
        s->t[s->nt][1] = base + CUBE[i][inward ? 2 : 1];
        s->t[s->nt][2] = base + CUBE[i][inward ? 1 : 2];
        s->nt++;
    }
}

static int check(const soup *s)
{
    return geom_mesh_is_boundary((const double(*)[3])s->v, s->nv, (const int(*)[3])s->t, s->nt);
}

static soup S; /* (large: not on the stack) */

Test(mesh_boundary, cubes_apart_and_alone)
{
    memset(&S, 0, sizeof S);
    cube(&S, 0, 0, 0, 10, 0);
    cr_expect_eq(check(&S), 1, "one cube");
    cube(&S, 12, 0, 0, 4, 0);
    cr_expect_eq(check(&S), 1, "two apart");

    memset(&S, 0, sizeof S);
    cube(&S, 0, 0, 0, 10, 1);
    cr_expect_eq(check(&S), 0, "inside out: winding -1 in front of it");
}

/* Two cubes wound alike, one inside the other: winding 2 in the inner,
 * whose faces bound nothing.  Wound inward it is a void, and a cube
 * inside the void an island: both boundaries. */
Test(mesh_boundary, nested_shells)
{
    memset(&S, 0, sizeof S);
    cube(&S, 0, 0, 0, 10, 0);
    cube(&S, 3, 3, 3, 4, 0);
    cr_expect_eq(check(&S), 0, "nested alike");

    memset(&S, 0, sizeof S);
    cube(&S, 0, 0, 0, 10, 0);
    cube(&S, 2, 2, 2, 6, 1);
    cr_expect_eq(check(&S), 1, "a void");
    cube(&S, 4, 4, 4, 2, 0);
    cr_expect_eq(check(&S), 1, "an island in the void");
}

/* Overlapping, touching along a face, touching at a corner (two vertices
 * at one place), sharing a corner vertex (two fans about it). */
Test(mesh_boundary, cubes_that_meet)
{
    memset(&S, 0, sizeof S);
    cube(&S, 0, 0, 0, 10, 0);
    cube(&S, 5, 5, 5, 10, 0);
    cr_expect_eq(check(&S), 0, "overlapping");

    memset(&S, 0, sizeof S);
    cube(&S, 0, 0, 0, 10, 0);
    cube(&S, 10, 2, 2, 5, 0);
    cr_expect_eq(check(&S), 0, "face to face");

    memset(&S, 0, sizeof S);
    cube(&S, 0, 0, 0, 10, 0);
    cube(&S, 10, 10, 10, 5, 0);
    cr_expect_eq(check(&S), 0, "corner to corner");

    for (int i = 0; i < S.nt; i++) /* the second's corner 0 made the first's corner 7 */
        for (int k = 0; k < 3; k++)
            if (S.t[i][k] == 8) S.t[i][k] = 7;
    cr_expect_eq(check(&S), 0, "one corner vertex, two fans");
}

/* A corner pulled through the opposite face: its faces cross the others. */
Test(mesh_boundary, corner_pushed_through)
{
    memset(&S, 0, sizeof S);
    cube(&S, 0, 0, 0, 10, 0);
    S.v[0][0] = 15; /* corner (0, 0, 0) to (15, 0, 0), past the face x = 10 */
    S.v[0][1] = 5;
    S.v[0][2] = 5;
    cr_expect_eq(check(&S), 0);
}

/* A flipped triangle, and a face split with a T-junction. */
Test(mesh_boundary, not_closed)
{
    memset(&S, 0, sizeof S);
    cube(&S, 0, 0, 0, 10, 0);
    int x = S.t[3][1];
    S.t[3][1] = S.t[3][2];
    S.t[3][2] = x;
    cr_expect_eq(check(&S), 0, "flipped");

    memset(&S, 0, sizeof S);
    cube(&S, 0, 0, 0, 10, 0);
    /* the -x face's triangle {0, 4, 6} split at the middle of 0-6: its
     * neighbour {0, 6, 2} still runs 6 -> 0 unsplit */
    S.v[8][0] = 0, S.v[8][1] = 5, S.v[8][2] = 5;
    S.nv = 9;
    S.t[0][0] = 0, S.t[0][1] = 4, S.t[0][2] = 8;
    S.t[S.nt][0] = 4, S.t[S.nt][1] = 6, S.t[S.nt][2] = 8;
    S.nt++;
    cr_expect_eq(check(&S), 0, "T-junction");
}

/* Midpoint of v[a] and v[b] pushed out to radius r, shared between the
 * two triangles of an edge. */
static int midpoint(soup *s, int (*seen)[3], int *nseen, int a, int b, double r)
{
    int lo = a < b ? a : b, hi = a < b ? b : a;
    for (int i = 0; i < *nseen; i++)
        if (seen[i][0] == lo && seen[i][1] == hi) return seen[i][2];
    double *p = s->v[s->nv];
    for (int k = 0; k < 3; k++)
        p[k] = 0.5 * (s->v[a][k] + s->v[b][k]);
    double l = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for (int k = 0; k < 3; k++)
        p[k] *= r / l;
    seen[*nseen][0] = lo, seen[*nseen][1] = hi, seen[*nseen][2] = s->nv;
    (*nseen)++;
    return s->nv++;
}

/* An octahedron subdivided four times on a sphere (2048 triangles, many
 * sharing a cell of the grid): a boundary; with a vertex pulled through
 * the far side, not; pushed in only a little way, a dent, again so. */
Test(mesh_boundary, subdivided_sphere)
{
    static soup T;
    static int seen[MAXT][3];
    memset(&S, 0, sizeof S);
    const double O[6][3] = {{5, 0, 0}, {-5, 0, 0}, {0, 5, 0}, {0, -5, 0}, {0, 0, 5}, {0, 0, -5}};
    const int F[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                         {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    memcpy(S.v, O, sizeof O);
    S.nv = 6;
    memcpy(S.t, F, sizeof F);
    S.nt = 8;
    cr_assert_eq(check(&S), 1, "the octahedron");
    for (int level = 0; level < 4; level++) {
        T = S;
        T.nt = 0;
        int nseen = 0;
        for (int i = 0; i < S.nt; i++) {
            int a = S.t[i][0], b = S.t[i][1], c = S.t[i][2];
            int ab = midpoint(&T, seen, &nseen, a, b, 5), bc = midpoint(&T, seen, &nseen, b, c, 5),
                ca = midpoint(&T, seen, &nseen, c, a, 5);
            const int q[4][3] = {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}};
            memcpy(T.t[T.nt], q, sizeof q);
            T.nt += 4;
        }
        S = T;
    }
    cr_assert_eq(S.nt, 8 << 8);
    cr_expect_eq(check(&S), 1, "2048 triangles on a sphere");
    for (int k = 0; k < 3; k++)
        S.v[0][k] = -1.4 * S.v[0][k]; /* the tip (5, 0, 0) to (-7, 0, 0) */
    cr_expect_eq(check(&S), 0, "a tip pulled through");
    for (int k = 0; k < 3; k++)
        S.v[0][k] /= -7; /* to (1, 0, 0): a dent, the cone of its fan inside */
    cr_expect_eq(check(&S), 1, "a tip pushed in");
}
