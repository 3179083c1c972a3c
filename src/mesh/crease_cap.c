/*
 * crease_cap.c — caps across acute creases unzipped (see crease.h,
 * crease_unzip_cap; a rule of mesh_split_creases, crease.c).
 *
 * Where two plane faces A and B meet at an acute crease — a star's point,
 * the end of a narrow slot: a wedge of solid or of air whose faces'
 * normals part by more than 90° — the wedge is thinner than a cell for
 * 1/tan(θ/2) cells from its edge (θ its angle), and the contour closes it
 * short of the edge: a cap of triangles across it, their corners on A, on
 * B, or on neither (vertices the contour put inside the wedge or just off
 * it: "loose").  A star's 24° points came out 0.2 short, 75 tolerances.
 *
 * The cap: the triangles reached from a misfit one (on no plane its
 * corners share) whose corners each lie on A, on B, or are loose, within
 * the reach of the crease (as far as the wedge is narrower than two cells,
 * and a cell more); tried first with misfits alone, then wide, with the
 * triangles of A and B beside the crease too (the contour's triangles fold
 * there, and a side's rim crosses itself) and any triangle about a loose
 * vertex (the loose ones must go).  It must be a disc (one rim loop, V - E
 * + F = 1) whose rim has no loose vertex and runs along A on one side and
 * along B on the other.  Where it passes from one side to the other:
 *   - a vertex on the crease (on both);
 *   - an edge whose triangle across lies on a third plane face C (a top
 *     face): that triangle split at the corner where A, B and C meet; or,
 *     where an end of the edge lies on C too (on the line where C meets A
 *     or B, which runs into the corner), that end moved into the corner;
 *   - a run of the rim on C alone: the corner put in its place, and the
 *     run with the corner a polygon on C.
 * The crease between the two ends gets a vertex under each of the sides'
 * (its nearest point, those closer than 0.05 cells along it as one); each
 * side with the crease back to its start is a polygon on its plane, cut
 * into triangles by ear clipping (a side's run may turn back along the
 * crease: no zipper).  Every new point must lie on the surface where its
 * planes meet, every new triangle on the surface (rays through five points
 * of it), with area, facing like its plane, and no new edge one the mesh
 * has outside the cap; else nothing changes.  A cap that reaches no
 * farther than half a cell from its crease is left alone (a quad's
 * diagonal across it: the chord rules' business).  mesh_split_creases
 * unzips caps only where its other rules change nothing more: run first,
 * caps about the crease unzipped left knots those rules would have tied
 * (a random turned star, exact before, came out 8 D off).
 *
 * Measured (tests/tools/meshdev, default tolerance): tests/mesh_models/
 * acute_tips.scad (two stars, points of 20° to 24°) 39 D and 2,168
 * triangles -> within D (2e-5), 844 (openscad 120; 220 once the
 * simplifier let collapses run along an acute crease, simplify.c folds).  24 random extruded
 * stars, holed triangles and slots, 8 beyond D: slots 34 and 8 D ->
 * exact (1,514 -> 90 triangles), stars 76 -> 0.01 D, 34 -> 8 D and 17 ->
 * 13 D, three unchanged.  40 random stars (some turned, some two unioned)
 * and slots: 10 of the 22 beyond D nearer (35 -> 0.02 D, 17 -> 0, 28 ->
 * 8, 34 -> 13, 98 -> 54 ...), none farther.  Not yet: a letter's counter,
 * whose sides are many facets of a curve (text("A"), 27 D); points whose
 * mesh the rules tangle before the caps are looked at; caps that are no
 * disc (a top face's triangle inside one).
 */
#include "crease.h"
#include "../intervals/vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { CAP_TRIS = 2048, CAP_RIM = 1024, CAP_POINTS = 2 * CAP_RIM + 2 };

