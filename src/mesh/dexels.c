/*
 * dexels.c — casting the three ray families (tri-dexels) and measuring the
 * solid from them.
 *
 * The grid: node (i, j, k) sits at org + h·(i, j, k).  org is the root's
 * bounds minus (1 + PAD_FRAC)·h on every axis and the last node lies at least
 * h beyond the upper bound, so every boundary node is outside the solid and
 * every crossing lies strictly inside the grid.  PAD_FRAC = 1/2 puts the
 * lower bound, and every face at a whole number of cells from it (with the
 * default h = longest side / 128: halves, quarters… of the model), midway
 * between two rows of nodes: no crossing falls on a node there, and a box
 * whose sides are multiples of h is measured exactly, since each ray then
 * stands for exactly the h × h square around it.
 *
 * Casting: rays are handed out a row at a time (n[u] + 1 parallel,
 * neighbouring rays, which touch the same subtrees) to worker threads.  Each
 * worker owns an iv_arena, reset after every ray, and appends the crossings
 * of its rows to its own growing buffer; at the end the rows are copied in
 * order into one array per family with a prefix sum of per-ray counts as the
 * offsets (CSR).  Memory is O(crossings + rays), i.e. O(surface / h²) plus
 * O(n²) offsets.
 *
 * Measurement integrates along the rays: a ray family is a midpoint rule on
 * the grid of ray positions for ∫∫ L(u, v) du dv, where L is the total length
 * of the ray's intervals, so each family gives the volume to O(h^1.5) for
 * smooth boundaries (the integrand has square-root edges at silhouettes) and
 * exactly for boxes whose faces lie between rays.  The three families'
 * estimates are averaged, which cancels part of the error.
 *
 * Patches: each crossing names the face of the primitive it lies on
 * (mesh_patch_of), and after casting, a face whose crossings all share one
 * normal is marked a plane (mark_planar).  Contouring then knows two
 * crossings on two planes lie either side of a sharp edge at any angle: a
 * polygon's facets at $fn = 30 meet at 12°, under the feature angle that
 * tells a curved surface's spread of normals from an edge.
 *
 * The thin-feature scan (mesh_dexels_thin) reads the same chords: two
 * consecutive crossings of a ray whose normals are nearly opposite bound a
 * wall (or a gap) whose thickness across it is the chord length times the
 * normals' component along the ray.
 */
#include "dexels.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define PAD_FRAC 0.5
#define MAX_CELLS 65536
#define MAX_RAYS ((size_t)1 << 31)

void mesh_options_default(mesh_options *o)
{
    o->h = 0;
    o->cells_per_side = 128;
    o->threads = 0;
    o->root = 0;
    o->feature_angle_deg = 30;
    o->max_cells = 0;
    o->max_intervals = 0;
    o->resolve_thin = 1;
    o->tolerance = 0;
    o->simplify_max_triangles = 0;
    o->simplify_max_triangles_smooth = 0;
    o->contour_all = 0;
    o->progress = NULL;
    o->progress_ud = NULL;
}

void mesh_dexels_free(mesh_dexels *d)
{
    while (d) {
        mesh_dexels *next = d->next;
        for (int a = 0; a < 3; a++) {
            free(d->off[a]);
            free(d->hit[a]);
        }
        mesh_palette_free(&d->pal);
        mesh_polyhedron_free(&d->poly);
        free(d->patch_key);
        free(d->patch_curved);
        free(d);
        d = next;
    }
}

void mesh_dexels_grid(const mesh_dexels *d, double *h, double origin[3], int n[3])
{
    *h = d->h;
    for (const mesh_dexels *e = d->next; e; e = e->next)
        *h = fmax(*h, e->h);
    for (int a = 0; a < 3; a++) {
        origin[a] = d->org[a];
        n[a] = d->n[a];
    }
}

/* ---- casting ------------------------------------------------------------ */

typedef struct row_src {
    int worker;
    size_t start; /* index of the row's first crossing in that worker's buffer */
} row_src;

typedef struct worker {
    struct job *job;
    int id;
    iv_arena *arena;
    mesh_hit *buf;
    size_t n, cap;
    int failed; /* an iv_arena_failure_kind (OUT_OF_MEMORY also for buf); 0: none */
} worker;

