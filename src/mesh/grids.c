/*
 * grids.c — which grids sample a model: mesh_dexels_new.
 *
 * With a spacing given (mesh_options.h > 0) every far-apart part of the
 * model (pieces.c) is cast on a grid of that spacing.  The default spacing
 * follows what is there to sample:
 *
 *   - Each part's own size: its longest side / cells_per_side, so a small
 *     part far from a large one is not sampled by the large one's cells.
 *     Parts on grids of their own may not spend more than
 *     MESH_PARTS_CROSSINGS together (a pilot of PILOT_CELLS per side
 *     predicts each one's crossings, which grow as 1/h²); over that, the
 *     model is sampled on one grid, its longest side / cells_per_side.
 *   - Thin walls and gaps: where those thinner than MESH_REFINE_CELLS cells
 *     hold more than MESH_REFINE_SHARE of a part's volume, and are not only
 *     a taper (only_a_taper), the part is cast
 *     again up to MESH_REFINE_MAX times finer (a whole factor), while its
 *     share of MESH_REFINE_CROSSINGS allows, in up to MESH_REFINE_ROUNDS
 *     rounds (a finer grid can find thin parts a coarser one missed).
 */
#include "dexels.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The most crossings that far-apart parts may have on grids of their own
 * (before refinement): about 4 times what a 128-cell grid finds on a plain
 * part.  More, and the model is sampled on one grid. */
#define MESH_PARTS_CROSSINGS (1 << 18)
/* The cells per side of the pilot sampling that predicts the crossings. */
#define PILOT_CELLS 32.0

/* Crossings of a sampling (all its grids). */
static long long crossings(const mesh_dexels *d)
{
    mesh_measure m;
    mesh_dexels_measure(d, &m);
    return m.crossings;
}

/* The share of the volume that walls and gaps thinner than w hold in *d. */
static double thin_share(const mesh_dexels *d, double w, double volume)
{
    mesh_thin t;
    mesh_dexels_thin(d, w, &t);
    return volume > 0 ? t.volume / volume : 0;
}

/* Whether the thin walls and gaps of *d are only a taper, with shares s[k]
 * of the volume below 4, 2, 1 and 1/2 cells.  A taper (the thin edge of a
 * wedge, a pyramid's apex, a cone's tip) has walls of every thickness down
 * to none, and the share below w falls as w² or faster (w³ at a tip): what
 * a grid loses there shrinks with the spacing as any other sampling error
 * does, and no finer grid resolves it all.  Walls or gaps of one thickness
 * (a plate or a slot thinner than the grid), which a grid is either fine
 * enough for or loses whole, keep the share steady over a halving of w, or
 * in a mixture make it fall more slowly than TAPER_FALL over the three
 * halvings from 4 cells to 1/2. */
#define TAPER_FALL 30.0 /* 8^1.65 */
static int only_a_taper(const double s[4])
{
    for (int k = 0; k < 2; k++)
        if (s[k + 1] > MESH_REFINE_SHARE && s[k + 1] >= 0.5 * s[k]) return 0;
    return !(s[3] * TAPER_FALL > s[0]);
}

/* How much finer than h0 the thin walls and gaps of *d ask for: 1 when they
 * hold too little of the volume to matter, or are only a taper, else the
 * whole factor that puts MESH_REFINE_CELLS cells across the thinnest that
 * hold MESH_REFINE_SHARE of it, within MESH_REFINE_MAX and `budget`
 * crossings. */
static int refine_factor(const mesh_dexels *d, double h0, double budget)
{
    mesh_measure m;
    mesh_dexels_measure(d, &m);
    double limit = MESH_REFINE_CELLS * d->h, s[4];
    for (int k = 0; k < 4; k++)
        s[k] = thin_share(d, limit / (1 << k), m.volume);
    if (!(s[0] > MESH_REFINE_SHARE) || only_a_taper(s)) return 1;
    double lo = 0, hi = limit; /* the thinnest that hold the share: bisected */
    for (int i = 0; i < 16; i++) {
        double mid = 0.5 * (lo + hi);
        if (thin_share(d, mid, m.volume) > MESH_REFINE_SHARE)
            hi = mid;
        else
            lo = mid;
    }
    double want = h0 * MESH_REFINE_CELLS / fmax(lo, 1e-9 * limit);
    double room = h0 / d->h * sqrt(budget / (double)(m.crossings + 1));
    double k = floor(fmin(ceil(want), fmin(room, MESH_REFINE_MAX)));
    return k > 1 ? (int)k : 1;
}

/* Cast one part at spacing h, refined for thin parts within `budget`
 * crossings when `refine`; 0, or an error code with a message. */