typedef struct crease_cap {
    const plane *ab[2];
    double p0[3], e[3];           /* the crease: p0 + t e */
    int n;                        /* points: rim vertices, then new ones */
    int32_t id[CAP_POINTS];       /* a rim vertex's number, -1 for a new point */
    double x[CAP_POINTS][3];      /* where each is */
    int loop[CAP_RIM + 2], nloop; /* the rim, as points, in the mesh's order */
    int32_t outer[CAP_RIM + 2];   /* the triangle across the rim's edge from loop[i] */
    int tri[2 * CAP_POINTS][3], ntri;
    int32_t split[2], split_tri[2][3]; /* triangles across the ends, split at a corner */
    int nsplit;
    int32_t moved[2]; /* rim vertices moved into a corner, at their points' x */
    int nmoved;
    uint32_t mk;                              /* the cap's triangles' mark */
    int cpoly[2][CAP_RIM + 2], ncpoly[2], nc; /* the ends on a third plane: polygons */
    const plane *cplane[2];
    /* scratch (the cap is large: it lives in the crease_mesh, not on the stack) */
    int32_t kt[CAP_TRIS], from[CAP_RIM], to[CAP_RIM], out[CAP_RIM], ids[CAP_RIM + 2];
    int run[2][CAP_RIM + 2], pts[2 * CAP_RIM], poly[CAP_POINTS], idx[CAP_POINTS];
    int loop2[CAP_RIM + 2];
    int32_t outer2[CAP_RIM + 2];
    double tp[2 * CAP_RIM], t[2 * CAP_RIM], q[CAP_POINTS][2];
    int wide;      /* the triangles of A or B beside the crease too */
    double reach2; /* how far from the crease a cap's corners lie, squared */
} crease_cap;

/* Which of the cap's planes x lies on: 1 A, 2 B, 3 both (the crease). */
static unsigned cap_side(const crease_mesh *c, const crease_cap *k, const double x[3])
{
    return crease_planes_near(c, x, k->ab, 2, ON);
}

/* The crease's parameter at x (along A x B from its point p0). */
static double along(const double p0[3], const double e[3], const double x[3])
{
    double d[3];
    sub3(x, p0, d);
    return dot3(d, e) / dot3(e, e);
}

/* How far x lies from the cap's crease, squared. */
static double off_crease2(const crease_cap *k, const double x[3])
{
    double d[3], u = along(k->p0, k->e, x);
    for (int q = 0; q < 3; q++)
        d[q] = x[q] - k->p0[q] - u * k->e[q];
    return dot3(d, d);
}

/* Whether triangle t is a cap's: each corner on A or B, or on no plane at
 * all (a vertex the contour put in the wedge, or just off its edge), all
 * as near the crease as the wedge is narrower than two cells, and a cell
 * (in a wide cap, a triangle about a loose vertex whatever its other
 * corners: the loose one must go); and the triangle on no plane its corners
 * share (not all on A, nor all on B), or, for a wide cap, on A or B beside
 * the crease (the contour's triangles fold there too, where a side's run
 * would cross itself). */
static int cap_like(crease_mesh *c, const crease_cap *k, int32_t t)
{
    unsigned all = 3;
    int32_t tv[3];
    double p[3][3];
    int loose = 0, other = 0;
    crease_corners_as(c, t, -1, -1, tv, p);
    int far = 0;
    for (int i = 0; i < 3; i++) {
        unsigned s = cap_side(c, k, p[i]);
        int out = !(off_crease2(k, p[i]) < k->reach2);
        if (!s) {
            int on = crease_on_a_plane(c, tv[i]);
            if (!on && out) return 0;
            loose += !on;
            other += on;
        }
        far += out;
        all &= s;
    }
    /* past the reach, or on a third plane, only about a loose vertex */
    if ((other || far) && !(k->wide && loose)) return 0;
    if (all) return k->wide;
    const plane *pl[MAX_PLANES];
    return !crease_fits(c, tv, p, pl, crease_candidates(c, tv, 3, pl));
}

/* A new point of the cap at x (float), on the surface where planes pl (n)
 * meet and where no vertex is; its index, -1 when none may be. */
static int cap_point(crease_mesh *c, crease_cap *k, const double x[3], const plane *const *pl,
                     int n)
{
    double r[3] = {x[0], x[1], x[2]};
    mesh_round_to_float(r);
    int32_t *slot = crease_place(c, r);
    if (!slot || *slot >= 0 || k->n == CAP_POINTS || !crease_meets_on_surface(c, r, pl, n))
        return -1;
    for (int i = 0; i < k->n; i++)
        if (k->x[i][0] == r[0] && k->x[i][1] == r[1] && k->x[i][2] == r[2]) return -1;
    k->id[k->n] = -1;
    memcpy(k->x[k->n], r, sizeof r);
    return k->n++;
}