typedef struct job {
    const csg_scene *s;
    int root;
    mesh_dexels *d;
    int axis, u, v;
    int nrows, rowlen;
    size_t *count; /* per ray */
    row_src *rows;
    pthread_mutex_t lock;
    int next_row;
    int stop;              /* set when a worker fails */
    const mesh_options *o; /* its progress callback, called from worker 0 */
} job;

static int take_row(job *j)
{
    pthread_mutex_lock(&j->lock);
    int r = j->stop || j->next_row >= j->nrows ? -1 : j->next_row++;
    pthread_mutex_unlock(&j->lock);
    return r;
}

static int reserve(worker *w, size_t more)
{
    if (w->n + more <= w->cap) return 0;
    size_t cap = w->cap ? w->cap : 1024;
    while (cap < w->n + more)
        cap *= 2;
    mesh_hit *b = realloc(w->buf, cap * sizeof *b);
    if (!b) return -1;
    w->buf = b;
    w->cap = cap;
    return 0;
}

/* Cast one row of rays (all iu for one iv) and append their crossings. */
static int cast_row(worker *w, int iv)
{
    job *j = w->job;
    const mesh_dexels *d = j->d;
    int a = j->axis;
    double o[3], dir[3] = {0, 0, 0};
    dir[a] = 1;
    o[a] = d->org[a];
    o[j->v] = d->org[j->v] + iv * d->h;
    double tmax = d->n[a] * d->h;
    for (int iu = 0; iu < j->rowlen; iu++) {
        o[j->u] = d->org[j->u] + iu * d->h;
        iv_arena_reset(w->arena);
        iv_list l;
        if (csg_trace(j->s, j->root, o, dir, 0, tmax, w->arena, &l) != 0) return -1;
        if (reserve(w, 2 * (size_t)l.n) != 0) return -1;
        for (int k = 0; k < l.n; k++) {
            for (int e = 0; e < 2; e++) {
                const iv_bound *b = e == 0 ? &l.v[k].enter : &l.v[k].exit;
                double nn[3];
                csg_scene_normal(j->s, b, o, dir, nn);
                mesh_hit *hp = &w->buf[w->n++];
                hp->t = b->t;
                hp->n[0] = (float)nn[0];
                hp->n[1] = (float)nn[1];
                hp->n[2] = (float)nn[2];
                hp->patch = mesh_patch_of(b->prim, b->part);
                hp->enter = e == 0;
                hp->color = mesh_palette_of(&d->pal, b->prim);
            }
        }
        j->count[(size_t)iv * j->rowlen + iu] = 2 * (size_t)l.n;
    }
    return 0;
}

static void *work(void *arg)
{
    worker *w = arg;
    job *j = w->job;
    int r;
    while ((r = take_row(j)) >= 0) {
        if (w->id == 0 && j->o->progress) /* the calling thread's worker */
            j->o->progress(j->o->progress_ud, "sampling", (j->axis + (double)r / j->nrows) / 3);
        j->rows[r].worker = w->id;
        j->rows[r].start = w->n;
        if (cast_row(w, r) != 0) {
            w->failed = iv_arena_failure(w->arena) == IV_ARENA_LIST_TOO_LONG
                            ? IV_ARENA_LIST_TOO_LONG
                            : IV_ARENA_OUT_OF_MEMORY;
            pthread_mutex_lock(&j->lock);
            j->stop = 1;
            pthread_mutex_unlock(&j->lock);
            break;
        }
    }
    return NULL;
}

