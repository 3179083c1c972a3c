/*
 * builtin_2d_ops.c — offset() and projection(): operations whose result is
 * a new 2D shape, made as one region leaf in the call's frame.
 *
 * offset(r | delta, chamfer) is OpenSCAD 2021.01's: the children flattened
 * (geom2d.c), then ClipperOffset through the paths_offset service with
 * OpenSCAD's parameters — r: round joins with arc tolerance
 * |r|·(1 − cos(180°/n)), n the fragments of a circle of radius |r| at the
 * call's $fn/$fa/$fs; delta: miter joins (limit 10^6, OpenSCAD's); with
 * chamfer = true: square joins.
 *
 * projection() works in rows: 1024 lines y = const, evenly spaced over the
 * solid's y extent, each holding the exact x spans of the result on that
 * line; consecutive rows with the same number of spans are joined span by
 * span into trapezoids (vertices on the boundary, chords between them),
 * other rows reach half a row each way, and the trapezoids are united.  The
 * error is a chord's sagitta (second order in the row spacing) except where
 * the topology changes between rows, where it is half a row spacing.
 *
 * cut = true (the section by z = 0): each row's spans are one exact ray
 * cast along x in the plane z = 0.
 *
 * cut = false (the shadow on z = 0): the 3D children are meshed by the
 * mesh_tree service (tri-dexel contouring at 1/256 of the longest side,
 * vertices within about that of the surface), and a row's spans are the
 * union of the cuts of the mesh's triangles by its line — so the outline
 * is that of the mesh, within about 1/256 of the size of the true
 * silhouette.
 */
#include "builtins.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- offset ---------------------------------------------------------------------- */

enum { OFFSET_R, OFFSET_DELTA, OFFSET_CHAMFER };

typedef struct offset_args {
    double delta;
    int round, chamfer;
    scad_facet_params f;
} offset_args;

/* OffsetModule's reading: r wins over delta; a value that is not a finite
 * number leaves the default, r = 1. */
static void offset_read(scad_call *c, void *out)
{
    offset_args *p = out;
    double x;
    p->delta = 1;
    p->round = 1;
    if (scad_arg_num(c->arg[OFFSET_R], &x)) {
        if (isfinite(x)) p->delta = x;
    } else if (scad_arg_num(c->arg[OFFSET_DELTA], &x)) {
        if (isfinite(x)) p->delta = x;
        p->round = 0;
        p->chamfer = scad_value_truthy(c->arg[OFFSET_CHAMFER]);
    }
    p->f = scad_facets_read(c);
}

static int offset_print(scad_call *c, const void *args, scad_buf *b)
{
    const offset_args *p = args;
    (void)c;
    scad_buf_puts(b, p->round ? "offset(r = " : "offset(delta = ");
    scad_print_g(b, p->delta);
    if (!p->round) {
        scad_buf_puts(b, ", chamfer = ");
        scad_print_bool(b, p->chamfer);
    }
    scad_print_facets(b, p->f, ", ", ")");
    return 1;
}

static scad_geom *offset_build(scad_call *c, const void *args)
{
    const offset_args *p = args;
    scad_eval *ev = c->ev;
    const scad_stmt *st = c->st;
    const scad_state *state = c->state;
    scad_geom *kids = scad_call_children(c, NULL);
    double delta = p->delta;
    int join = p->round ? SCAD_JOIN_ROUND : p->chamfer ? SCAD_JOIN_SQUARE : SCAD_JOIN_MITER;
    if (!kids) return NULL;
    const scad_services *s = ev->services;
    if (!s->paths_offset || !s->paths_clip) {
        scad_eval_error(ev, st->loc, "offset() is not available here (no polygon service)");
        return NULL;
    }
    csg_affine inv;
    if (csg_affine_invert(state->xf, inv) != 0) return NULL;
    scad_facet_params f = p->f;
    scad_paths in;
    if (scad_flatten_2d(ev, kids, inv, f, st->loc, "offset", &in) != 0) return NULL;
    if (in.npaths == 0) return NULL;
    double n = scad_fragments(fabs(delta), f);
    double tol = fabs(delta) * (1 - iv_cos_degrees(180 / n));
    scad_paths out = {NULL, NULL, 0};
    char err[256];
    scad_geom *g = NULL;
    if (s->paths_offset(s->ud, &in, delta, join, 1000000.0, tol, &out, err, sizeof err) != 0)
        scad_eval_error(ev, st->loc, "offset(): %s", err);
    else
        g = scad_region_geom(ev, &out, state);
    scad_paths_free(&in);
    scad_paths_free(&out);
    return g;
}

