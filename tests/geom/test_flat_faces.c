/*
 * test_flat_faces.c — geom_merge_flat_faces (src/geom/flat_faces.c): a
 * cube whose faces are cut into many triangles comes back as its twelve,
 * a box with a square hole through it as the 32 its outlines need, the
 * volume unchanged (closed forms), every edge still once each way.
 */
#include <criterion/criterion.h>

#include <stdlib.h>
#include <string.h>

#include "../../src/geom/flat_faces.h"

#define MAXV 2048
#define MAXT 4096

static double V[MAXV][3];
static int nv;

/* The vertex at p, added where new. */
static int vertex(double x, double y, double z)
{
    for (int i = 0; i < nv; i++)
        if (V[i][0] == x && V[i][1] == y && V[i][2] == z) return i;
    V[nv][0] = x, V[nv][1] = y, V[nv][2] = z;
    return nv++;
}

/* The quad of corners (u, v) in [u0, u1] × [v0, v1] on the plane
 * coordinate `axis` = w, cut into an n × n grid of triangle pairs, wound
 * outward along sgn. */
static void grid_quad(int (*T)[3], int *nt, int axis, double w, int sgn, double u0, double u1,
                      double v0, double v1, int n)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            int q[4];
            for (int c = 0; c < 4; c++) {
                double u = u0 + (u1 - u0) * (i + (c == 1 || c == 2)) / n,
                       v = v0 + (v1 - v0) * (j + (c >= 2)) / n, p[3];
                p[axis] = w;
                p[(axis + 1) % 3] = u;
                p[(axis + 2) % 3] = v;
                q[c] = vertex(p[0], p[1], p[2]);
            }
            /* (u, v, axis) right-handed: counter-clockwise about +axis */
            int a = q[0], b = sgn > 0 ? q[1] : q[3], c = q[2], d = sgn > 0 ? q[3] : q[1];
            T[*nt][0] = a, T[*nt][1] = b, T[*nt][2] = c, (*nt)++;
            T[*nt][0] = a, T[*nt][1] = c, T[*nt][2] = d, (*nt)++;
        }
}

static double volume(int (*T)[3], int nt)
{
    double s = 0;
    for (int i = 0; i < nt; i++) {
        const double *a = V[T[i][0]], *b = V[T[i][1]], *c = V[T[i][2]];
        s += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
              a[2] * (b[0] * c[1] - b[1] * c[0])) /
             6;
    }
    return s;
}

/* Every directed edge once, and its reverse once. */
static int closed(int (*T)[3], int nt)
{
    for (int i = 0; i < nt; i++)
        for (int k = 0; k < 3; k++) {
            int a = T[i][k], b = T[i][(k + 1) % 3], same = 0, back = 0;
            for (int j = 0; j < nt; j++)
                for (int l = 0; l < 3; l++) {
                    same += T[j][l] == a && T[j][(l + 1) % 3] == b;
                    back += T[j][l] == b && T[j][(l + 1) % 3] == a;
                }
            if (same != 1 || back != 1) return 0;
        }
    return 1;
}

Test(flat_faces, cube_of_many_triangles)
{
    nv = 0;
    int(*T)[3] = malloc(MAXT * sizeof *T), nt = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int s = 0; s < 2; s++)
            grid_quad(T, &nt, axis, s ? 10 : 0, s ? 1 : -1, 0, 10, 0, 10, 4);
    cr_assert_eq(nt, 6 * 32);
    cr_assert(closed(T, nt));
    cr_assert_float_eq(volume(T, nt), 1000, 1e-9);
    cr_assert_eq(geom_merge_flat_faces((const double(*)[3])V, nv, &T, NULL, &nt, 1e-9), 0);
    cr_expect_eq(nt, 12);
    cr_expect(closed(T, nt));
    cr_expect_float_eq(volume(T, nt), 1000, 1e-9);
    free(T);
}

/* Quad a b c d (counter-clockwise from outside) as two triangles. */
static void quad(int (*T)[3], int *nt, int a, int b, int c, int d)
{
    T[*nt][0] = a, T[*nt][1] = b, T[*nt][2] = c, (*nt)++;
    T[*nt][0] = a, T[*nt][1] = c, T[*nt][2] = d, (*nt)++;
}

/* A cube 10 with a 4 × 4 hole through it along z, its top and bottom
 * each eight cells of a 3 × 3 grid, its outer walls three quads each:
 * top and bottom a square ring (8 corners and a hole: 8 triangles each),
 * the eight walls two each, 32 in all. */
Test(flat_faces, box_with_a_square_hole)
{
    nv = 0;
    int(*T)[3] = malloc(MAXT * sizeof *T), nt = 0;
    const double X[4] = {0, 3, 7, 10};
    int id[4][4][2];
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            for (int k = 0; k < 2; k++)
                id[i][j][k] = vertex(X[i], X[j], k ? 10 : 0);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            if (i == 1 && j == 1) continue; /* the hole */
            quad(T, &nt, id[i][j][1], id[i + 1][j][1], id[i + 1][j + 1][1], id[i][j + 1][1]);
            quad(T, &nt, id[i][j][0], id[i][j + 1][0], id[i + 1][j + 1][0], id[i + 1][j][0]);
        }
    for (int s = 0; s < 3; s++) { /* outer walls, a quad per stretch */
        quad(T, &nt, id[s][0][0], id[s + 1][0][0], id[s + 1][0][1], id[s][0][1]); /* y = 0 */
        quad(T, &nt, id[3][s][0], id[3][s + 1][0], id[3][s + 1][1], id[3][s][1]); /* x = 10 */
        quad(T, &nt, id[s + 1][3][0], id[s][3][0], id[s][3][1], id[s + 1][3][1]); /* y = 10 */
        quad(T, &nt, id[0][s + 1][0], id[0][s][0], id[0][s][1], id[0][s + 1][1]); /* x = 0 */
    }
    /* the hole's walls, facing into it */
    quad(T, &nt, id[2][1][0], id[1][1][0], id[1][1][1], id[2][1][1]); /* y = 3 */
    quad(T, &nt, id[2][2][0], id[2][1][0], id[2][1][1], id[2][2][1]); /* x = 7 */
    quad(T, &nt, id[1][2][0], id[2][2][0], id[2][2][1], id[1][2][1]); /* y = 7 */
    quad(T, &nt, id[1][1][0], id[1][2][0], id[1][2][1], id[1][1][1]); /* x = 3 */
    cr_assert(closed(T, nt));
    cr_assert_float_eq(volume(T, nt), 1000 - 160, 1e-9);
    cr_assert_eq(geom_merge_flat_faces((const double(*)[3])V, nv, &T, NULL, &nt, 1e-9), 0);
    cr_expect_eq(nt, 32);
    cr_expect_float_eq(volume(T, nt), 840, 1e-9);
    cr_expect(closed(T, nt), "open after merging");
    free(T);
}