/* The triangle p, q, r of the cap on plane pl, where it has area and faces
 * like it; 0 when it does not. */
static int cap_triangle(const crease_mesh *c, crease_cap *k, int p, int q, int r, const plane *pl)
{
    const plane *one[1] = {pl};
    if (k->ntri == 2 * CAP_POINTS ||
        !crease_half_ok(one, 1, k->x[p], k->x[q], k->x[r], NULL, c->min2))
        return 0;
    k->tri[k->ntri][0] = p, k->tri[k->ntri][1] = q, k->tri[k->ntri][2] = r;
    k->ntri++;
    return 1;
}

/* Whether vertices p and q share an edge outside the cap (its triangles
 * marked mk). */
static int joined_outside(const crease_mesh *c, int32_t p, int32_t q, uint32_t mk)
{
    for (int32_t f = c->start[p]; f < c->start[p + 1]; f++)
        if (c->tmark[c->fan[f]] != mk && crease_has(c->m, c->fan[f], q)) return 1;
    return 0;
}

/* The polygon poly (n points of the cap, in order, on plane pl) cut into
 * triangles facing like pl, ears first (an ear: a corner turning like pl
 * with no other corner in its triangle, whose new edge the mesh has not
 * outside the cap); 0 when it cannot be.  A side's
 * run may turn back along the crease, so the strip is no zipper. */
static int clip_ears(const crease_mesh *c, crease_cap *k, int *poly, int n, const plane *pl)
{
    double u[3], w[3], (*q)[2] = k->q;
    const double *nn = pl->n;
    double ax[3] = {fabs(nn[0]) < 0.6 ? 1 : 0, fabs(nn[0]) < 0.6 ? 0 : 1, 0};
    cross3(nn, ax, u);
    cross3(nn, u, w);
    for (int i = 0; i < n; i++) /* in the plane: u x w is along n */
        q[i][0] = dot3(k->x[poly[i]], u), q[i][1] = dot3(k->x[poly[i]], w);
    int *idx = k->idx;
    for (int i = 0; i < n; i++)
        idx[i] = i;
    for (int from = 0; n > 3;) { /* the search resumes where the last ear was */
        int ear = -1;
        for (int s = 0; s < n && ear < 0; s++) {
            int i = (from + s) % n;
            const double *a = q[idx[(i + n - 1) % n]], *b = q[idx[i]], *d = q[idx[(i + 1) % n]];
            double turn = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
            if (!(turn > 0)) continue;
            int inside = 0;
            for (int j = 0; j < n && !inside; j++) {
                if (j == i || j == (i + n - 1) % n || j == (i + 1) % n) continue;
                const double *x = q[idx[j]];
                double s0 = (b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0]);
                double s1 = (d[0] - b[0]) * (x[1] - b[1]) - (d[1] - b[1]) * (x[0] - b[0]);
                double s2 = (a[0] - d[0]) * (x[1] - d[1]) - (a[1] - d[1]) * (x[0] - d[0]);
                inside = s0 >= 0 && s1 >= 0 && s2 >= 0;
            }
            int32_t ia = k->id[poly[idx[(i + n - 1) % n]]], id = k->id[poly[idx[(i + 1) % n]]];
            if (!inside && !(ia >= 0 && id >= 0 && joined_outside(c, ia, id, k->mk))) ear = i;
        }
        if (ear < 0 || !cap_triangle(c, k, poly[idx[(ear + n - 1) % n]], poly[idx[ear]],
                                     poly[idx[(ear + 1) % n]], pl))
            return 0;
        memmove(&idx[ear], &idx[ear + 1], (size_t)(n - ear - 1) * sizeof *idx);
        n--;
        from = ear > 0 ? ear - 1 : 0;
    }
    return n < 3 || cap_triangle(c, k, poly[idx[0]], poly[idx[1]], poly[idx[2]], pl);
}

/* Whether rim vertex v (point j of the cap) may move to x: its triangles
 * outside the cap unchanged this pass, keeping their area and facing. */