static const char *const offset_params[] = {"r", "delta", "chamfer", NULL};
static const scad_module_def offset = {"offset",    offset_params, 1,           sizeof(offset_args),
                                       offset_read, offset_print,  offset_build};

/* ---- projection ------------------------------------------------------------------ */

/* The 3D leaves of g as a csg tree in the frame local_from_world (NULL when
 * there are none or out of memory: *oom says which). */
static csg_node *local_tree(const scad_geom *g, const csg_affine lfw, int *oom)
{
    if (!g || *oom) return NULL;
    if (g->is_leaf) {
        if (scad_geom_is_flat(g)) return NULL;
        csg_affine t;
        csg_affine_mul(lfw, g->xf, t);
        csg_node *n = csg_node_shape(&g->shape, t, &g->mat);
        if (!n) *oom = 1;
        return n;
    }
    csg_node *n = csg_node_op(g->op);
    if (!n) {
        *oom = 1;
        return NULL;
    }
    for (int i = 0; i < g->n; i++) {
        csg_node *k = local_tree(g->kids[i], lfw, oom);
        if (k && csg_node_add(n, k)) *oom = 1;
    }
    return n;
}

/* A growing set of paths. */
typedef struct pathbuf {
    scad_paths p;
    int npts, cappts, cappaths;
    int oom;
} pathbuf;

static void pb_add(pathbuf *b, const double (*q)[2], int n)
{
    if (b->oom) return;
    if (b->npts + n > b->cappts) {
        int cap = b->cappts ? 2 * b->cappts : 1024;
        while (cap < b->npts + n)
            cap *= 2;
        double(*v)[2] = realloc(b->p.pts, (size_t)cap * sizeof *v);
        if (!v) {
            b->oom = 1;
            return;
        }
        b->p.pts = v;
        b->cappts = cap;
    }
    if (b->p.npaths + 2 > b->cappaths) {
        int cap = b->cappaths ? 2 * b->cappaths : 256;
        int *v = realloc(b->p.start, (size_t)cap * sizeof *v);
        if (!v) {
            b->oom = 1;
            return;
        }
        b->p.start = v;
        b->cappaths = cap;
    }
    memcpy(b->p.pts + b->npts, q, (size_t)n * sizeof *q);
    b->p.start[b->p.npaths] = b->npts;
    b->npts += n;
    b->p.npaths++;
    b->p.start[b->p.npaths] = b->npts;
}

enum { ROWS = 1024 };

/* One row of a section or shadow: its spans along x at one height y. */
typedef struct row {
    double *x; /* 2 per span: start, end */
    int n, cap;
} row;

static int row_add(row *r, double x0, double x1)
{
    if (r->n * 2 + 2 > r->cap) {
        int cap = r->cap ? 2 * r->cap : 16;
        double *v = realloc(r->x, (size_t)cap * sizeof *v);
        if (!v) return -1;
        r->x = v;
        r->cap = cap;
    }
    r->x[2 * r->n] = x0;
    r->x[2 * r->n + 1] = x1;
    r->n++;
    return 0;
}

static int overlaps(const row *a, const row *b)
{
    if (a->n != b->n) return 0;
    for (int k = 0; k < a->n; k++)
        if (!(a->x[2 * k] < b->x[2 * k + 1] && b->x[2 * k] < a->x[2 * k + 1])) return 0;
    return 1;
}

/* Rows j at y = y0 + (j + ½)·h into trapezoids: a row is joined span by
 * span to the next when both have the same number of spans, each
 * overlapping its partner; otherwise each reaches half a row that way. */
static void rows_to_paths(const row *rows, double y0, double h, pathbuf *b)
{
    for (int j = 0; j < ROWS; j++) {
        double y = y0 + (j + 0.5) * h;
        const row *r = &rows[j];
        int up = j + 1 < ROWS && overlaps(r, &rows[j + 1]);
        int down = j > 0 && overlaps(r, &rows[j - 1]);
        for (int k = 0; k < r->n; k++) {
            double x0 = r->x[2 * k], x1 = r->x[2 * k + 1];
            if (!down) {
                double q[4][2] = {{x0, y - h / 2}, {x1, y - h / 2}, {x1, y}, {x0, y}};
                pb_add(b, (const double(*)[2])q, 4);
            }
            if (up) {
                const row *u = &rows[j + 1];
                double q[4][2] = {{x0, y}, {x1, y}, {u->x[2 * k + 1], y + h}, {u->x[2 * k], y + h}};
                pb_add(b, (const double(*)[2])q, 4);
            } else {
                double q[4][2] = {{x0, y}, {x1, y}, {x1, y + h / 2}, {x0, y + h / 2}};
                pb_add(b, (const double(*)[2])q, 4);
            }
        }
    }
}