static int cast_family(const csg_scene *s, const mesh_options *o, mesh_dexels *d, int a,
                       int nthreads, char *err, size_t errlen)
{
    int root = o->root, max_intervals = o->max_intervals;
    job j;
    memset(&j, 0, sizeof j);
    j.o = o;
    j.s = s;
    j.root = root;
    j.d = d;
    j.axis = a;
    mesh_axes_other(a, &j.u, &j.v);
    j.rowlen = d->n[j.u] + 1;
    j.nrows = d->n[j.v] + 1;
    size_t nrays = (size_t)j.rowlen * (size_t)j.nrows;
    j.count = calloc(nrays, sizeof *j.count);
    j.rows = calloc((size_t)j.nrows, sizeof *j.rows);
    worker *ws = calloc((size_t)nthreads, sizeof *ws);
    pthread_t *th = calloc((size_t)nthreads, sizeof *th);
    int rc = -1, started = 0;
    if (!j.count || !j.rows || !ws || !th || pthread_mutex_init(&j.lock, NULL) != 0) {
        snprintf(err, errlen, "out of memory casting rays");
        free(j.count);
        free(j.rows);
        free(ws);
        free(th);
        return -1;
    }
    for (int t = 0; t < nthreads; t++) {
        ws[t].job = &j;
        ws[t].id = t;
        ws[t].arena = iv_arena_new(0);
        if (ws[t].arena)
            iv_arena_set_list_limit(ws[t].arena, max_intervals);
        else
            ws[t].failed = IV_ARENA_OUT_OF_MEMORY;
    }
    for (int t = 0; t < nthreads; t++)
        if (ws[t].failed) j.stop = 1;
    /* Worker 0 runs on this thread. */
    for (int t = 1; t < nthreads && !j.stop; t++) {
        if (pthread_create(&th[t], NULL, work, &ws[t]) != 0) break;
        started = t;
    }
    if (!j.stop) work(&ws[0]);
    for (int t = 1; t <= started; t++)
        pthread_join(th[t], NULL);
    pthread_mutex_destroy(&j.lock);

    int failed = j.stop, too_long = 0;
    for (int t = 0; t < nthreads; t++) {
        failed |= ws[t].failed != 0;
        too_long |= ws[t].failed == IV_ARENA_LIST_TOO_LONG;
    }
    if (too_long) {
        snprintf(err, errlen, "a ray's interval list holds more than %d intervals",
                 max_intervals > 0 ? max_intervals : IV_LIST_LIMIT_DEFAULT);
        rc = RAYSCAD_ERROR_INTERVALS;
        goto done;
    }
    if (failed) {
        snprintf(err, errlen, "out of memory casting rays");
        goto done;
    }
    d->off[a] = malloc((nrays + 1) * sizeof *d->off[a]);
    if (!d->off[a]) {
        snprintf(err, errlen, "out of memory casting rays");
        goto done;
    }
    size_t total = 0;
    for (size_t r = 0; r < nrays; r++) {
        d->off[a][r] = total;
        total += j.count[r];
    }
    d->off[a][nrays] = total;
    d->nhit[a] = total;
    d->hit[a] = malloc((total ? total : 1) * sizeof *d->hit[a]);
    if (!d->hit[a]) {
        snprintf(err, errlen, "out of memory casting rays");
        goto done;
    }
    for (int r = 0; r < j.nrows; r++) {
        size_t first = (size_t)r * j.rowlen;
        size_t len = d->off[a][first + j.rowlen] - d->off[a][first];
        if (len)
            memcpy(d->hit[a] + d->off[a][first], ws[j.rows[r].worker].buf + j.rows[r].start,
                   len * sizeof(mesh_hit));
    }
    rc = 0;
done:
    for (int t = 0; t < nthreads; t++) {
        iv_arena_free(ws[t].arena);
        free(ws[t].buf);
    }
    free(ws);
    free(th);
    free(j.count);
    free(j.rows);
    return rc;
}

int mesh_thread_count(const mesh_options *o)
{
    int n = o ? o->threads : 0;
    if (n <= 0) {
        long c = sysconf(_SC_NPROCESSORS_ONLN);
        n = c > 0 ? (int)c : 1;
    }
    return n > 256 ? 256 : n;
}

/* The slot of patch k in an open-addressing set of cap slots. */
static size_t patch_slot(const uint32_t *key, size_t cap, uint32_t k)
{
    size_t p = mesh_hash_mix(k) & (cap - 1);
    while (key[p] && key[p] != k)
        p = (p + 1) & (cap - 1);
    return p;
}

/* Whether grid d has crossings of patch p (without the flag): 0 none, 1
 * all of one normal, 2 not. */
static int patch_in(const mesh_dexels *d, uint32_t p)
{
    if (!d->patch_key) return 0;
    size_t q = patch_slot(d->patch_key, d->patch_cap, p);
    return d->patch_key[q] != p ? 0 : d->patch_curved[q] ? 2 : 1;
}