static int may_move(crease_mesh *c, const crease_cap *k, int32_t v, const double x[3])
{
    int32_t *slot = crease_place(c, x);
    if (!slot || *slot >= 0 || k->nmoved == 2) return 0;
    for (int32_t f = c->start[v]; f < c->start[v + 1]; f++) {
        int32_t t = c->fan[f], tv[3];
        double p[3][3], n0[3], n1[3];
        if (c->tmark[t] == k->mk) continue;
        if (c->used[t]) return 0;
        crease_corners_as(c, t, -1, -1, tv, p);
        tri_normal3(p[0], p[1], p[2], n0);
        for (int q = 0; q < 3; q++)
            if (tv[q] == v) memcpy(p[q], x, sizeof p[q]);
        tri_normal3(p[0], p[1], p[2], n1);
        if (!(dot3(n1, n1) > c->min2) || !(dot3(n0, n1) > 0)) return 0;
    }
    return 1;
}

/* The cap's end at rim edge i (from a point on one plane to one on the
 * other): the corner where A, B and the plane of the triangle across meet,
 * put between them in the loop, and that triangle split there; or, where
 * an end of the edge lies on that plane too (on the line where it meets A
 * or B, which runs into the corner), that end moved into the corner.  0
 * when there is none. */
static int cap_end(crease_mesh *c, crease_cap *k, int i)
{
    mesh *m = c->m;
    int32_t o = k->outer[i], ov[3], f = -1;
    int32_t a = k->id[k->loop[i]], b = k->id[k->loop[(i + 1) % k->nloop]];
    memcpy(ov, &m->t[3 * (size_t)o], sizeof ov);
    for (int q = 0; q < 3; q++)
        if (ov[q] != a && ov[q] != b) f = ov[q];
    if (f < 0 || k->nsplit == 2 || (k->nsplit && k->split[0] == o)) return 0;
    const plane *pl[MAX_PLANES], *three[3] = {k->ab[0], k->ab[1], NULL};
    int np = crease_candidates(c, ov, 3, pl);
    unsigned on = crease_on_planes(c, ov[0], pl, np) & crease_on_planes(c, ov[1], pl, np) &
                  crease_on_planes(c, ov[2], pl, np);
    for (int q = 0; q < np && !three[2]; q++)
        if (on >> q & 1 && pl[q] != k->ab[0] && pl[q] != k->ab[1]) three[2] = pl[q];
    double x[3], d[3];
    if (!three[2] || !crease_corner(three[0], three[1], three[2], x)) return 0;
    sub3(x, k->x[k->loop[i]], d);
    if (!(dot3(d, d) < KNOT_R * KNOT_R * c->h * c->h)) return 0;
    double r[3] = {x[0], x[1], x[2]};
    mesh_round_to_float(r);
    for (int e = 0; e < 2; e++) {
        int j = (i + e) % k->nloop;
        int32_t v = e ? b : a;
        if (!crease_planes_near(c, k->x[k->loop[j]], &three[2], 1, ON) ||
            !crease_meets_on_surface(c, r, three, 3) || !may_move(c, k, v, r))
            continue;
        k->moved[k->nmoved++] = v;
        memcpy(k->x[k->loop[j]], r, sizeof r);
        return 1;
    }
    int px = cap_point(c, k, x, three, 3);
    if (px < 0 || k->nloop == CAP_RIM + 2) return 0;
    /* the triangle across runs b -> a: it becomes (b, x, f) and (x, a, f) */
    int s = k->nsplit++;
    k->split[s] = o;
    k->split_tri[s][0] = b, k->split_tri[s][1] = px, k->split_tri[s][2] = f;
    double pb[3], pf[3], pa[3];
    mesh_vertex_at(m, b, pb);
    mesh_vertex_at(m, f, pf);
    mesh_vertex_at(m, a, pa);
    const plane *cp[1] = {three[2]};
    if (!crease_half_ok(cp, 1, pb, k->x[px], pf, NULL, c->min2) ||
        !crease_half_ok(cp, 1, k->x[px], pa, pf, NULL, c->min2))
        return 0;
    memmove(&k->loop[i + 2], &k->loop[i + 1], (size_t)(k->nloop - i - 1) * sizeof *k->loop);
    memmove(&k->outer[i + 2], &k->outer[i + 1], (size_t)(k->nloop - i - 1) * sizeof *k->outer);
    k->loop[i + 1] = px;
    k->outer[i + 1] = -1;
    k->nloop++;
    return 1;
}