static int cmp_span(const void *a, const void *b)
{
    const double *p = a, *q = b;
    return (p[0] > q[0]) - (p[0] < q[0]);
}

/* Sort a row's spans and merge the overlapping ones. */
static void row_merge(row *r)
{
    if (r->n < 2) return;
    qsort(r->x, (size_t)r->n, 2 * sizeof *r->x, cmp_span);
    int m = 0;
    for (int k = 1; k < r->n; k++) {
        if (r->x[2 * k] <= r->x[2 * m + 1]) {
            r->x[2 * m + 1] = fmax(r->x[2 * m + 1], r->x[2 * k + 1]);
        } else {
            m++;
            r->x[2 * m] = r->x[2 * k];
            r->x[2 * m + 1] = r->x[2 * k + 1];
        }
    }
    r->n = m + 1;
}

static void rows_free(row *rows)
{
    if (!rows) return;
    for (int j = 0; j < ROWS; j++)
        free(rows[j].x);
    free(rows);
}

/* cut = false: the shadow of the mesh of the tree — in each row, the union
 * of the triangles' cuts by the line y = row height. */
static int shadow(scad_eval *ev, csg_node *root, pathbuf *b, char *err, size_t errlen)
{
    const scad_services *s = ev->services;
    float *v = NULL;
    int32_t *t = NULL;
    int nv = 0, nt = 0;
    if (s->mesh_tree(s->ud, root, 0, &v, &nv, &t, &nt, err, errlen) != 0) return -1;
    double ylo = INFINITY, yhi = -INFINITY;
    for (int i = 0; i < nv; i++) {
        ylo = fmin(ylo, v[3 * i + 1]);
        yhi = fmax(yhi, v[3 * i + 1]);
    }
    row *rows = nt > 0 && yhi > ylo ? calloc(ROWS, sizeof *rows) : NULL;
    int rc = 0;
    if (rows) {
        double h = (yhi - ylo) / ROWS;
        for (int i = 0; i < nt && rc == 0; i++) {
            const float *p[3] = {v + 3 * t[3 * i], v + 3 * t[3 * i + 1], v + 3 * t[3 * i + 2]};
            double a = fmin(p[0][1], fmin(p[1][1], p[2][1]));
            double c = fmax(p[0][1], fmax(p[1][1], p[2][1]));
            int j0 = (int)ceil((a - ylo) / h - 0.5), j1 = (int)floor((c - ylo) / h - 0.5);
            for (int j = j0 < 0 ? 0 : j0; j <= j1 && j < ROWS; j++) {
                double y = ylo + (j + 0.5) * h, x0 = INFINITY, x1 = -INFINITY;
                for (int e = 0; e < 3; e++) {
                    const float *u = p[e], *w = p[(e + 1) % 3];
                    if ((u[1] <= y && w[1] >= y) || (u[1] >= y && w[1] <= y)) {
                        double x =
                            u[1] == w[1] ? u[0] : u[0] + (y - u[1]) / (w[1] - u[1]) * (w[0] - u[0]);
                        double xx = u[1] == w[1] ? w[0] : x;
                        x0 = fmin(x0, fmin(x, xx));
                        x1 = fmax(x1, fmax(x, xx));
                    }
                }
                if (x0 < x1 && row_add(&rows[j], x0, x1) != 0) rc = -1;
            }
        }
        for (int j = 0; j < ROWS; j++)
            row_merge(&rows[j]);
        if (rc == 0) rows_to_paths(rows, ylo, h, b);
    } else if (nt > 0 && yhi > ylo) {
        rc = -1;
    }
    if (rc != 0) snprintf(err, errlen, "out of memory");
    rows_free(rows);
    free(v);
    free(t);
    return rc;
}