uint32_t mesh_patch_flagged(const mesh_dexels *d, uint32_t p)
{
    p &= ~MESH_PATCH_PLANAR;
    int seen = 0;
    for (; d; d = d->next) { /* every grid of the sampling: each holds its part's patches */
        int k = patch_in(d, p);
        if (k == 2) return p;
        seen |= k;
    }
    return seen ? p | MESH_PATCH_PLANAR : p;
}

double mesh_dexels_h_at(const mesh_dexels *d, const double p[3])
{
    for (const mesh_dexels *g = d; g; g = g->next) {
        int in = 1;
        for (int a = 0; a < 3 && in; a++)
            in = p[a] >= g->org[a] - g->h && p[a] <= g->org[a] + (g->n[a] + 1) * g->h;
        if (in) return g->h;
    }
    return d->h;
}

/* The patches seen so far: an open-addressing table, kept at most half
 * full, of each patch's first normal and whether another differed. */
typedef struct patch_table {
    uint32_t *key; /* 0: empty */
    float (*n)[3];
    uint8_t *curved;
    size_t cap, used;
} patch_table;

static int table_alloc(patch_table *t, size_t cap)
{
    t->key = calloc(cap, sizeof *t->key);
    t->n = malloc(cap * sizeof *t->n);
    t->curved = calloc(cap, 1);
    t->cap = cap;
    t->used = 0;
    return t->key && t->n && t->curved ? 0 : -1;
}

static void table_free(patch_table *t)
{
    free(t->key);
    free(t->n);
    free(t->curved);
}

/* Note a crossing of patch k with normal n; 0 or -1. */
static int table_note(patch_table *t, uint32_t k, const float n[3])
{
    if (2 * (t->used + 1) > t->cap) {
        patch_table g;
        if (table_alloc(&g, 2 * t->cap) != 0) {
            table_free(&g);
            return -1;
        }
        for (size_t p = 0; p < t->cap; p++) {
            if (!t->key[p]) continue;
            size_t q = patch_slot(g.key, g.cap, t->key[p]);
            g.key[q] = t->key[p];
            memcpy(g.n[q], t->n[p], sizeof g.n[q]);
            g.curved[q] = t->curved[p];
            g.used++;
        }
        table_free(t);
        *t = g;
    }
    size_t p = patch_slot(t->key, t->cap, k);
    if (!t->key[p]) {
        t->key[p] = k;
        memcpy(t->n[p], n, sizeof t->n[p]);
        t->used++;
        return 0;
    }
    for (int c = 0; c < 3; c++)
        if (fabsf(t->n[p][c] - n[c]) > 1e-6f) t->curved[p] = 1;
    return 0;
}

/* Find the plane patches of d's crossings — those whose crossings all have
 * one normal, to float rounding — keeping the table in d, and flag their
 * crossings (MESH_PATCH_PLANAR); 0 or -1. */
static int mark_planar(mesh_dexels *d)
{
    patch_table t;
    int rc = table_alloc(&t, 1024);
    for (int a = 0; a < 3 && rc == 0; a++)
        for (size_t i = 0; i < d->nhit[a] && rc == 0; i++)
            rc = table_note(&t, d->hit[a][i].patch, d->hit[a][i].n);
    if (rc != 0) {
        table_free(&t);
        return -1;
    }
    free(t.n);
    d->patch_key = t.key;
    d->patch_curved = t.curved;
    d->patch_cap = t.cap;
    for (int a = 0; a < 3; a++)
        for (size_t i = 0; i < d->nhit[a]; i++) {
            uint32_t p = d->hit[a][i].patch & ~MESH_PATCH_PLANAR;
            d->hit[a][i].patch = patch_in(d, p) == 1 ? p | MESH_PATCH_PLANAR : p;
        }
    return 0;
}

