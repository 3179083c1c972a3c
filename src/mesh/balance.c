/*
 * balance.c — a simplified mesh's smooth vertices moved off the surface by
 * half the sag of their triangles (see dexels.h, mesh_balance).
 *
 * A triangle whose corners lie on a curved surface lies inside it where the
 * surface is convex (outside where concave) by up to its sag; the corners
 * are on it.  Moving each corner out by half the sag of its triangles
 * splits the deviation between both sides: the same bound then holds with
 * triangles about twice the area (sag grows with the square of size).  The
 * sag of a triangle is measured by a ray along its normal through its
 * centroid.  A vertex on a sharp edge or corner (its triangles' normals
 * spread more than 20°) stays: it is exact, and moving it would move the
 * edge.  A move that would turn one of its triangles by more than 30° is
 * not made.
 */
#include "../intervals/vec3.h"
#include "dexels.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define COS_SMOOTH 0.94 /* cos 20° */
#define COS_KEEP 0.866  /* cos 30° */

static void tri_points(const mesh *m, int32_t t, double p[3][3])
{
    for (int k = 0; k < 3; k++)
        for (int c = 0; c < 3; c++)
            p[k][c] = m->v[3 * (size_t)m->t[3 * (size_t)t + k] + c];
}

static void cross_of(double p[3][3], double n[3])
{
    double e1[3], e2[3];
    sub3(p[1], p[0], e1);
    sub3(p[2], p[0], e2);
    cross3(e1, e2, n);
}

int mesh_balance(mesh *m, mesh_snapper *sn, double reach)
{
    if (!sn->arena) return 0;
    int nv = m->nv, nt = m->nt;
    double *sag = malloc((size_t)nt * sizeof *sag);
    double(*vn)[3] = calloc((size_t)nv, sizeof *vn);
    double *vs = calloc((size_t)nv, sizeof *vs), *va = calloc((size_t)nv, sizeof *va);
    uint8_t *sharp = calloc((size_t)nv, 1);
    int32_t *start = calloc((size_t)nv + 1, sizeof *start),
            *fan = malloc(3 * (size_t)nt * sizeof *fan);
    int rc = -1;
    if (!sag || !vn || !vs || !va || !sharp || !start || !fan) goto done;
    for (int32_t t = 0; t < nt; t++) {
        double p[3][3], n[3], c[3];
        tri_points(m, t, p);
        cross_of(p, n);
        double len = sqrt(dot3(n, n));
        sag[t] = 0;
        if (!(len > 0)) continue;
        for (int q = 0; q < 3; q++) {
            c[q] = (p[0][q] + p[1][q] + p[2][q]) / 3;
            n[q] /= len;
        }
        double hit[3], hn[3], d[3];
        if (mesh_snap_probe(sn, c, n, reach, -1, hit, hn) && dot3(hn, n) > COS_KEEP) {
            sub3(hit, c, d);
            sag[t] = dot3(d, n); /* > 0: the surface is outside the triangle */
        }
        for (int k = 0; k < 3; k++) {
            int32_t v = m->t[3 * (size_t)t + k];
            for (int q = 0; q < 3; q++)
                vn[v][q] += n[q] * len;
            if (fabs(sag[t]) > fabs(vs[v])) vs[v] = sag[t];
            va[v] += len;
            start[v + 1]++;
        }
    }
    for (int v = 0; v < nv; v++)
        start[v + 1] += start[v];
    {
        int32_t *at = malloc((size_t)nv * sizeof *at);
        if (!at) goto done;
        memcpy(at, start, (size_t)nv * sizeof *at);
        for (int32_t t = 0; t < nt; t++)
            for (int k = 0; k < 3; k++)
                fan[at[m->t[3 * (size_t)t + k]]++] = t;
        free(at);
    }
    for (int v = 0; v < nv; v++) {
        double l = sqrt(dot3(vn[v], vn[v]));
        if (!(l > 0)) {
            sharp[v] = 1;
            continue;
        }
        for (int q = 0; q < 3; q++)
            vn[v][q] /= l;
        for (int f = start[v]; f < start[v + 1] && !sharp[v]; f++) {
            double p[3][3], n[3];
            tri_points(m, fan[f], p);
            cross_of(p, n);
            double len = sqrt(dot3(n, n));
            if (!(len > 0) || dot3(n, vn[v]) < COS_SMOOTH * len) sharp[v] = 1;
        }
    }
    for (int v = 0; v < nv; v++) {
        if (sharp[v] || !(va[v] > 0)) continue;
        double move = 0.5 * vs[v], old[3], p0[3][3], n0[3];
        float *pv = &m->v[3 * (size_t)v];
        for (int q = 0; q < 3; q++)
            old[q] = pv[q];
        double before[64][3];
        int nf = start[v + 1] - start[v];
        if (nf > 64) continue;
        for (int f = 0; f < nf; f++) {
            tri_points(m, fan[start[v] + f], p0);
            cross_of(p0, before[f]);
        }
        for (int q = 0; q < 3; q++)
            pv[q] = (float)(old[q] + move * vn[v][q]);
        for (int f = 0; f < nf; f++) {
            tri_points(m, fan[start[v] + f], p0);
            cross_of(p0, n0);
            double l0 = sqrt(dot3(before[f], before[f])), l1 = sqrt(dot3(n0, n0));
            if (!(dot3(n0, before[f]) > COS_KEEP * l0 * l1)) {
                for (int q = 0; q < 3; q++)
                    pv[q] = (float)old[q];
                break;
            }
        }
    }
    rc = 0;
done:
    free(sag);
    free(vn);
    free(vs);
    free(va);
    free(sharp);
    free(start);
    free(fan);
    return rc;
}

/* Smooth parts are simplified to SMOOTH times the tolerance, the sag then
 * split in two by mesh_balance: 2 would split it exactly, 1.8 leaves room
 * for the surface between the contour's points. */
#define SMOOTH 1.8

int mesh_dexels_simplify(const mesh_dexels *d, mesh *m, double tol, char *err, size_t errlen)
{
    if (mesh_simplify(m, SMOOTH * tol, tol, err, errlen) != 0) return -1;
    mesh_snapper sn;
    int rc = mesh_snapper_init(&sn, d, cos(3.14159265358979323846 / 6));
    if (rc == 0) rc = mesh_balance(m, &sn, 4 * SMOOTH * tol);
    mesh_snapper_free(&sn);
    if (rc != 0) snprintf(err, errlen, "out of memory simplifying the mesh");
    return rc;
}