/* cut = true: the section by z = 0 from rays in that plane. */
static int section(csg_node *root, pathbuf *b, char *err, size_t errlen)
{
    csg_scene *sc = csg_scene_new(&root, 1, err, errlen);
    if (!sc) return -1;
    double lo[3], hi[3];
    if (csg_scene_bounds(sc, 0, lo, hi) != 0 || !(lo[2] <= 0 && hi[2] >= 0)) {
        csg_scene_free(sc);
        return 0;
    }
    if (!isfinite(lo[0]) || !isfinite(hi[0]) || !isfinite(lo[1]) || !isfinite(hi[1])) {
        csg_scene_free(sc);
        snprintf(err, errlen, "the solid is unbounded");
        return -1;
    }
    iv_arena *arena = iv_arena_new(0);
    row *rows = calloc(ROWS, sizeof *rows);
    int rc = arena && rows ? 0 : -1;
    double h = (hi[1] - lo[1]) / ROWS, margin = 1 + (hi[0] - lo[0]);
    for (int j = 0; j < ROWS && rc == 0; j++) {
        double o[3] = {lo[0] - margin, lo[1] + (j + 0.5) * h, 0}, d[3] = {1, 0, 0};
        iv_list l;
        iv_arena_reset(arena);
        if (csg_trace(sc, 0, o, d, 0, INFINITY, arena, &l) != 0) rc = -1;
        for (int k = 0; rc == 0 && k < l.n; k++)
            rc = row_add(&rows[j], o[0] + l.v[k].enter.t, o[0] + l.v[k].exit.t);
    }
    if (rc == 0)
        rows_to_paths(rows, lo[1], h, b);
    else
        snprintf(err, errlen, "out of memory");
    rows_free(rows);
    if (arena) iv_arena_free(arena);
    csg_scene_free(sc);
    return rc;
}

typedef struct projection_args {
    int cut, convexity;
} projection_args;

static void projection_read(scad_call *c, void *out)
{
    projection_args *p = out;
    p->cut = scad_arg_bool(c->arg[0], 0);
    p->convexity = scad_arg_int(c->arg[1], 0);
}

static int projection_print(scad_call *c, const void *args, scad_buf *b)
{
    const projection_args *p = args;
    (void)c;
    scad_buf_puts(b, "projection(cut = ");
    scad_print_bool(b, p->cut);
    scad_buf_printf(b, ", convexity = %d)", p->convexity);
    return 1;
}

static scad_geom *projection_build(scad_call *c, const void *args)
{
    scad_eval *ev = c->ev;
    const scad_stmt *st = c->st;
    const scad_state *state = c->state;
    scad_geom *kids = scad_call_children(c, NULL);
    if (!kids || !(scad_geom_dims(kids) & 2)) return NULL;
    int cut = ((const projection_args *)args)->cut;
    const scad_services *s = ev->services;
    if (!s->paths_clip || (!cut && !s->mesh_tree)) {
        scad_eval_error(ev, st->loc,
                        "projection() is not available here (no meshing or polygon service)");
        return NULL;
    }
    csg_affine inv;
    if (csg_affine_invert(state->xf, inv) != 0) return NULL;
    int oom = 0;
    csg_node *root = local_tree(kids, inv, &oom);
    if (oom) {
        csg_node_free(root);
        scad_eval_error(ev, st->loc, "projection(): out of memory");
        return NULL;
    }
    pathbuf b;
    memset(&b, 0, sizeof b);
    char err[256] = "out of memory";
    int rc = cut ? section(root, &b, err, sizeof err) : shadow(ev, root, &b, err, sizeof err);
    scad_geom *g = NULL;
    if (rc != 0 || b.oom) {
        scad_eval_error(ev, st->loc, "projection(): %s", err);
    } else if (b.p.npaths > 0) {
        scad_paths none = {NULL, NULL, 0}, out = {NULL, NULL, 0};
        if (s->paths_clip(s->ud, CSG_OP_UNION, &b.p, 0, &none, 0, &out, err, sizeof err) != 0)
            scad_eval_error(ev, st->loc, "projection(): %s", err);
        else
            g = scad_region_geom(ev, &out, state);
        scad_paths_free(&out);
    }
    scad_paths_free(&b.p);
    return g;
}

static const char *const projection_params[] = {"cut", "convexity", NULL};
static const scad_module_def projection = {
    "projection",     projection_params, 1, sizeof(projection_args), projection_read,
    projection_print, projection_build};

const scad_module_def *const scad_ops2d_modules[] = {&offset, &projection, NULL};