int mesh_dexels_cast(const csg_scene *s, const mesh_options *o, double h, const double lo[3],
                     const double hi[3], mesh_dexels **out, char *err, size_t errlen)
{
    *out = NULL;
    mesh_dexels *d = calloc(1, sizeof *d);
    if (!d) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    d->h = h;
    d->scene = s;
    d->root = o->root;
    d->exact = -1;
    size_t rays = 1;
    double cells[3], total = 1;
    for (int a = 0; a < 3; a++) {
        d->org[a] = lo[a] - (1 + PAD_FRAC) * h;
        cells[a] = ceil((hi[a] - d->org[a]) / h) + 1;
        total *= cells[a];
    }
    /* The limit the caller chose comes first, so that it is the one named
     * for a grid that breaks both. */
    long long max_cells = o->max_cells > 0 ? o->max_cells : MESH_MAX_CELLS_DEFAULT;
    if (!(total <= (double)max_cells)) {
        snprintf(err, errlen,
                 "a grid of %.0f x %.0f x %.0f cells (spacing %g) is %.0f cells, more than %lld",
                 cells[0], cells[1], cells[2], h, total, max_cells);
        free(d);
        return RAYSCAD_ERROR_CELLS;
    }
    for (int a = 0; a < 3; a++) {
        if (!(cells[a] <= MAX_CELLS)) {
            snprintf(err, errlen, "grid of %.0f cells along %c is more than %d cells per side",
                     cells[a], "xyz"[a], MAX_CELLS);
            free(d);
            return -1;
        }
        d->n[a] = (int)cells[a];
    }
    for (int a = 0; a < 3; a++) {
        int u, v;
        mesh_axes_other(a, &u, &v);
        rays = (size_t)(d->n[u] + 1) * (size_t)(d->n[v] + 1);
        if (rays > MAX_RAYS) {
            snprintf(err, errlen, "grid needs more than 2^31 rays per family");
            free(d);
            return -1;
        }
    }
    if (mesh_palette_build(s, o->root, &d->pal) != 0) {
        snprintf(err, errlen, "out of memory");
        free(d);
        return -1;
    }
    int nt = mesh_thread_count(o);
    for (int a = 0; a < 3; a++) {
        int rc = cast_family(s, o, d, a, nt, err, errlen);
        if (rc != 0) {
            mesh_dexels_free(d);
            return rc;
        }
    }
    if (mark_planar(d) != 0) {
        snprintf(err, errlen, "out of memory casting rays");
        mesh_dexels_free(d);
        return -1;
    }
    *out = d;
    return 0;
}

/* ---- measuring ---------------------------------------------------------- */

static void measure_grid(const mesh_dexels *d, mesh_measure *m)
{
    memset(m, 0, sizeof *m);
    for (int a = 0; a < 3; a++) {
        m->lo[a] = INFINITY;
        m->hi[a] = -INFINITY;
    }
    if (!d->off[0]) return;
    double h = d->h, vol = 0, mom[3] = {0, 0, 0}, area = 0;
    long long crossings = 0;
    for (int a = 0; a < 3; a++) {
        int u, v;
        mesh_axes_other(a, &u, &v);
        int rowlen = d->n[u] + 1;
        double fvol = 0, fmom[3] = {0, 0, 0};
        for (int iv = 0; iv <= d->n[v]; iv++) {
            double cv = iv * h; /* relative to org */
            for (int iu = 0; iu < rowlen; iu++) {
                size_t r = (size_t)iv * rowlen + iu;
                const mesh_hit *hp = d->hit[a] + d->off[a][r];
                size_t nh = d->off[a][r + 1] - d->off[a][r];
                if (!nh) continue;
                double cu = iu * h, len = 0, ta = 0;
                for (size_t k = 0; k + 1 < nh; k += 2) {
                    double t0 = hp[k].t, t1 = hp[k + 1].t;
                    len += t1 - t0;
                    ta += 0.5 * (t1 * t1 - t0 * t0);
                }
                fvol += len;
                fmom[a] += ta;
                fmom[u] += cu * len;
                fmom[v] += cv * len;
                /* Bounds: the crossings are surface points; the ray's own
                 * position is inside the solid's extent on u and v. */
                double t0 = d->org[a] + hp[0].t, t1 = d->org[a] + hp[nh - 1].t;
                double pu = d->org[u] + cu, pv = d->org[v] + cv;
                if (t0 < m->lo[a]) m->lo[a] = t0;
                if (t1 > m->hi[a]) m->hi[a] = t1;
                if (pu < m->lo[u]) m->lo[u] = pu;
                if (pu > m->hi[u]) m->hi[u] = pu;
                if (pv < m->lo[v]) m->lo[v] = pv;
                if (pv > m->hi[v]) m->hi[v] = pv;
                for (size_t k = 0; k < nh; k++) {
                    double l1 = fabs(hp[k].n[0]) + fabs(hp[k].n[1]) + fabs(hp[k].n[2]);
                    /* A unit normal has 1 <= |n|₁ <= √3; guard a zero normal. */
                    area += 1.0 / (l1 >= 1e-6 ? l1 : 1.0);
                }
                crossings += (long long)nh;
            }
        }
        vol += fvol;
        for (int c = 0; c < 3; c++)
            mom[c] += fmom[c];
    }
    /* Each family's sums times h² estimate ∫dV and ∫x dV; average them. */
    m->volume = vol * h * h / 3;
    m->area = area * h * h;
    m->crossings = crossings;
    for (int c = 0; c < 3; c++)
        m->centroid[c] = vol > 0 ? d->org[c] + mom[c] / vol : 0;
}