/* The crease's points under the sides' vertices (runs ra, rb of the loop),
 * strictly between the ends' parameters t1 and t2, into k and pts (their
 * parameters into tp), sorted from t1 to t2; their count, -1 when one may
 * not be. */
static int crease_points(crease_mesh *c, crease_cap *k, const int *ra, int na, const int *rb,
                         int nb, const double p0[3], const double e[3], double t1, double t2,
                         int *pts, double *tp)
{
    double *t = k->t, gap = 0.05 * c->h / sqrt(dot3(e, e)), lo = fmin(t1, t2), hi = fmax(t1, t2);
    int n = 0;
    for (int i = 0; i < na + nb; i++) {
        double ti = along(p0, e, k->x[i < na ? ra[i] : rb[i - na]]);
        if (ti > lo + gap && ti < hi - gap) t[n++] = ti;
    }
    for (int i = 1; i < n; i++) /* sorted from t1 */
        for (int j = i; j > 0 && (t[j] - t[j - 1]) * (t2 - t1) < 0; j--) {
            double s = t[j];
            t[j] = t[j - 1];
            t[j - 1] = s;
        }
    int m = 0;
    for (int i = 0; i < n; i++) {
        if (m && fabs(t[i] - tp[m - 1]) < gap) continue;
        double x[3];
        for (int q = 0; q < 3; q++)
            x[q] = p0[q] + t[i] * e[q];
        if ((pts[m] = cap_point(c, k, x, k->ab, 2)) < 0) return -1;
        tp[m++] = t[i];
    }
    return m;
}

/* The cap's ends on a third plane C (a wide cap's, at a top face): runs of
 * the rim on C alone, from a point on A and C to one on B and C.  Each
 * becomes the corner where A, B and C meet in the loop, and the run with
 * that corner a polygon on C.  0 when the rim has a loose vertex, or such
 * a run is none of these. */
static int cap_ends_on_planes(crease_mesh *c, crease_cap *k)
{
    int at = -1, *loop = k->loop2, n = 0;
    int32_t *outer = k->outer2;
    for (int i = 0; i < k->nloop && at < 0; i++)
        if (cap_side(c, k, k->x[k->loop[i]])) at = i;
    if (at < 0) return 0;
    for (int i = at, seen = 0; seen < k->nloop;) {
        if (n == CAP_RIM + 2) return 0;
        loop[n] = k->loop[i];
        outer[n++] = k->outer[i];
        seen++;
        int32_t *ids = k->ids;
        int m = 0, q = (i + 1) % k->nloop;
        for (; seen < k->nloop && !cap_side(c, k, k->x[k->loop[q]]); q = (q + 1) % k->nloop) {
            ids[m++] = k->id[k->loop[q]];
            seen++;
            if (!crease_on_a_plane(c, ids[m - 1])) return 0; /* loose */
        }
        if (m) {
            unsigned sp = cap_side(c, k, k->x[k->loop[i]]), sq = cap_side(c, k, k->x[k->loop[q]]);
            const plane *pl[MAX_PLANES], *three[3] = {k->ab[0], k->ab[1], NULL};
            int np = crease_candidates(c, ids, m, pl);
            if ((sp | sq) != 3 || sp == 3 || sq == 3 || k->nc == 2 || n == CAP_RIM + 2) return 0;
            for (int a = 0; a < np && !three[2]; a++) {
                int on = pl[a] != k->ab[0] && pl[a] != k->ab[1] &&
                         crease_planes_near(c, k->x[k->loop[i]], &pl[a], 1, ON) &&
                         crease_planes_near(c, k->x[k->loop[q]], &pl[a], 1, ON);
                for (int r = 0; r < m && on; r++) {
                    double x[3];
                    mesh_vertex_at(c->m, ids[r], x);
                    on = crease_planes_near(c, x, &pl[a], 1, ON) != 0;
                }
                if (on) three[2] = pl[a];
            }
            double x[3];
            if (!three[2] || !crease_corner(three[0], three[1], three[2], x)) return 0;
            int px = cap_point(c, k, x, three, 3), *poly = k->cpoly[k->nc], np2 = 0;
            if (px < 0) return 0;
            for (int r = i;; r = (r + 1) % k->nloop) {
                poly[np2++] = k->loop[r];
                if (r == q) break;
            }
            poly[np2++] = px;
            k->ncpoly[k->nc] = np2;
            k->cplane[k->nc++] = three[2];
            loop[n] = px;
            outer[n++] = -1;
        }
        i = q;
    }
    memcpy(k->loop, loop, (size_t)n * sizeof *loop);
    memcpy(k->outer, outer, (size_t)n * sizeof *outer);
    k->nloop = n;
    return 1;
}