static int cast_part(const csg_scene *s, const mesh_options *o, const mesh_piece *p, double h,
                     int refine, double budget, mesh_dexels **out, char *err, size_t errlen)
{
    *out = NULL;
    if (!(h > 0) || !isfinite(h)) return 0; /* a point: nothing to sample */
    mesh_dexels *d;
    int split = 0;
    int rc = mesh_dexels_cast(s, o, h, p->lo, p->hi, &d, err, errlen);
    if (rc == 0 && o->tolerance > 0 && !o->contour_all && p->prim >= 0 &&
        mesh_exact_faces(s, p->prim)) {
        d->exact = p->prim; /* meshed as its own faces: no finer grid needed */
        refine = 0;
    } else if (rc == 0 && o->tolerance > 0 && !o->contour_all) {
        /* (out of memory there, the BSP's pools the likely cause: the
         * contour, which needs less, is tried instead) */
        if (mesh_polyhedral(d, p->lo, p->hi, &d->poly) == 1) {
            d->exact = MESH_POLYHEDRAL; /* the exact boundary of its booleans */
            refine = 0;
        } else if (p->prim < 0) {
            /* its plane-faced clusters exact, the rest contoured */
            split = mesh_polyhedral_clusters(d, p->lo, p->hi) == 1;
        }
    }
    for (int round = 0, k = 1; rc == 0 && refine && round < MESH_REFINE_ROUNDS; round++) {
        int f = refine_factor(d, h, budget);
        if (f <= k) break;
        mesh_dexels *finer;
        rc = mesh_dexels_cast(s, o, (double)(float)(h / f), p->lo, p->hi, &finer, err, errlen);
        if (rc == RAYSCAD_ERROR_CELLS) {
            rc = 0; /* keep the coarser one */
            break;
        }
        if (rc != 0) break;
        if (split && mesh_polyhedral_clusters(finer, p->lo, p->hi) != 1) {
            mesh_dexels_free(finer); /* its clusters did not split: the coarser one stays */
            break;
        }
        mesh_dexels_free(d);
        d = finer;
        k = f;
    }
    if (rc != 0) {
        mesh_dexels_free(d);
        return rc;
    }
    *out = d;
    return 0;
}

/* Predict each part's crossings at spacing h[i] into pred[i], from a pilot
 * of PILOT_CELLS per side (they grow as 1/h²); 0 or an error code. */
static int predict(const csg_scene *s, const mesh_options *o, const mesh_piece *p, int np,
                   const double *h, double *pred, char *err, size_t errlen)
{
    mesh_options pilot = *o;
    pilot.max_cells = 0;
    for (int i = 0; i < np; i++) {
        double hp = fmax(mesh_piece_longest(&p[i]) / PILOT_CELLS, h[i]);
        mesh_dexels *d;
        int rc = mesh_dexels_cast(s, &pilot, hp, p[i].lo, p[i].hi, &d, err, errlen);
        if (rc != 0) return rc;
        pred[i] = (double)crossings(d) * (hp / h[i]) * (hp / h[i]);
        mesh_dexels_free(d);
    }
    return 0;
}

/* The default spacings of the parts (see the top of the file), and each
 * one's predicted crossings; 0 or an error code. */
static int default_spacings(const csg_scene *s, const mesh_options *o, mesh_piece *p, int *np,
                            const double lo[3], const double hi[3], double *h, double *pred,
                            char *err, size_t errlen)
{
    int cells = o->cells_per_side > 0 ? o->cells_per_side : 128;
    /* Rounded to float precision: that drops the 1e-9 relative padding
     * csg_scene_bounds adds, so a model whose longest side is 8 gets
     * h = 8/128 exactly, and its faces lie midway between nodes. */
    for (int i = 0; i < *np; i++)
        h[i] = (double)(float)(mesh_piece_longest(&p[i]) / cells);
    pred[0] = 1;
    if (*np == 1) return 0;
    int rc = predict(s, o, p, *np, h, pred, err, errlen);
    if (rc != 0) return rc;
    double total = 0;
    for (int i = 0; i < *np; i++)
        total += pred[i];
    if (total > MESH_PARTS_CROSSINGS) { /* too many parts: one grid */
        *np = 1;
        p[0].prim = -1;
        for (int a = 0; a < 3; a++) {
            p[0].lo[a] = lo[a];
            p[0].hi[a] = hi[a];
        }
        h[0] = (double)(float)(mesh_piece_longest(&p[0]) / cells);
        pred[0] = 1;
    }
    return 0;
}

int mesh_dexels_new(const csg_scene *s, const mesh_options *opt, mesh_dexels **out, char *err,
                    size_t errlen)
{
    mesh_options def;
    mesh_options_default(&def);
    const mesh_options *o = opt ? opt : &def;
    *out = NULL;
    double lo[3], hi[3];
    int np = 0, rc = 0;
    mesh_piece *p = NULL;
    if (o->root >= 0 && o->root < csg_scene_root_count(s) &&
        csg_scene_bounds(s, o->root, lo, hi) == 0) {
        for (int a = 0; a < 3; a++)
            if (!isfinite(lo[a]) || !isfinite(hi[a])) {
                snprintf(err, errlen, "the model is unbounded (infinite along %c); cannot mesh it",
                         "xyz"[a]);
                return -1;
            }
        np = mesh_pieces(s, o->root, o->h, o->cells_per_side > 0 ? o->cells_per_side : 128, &p);
    }
    double *h = np > 0 ? malloc(2 * (size_t)np * sizeof *h) : NULL;
    if (np < 0 || (np > 0 && !h)) {
        free(p);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    double *pred = h + np, total = 0;
    int dflt = !(o->h > 0);
    if (dflt && np > 0) rc = default_spacings(s, o, p, &np, lo, hi, h, pred, err, errlen);
    for (int i = 0; i < np; i++) {
        if (!dflt) h[i] = o->h;
        total += dflt ? pred[i] : 1;
    }
    mesh_dexels *head = NULL, **tail = &head;
    for (int i = 0; i < np && rc == 0; i++) {
        double budget = MESH_REFINE_CROSSINGS * (pred[i] / total);
        rc = cast_part(s, o, &p[i], h[i], dflt && o->resolve_thin, budget, tail, err, errlen);
        while (*tail) /* (a part split into clusters is two grids) */
            tail = &(*tail)->next;
    }
    free(p);
    free(h);
    if (rc != 0) {
        mesh_dexels_free(head);
        return rc;
    }
    if (!head && (head = calloc(1, sizeof *head)) != NULL) head->exact = -1; /* empty: no rays */
    if (!head) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    *out = head;
    return 0;
}