void mesh_dexels_measure(const mesh_dexels *d, mesh_measure *m)
{
    measure_grid(d, m);
    double mom[3];
    for (int c = 0; c < 3; c++)
        mom[c] = m->centroid[c] * m->volume;
    for (d = d->next; d; d = d->next) {
        mesh_measure e;
        measure_grid(d, &e);
        m->volume += e.volume;
        m->area += e.area;
        m->crossings += e.crossings;
        for (int c = 0; c < 3; c++) {
            mom[c] += e.centroid[c] * e.volume;
            m->lo[c] = fmin(m->lo[c], e.lo[c]);
            m->hi[c] = fmax(m->hi[c], e.hi[c]);
        }
    }
    for (int c = 0; c < 3; c++)
        m->centroid[c] = m->volume > 0 ? mom[c] / m->volume : 0;
}

/* ---- thin features ------------------------------------------------------ */

static void thin_grid(const mesh_dexels *d, double thickness, mesh_thin *out)
{
    if (!d->off[0]) return;
    double h = d->h;
    if (!(thickness > 0)) thickness = h;
    for (int a = 0; a < 3; a++) {
        int u, v;
        mesh_axes_other(a, &u, &v);
        size_t rowlen = (size_t)d->n[u] + 1, rays = rowlen * ((size_t)d->n[v] + 1);
        for (size_t r = 0; r < rays; r++) {
            const mesh_hit *hp = d->hit[a] + d->off[a][r];
            size_t nh = d->off[a][r + 1] - d->off[a][r];
            for (size_t k = 0; k + 1 < nh; k++) {
                const float *n0 = hp[k].n, *n1 = hp[k + 1].n;
                double dot = (double)n0[0] * n1[0] + (double)n0[1] * n1[1] + (double)n0[2] * n1[2];
                if (!(dot < MESH_THIN_COS)) continue;
                double w = (hp[k + 1].t - hp[k].t) * 0.5 * (fabs(n0[a]) + fabs(n1[a]));
                if (!(w < thickness)) continue;
                /* Crossings alternate enter / exit from an enter, so an even
                 * k starts a span of solid and an odd k a gap. */
                int wall = (k & 1) == 0;
                double *best = wall ? &out->min_wall : &out->min_gap;
                double *at = wall ? out->wall_at : out->gap_at;
                if (wall)
                    out->walls++;
                else
                    out->gaps++;
                out->volume += (hp[k + 1].t - hp[k].t) * h * h;
                if (w < *best) {
                    *best = w;
                    *(wall ? &out->wall_h : &out->gap_h) = h;
                    at[a] = d->org[a] + 0.5 * (hp[k].t + hp[k + 1].t);
                    at[u] = d->org[u] + (double)(r % rowlen) * h;
                    at[v] = d->org[v] + (double)(r / rowlen) * h;
                }
            }
        }
    }
}

void mesh_dexels_thin(const mesh_dexels *d, double thickness, mesh_thin *out)
{
    memset(out, 0, sizeof *out);
    out->min_wall = out->min_gap = INFINITY;
    for (; d; d = d->next)
        if (d->exact == -1) thin_grid(d, thickness, out); /* its own faces lose nothing */
}