/* Unzip the cap of triangle t0 across the crease of planes A and B (see
 * above); 1 when done, 0 when not, -1 when out of memory. */
static int unzip_pair(crease_mesh *c, int32_t t0, const plane *A, const plane *B, int wide)
{
    mesh *m = c->m;
    crease_cap *k = c->capk;
    k->ab[0] = A, k->ab[1] = B;
    k->n = k->ntri = k->nsplit = k->nloop = k->nmoved = k->nc = 0;
    k->wide = wide;
    /* as far as the wedge is narrower than two cells, and a cell more */
    double half = 0.5 * (3.14159265358979323846 - acos(fmax(-1, fmin(1, dot3(A->n, B->n)))));
    double reach = 1 / tan(half) + 1;
    k->reach2 = reach * reach * c->h * c->h;
    double *p0 = k->p0, *e = k->e;
    if (!crease_line(A, B, p0, e)) return 0;
    /* the cap: breadth first across edges */
    int32_t *kt = k->kt;
    int nkt = 0, nverts = 0;
    uint32_t mk = k->mk = ++c->mark_now;
    if (!cap_like(c, k, t0)) return 0;
    kt[nkt++] = t0;
    c->tmark[t0] = mk;
    for (int i = 0; i < nkt; i++)
        for (int q = 0; q < 3; q++) {
            int32_t y = c->opp[3 * kt[i] + q], o = y / 3;
            if (y < 0 || c->used[o] || m->t[3 * (size_t)o] < 0) return 0;
            if (c->tmark[o] == mk || !cap_like(c, k, o)) continue;
            if (nkt == CAP_TRIS) return 0;
            kt[nkt++] = o;
            c->tmark[o] = mk;
        }
    /* its rim: one loop, the cap a disc */
    int32_t *from = k->from, *to = k->to, *out = k->out;
    int nr = 0;
    double deep = 0; /* how far from the crease it reaches, squared */
    for (int i = 0; i < nkt; i++)
        for (int q = 0; q < 3; q++) {
            const int32_t *tv = &m->t[3 * (size_t)kt[i]];
            if (c->vmark[tv[q]] != mk) {
                double x[3];
                mesh_vertex_at(m, tv[q], x);
                deep = fmax(deep, off_crease2(k, x));
                c->vmark[tv[q]] = mk;
                nverts++;
            }
            int32_t y = c->opp[3 * kt[i] + q];
            if (c->tmark[y / 3] == mk) continue;
            if (nr == CAP_RIM) return 0;
            from[nr] = tv[q], to[nr] = tv[(q + 1) % 3], out[nr++] = y / 3;
        }
    if (nr < 3 || nverts - (3 * nkt + nr) / 2 + nkt != 1) return 0;
    /* a cap that reaches no farther than half a cell from the crease is
     * the chord rules' (a quad's diagonal across it, flipped) */
    if (!(deep > 0.25 * c->h * c->h)) return 0;
    for (int i = 0, cur = 0; i < nr; i++) {
        int next = -1;
        for (int j = 0; j < nr; j++)
            if (from[j] == to[cur]) next = next < 0 ? j : -2;
        if (next < 0 || (next == 0) != (i == nr - 1)) return 0;
        k->id[k->n] = from[cur];
        mesh_vertex_at(m, from[cur], k->x[k->n]);
        k->outer[k->nloop] = out[cur];
        k->loop[k->nloop++] = k->n++;
        cur = next;
    }
    if (!cap_ends_on_planes(c, k)) return 0;
    /* its ends: points on the crease, or edges from one side to the other
     * (split at a corner) */
    for (int i = 0; i < k->nloop; i++) {
        unsigned si = cap_side(c, k, k->x[k->loop[i]]),
                 sj = cap_side(c, k, k->x[k->loop[(i + 1) % k->nloop]]);
        if ((si | sj) == 3 && si != 3 && sj != 3 && !cap_end(c, k, i++)) return 0;
    }
    int end[2], ne = 0;
    for (int i = 0; i < k->nloop; i++)
        if (cap_side(c, k, k->x[k->loop[i]]) == 3) {
            if (ne == 2) return 0;
            end[ne++] = i;
        }
    if (ne != 2) return 0;
    /* the two sides: runs from one end to the other, each on one plane */
    int(*run)[CAP_RIM + 2] = k->run, nrun[2] = {0, 0};
    unsigned side[2] = {0, 0};
    for (int s = 0; s < 2; s++)
        for (int i = (end[s] + 1) % k->nloop; i != end[1 - s]; i = (i + 1) % k->nloop) {
            run[s][nrun[s]++] = k->loop[i];
            side[s] |= cap_side(c, k, k->x[k->loop[i]]);
        }
    if (side[0] == 3 || side[1] == 3 || side[0] == side[1]) return 0; /* mixed, or alike */
    if (!side[0]) side[0] = 3 ^ side[1];
    if (!side[1]) side[1] = 3 ^ side[0];
    int e1 = k->loop[end[0]], e2 = k->loop[end[1]];
    double t1 = along(p0, e, k->x[e1]), t2 = along(p0, e, k->x[e2]);
    int *pts = k->pts;
    double *tp = k->tp;
    int npts = nrun[0] && nrun[1]
                   ? crease_points(c, k, run[0], nrun[0], run[1], nrun[1], p0, e, t1, t2, pts, tp)
                   : 0;
    if (npts < 0) return 0;
    /* each side's strip: the polygon e1 -> run -> e2 -> the crease's points
     * back to e1 (the second's e2 -> run -> e1 -> the points to e2) */
    for (int s = 0; s < 2; s++) {
        int *poly = k->poly, n = 0;
        poly[n++] = s ? e2 : e1;
        for (int i = 0; i < nrun[s]; i++)
            poly[n++] = run[s][i];
        poly[n++] = s ? e1 : e2;
        for (int i = 0; i < npts; i++)
            poly[n++] = pts[s ? i : npts - 1 - i];
        if (!clip_ears(c, k, poly, n, side[s] == 1 ? A : B)) return 0;
    }
    for (int i = 0; i < k->nc; i++)
        if (!clip_ears(c, k, k->cpoly[i], k->ncpoly[i], k->cplane[i])) return 0;
    /* sound: on the surface, and no edge the mesh has outside the cap */
    for (int i = 0; i < k->ntri; i++) {
        double p[3][3];
        for (int q = 0; q < 3; q++)
            memcpy(p[q], k->x[k->tri[i][q]], sizeof p[q]);
        if (!crease_lies_on_surface(c, p)) return 0;
        for (int q = 0; q < 3; q++) {
            int32_t u = k->id[k->tri[i][q]], w = k->id[k->tri[i][(q + 1) % 3]];
            if (u >= 0 && w >= 0 && joined_outside(c, u, w, mk)) {
                int rim = 0;
                for (int r = 0; r < nr && !rim; r++)
                    rim = from[r] == u && to[r] == w;
                if (!rim) return 0;
            }
        }
    }
    /* done: the moved vertices, the new points, the cap's inner vertices
     * gone, the triangles */
    for (int j = 0; j < k->nmoved; j++) {
        int32_t v = k->moved[j];
        const double *at = NULL;
        for (int i = 0; i < k->n && !at; i++)
            if (k->id[i] == v) at = k->x[i];
        if (crease_leave_place(c, v) != 0) return -1;
        int32_t *slot = crease_place(c, at);
        if (!slot) return -1;
        *slot = v;
        for (int q = 0; q < 3; q++)
            m->v[3 * (size_t)v + q] = (float)at[q];
        for (int32_t f = c->start[v]; f < c->start[v + 1]; f++)
            c->used[c->fan[f]] = 1;
    }
    for (int i = 0; i < k->n; i++)
        if (k->id[i] < 0) {
            int32_t v = crease_add_vertex(c, k->x[i]);
            if (v < 0) return v == -2 ? -1 : 0;
            k->id[i] = v;
        }
    for (int i = 0; i < nkt; i++)
        for (int q = 0; q < 3; q++) {
            int32_t v = m->t[3 * (size_t)kt[i] + q];
            int rim = 0;
            for (int r = 0; r < k->nloop && !rim; r++)
                rim = k->id[k->loop[r]] == v;
            if (!rim && crease_leave_place(c, v) != 0) return -1;
        }
    uint16_t col = m->tc && m->npal ? m->tc[kt[0]] : 0;
    for (int i = 0; i < k->ntri || i < nkt; i++) {
        int32_t tv[3] = {-1, -1, -1};
        if (i < k->ntri)
            for (int q = 0; q < 3; q++)
                tv[q] = k->id[k->tri[i][q]];
        if (i < nkt) {
            memcpy(&m->t[3 * (size_t)kt[i]], tv, sizeof tv);
            if (m->tc && m->npal) m->tc[kt[i]] = col;
            c->used[kt[i]] = 1;
            c->gone |= i >= k->ntri;
        } else if (mesh_push_triangle(m, tv[0], tv[1], tv[2], col) < 0) {
            return -1;
        }
    }
    for (int s = 0; s < k->nsplit; s++) {
        int32_t o = k->split[s], *ov = &m->t[3 * (size_t)o], x = k->id[k->split_tri[s][1]];
        int32_t b = k->split_tri[s][0], f = k->split_tri[s][2], a = -1;
        for (int q = 0; q < 3; q++)
            if (ov[q] != b && ov[q] != f) a = ov[q];
        uint16_t oc = m->tc && m->npal ? m->tc[o] : 0;
        ov[0] = b, ov[1] = x, ov[2] = f;
        c->used[o] = 1;
        if (mesh_push_triangle(m, x, a, f, oc) < 0) return -1;
    }
    return 1;
}

/* Unzip the cap of triangle t, whose corners share no plane and lie on two
 * (see above); 1 when done, 0 when not, -1 when out of memory. */
int crease_unzip_cap(crease_mesh *c, int32_t t)
{
    if (c->used[t]) return 0;
    if (!c->capk && !(c->capk = malloc(sizeof *c->capk))) return -1;
    int32_t vs[3];
    memcpy(vs, &c->m->t[3 * (size_t)t], sizeof vs);
    const plane *pl[MAX_PLANES];
    int np = crease_candidates(c, vs, 3, pl);
    unsigned sv[3], all = 0;
    for (int i = 0; i < 3; i++) { /* a loose corner (on no plane) may lie on either */
        sv[i] = crease_on_planes(c, vs[i], pl, np);
        if (!sv[i] && !crease_on_a_plane(c, vs[i])) sv[i] = ~0u;
        all |= sv[i] == ~0u ? 0 : sv[i];
    }
    int loose = sv[0] == ~0u || sv[1] == ~0u || sv[2] == ~0u;
    if (!sv[0] || !sv[1] || !sv[2] || !all || (!loose && (sv[0] & sv[1] & sv[2]))) return 0;
    for (int a = 0; a < np; a++)
        for (int b = a + 1; b < np; b++) {
            unsigned ab = 1u << a | 1u << b;
            /* an acute wedge (a wider one's cap is less than half a cell
             * deep, and the rules above take its chords) whose planes the
             * corners lie on (or are loose) */
            if (!(sv[0] & ab) || !(sv[1] & ab) || !(sv[2] & ab) || !(all & ab) ||
                dot3(pl[a]->n, pl[b]->n) >= 0)
                continue;
            for (int wide = 0; wide < 2; wide++) {
                int r = unzip_pair(c, t, pl[a], pl[b], wide);
                if (r) return r;
            }
        }
    return 0;
}
