/*
 * exact.c — volume, centre of mass, surface area and bounds from ray
 * queries, to a tolerance, without a grid (mesh_measure_exact).
 *
 * Rays along a direction d, oblique to every axis, through the points
 * (u, v) of a plane across it:
 *
 *   V = ∫∫ L(u, v) du dv       L: the length of solid along the ray
 *   ∫ p dV = ∫∫ ∫ p(t) dt du dv over the ray's intervals
 *   A = Σ_k ∫∫ Σ |n·d_k| du dv over the crossings, in three passes along
 *                              the three directions d_k of an orthonormal
 *                              frame
 *
 * (a crossing of normal n in pass k stands for du dv / |n·d_k| of surface;
 * weighed by (n·d_k)², which the three directions sum to |n|² = 1, it adds
 * |n·d_k| du dv.  That is smooth along a piece, since n·d_k keeps its sign
 * between events — it tells an entry from an exit — and vanishes at a
 * silhouette, where the 1 / |n·d| of one pass would not be bounded; a
 * weight |n·d_k| / Σ_j |n·d_j| had kinks inside the pieces wherever the
 * surface turned edge-on to another pass's direction, and the Kronrod rule
 * halved its panels down to each: nine rays in ten on two spheres).
 *
 * Along a line v = const the ray's interval list changes its make-up (which
 * faces of which primitives bound it, in order: its signature) only at
 * isolated events, and between two events every quantity is a smooth
 * function of u — on plane faces a linear one.  So the inner integral over u
 * is a sum over pieces of one signature each.  Events between samples of
 * differing signatures are bracketed to EPS of the span, each step first
 * trying where the two sides' lines (length and its slope, from the
 * normals) meet — the event itself between plane faces — then halving.
 * Each piece is integrated whole: by Simpson's rule when it agrees with its
 * two halves to rounding (plane faces: a polynomial of degree 3 at most),
 * else by Gauss–Kronrod (7/15 points), halved until the rules agree.  The
 * Kronrod rule runs through u = a + (b − a)(3s² − 2s³), which turns the
 * square-root edge of a curved silhouette, where L goes as √(u − a), into a
 * smooth function.  The outer integral over v is the same scheme again
 * (the level `across`), its events tried where the two sides' section areas
 * join with one slope.  A line's signature there is the multiset of its
 * events, each the change in the set of faces from one piece to the next,
 * not their order along it: two events crossing in the projection (a near
 * face's edge passing a far one's) swap their order but leave the section
 * area smooth, since each adds its own kink to L, while an event that
 * appears, ends or changes its faces (a curve's extreme in v, a corner, a
 * silhouette's end) changes the multiset (a fifth as many events across
 * the lines on the bench part as its ordered pieces had, 2.3 times fewer
 * rays).
 * Along a line, every boundary of a ray lies on a plane or a quadric
 * (follow.h): the rays of one piece cross the same surfaces, so a piece's
 * values anywhere follow from one ray's boundaries without casting another.
 * A curved piece's Kronrod nodes are followed, but for the centre of its
 * first panel, which is cast (a node of another signature is a piece that
 * the first samples stepped over, a corner poking through between them;
 * the plane pieces' three samples are all cast, and on random faceted
 * scenes those find such corners, where on the bench part the curved
 * pieces' nodes found none).  An event between two samples is foreseen
 * from their boundaries — where one that either lacks reaches its
 * silhouette or meets another — and tried there first: two rays an event
 * where halving took about thirty.  And the events of a line's neighbour
 * are carried to it the same way, solved from the surfaces of the pieces
 * either side (event_hints): its first samples pair them to within eps,
 * and no bracket is searched.  A piece one neighbour has and the other
 * lacks is followed from the one that has it alike.  The bench part:
 * 381,000 rays, 1.86 million before all this; two spheres 37,000, 168,000.
 * The oblique direction leaves no face of an ordinary model parallel to
 * the rays, so L has no jumps inside the model and a bracketed event costs
 * at most its width times a kink's slope.
 *
 * A polyhedral model comes out exact to rounding; a curved one converges
 * as the tolerance falls.  A feature narrower than the first samples can
 * slip between two that agree: lines are hinted by their neighbours' pieces
 * and by the primitives' boxes, the Kronrod nodes catch what they can, a
 * section area that jumps across the lines sends the line with less of it
 * back for the piece it missed, and three passes whose volumes disagree run
 * again with twice the samples (passes_disagree).
 */
#include "mesh.h"

#include "follow.h"

#include "../intervals/vec3.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NF 6           /* per ray: length, moment (3), area, d(length)/dv */
#define SAMPLES 24     /* first samples along each line */
#define EPS 1e-11      /* event brackets along a line, relative to the span */
#define OUTER_EPS 1e-6 /* across the lines, at the least (see pass_init) */
#define MAX_DEPTH 48   /* panel halvings */
#define MAX_HINTS 512  /* hinted first samples of a line */
#define MIN_PANEL 1e-7 /* of the span: see panel() */
#define SLIVER 1e-9    /* of the span: a piece too narrow to sign a line */
#define MAX_SEEDS 4096 /* primitives whose boxes hint first samples */
#define RECHECKS 2     /* passes run again, twice the samples each time (see passes_disagree) */
#define PAIR 1e-7      /* of the span: samples either side of an event foreseen */
#define NARROW 0.03    /* of the span: see cubic_piece */
#define PAD 1e-7       /* around the model's box, of the span */
/* A ray of n intervals counts 1 + n / RAY_INTERVALS rays against the
 * budget: its cost grows with them (a bar cut by 1500 slots, 300 intervals
 * a ray, spent four minutes on 2^25 rays before it gave way; 16 s now).
 * The bench part's rays have fewer than four. */
#define RAY_INTERVALS 4
#define FORESEEN 64 /* events foreseen between two samples along a line */
/* Boundaries kept per line to follow (40 bytes each, 200 once followed);
 * the rays past that are not followed. */
#define MAX_FORMS (1 << 16)
#define FOLLOWS_PER_RAY 8 /* followed samples that count as a ray against the budget */

/* A stretch of one signature along a line, and its set of faces. */
typedef struct piece {
    uint64_t sig, set;
    double x0, x1;
    int fo, nf; /* along a line: the boundaries of one of its rays (see sample) */
} piece;

/* The integrand at x: its values, the slope of the first (NAN: unknown),
 * its signature and (along a line) its set of faces, a sum that does not
 * depend on their order. */
typedef struct sample {
    double x, f[NF], slope;
    uint64_t sig, set;
    int fo, nf; /* along a line: its boundaries, pass.forms[fo .. fo+nf-1]; nf < 0: unknown */
} sample;

/* Fill s->f, s->slope and s->sig for s->x; 0 or -1. */
typedef int (*eval_fn)(void *ctx, sample *s);

/* One level of the nesting: integrate eval over [a, b]. */
typedef struct level {
    eval_fn eval;
    /* Evaluate s again, hinted by guide (see bracket); NULL: none. */
    int (*again)(void *ctx, sample *s, const sample *guide);
    /* Where an event between samples at a and b may be (see bracket),
     * the way `kind` (0 or 1) foresees it; NAN: no guess.  NULL: none. */
    double (*guess)(void *ctx, double a, double b, int kind);
    /* Fill s at s->x from like's boundaries, followed there: 0; 1 where
     * they cannot say (then eval does); -1.  NULL: none. */
    int (*follow)(void *ctx, sample *s, const sample *like);
    /* Where the events between samples a and b may be, from their
     * boundaries (see mesh_forms_events): into x, their number.  NULL: none. */
    int (*foresee)(void *ctx, const sample *a, const sample *b, double *x, int cap);
    void *ctx;
    double tol; /* absolute error allowed per unit of x (error norm below) */
    double weight[NF];
    double eps;       /* event bracket width */
    double try_eps;   /* a try's two samples apart (<= eps: see pass_init) */
    double min_panel; /* a panel narrower is not split at a node of another signature */
    double sum[NF];
    piece *pieces; /* the pieces of the last integration, in order */
    int npieces, cap;
    int failed;          /* out of memory for pieces or hints */
    int across;          /* the level across the lines (see integrate, bracket) */
    int quick;           /* pieces by the trapezoid rule, for signatures (see bracket) */
    int bisecting;       /* evaluating a bracket's samples (see line_eval) */
    int slow;            /* bracket's samples in full too (see bracket_all) */
    int misled;          /* quick samples misled a search (see bracket) */
    int samples;         /* even first samples */
    const double *hints; /* points to sample first, besides the even ones */
    int nhints;
} level;

/* Gauss–Kronrod 7/15 on [-1, 1]: Kronrod nodes (positive half, the centre
 * last), their weights, and the Gauss weights of the odd ones. */
static const double XK[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
static const double WK[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double WG[4] = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

static uint64_t mix(uint64_t h, uint64_t k)
{
    h ^= k + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h ^= h >> 31;
    h *= 0xbf58476d1ce4e5b9ULL;
    return h ^ (h >> 29);
}

/* Record that [x0, x1] has sample s's signature. */
static void add_piece(level *L, const sample *s, double x0, double x1)
{
    if (L->npieces && L->pieces[L->npieces - 1].sig == s->sig) {
        L->pieces[L->npieces - 1].x1 = x1;
        return;
    }
    if (L->npieces == L->cap) {
        int cap = L->cap ? 2 * L->cap : 16;
        piece *p = realloc(L->pieces, (size_t)cap * sizeof *p);
        if (!p) {
            L->failed = 1;
            return;
        }
        L->pieces = p;
        L->cap = cap;
    }
    L->pieces[L->npieces++] = (piece){s->sig, s->set, x0, x1, s->fo, s->nf};
}

/* The error of the Kronrod sum k of a panel of width w, from its Gauss
 * sum g and the values fv at its nodes (times their weights and Jacobians
 * wj) as QUADPACK estimates it: |k − g| is the Gauss rule's error, and the
 * Kronrod rule's is far smaller on a smooth integrand; the largest
 * component, weighted. */
static double err_norm(const level *L, const double k[NF], const double g[NF], double fv[15][NF],
                       const double wj[15], double w)
{
    double e = 0;
    for (int c = 0; c < NF; c++) {
        double d = fabs(k[c] - g[c]), mean = k[c] / w, asc = 0;
        for (int i = 0; i < 15; i++)
            asc += wj[i] * fabs(fv[i][c] - mean);
        if (asc > 0 && d > 0) d = asc * fmin(1, pow(200 * d / asc, 1.5));
        e = fmax(e, d * L->weight[c]);
    }
    return e;
}

static int stretch(level *L, const sample *s, int n, int depth);

/* s at s->x, of like's signature where like's boundaries can follow it
 * there (no ray), else by a ray. */
static int eval_like(level *L, sample *s, const sample *like)
{
    if (L->follow) {
        int rc = L->follow(L->ctx, s, like);
        if (rc <= 0) return rc;
    }
    return L->eval(L->ctx, s);
}

/* A piece of plane faces is a polynomial of degree 3 at most (a line's
 * length linear in u, its moments quadratic; across the lines one degree
 * more), which Simpson's rule integrates exactly: when it gives the same
 * sum over [l, r] as over its two halves, to rounding, the piece is
 * integrated (*done) with three samples instead of fifteen.  With loose,
 * a curved piece is too where the two sums agree within the tolerance: a
 * piece across the lines narrower than NARROW of the span, whose section
 * area is smooth (one signature) and over so short a stretch nearly cubic
 * (the bench part: 14 % fewer rays, its area then 1e-7 off at the default
 * tolerance of 1e-6, not 1e-9; along a line, where the pieces are narrow
 * but the three samples mostly failed, it cost rays).  A sample of another
 * signature splits it there. */
static int cubic_piece(level *L, const sample *l, const sample *r, int depth, int *done, int loose)
{
    double w = r->x - l->x;
    sample m[5] = {*l, {.x = l->x + 0.25 * w}, {.x = l->x + 0.5 * w}, {.x = l->x + 0.75 * w}, *r};
    *done = 0;
    for (int i = 1; i < 4; i++) {
        if (L->eval(L->ctx, &m[i]) != 0) return -1;
        if (m[i].sig != l->sig && w > L->min_panel && depth < MAX_DEPTH) {
            *done = 1;
            m[i + 1] = m[4]; /* (the samples past m[i] were not evaluated) */
            return stretch(L, m, i + 2, depth + 1);
        }
    }
    double s2[NF];
    for (int c = 0; c < NF; c++) {
        double s1 = w / 6 * (m[0].f[c] + 4 * m[2].f[c] + m[4].f[c]);
        s2[c] = w / 12 * (m[0].f[c] + 4 * m[1].f[c] + 2 * m[2].f[c] + 4 * m[3].f[c] + m[4].f[c]);
        double big = 0;
        for (int i = 0; i < 5; i++)
            big = fmax(big, fabs(m[i].f[c]));
        if (!(fabs(s1 - s2[c]) <= 1e-12 * w * big) &&
            !(loose && fabs(s1 - s2[c]) * L->weight[c] <= L->tol * w))
            return 0;
    }
    for (int c = 0; c < NF; c++)
        L->sum[c] += s2[c];
    add_piece(L, l, l->x, r->x);
    *done = 1;
    return 0;
}

/* Whether the piece between l and r may be plane-faced, as far as the
 * ends' values and slopes tell (unknown slopes: it may): along a line its
 * length is then linear, one slope at both ends; across the lines its
 * section area quadratic, the mean of the end slopes its secant.  A curved
 * piece fails this, and cubic_piece's three samples would be wasted on it
 * (a fifth of the bench part's rays). */
static int maybe_planar(const level *L, const sample *l, const sample *r)
{
    double sl = l->slope, sr = r->slope;
    if (!isfinite(sl) || !isfinite(sr)) return 1;
    if (!L->across) return fabs(sl - sr) <= 1e-9 * (fabs(sl) + fabs(sr)) + 1e-12;
    double w = r->x - l->x, d = r->f[0] - l->f[0] - 0.5 * w * (sl + sr);
    return fabs(d) <= 1e-6 * (fabs(l->f[0]) + fabs(r->f[0]) + w * (fabs(sl) + fabs(sr)));
}

/* Integrate the piece between samples l and r of one signature, halved
 * until the two rules agree; a node of another signature splits it there. */
static int panel(level *L, const sample *l, const sample *r, int depth)
{
    if (L->quick) {
        for (int c = 0; c < NF; c++)
            L->sum[c] += 0.5 * (r->x - l->x) * (l->f[c] + r->f[c]);
        add_piece(L, l, l->x, r->x);
        return 0;
    }
    int done = 0;
    int loose = L->across && r->x - l->x < NARROW * L->min_panel / MIN_PANEL;
    if ((loose || maybe_planar(L, l, r)) && cubic_piece(L, l, r, depth, &done, loose) != 0)
        return -1;
    if (done) return 0;
    double w = r->x - l->x, k[NF] = {0}, g[NF] = {0}, fv[15][NF], wj[15];
    for (int i = 0; i < 15; i++) {
        int j = i < 8 ? i : 14 - i; /* node j, mirrored past the centre */
        double s = 0.5 * (1 + (i < 8 ? -XK[j] : XK[j]));
        sample m[3] = {*l, {.x = l->x + w * s * s * (3 - 2 * s)}, *r};
        double jac = 0.5 * w * 6 * s * (1 - s);
        /* (the centre of a piece between first samples cast: see the top) */
        if ((i == 7 && depth == 0 ? L->eval(L->ctx, &m[1]) : eval_like(L, &m[1], l)) != 0)
            return -1;
        if (m[1].sig != l->sig && m[1].x > l->x && m[1].x < r->x && w > L->min_panel &&
            depth < MAX_DEPTH)
            return stretch(L, m, 3, depth + 1);
        wj[i] = WK[j] * jac;
        for (int c = 0; c < NF; c++) {
            fv[i][c] = m[1].f[c];
            k[c] += WK[j] * jac * m[1].f[c];
            if (j & 1) g[c] += WG[j / 2] * jac * m[1].f[c];
        }
    }
    if (err_norm(L, k, g, fv, wj, w) > L->tol * w && depth < MAX_DEPTH && w > L->eps) {
        sample m[3] = {*l, {.x = 0.5 * (l->x + r->x)}, *r};
        if (eval_like(L, &m[1], l) != 0) return -1;
        if (m[1].sig != l->sig) return stretch(L, m, 3, depth + 1);
        if (panel(L, l, &m[1], depth + 1) != 0) return -1;
        return panel(L, &m[1], r, depth + 1);
    }
    for (int c = 0; c < NF; c++)
        L->sum[c] += k[c];
    add_piece(L, l, l->x, r->x);
    return 0;
}

/* Where the first components' lines through a and b (value and slope)
 * meet: the kink between two plane-faced pieces, exactly; NAN when the
 * slopes are unknown or alike. */
static double kink(const sample *a, const sample *b)
{
    double ds = a->slope - b->slope;
    if (!isfinite(ds) || !(fabs(ds) > 1e-12 * (fabs(a->slope) + fabs(b->slope)))) return NAN;
    return (b->f[0] - a->f[0] + a->slope * a->x - b->slope * b->x) / ds;
}

/* Events found between two samples: brackets [a, b] of width L->eps or
 * less, in order. */
typedef struct events {
    sample (*ab)[2];
    int n, cap;
} events;

static int push_event(events *E, const sample *a, const sample *b)
{
    if (E->n == E->cap) {
        int cap = E->cap ? 2 * E->cap : 8;
        sample(*g)[2] = realloc(E->ab, (size_t)cap * sizeof *g);
        if (!g) return -1;
        E->ab = g;
        E->cap = cap;
    }
    E->ab[E->n][0] = *a;
    E->ab[E->n][1] = *b;
    E->n++;
    return 0;
}

/* Whether the section area jumps between lines a and b: it is continuous
 * (no face lies along the lines), and where it rises steepest, as the
 * square root of the distance past a silhouette's turn, it changes across
 * a bracket by at most twice the bracket times its steeper end's slope.  A
 * jump is a piece that one line missed: less area. */
static int jumps(const sample *a, const sample *b)
{
    double w = b->x - a->x, s = fmax(fabs(a->slope), fabs(b->slope));
    return fabs(b->f[0] - a->f[0]) > 4 * w * (isfinite(s) ? s : 0) + 1e-9 * (a->f[0] + b->f[0]);
}

/* Bracket the events between samples l and r of different signatures into
 * E.  Where the samples know their slopes, a step first tries the kink of
 * their lines, two samples eps/2 either side of it — one try, where both
 * pieces are plane-faced — and halves the bracket when the try did not.  A
 * try whose two samples fell on one side moved that end of the bracket
 * toward the event but not past it (the lines of curved pieces meet short
 * of their kink, on the same side try after try, while the far end stays
 * where it was): the next sample goes twice that move beyond the moved end,
 * which brackets the event close on both sides (a sixth fewer rays on the
 * bench part; along the lines only).  Across the lines a step tries where
 * the lines' own pieces foresee the event (line_guess: a piece that one
 * end has and the other lacks, followed to where it closes, then its width
 * carried to zero from the lines beyond), then the bracket is halved (the
 * section areas' kink brackets an event between curved faces only by
 * degrees: tried first, as it was, with the width carried straight to zero
 * as a third guess, the bench part took 22 % more rays, the tricylinder
 * 2.5 times as many; tried second, 9 % and 19 % more).  A guess within a
 * try's half-width of an end is tried by one sample just
 * past it.  Across the lines, a bracket's samples are lines integrated
 * quickly, their pieces by the trapezoid rule (exact on plane faces, where
 * the tries use their values): what they must tell is their signature, and
 * only the two lines that end the search are integrated in full (a fifth
 * fewer rays on the bench part). */
static int bracket(level *L, const sample *l, const sample *r, int depth, events *E)
{
    sample a = *l, b = *r;
    int tries = 0;
    double step = 0; /* > 0: the last try moved a only, by step; < 0: b only */
    double fx[FORESEEN];
    int nfx = 0, fi = 0;
    if (L->foresee && b.x - a.x > L->eps) nfx = L->foresee(L->ctx, l, r, fx, FORESEEN);
    while (b.x - a.x > L->eps) {
        /* where to try: where the sides' lines meet (kink) or, with the
         * level's guesses (level.guess), each guess in turn; a try at
         * each, then a halving */
        double h = 0.5 * L->try_eps, k, x = step > 0 ? a.x + 2 * step : b.x + 2 * step;
        int ways = 2;
        if (L->guess)
            k = tries < ways ? L->guess(L->ctx, a.x, b.x, tries) : NAN;
        else
            k = kink(&a, &b);
        sample m[2];
        int n = 1;
        while (fi < nfx && !(fx[fi] > a.x && fx[fi] < b.x))
            fi++;
        if (fi < nfx) {
            /* foreseen from the ends' boundaries: a try there, its samples
             * closer than eps (c ± h may round to a bracket just over it) */
            double c = fx[fi++];
            h *= 0.8;
            if (c - h > a.x && c + h < b.x) {
                m[0].x = c - h;
                m[1].x = c + h;
                n = 2;
            } else {
                m[0].x = c - h <= a.x ? fmin(c + h, 0.5 * (c + b.x)) : fmax(c - h, 0.5 * (a.x + c));
            }
        } else if (L->guess && tries < ways && k > a.x && k < b.x &&
                   (k - h <= a.x || k + h >= b.x)) {
            /* foreseen within h of an end: one sample past it */
            m[0].x = k - h <= a.x ? fmin(k + h, 0.5 * (k + b.x)) : fmax(k - h, 0.5 * (a.x + k));
            tries++;
        } else if (step != 0 && x > a.x && x < b.x && !L->guess) {
            m[0].x = x; /* twice the move past the moved end */
        } else if (tries < ways && k - h > a.x && k + h < b.x) {
            m[0].x = k - h;
            m[1].x = k + h;
            n = 2;
            tries++;
        } else if (L->guess && tries < ways) {
            tries++; /* nothing foreseen this way */
            continue;
        } else {
            m[0].x = a.x + 0.5 * (b.x - a.x);
            tries = 0;
        }
        step = 0;
        double a0 = a.x, b0 = b.x;
        for (int i = 0; i < n; i++) {
            L->bisecting = L->across && !L->slow;
            int rc = L->eval(L->ctx, &m[i]);
            L->bisecting = 0;
            if (rc != 0) return -1;
            if (m[i].sig == a.sig && m[i].x > a.x) {
                a = m[i];
            } else if (m[i].sig == b.sig && m[i].x < b.x) {
                b = m[i];
            } else if (m[i].sig != a.sig && m[i].sig != b.sig && depth < MAX_DEPTH) {
                /* a third signature: two events or more */
                if (bracket(L, &a, &m[i], depth + 1, E) != 0) return -1;
                if (L->misled) return 0;
                return bracket(L, &m[i], &b, depth + 1, E);
            } else if (m[i].sig != a.sig && m[i].sig != b.sig && m[i].x > a.x && m[i].x < b.x) {
                /* (too deep to split: the bracket closes in on the first
                 * event, between a and m, where it had stayed as it was try
                 * after try, to the end of the rays allowed, on a faceted
                 * difference whose lines' signatures flickered) */
                b = m[i];
            }
        }
        if (n == 2 && (a.x == a0) != (b.x == b0)) step = a.x != a0 ? a.x - a0 : b.x - b0;
    }
    if (L->across && depth < MAX_DEPTH) {
        /* The two ends integrated in full.  A line is also only as good as
         * its hints: one integrated while its nearest neighbours were far
         * may have missed a narrow piece that the lines now either side of
         * it show.  An end whose signature changes moves the search, and
         * where the search ran on quick lines, misled it (bracket_all). */
        sample s[4] = {*l, a, b, *r};
        if (L->eval(L->ctx, &s[1]) != 0 || L->eval(L->ctx, &s[2]) != 0) return -1;
        if (L->again && jumps(&s[1], &s[2])) {
            int k = s[1].f[0] < s[2].f[0] ? 1 : 2;
            if (L->again(L->ctx, &s[k], &s[3 - k]) != 0) return -1;
        }
        if (s[1].sig != a.sig || s[2].sig != b.sig) {
            if (!L->slow) {
                L->misled = 1;
                return 0;
            }
            /* (an end that had not moved is its own line again: no width
             * between the two, and nothing to bracket; its signature may
             * differ once more, and bracketing that recursed to MAX_DEPTH
             * on one line: the tricylinder's ten thousand brackets) */
            for (int i = 0; i < 3; i++)
                if (s[i].sig != s[i + 1].sig && s[i + 1].x > s[i].x &&
                    bracket(L, &s[i], &s[i + 1], depth + 1, E) != 0)
                    return -1;
            return 0;
        }
        return push_event(E, &s[1], &s[2]);
    }
    return push_event(E, &a, &b);
}

/* bracket() between samples integrated in full: where a full line's
 * signature showed that the quick ones misled the search (a piece found
 * between a quick line's samples), the search again with every line in
 * full. */
static int bracket_all(level *L, const sample *l, const sample *r, int depth, events *E)
{
    int n = E->n;
    L->misled = 0;
    int rc = bracket(L, l, r, depth, E);
    if (rc == 0 && L->misled) {
        E->n = n;
        L->misled = 0;
        L->slow = 1;
        rc = bracket(L, l, r, depth, E);
        L->slow = 0;
    }
    return rc;
}

/* Integrate over samples s[0 .. n-1] (in order): each piece of one
 * signature from event to event whole, and each event's bracket by the
 * values either side up to the kink (its middle where the slopes do not
 * say). */
static int stretch(level *L, const sample *s, int n, int depth)
{
    events E = {NULL, 0, 0};
    sample start = s[0];
    int rc = 0;
    for (int i = 1; i < n && rc == 0; i++) {
        if (s[i].sig == start.sig) continue;
        E.n = 0;
        rc = bracket_all(L, &s[i - 1], &s[i], depth, &E);
        for (int e = 0; e < E.n && rc == 0; e++) {
            const sample *a = &E.ab[e][0], *b = &E.ab[e][1];
            if (a->x > start.x) rc = panel(L, &start, a, depth);
            double k = L->across ? NAN : kink(a, b);
            if (!(k >= a->x && k <= b->x)) k = 0.5 * (a->x + b->x);
            for (int c = 0; c < NF; c++)
                L->sum[c] += (k - a->x) * a->f[c] + (b->x - k) * b->f[c];
            add_piece(L, a, a->x, k);
            add_piece(L, b, k, b->x);
            start = *b;
        }
    }
    if (rc == 0 && s[n - 1].x > start.x) rc = panel(L, &start, &s[n - 1], depth);
    free(E.ab);
    return rc;
}

static int by_x(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* ∫ over [a, b] of L->eval into L->sum, its pieces into L->pieces; 0 or
 * -1.  The first samples are SAMPLES + 1 even ones and L->hints. */
static int integrate(level *L, double a, double b)
{
    memset(L->sum, 0, sizeof L->sum);
    L->npieces = 0;
    int ns = L->samples;
    int n = ns + 1 + L->nhints;
    double *x = malloc((size_t)n * sizeof *x);
    if (!x) return -1;
    for (int i = 0; i <= ns; i++)
        x[i] = a + (b - a) * i / ns;
    int m = ns + 1;
    for (int i = 0; i < L->nhints; i++)
        if (L->hints[i] > a && L->hints[i] < b) x[m++] = L->hints[i];
    qsort(x, (size_t)m, sizeof *x, by_x);
    sample *sm = malloc((size_t)m * sizeof *sm);
    int rc = sm ? 0 : -1;
    for (int i = 0; i < m && rc == 0; i++) {
        sm[i].x = x[i];
        rc = L->eval(L->ctx, &sm[i]);
    }
    /* the lines once more from the other end: each then has hints from
     * both sides */
    for (int i = m - 1; i >= 0 && rc == 0 && L->across; i--)
        rc = L->eval(L->ctx, &sm[i]);
    if (rc == 0) rc = stretch(L, sm, m, 0);
    free(sm);
    free(x);
    return rc == 0 && !L->failed ? 0 : -1;
}

/* ---- the rays ------------------------------------------------------------ */

/* A line integrated: where it is and its pieces. */
typedef struct line {
    double v;
    uint64_t seq;
    int np;
    piece *p;
    iv_bound *b;      /* its pieces' boundaries (piece.fo, nf) */
    double (*org)[3]; /* and the origins of their rays */
    /* and their surfaces, once asked for (qs: 0 not yet, 1 q, 2 not on a
     * quadric): the same on every line they are followed to */
    iv_quadric *q;
    unsigned char *qs;
} line;

/* A primitive's box seen along a pass's direction. */
typedef struct seed {
    double corner[8][2], vlo, vhi;
} seed;

/* One pass: rays along d through the points c + u e1 + v e2 − reach d. */
typedef struct pass {
    const csg_scene *s;
    int root;
    double c[3], d[3], e1[3], e2[3], reach;
    seed box; /* the model's box seen along d */
    iv_arena *arena;
    long long count;
    long long followed; /* samples followed (see follow_eval) */
    double v;           /* the current line's v */
    level inner, outer;
    line *lines; /* the lines integrated, by v */
    int nlines, caplines;
    double hints[MAX_HINTS];
    double ext[2][3][3]; /* the lowest and highest hit along each axis */
    seed *seeds;         /* the primitives' boxes */
    int nseeds;
    double outer_hints[MAX_HINTS];
    const line *guide; /* a line whose pieces hint the next one (see line_again) */
    long long budget;  /* rays this pass may cast (see RAY_INTERVALS); < 0: no limit */
    long long spent;   /* of it */
    int over;          /* it needed more */
    const mesh_exact_limits *limits;
    int cancelled;         /* the limits' hook said stop */
    mesh_line_frame frame; /* the current line's rays */
    /* The boundaries of its rays (sample.fo, nf), followed (forms) once
     * asked to (state: 0 not yet, 1 done, 2 not on a quadric). */
    iv_bound *bounds;
    double (*org)[3]; /* the origin of each one's ray */
    mesh_form *forms;
    unsigned char *state;
    int nforms, capforms;
    int rc;
} pass;

/* The stretch [*lo, *hi] of u on the line at v that box q covers, padded
 * by pad; 0 when the line misses it. */
static int box_span(const seed *q, double v, double pad, double *lo, double *hi)
{
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int i = 0; i < 8; i++)
        for (int j = i; j < 8; j++) {
            const double *a = q->corner[i], *b = q->corner[j];
            if ((a[1] - v) * (b[1] - v) > 0) continue;
            double u = a[1] == b[1] ? a[0] : a[0] + (b[0] - a[0]) * (v - a[1]) / (b[1] - a[1]);
            double u2 = a[1] == b[1] ? b[0] : u;
            *lo = fmin(*lo, fmin(u, u2));
            *hi = fmax(*hi, fmax(u, u2));
        }
    *lo -= pad;
    *hi += pad;
    return *lo <= *hi;
}

/* Box lo..hi seen along P's direction: its corners (u, v) and the least
 * and greatest v among them. */
static void project_box(const pass *P, const double lo[3], const double hi[3], seed *q)
{
    q->vlo = INFINITY;
    q->vhi = -INFINITY;
    for (int i = 0; i < 8; i++) {
        double x[3];
        for (int a = 0; a < 3; a++)
            x[a] = ((i >> a) & 1 ? hi[a] : lo[a]) - P->c[a];
        q->corner[i][0] = dot3(x, P->e1);
        q->corner[i][1] = dot3(x, P->e2);
        q->vlo = fmin(q->vlo, q->corner[i][1]);
        q->vhi = fmax(q->vhi, q->corner[i][1]);
    }
}

/* Hints from the primitives' boxes (P->seeds) narrower than
 * `spacing` along the line at v (or, v NAN, across the lines): their
 * middles, appended to h[*n] up to cap.  Even samples can step over a
 * small part far from the rest; these cannot. */
static void seed_hints(const pass *P, double v, double spacing, double *h, int *n, int cap)
{
    for (int i = 0; i < P->nseeds && *n < cap; i++) {
        const seed *q = &P->seeds[i];
        if (isnan(v)) {
            if (q->vhi - q->vlo < spacing) h[(*n)++] = 0.5 * (q->vlo + q->vhi);
            continue;
        }
        double lo, hi;
        if (v < q->vlo || v > q->vhi || !box_span(q, v, 0, &lo, &hi)) continue;
        if (hi - lo < spacing) h[(*n)++] = 0.5 * (lo + hi);
    }
}

/* Which surface boundary b lies on: its primitive, part and side. */
static uint64_t face_of(const iv_bound *b)
{
    return (uint64_t)(uint32_t)b->prim << 32 | (uint64_t)b->part << 1 | b->flip;
}

/* Whether the pass may not go on: its budget spent (P->over) or its
 * limits' hook says stop (P->cancelled), asked every 4096th time
 * (n counts the times). */
static int out_of_budget(pass *P, long long n)
{
    if (P->budget >= 0 && P->spent >= P->budget) {
        P->over = 1;
        return 1;
    }
    if ((n & 4095) == 0 && P->limits->cancelled &&
        (P->cancelled || P->limits->cancelled(P->limits->cancel_ud))) {
        P->cancelled = 1;
        return 1;
    }
    return 0;
}

/* Room for n more boundaries; 0 or -1. */
static int grow_forms(pass *P, int n)
{
    if (n <= P->capforms - P->nforms) return 0;
    size_t cap = 2 * ((size_t)P->nforms + (size_t)n);
    iv_bound *b = realloc(P->bounds, cap * sizeof *b);
    if (b) P->bounds = b;
    double(*org)[3] = b ? realloc(P->org, cap * sizeof *org) : NULL;
    if (org) P->org = org;
    mesh_form *f = org ? realloc(P->forms, cap * sizeof *f) : NULL;
    if (f) P->forms = f;
    unsigned char *st = f ? realloc(P->state, cap) : NULL;
    if (!st) return -1;
    P->state = st;
    P->capforms = (int)cap;
    return 0;
}

/* Boundary i of the pass, on surface q, followed on the current line: the
 * ray leaves the solid there where `exits`. */
static void form_on(pass *P, int i, const iv_quadric *q, int exits)
{
    const iv_bound *b = &P->bounds[i];
    const double *o = P->org[i];
    double x[3] = {o[0] + b->t * P->d[0], o[1] + b->t * P->d[1], o[2] + b->t * P->d[2]};
    mesh_form_init(&P->forms[i], q, &P->frame, x, exits ? 1 : -1, face_of(b));
    P->state[i] = 1;
}

/* Sample s's boundaries followed (pass.forms); 0, or -1 where one is not
 * on a quadric. */
static int forms_of(pass *P, const sample *s)
{
    if (s->nf < 0) return -1;
    for (int i = s->fo; i < s->fo + s->nf; i++) {
        if (P->state[i] == 0) {
            iv_quadric q;
            if (csg_scene_quadric(P->s, &P->bounds[i], P->org[i], P->d, &q) == 0)
                form_on(P, i, &q, (i - s->fo) & 1);
            else
                P->state[i] = 2;
        }
        if (P->state[i] == 2) return -1;
    }
    return 0;
}

/* The origin of the current line's ray u. */
static void ray_origin(const pass *P, double u, double o[3])
{
    for (int k = 0; k < 3; k++)
        o[k] = P->c[k] + u * P->e1[k] + P->v * P->e2[k] - P->reach * P->d[k];
}

/* s's values from what its ray (from o) crosses: the moments about c, as
 * p − c = (o − c) + t d. */
static void put_sums(const pass *P, sample *s, const double o[3], const mesh_follow_sums *m)
{
    s->f[0] = m->len;
    for (int k = 0; k < 3; k++)
        s->f[1 + k] = (o[k] - P->c[k]) * m->len + P->d[k] * m->tt;
    s->f[4] = m->area;
    s->f[5] = m->across;
    s->slope = m->slope;
}

/* Boundary b of the ray from o onto the pass's list (room made). */
static void push_bound(pass *P, const iv_bound *b, const double o[3])
{
    P->bounds[P->nforms] = *b;
    memcpy(P->org[P->nforms], o, sizeof *P->org);
    P->state[P->nforms++] = 0;
}

static int ray_eval(void *ctx, sample *sm)
{
    pass *P = ctx;
    double u = sm->x, o[3];
    ray_origin(P, u, o);
    iv_arena_reset(P->arena);
    iv_list l;
    if (out_of_budget(P, P->count++)) return -1;
    if (csg_trace(P->s, P->root, o, P->d, 0, 2 * P->reach, P->arena, &l) != 0) return -1;
    P->spent += 1 + l.n / RAY_INTERVALS;
    sm->fo = P->nforms;
    sm->nf = -1;
    if (P->nforms + 2 * l.n <= MAX_FORMS && grow_forms(P, 2 * l.n) == 0) {
        for (int i = 0; i < l.n; i++) {
            push_bound(P, &l.v[i].enter, o);
            push_bound(P, &l.v[i].exit, o);
        }
        sm->nf = 2 * l.n;
    }
    mesh_follow_sums m = {0, 0, 0, 0, 0};
    uint64_t h = 0x2545f4914f6cdd1dULL, set = 0;
    for (int i = 0; i < l.n; i++)
        for (int e = 0; e < 2; e++) {
            const iv_bound *b = e ? &l.v[i].exit : &l.v[i].enter;
            double n[3];
            csg_scene_normal(P->s, b, o, P->d, n);
            m.area += fabs(dot3(n, P->d));
            /* t on the plane of b as u moves: dt/du = −(n·e1)/(n·d) */
            m.slope += (e ? -1 : 1) * dot3(n, P->e1) / dot3(n, P->d);
            m.across += (e ? -1 : 1) * dot3(n, P->e2) / dot3(n, P->d);
            uint64_t face = face_of(b);
            h = mix(h, face);
            set += mix(0, face);
            for (int a = 0; a < 3; a++) {
                /* (which end, decided before the point is copied: the copy
                 * moves the end it is compared with) */
                double x = o[a] + b->t * P->d[a];
                for (int e2 = 0; e2 < 2; e2++)
                    if (e2 ? x > P->ext[1][a][a] : x < P->ext[0][a][a])
                        for (int c = 0; c < 3; c++)
                            P->ext[e2][a][c] = o[c] + b->t * P->d[c];
            }
            if (e) {
                double t0 = l.v[i].enter.t, t1 = b->t;
                m.len += t1 - t0;
                m.tt += 0.5 * (t1 * t1 - t0 * t0);
            }
        }
    put_sums(P, sm, o, &m);
    sm->sig = h;
    sm->set = set;
    return 0;
}

/* The level's follow (see level.follow): like's boundaries at s->x. */
static int follow_eval(void *ctx, sample *s, const sample *like)
{
    pass *P = ctx;
    /* Following costs no ray, but it is not free: every FOLLOWS_PER_RAY
     * count one against the budget, so that no integrand a panel cannot
     * settle runs on unbounded. */
    if (out_of_budget(P, P->followed)) return -1;
    if (++P->followed % FOLLOWS_PER_RAY == 0) P->spent++;
    mesh_follow_sums m;
    if (forms_of(P, like) != 0 ||
        mesh_forms_sums(P->forms + like->fo, like->nf, &P->frame, s->x, &m) != 0)
        return 1;
    double o[3];
    ray_origin(P, s->x, o);
    put_sums(P, s, o, &m);
    s->sig = like->sig;
    s->set = like->set;
    s->fo = like->fo;
    s->nf = like->nf;
    return 0;
}

/* The level's foresee (see level.foresee). */
static int foresee(void *ctx, const sample *a, const sample *b, double *x, int cap)
{
    pass *P = ctx;
    if (forms_of(P, a) != 0 || forms_of(P, b) != 0) return 0;
    return mesh_forms_events(P->forms + a->fo, a->nf, P->forms + b->fo, b->nf, a->x, b->x, x, cap);
}

/* Whether one of x[0 .. n-1] lies within tol of y. */
static int near_one(const double *x, int n, double y, double tol)
{
    for (int i = 0; i < n; i++)
        if (fabs(x[i] - y) <= tol) return 1;
    return 0;
}

/* Hints for the line at v from lines a and b of the history (a pair of
 * the same make-up: each piece's ends carried to v along the straight line
 * through theirs, which is where they are on plane faces; else the middles
 * of a's pieces) appended to h[*n], up to cap: the pieces' middles, but
 * for a piece whose ends both lie within a tenth of its width of events
 * found exactly on this line (paired[0 .. npaired-1], each sampled either
 * side: event_hints) or are the line's ends (sampled too): those samples
 * fall inside it (a sixth of the bench part's rays). */
static void hints_from(const line *a, const line *b, double v, const double *paired, int npaired,
                       double *h, int *n, int cap)
{
    int same = b && b->seq == a->seq && b->np == a->np && b->v != a->v;
    for (int k = 0; k < a->np && *n < cap; k++) {
        double x0 = a->p[k].x0, x1 = a->p[k].x1;
        if (same) {
            double s = (v - a->v) / (b->v - a->v);
            x0 += s * (b->p[k].x0 - x0);
            x1 += s * (b->p[k].x1 - x1);
        }
        double t = 0.1 * (x1 - x0);
        if ((k == 0 || near_one(paired, npaired, x0, t)) &&
            (k == a->np - 1 || near_one(paired, npaired, x1, t)))
            continue;
        if (x1 > x0) h[(*n)++] = 0.5 * (x0 + x1);
    }
}

/* Where line l's pieces change (x) and what changes there (the set of
 * faces after less the set before: the same event on every line that has
 * it, whatever else the ray crosses), and which of the line's events with
 * that change it is, counted along the line (occ) out of how many (of). */
typedef struct event_at {
    double x;
    uint64_t key;
    int occ, of;
} event_at;

static int line_events(const line *l, event_at *e, int cap)
{
    int n = 0;
    for (int k = 0; k + 1 < l->np && n < cap; k++)
        e[n++] = (event_at){l->p[k].x1, l->p[k + 1].set - l->p[k].set, 0, 1};
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (e[j].key == e[i].key) {
                e[j].occ++;
                e[i].of++;
                e[j].of++;
            }
    return n;
}

/* Line l's event like e (the same change, as many of them, the same one
 * of those counted along the line): its x, NAN where l has none. */
static double event_like(const event_at *le, int ln, const event_at *e)
{
    for (int i = 0; i < ln; i++)
        if (le[i].key == e->key && le[i].occ == e->occ) return le[i].of == e->of ? le[i].x : NAN;
    return NAN;
}

#define LINE_EVENTS 256

/* The boundaries of piece k of line l followed on the current line
 * (P->frame) into s (its fo, nf); 0, or -1 where they cannot be. */
static int piece_forms(pass *P, const line *l, int k, sample *s)
{
    const piece *q = &l->p[k];
    if (q->nf < 0 || grow_forms(P, q->nf) != 0) return -1;
    s->fo = P->nforms;
    s->nf = q->nf;
    for (int i = 0; i < q->nf; i++) {
        int j = q->fo + i;
        if (l->qs[j] == 0)
            l->qs[j] = csg_scene_quadric(P->s, &l->b[j], l->org[j], P->d, &l->q[j]) == 0 ? 1 : 2;
        if (l->qs[j] == 2) return -1;
        push_bound(P, &l->b[j], l->org[j]);
        form_on(P, P->nforms - 1, &l->q[j], i & 1);
    }
    return 0;
}

/* Where the event between pieces k and k + 1 of line l lies on the
 * current line (P->frame), foreseen from their boundaries: the foreseen
 * place nearest guess within window of it; NAN where none.  *last holds
 * the boundaries of piece *lastk (-1: none), followed by the call before:
 * piece k's where the events go in order, and piece k + 1's after. */
static double exact_event(pass *P, const line *l, int k, double guess, double window, sample *last,
                          int *lastk)
{
    sample s[2];
    int left = *lastk == k ? 0 : piece_forms(P, l, k, &s[0]);
    if (*lastk == k) s[0] = *last;
    *lastk = -1;
    if (left != 0 || piece_forms(P, l, k + 1, &s[1]) != 0) return NAN;
    *last = s[1];
    *lastk = k + 1;
    double x[FORESEEN], best = NAN, w = 0.4 * P->inner.try_eps, span = 2 * P->reach;
    int n = mesh_forms_events(P->forms + s[0].fo, s[0].nf, P->forms + s[1].fo, s[1].nf,
                              guess - window, guess + window, x, FORESEEN);
    for (int i = 0; i < n; i++) {
        if (fabs(best - guess) <= fabs(x[i] - guess)) continue;
        /* the length of solid is continuous at an event (no face lies
         * along the rays): the two pieces' just either side of it alike,
         * where at the silhouette of a face that neither side's
         * boundaries meet there they are not */
        mesh_follow_sums lo, hi;
        if (mesh_forms_sums(P->forms + s[0].fo, s[0].nf, &P->frame, x[i] - w, &lo) == 0 &&
            mesh_forms_sums(P->forms + s[1].fo, s[1].nf, &P->frame, x[i] + w, &hi) == 0 &&
            fabs(lo.len - hi.len) <= 1e-5 * span)
            best = x[i];
    }
    return best;
}

/* Hints for the line at v from the events of the lines about it (ls[0..3]:
 * two below v and two above, nearest in the middle; NULL where none): each
 * event of the nearest line below (ls[1]) that the nearest above has too,
 * its place at v interpolated through every line that has it (Neville), and
 * two samples either side of it, the larger of pair and three times the
 * interpolation's own error estimate (the last term it added) apart.  Lines
 * whose make-up differs (an event between them that appears, ends or
 * passes another) share their other events: matched one by one, those are
 * foreseen too (a quick line bracketing an event across the lines had
 * none, and its every event started from the first samples). */
static void event_hints(pass *P, const line *const ls[4], double v, double pair, double span,
                        double *h, int *n, int cap, double *paired, int *npaired)
{
    *npaired = 0;
    static _Thread_local event_at ev[4][LINE_EVENTS];
    int ne[4] = {0, 0, 0, 0};
    if (!ls[1] || !ls[2]) return;
    for (int i = 0; i < 4; i++)
        if (ls[i]) ne[i] = line_events(ls[i], ev[i], LINE_EVENTS);
    sample last; /* the boundaries of piece lastk of ls[1] (see exact_event) */
    int lastk = -1;
    for (int k = 0; k < ne[1] && *n + 2 <= cap; k++) {
        double vs[4], xs[4];
        int m = 0, both = 1; /* the nearest either side both have it */
        for (int i = 0; i < 4; i++) {
            double x = ls[i] ? event_like(ev[i], ne[i], &ev[1][k]) : NAN;
            if (isnan(x)) {
                both &= i == 0 || i == 3;
                continue;
            }
            vs[m] = ls[i]->v;
            xs[m++] = x;
        }
        if (!both) continue;
        /* Neville: xs[0] becomes the polynomial through all m at v */
        double err = 0;
        for (int d = 1; d < m; d++) {
            for (int i = 0; i + d < m; i++)
                xs[i] = ((v - vs[i + d]) * xs[i] + (vs[i] - v) * xs[i + 1]) / (vs[i] - vs[i + d]);
            if (d == m - 1 && m > 2) err = fabs(xs[0] - xs[1]);
        }
        double w = fmax(pair, 3 * err);
        double x = exact_event(P, ls[1], k, xs[0], fmax(4 * fabs(xs[0] - ev[1][k].x), 16 * w),
                               &last, &lastk);
        if (!isnan(x)) {
            w = 0.4 * P->inner.try_eps; /* a bracket no wider than eps */
            paired[(*npaired)++] = x;
        } else {
            x = xs[0];
            if (!(w < 1e-3 * span)) continue; /* foreseen too roughly to pair */
        }
        h[(*n)++] = x - w;
        h[(*n)++] = x + w;
    }
    /* A piece of one nearest line that the other lacks (one of its ends
     * not there) narrows to nothing between them (the piece a vertex of
     * plane faces starts, too narrow for the first samples near the
     * vertex): its two events followed to v from that line's boundaries,
     * each sampled either side where both are there (a piece found by one
     * line only was found again by the lines toward where it starts only
     * by chance, their signatures flickering: 40 brackets in a row on a
     * union of three faceted solids, its start missed), else its middle,
     * its ends carried on to v straight from that line and the next beyond
     * it. */
    for (int s = 1; s <= 2; s++) {
        int o = 3 - s, b = s == 1 ? 0 : 3;
        lastk = -1;
        for (int k = 0; k + 1 < ne[s] && *n + 4 <= cap; k++) {
            const event_at *e = &ev[s][k], *f = &ev[s][k + 1];
            if (!isnan(event_like(ev[o], ne[o], e)) && !isnan(event_like(ev[o], ne[o], f)))
                continue;
            /* (each foreseen within a window about where it is carried:
             * over the whole line, two meetings of curved faces that close
             * in on each other can fall between the steps looking for them) */
            double t = ls[b] ? (v - ls[s]->v) / (ls[b]->v - ls[s]->v) : 0, dv = fabs(v - ls[s]->v);
            double xe = ls[b] ? e->x + t * (event_like(ev[b], ne[b], e) - e->x) : NAN;
            double xf = ls[b] ? f->x + t * (event_like(ev[b], ne[b], f) - f->x) : NAN;
            double we = isnan(xe) ? 2 * dv : 4 * fabs(xe - e->x);
            double wf = isnan(xf) ? 2 * dv : 4 * fabs(xf - f->x);
            double x0 =
                exact_event(P, ls[s], k, isnan(xe) ? e->x : xe, fmax(we, 16 * pair), &last, &lastk);
            double x1 = isnan(x0) ? NAN
                                  : exact_event(P, ls[s], k + 1, isnan(xf) ? f->x : xf,
                                                fmax(wf, 16 * pair), &last, &lastk);
            if (x1 > x0) {
                double w = 0.4 * P->inner.try_eps;
                h[(*n)++] = x0 - w;
                h[(*n)++] = x0 + w;
                h[(*n)++] = x1 - w;
                h[(*n)++] = x1 + w;
                paired[(*npaired)++] = x0;
                paired[(*npaired)++] = x1;
                continue;
            }
            if (xf > xe) h[(*n)++] = 0.5 * (xe + xf);
        }
    }
}

/* The rays of the line at v as the current line (P->frame), none of its
 * boundaries followed yet. */
static void frame_at(pass *P, double v)
{
    for (int k = 0; k < 3; k++) {
        P->frame.p0[k] = P->c[k] + v * P->e2[k] - P->reach * P->d[k];
        P->frame.e1[k] = P->e1[k];
        P->frame.e2[k] = P->e2[k];
        P->frame.d[k] = P->d[k];
    }
    P->nforms = 0;
}

/* The index of the first line of the history at v or beyond. */
static int line_index(const pass *P, double v)
{
    int lo = 0, hi = P->nlines;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (P->lines[mid].v < v)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

static void free_line(line *l)
{
    free(l->p);
    free(l->b);
    free(l->org);
    free(l->q);
    free(l->qs);
}

/* Line l's pieces' boundaries copied from the pass's (l->b, l->org; left
 * NULL, and the pieces without, where there is no room). */
static void keep_bounds(const pass *P, line *l)
{
    int n = 0;
    for (int k = 0; k < l->np; k++)
        n += l->p[k].nf > 0 ? l->p[k].nf : 0;
    l->b = n ? malloc((size_t)n * sizeof *l->b) : NULL;
    l->org = n ? malloc((size_t)n * sizeof *l->org) : NULL;
    l->q = n ? malloc((size_t)n * sizeof *l->q) : NULL;
    l->qs = n ? calloc((size_t)n, 1) : NULL;
    int m = 0;
    for (int k = 0; k < l->np; k++) {
        piece *q = &l->p[k];
        if (!l->b || !l->org || !l->q || !l->qs || q->nf < 0) {
            q->nf = -1;
            continue;
        }
        memcpy(l->b + m, P->bounds + q->fo, (size_t)q->nf * sizeof *l->b);
        memcpy(l->org + m, P->org + q->fo, (size_t)q->nf * sizeof *l->org);
        q->fo = m;
        m += q->nf;
    }
}

/* Put line l into the history at index at, replacing one at the same v. */
static int keep_line(pass *P, int at, line l)
{
    if (at < P->nlines && P->lines[at].v == l.v) {
        free_line(&P->lines[at]);
        P->lines[at] = l;
        return 0;
    }
    if (P->nlines == P->caplines) {
        int cap = P->caplines ? 2 * P->caplines : 64;
        line *g = realloc(P->lines, (size_t)cap * sizeof *g);
        if (!g) return -1;
        P->lines = g;
        P->caplines = cap;
    }
    memmove(&P->lines[at + 1], &P->lines[at], (size_t)(P->nlines - at) * sizeof *P->lines);
    P->lines[at] = l;
    P->nlines++;
    return 0;
}

/* The inner integral along the line at v, its first samples hinted by the
 * lines already integrated nearest to it: where a piece narrows to a point
 * (the tip of a face, a sphere's pole) the even samples can miss it, the
 * pieces of two lines either side cannot.  The line joins the history. */
static int line_eval(void *ctx, sample *sm)
{
    pass *P = ctx;
    double v = sm->x, *f = sm->f;
    uint64_t *sig = &sm->sig;
    sm->slope = NAN; /* set below: d(area of the line's section)/dv */
    sm->fo = 0;
    sm->nf = -1; /* (no boundaries across the lines) */
    double ua, ub;
    if (!box_span(&P->box, v, PAD * 2 * P->reach, &ua, &ub)) {
        memset(f, 0, NF * sizeof *f);
        *sig = 0;
        return 0;
    }
    frame_at(P, v);
    int lo = line_index(P, v);
    int up = lo < P->nlines && P->lines[lo].v == v ? lo + 1 : lo; /* past itself */
    const line *L0 = lo >= 2 ? &P->lines[lo - 2] : NULL, *L1 = lo >= 1 ? &P->lines[lo - 1] : NULL,
               *L2 = up < P->nlines ? &P->lines[up] : NULL,
               *L3 = up + 1 < P->nlines ? &P->lines[up + 1] : NULL;
    int n = 0;
    if (P->guide) hints_from(P->guide, NULL, v, NULL, 0, P->hints, &n, MAX_HINTS);
    /* (lines either side alike: their pieces carried to v below cover
     * their own middles, 3 % of the bench part's rays) */
    int alike = L1 && L2 && L1->seq == L2->seq && L1->np == L2->np;
    const line *ls[4] = {L0, L1, L2, L3};
    double paired[MAX_HINTS / 2];
    int np = 0;
    event_hints(P, ls, v, PAIR * 2 * P->reach, 2 * P->reach, P->hints, &n, MAX_HINTS, paired, &np);
    if (L1 && !alike) hints_from(L1, L0, v, paired, np, P->hints, &n, MAX_HINTS);
    if (L2 && !alike) hints_from(L2, L3, v, paired, np, P->hints, &n, MAX_HINTS);
    if (L1 && L2) hints_from(L1, L2, v, paired, np, P->hints, &n, MAX_HINTS);
    seed_hints(P, v, (ub - ua) / SAMPLES, P->hints, &n, MAX_HINTS);
    P->v = v;
    P->inner.quick = P->outer.bisecting;
    P->inner.hints = P->hints;
    P->inner.nhints = n;
    if (integrate(&P->inner, ua, ub) != 0) return -1;
    memcpy(f, P->inner.sum, sizeof P->inner.sum);
    sm->slope = f[5];
    /* The line's signature: the multiset of its events (the changes in
     * the set of faces from piece to piece), less slivers narrower than
     * SLIVER of the span; the pieces' order (seq) matches lines for
     * hints.  Where bisection lands decides whether it sees a sliver at
     * all (one that exists only next to an event), and a signature that
     * flickered with it would bracket events that are not there; a true
     * event's new piece is dropped only while it is a sliver, which moves
     * the event by as little. */
    uint64_t seq = 0, last = 0, lastset = 0, changes = 0;
    int any = 0;
    for (int k = 0; k < P->inner.npieces; k++) {
        const piece *q = &P->inner.pieces[k];
        if (q->x1 - q->x0 < SLIVER * 2 * P->reach || (any && q->sig == last)) continue;
        seq = mix(seq, q->sig);
        if (any) changes += mix(1, q->set - lastset);
        last = q->sig;
        lastset = q->set;
        any = 1;
    }
    *sig = changes;
    line l = {.v = v,
              .seq = seq,
              .np = P->inner.npieces,
              .p = malloc((size_t)P->inner.npieces * sizeof(piece))};
    if (!l.p) return -1;
    memcpy(l.p, P->inner.pieces, (size_t)l.np * sizeof *l.p);
    keep_bounds(P, &l);
    if (keep_line(P, lo, l) != 0) {
        free_line(&l);
        return -1;
    }
    return 0;
}

/* The index of the history's line at v exactly, or -1. */
static int line_at(const pass *P, double v)
{
    int i = line_index(P, v);
    return i < P->nlines && P->lines[i].v == v ? i : -1;
}

/* The line at s->x again, hinted first by the pieces of the line at
 * guide->x: a piece that the line missed while its nearest lines did too
 * (the tip of a primitive, narrower than the first samples, that a later
 * line found). */
static int line_again(void *ctx, sample *s, const sample *guide)
{
    pass *P = ctx;
    int lo = line_at(P, guide->x);
    if (lo < 0) return 0;
    P->guide = &P->lines[lo]; /* (read for hints before line_eval moves the lines) */
    int rc = line_eval(P, s);
    P->guide = NULL;
    return rc;
}

/* The root of the polynomial through (w, y) (n of them, 2 or 3, w[0] = 0)
 * nearest to 0 on the side of sgn; NAN where none. */
static double root_toward(const double *w, const double *y, int n, double sgn)
{
    double al = y[0], be, ga = 0;
    if (n == 3) {
        double det = w[1] * w[2] * (w[2] - w[1]);
        if (!(fabs(det) > 0)) return NAN;
        be = ((y[1] - al) * w[2] * w[2] - (y[2] - al) * w[1] * w[1]) / det;
        ga = ((y[2] - al) * w[1] - (y[1] - al) * w[2]) / det;
    } else {
        be = (y[1] - al) / w[1];
    }
    double r[2] = {NAN, NAN};
    if (fabs(ga) <= 1e-9 * fabs(be) * fmax(fabs(w[1]), fabs(w[n - 1]))) {
        r[0] = -al / be;
    } else {
        double disc = be * be - 4 * al * ga;
        if (disc < 0) return NAN;
        double q = -0.5 * (be + copysign(sqrt(disc), be));
        r[0] = q / ga;
        r[1] = q != 0 ? al / q : NAN;
    }
    double best = NAN;
    for (int i = 0; i < 2; i++)
        if (r[i] * sgn > 0 && !(fabs(best) <= fabs(r[i]))) best = r[i];
    return best;
}

/* The width of piece k + 1 of line l (between its events k and k + 1) on
 * the line at v: those two events followed there from l's pieces k to
 * k + 2 (exact_event, each the one foreseen nearest to where it is on l);
 * NAN where either is not foreseen.  Leaves P->frame at v. */
static double width_at(pass *P, const line *l, int k, double v)
{
    frame_at(P, v);
    sample last;
    int lastk = -1;
    double span = 2 * P->reach;
    double x0 = exact_event(P, l, k, l->p[k].x1, span, &last, &lastk);
    double x1 = isnan(x0) ? NAN : exact_event(P, l, k + 1, l->p[k + 1].x1, span, &last, &lastk);
    return x1 - x0;
}

/* Where piece k + 1 of line near closes on its way to line far: its width
 * followed to each line tried (width_at, no rays cast), the tries where a
 * straight line through the last two widths reaches the width of a sliver
 * (SLIVER: where the piece leaves the lines' signatures) — exact where two
 * faces or silhouettes cross — and where one through their squares does
 * — exact where a silhouette turns back, a sphere's top — (guess first,
 * where given), each kept inside a bracket of a line where the piece is
 * wider and one where it is not or cannot be followed, and halved where
 * neither try falls inside.  Closed to a quarter of a try's width, where
 * the piece has narrowed to under a hundredth of its width on near (its
 * boundaries lost on the way, rather than closing: a piece that far has
 * too where another event turns up between them); NAN where it has not. */
static double closing(pass *P, const line *near, double lim, int k, double guess)
{
    double lo = near->v, hi = lim, w = near->p[k + 1].x1 - near->p[k + 1].x0, w0 = w;
    double lo1 = NAN, w1 = NAN, s = SLIVER * 2 * P->reach;
    if (!(w > s) || isnan(width_at(P, near, k, lo)) || width_at(P, near, k, hi) > s) return NAN;
    for (int it = 0; it < 64 && fabs(hi - lo) > 0.25 * P->outer.try_eps; it++) {
        double c[3] = {guess, NAN, 0.5 * (lo + hi)};
        if (!isnan(lo1)) {
            c[0] = lo - (w - s) * (lo - lo1) / (w - w1);
            c[1] = lo - (w * w - s * s) * (lo - lo1) / (w * w - w1 * w1);
            /* neither foresees it closing ahead within three brackets: the
             * piece is being lost, not closing */
            double r0 = (c[0] - lo) / (hi - lo), r1 = (c[1] - lo) / (hi - lo);
            if (!(r0 > 0 && r0 <= 3) && !(r1 > 0 && r1 <= 3)) break;
        } else if (it >= 16) {
            break; /* lost within a 65536th of the way */
        }
        int moved = 0;
        for (int i = 0; i < 3 && !moved; i++) {
            if (!((c[i] - lo) * (hi - c[i]) > 0)) continue;
            double wc = width_at(P, near, k, c[i]);
            if (wc > s) {
                lo1 = lo;
                w1 = w;
                lo = c[i];
                w = wc;
                moved = 1;
            } else {
                hi = c[i];
            }
        }
    }
    return w < 0.01 * w0 ? 0.5 * (lo + hi) : NAN;
}

/* Where a piece of line `near` that line `far` lacks (an event of its two
 * that far has not) narrows to nothing, from its widths on near and on
 * the lines beyond near away from far (next, and next2; NULL where none),
 * where it was wider: the square of its width extrapolated to zero as a
 * polynomial (a silhouette turning back, where it goes to zero linearly;
 * short of where two faces cross) — with exact, that refined by closing()
 * (or where it cannot be extrapolated, found by it).  The nearest to near
 * of what the pieces foresee; NAN where none does. */
static double narrowing(pass *P, const line *next2, const line *next, const line *near,
                        const line *far, int exact)
{
    static _Thread_local event_at ev[4][LINE_EVENTS];
    const line *ls[4] = {near, next, next2, far};
    int ne[4];
    for (int i = 0; i < 4; i++)
        ne[i] = ls[i] ? line_events(ls[i], ev[i], LINE_EVENTS) : 0;
    double best = NAN, sgn = far->v - near->v;
    for (int k = 0; k + 1 < ne[0]; k++) {
        const event_at *e = &ev[0][k], *f = &ev[0][k + 1];
        if (!isnan(event_like(ev[3], ne[3], e)) && !isnan(event_like(ev[3], ne[3], f))) continue;
        double w[3], y[3];
        int n = 0;
        for (int i = 0; i < 3; i++) {
            double d = i ? event_like(ev[i], ne[i], f) - event_like(ev[i], ne[i], e) : f->x - e->x;
            if (!ls[i] || !(d > 0) || (n && !(d * d > y[n - 1]))) break; /* narrowing toward far */
            w[n] = ls[i]->v - near->v;
            y[n++] = d * d;
        }
        double t = n < 2 ? NAN : root_toward(w, y, n, sgn);
        if (exact) {
            t = closing(P, near, isnan(best) ? far->v : best, k, near->v + t) - near->v;
            P->nforms = 0;
        }
        if (!isnan(t) && !(fabs(best - near->v) <= fabs(t))) best = near->v + t;
    }
    return best;
}

/* The outer level's guess (level.guess): narrowing() from the lines at a
 * and at b, each with its neighbours in the history beyond it, exact
 * (kind 0) or extrapolated (1); the one foreseen nearer to its line.  A
 * line that missed the model's box is not kept: it has no pieces. */
static double line_guess(void *ctx, double a, double b, int kind)
{
    pass *P = ctx;
    int ia = line_at(P, a), ib = line_at(P, b);
    const line none[2] = {{.v = a}, {.v = b}};
    if ((ia < 0 || ib < 0) && (kind != 0 || (ia < 0 && ib < 0))) return NAN;
    const line *A = ia >= 0 ? &P->lines[ia] : &none[0], *B = ib >= 0 ? &P->lines[ib] : &none[1];
    double ga = ia < 0 ? NAN
                       : narrowing(P, ia > 1 ? &P->lines[ia - 2] : NULL,
                                   ia > 0 ? &P->lines[ia - 1] : NULL, A, B, kind == 0);
    double gb = ib < 0 ? NAN
                       : narrowing(P, ib + 2 < P->nlines ? &P->lines[ib + 2] : NULL,
                                   ib + 1 < P->nlines ? &P->lines[ib + 1] : NULL, B, A, kind == 0);
    if (!(ga > a && ga < b)) ga = NAN;
    if (!(gb > a && gb < b)) gb = NAN;
    if (isnan(ga)) return gb;
    if (isnan(gb)) return ga;
    return ga - a < b - gb ? ga : gb;
}

static void *run_pass(void *arg)
{
    pass *P = arg;
    double va = P->box.vlo, vb = P->box.vhi, pad = PAD * 2 * P->reach;
    int n = 0;
    seed_hints(P, NAN, (vb - va) / SAMPLES, P->outer_hints, &n, MAX_HINTS);
    P->outer.hints = P->outer_hints;
    P->outer.nhints = n;
    P->rc = integrate(&P->outer, va - pad, vb + pad);
    return NULL;
}

/* Set up pass k of the three: along frame direction k, the scene's box
 * lo..hi, tolerance tol. */
static void pass_init(pass *P, const csg_scene *s, int root, double frame[3][3], int k,
                      const double lo[3], const double hi[3], double tol)
{
    memset(P, 0, sizeof *P);
    P->s = s;
    P->root = root;
    memcpy(P->d, frame[k], sizeof P->d);
    memcpy(P->e1, frame[(k + 1) % 3], sizeof P->e1);
    memcpy(P->e2, frame[(k + 2) % 3], sizeof P->e2);
    double diag[3];
    for (int a = 0; a < 3; a++) {
        P->c[a] = 0.5 * (lo[a] + hi[a]);
        diag[a] = hi[a] - lo[a];
    }
    P->reach = fmax(0.5 * sqrt(dot3(diag, diag)) * (1 + 1e-6), 1e-300);
    for (int a = 0; a < 3; a++) {
        P->ext[0][a][a] = INFINITY;
        P->ext[1][a][a] = -INFINITY;
    }
    project_box(P, lo, hi, &P->box);
    double span = 2 * P->reach;
    /* Error norms: the volume and moments in units of the bounding
     * sphere's, the area in its. */
    P->outer.eval = line_eval;
    P->outer.again = line_again;
    P->outer.guess = line_guess;
    P->outer.ctx = P;
    /* An event across the lines is bracketed by whole lines; the bracket
     * is integrated by the trapezoid rule.  Where a silhouette turns back
     * in v (a sphere's top) the projected area of the part beyond goes as
     * (v0 − v)^1.5, so a bracket eps wide is off by about eps^1.5 of it
     * (a kink costs eps²): 0.1 tol^(2/3) of the span keeps that below the
     * tolerance and falling with it (the bench part at 1e-6: area 4e-8
     * off).  A try's samples are a tenth of the tolerance of the span
     * apart (1e-9 to 1e-6): a try at a guess that foresaw such a turn
     * exactly (line_guess) brackets it that narrowly, its part then off by
     * far less (the cube less a sphere at 1e-7: area 2.4e-9 off with the
     * samples 1e-6 apart, 2.4e-11 at 1e-8); an event between plane faces,
     * which the try finds exactly, is still integrated exactly. */
    P->outer.eps = fmin(fmax(OUTER_EPS, 0.1 * pow(tol, 2.0 / 3)), 1e-3) * span;
    P->outer.try_eps = fmin(fmax(0.1 * tol, 1e-9), OUTER_EPS) * span;
    P->outer.min_panel = MIN_PANEL * span;
    P->outer.tol = tol * span * span;
    P->outer.weight[0] = 1;
    for (int a = 1; a < 4; a++)
        P->outer.weight[a] = 1 / span;
    P->outer.weight[4] = 1;
    P->inner = P->outer;
    P->inner.eval = ray_eval;
    P->inner.again = NULL;
    P->inner.guess = NULL;
    P->inner.follow = follow_eval;
    P->inner.foresee = foresee;
    P->inner.tol = 0.1 * tol * span;
    P->inner.eps = P->inner.try_eps = EPS * span;
    P->outer.across = 1;
    P->outer.samples = P->inner.samples = SAMPLES;
}

/* run_pass on the three passes, side by side. */
static void run_passes(pass *P)
{
    pthread_t th[3];
    int started[3] = {0, 0, 0};
    for (int k = 1; k < 3; k++)
        started[k] = pthread_create(&th[k], NULL, run_pass, &P[k]) == 0;
    run_pass(&P[0]);
    for (int k = 1; k < 3; k++) {
        if (!started[k]) run_pass(&P[k]);
        if (started[k]) pthread_join(th[k], NULL);
    }
}

/* The three passes each measure the volume: where they disagree by more
 * than a tenth of the tolerance, the first samples of one stepped over a
 * piece (a fragment of a difference seen edge-on, a thin wall) that another
 * found, and which one cannot be told (two can miss alike): 1, all three
 * to run again.  Likewise where none found anything in the model's box: a
 * small fragment can slip between the first samples of all three (a
 * difference's sliver of 1.3e-4 in a box of 30). */
static int passes_disagree(const pass *P, double tol)
{
    double lo = INFINITY, hi = -INFINITY, span = 2 * P[0].reach;
    for (int k = 0; k < 3; k++) {
        lo = fmin(lo, P[k].outer.sum[0]);
        hi = fmax(hi, P[k].outer.sum[0]);
    }
    return hi - lo > 0.1 * tol * fmax(fabs(lo), fabs(hi)) + 1e-12 * span * span * span || hi <= 0;
}

/* Empty pass P's history of lines. */
static void forget_lines(pass *P)
{
    for (int i = 0; i < P->nlines; i++)
        free_line(&P->lines[i]);
    P->nlines = 0;
}

/* Ready pass P to run again with twice the first samples. */
static void pass_again(pass *P)
{
    forget_lines(P);
    P->outer.samples *= 2;
    P->inner.samples *= 2;
}

static void pass_free(pass *P)
{
    forget_lines(P);
    free(P->lines);
    free(P->inner.pieces);
    free(P->outer.pieces);
    free(P->seeds);
    free(P->bounds);
    free(P->forms);
    free(P->org);
    free(P->state);
    if (P->arena) iv_arena_free(P->arena);
}

/* The first hit of the ray along axis a (direction sgn, from outside the
 * model's box) through the point with x's other two coordinates shifted by
 * (du, dv): 1 with its point p and (n not NULL) normal n, 0 when it
 * misses, -1. */
static int probe_axis(pass *P, int a, int sgn, const double x[3], double du, double dv, double p[3],
                      double n[3])
{
    int u = (a + 1) % 3, v = (a + 2) % 3;
    double o[3], d[3] = {0, 0, 0};
    d[a] = -sgn;
    o[a] = P->c[a] + sgn * P->reach;
    o[u] = x[u] + du;
    o[v] = x[v] + dv;
    iv_arena_reset(P->arena);
    iv_bound hit;
    int rc = csg_trace_first(P->s, P->root, o, d, 0, 2 * P->reach, P->arena, &hit);
    if (rc <= 0) return rc;
    for (int c = 0; c < 3; c++)
        p[c] = o[c] + hit.t * d[c];
    if (n) csg_scene_normal(P->s, &hit, o, d, n);
    return 1;
}

/* Where the extreme is a corner of plane faces, the compass search can
 * stall on one of its ridges short of it.  The faces around x (rays on three
 * rings about it) meet at the corner: of the points where three of their
 * planes meet, the farthest along the axis that a ray through it confirms
 * (its first hit there, to 1e-9 of the span) replaces x. */
static int corner(pass *P, int a, int sgn, double x[3], long long *count)
{
    enum { MAXP = 16 };
    double pl[MAXP][4], span = 2 * P->reach;
    int np = 0;
    static const double radius[3] = {1e-5, 1e-3, 3e-2};
    for (int ring = 0; ring < 3; ring++)
        for (int k = 0; k < 16; k++) {
            double r = radius[ring] * span, ang = 0.39269908169872414 * (k + 0.5 * ring), p[3],
                   n[3];
            (*count)++;
            int rc = probe_axis(P, a, sgn, x, r * cos(ang), r * sin(ang), p, n);
            if (rc < 0) return -1;
            if (rc == 0) continue;
            int dup = 0;
            for (int i = 0; i < np && !dup; i++)
                dup = fabs(dot3(n, pl[i]) - 1) < 1e-12 && fabs(dot3(n, p) - pl[i][3]) < 1e-9 * span;
            if (dup || np == MAXP) continue;
            memcpy(pl[np], n, sizeof n);
            pl[np++][3] = dot3(n, p);
        }
    for (int i = 0; i < np; i++)
        for (int j = i + 1; j < np; j++)
            for (int k = j + 1; k < np; k++) {
                double jk[3], ki[3], ij[3], q[3], p[3], n[3];
                cross3(pl[j], pl[k], jk);
                cross3(pl[k], pl[i], ki);
                cross3(pl[i], pl[j], ij);
                double det = dot3(pl[i], jk);
                if (!(fabs(det) > 1e-6)) continue;
                for (int c = 0; c < 3; c++)
                    q[c] = (pl[i][3] * jk[c] + pl[j][3] * ki[c] + pl[k][3] * ij[c]) / det;
                if (!((q[a] - x[a]) * sgn > 0)) continue;
                double sh[3] = {q[0] - x[0], q[1] - x[1], q[2] - x[2]};
                (*count)++;
                int rc = probe_axis(P, a, sgn, x, sh[(a + 1) % 3], sh[(a + 2) % 3], p, n);
                if (rc < 0) return -1;
                if (rc == 1 && fabs(p[a] - q[a]) < 1e-9 * span) memcpy(x, q, sizeof q);
            }
    return 0;
}

/* The model's extent along axis a, in direction sgn (+1: its highest
 * point), from a hit *x of the integration: a compass search over rays
 * along the axis, each moving to the farthest first hit of eight
 * neighbours, the step halved from 1e-2 to 1e-12 of the span where none is
 * farther.  *x is updated; rays counted in *count; 0 or -1. */
static int extreme(pass *P, int a, int sgn, double x[3], long long *count)
{
    double span = 2 * P->reach;
    for (double step = 1e-2 * span; step > 1e-12 * span;) {
        double best = x[a] * sgn, at[3];
        int moved = 0;
        for (int k = 0; k < 8; k++) {
            static const int du[8] = {1, 1, 0, -1, -1, -1, 0, 1},
                             dv[8] = {0, 1, 1, 1, 0, -1, -1, -1};
            double p[3];
            (*count)++;
            int rc = probe_axis(P, a, sgn, x, du[k] * step, dv[k] * step, p, NULL);
            if (rc < 0) return -1;
            if (rc == 0 || !(p[a] * sgn > best)) continue;
            best = p[a] * sgn;
            memcpy(at, p, sizeof p);
            moved = 1;
        }
        if (moved)
            memcpy(x, at, sizeof at);
        else
            step *= 0.5;
    }
    return corner(P, a, sgn, x, count);
}

/* The boxes of root's primitives (finite ones, up to MAX_SEEDS; none
 * past that) into *box (lo, hi; free); their number, or -1. */
static int leaf_boxes(const csg_scene *s, int root, double (**box)[2][3])
{
    *box = NULL;
    int32_t top = csg_scene_root_node(s, root);
    if (top < 0) return 0;
    csg_scene_node_info t;
    csg_scene_node_get(s, top, &t);
    int n = 0;
    for (int32_t i = top; i < t.end; i++) {
        csg_scene_node_info f;
        csg_scene_node_get(s, i, &f);
        if (!f.is_leaf || !isfinite(f.lo[0] + f.lo[1] + f.lo[2] + f.hi[0] + f.hi[1] + f.hi[2]))
            continue;
        if (n == MAX_SEEDS) {
            free(*box);
            *box = NULL;
            return 0;
        }
        if (n % 64 == 0) {
            double(*g)[2][3] = realloc(*box, (size_t)(n + 64) * sizeof *g);
            if (!g) return -1;
            *box = g;
        }
        memcpy((*box)[n][0], f.lo, sizeof f.lo);
        memcpy((*box)[n][1], f.hi, sizeof f.hi);
        n++;
    }
    return n;
}

int mesh_measure_exact(const csg_scene *s, int root, double tol, const mesh_exact_limits *limits,
                       mesh_measure *out, char *err, size_t errlen)
{
    long long max_rays = limits->max_rays;
    int max_intervals = limits->max_intervals;
    memset(out, 0, sizeof *out);
    for (int k = 0; k < 3; k++) {
        out->lo[k] = INFINITY;
        out->hi[k] = -INFINITY;
    }
    double lo[3], hi[3];
    if (root < 0 || root >= csg_scene_root_count(s) || csg_scene_bounds(s, root, lo, hi) != 0)
        return 0; /* empty */
    for (int k = 0; k < 3; k++)
        if (!isfinite(lo[k]) || !isfinite(hi[k])) {
            snprintf(err, errlen, "the model is unbounded (infinite along %c); cannot measure it",
                     "xyz"[k]);
            return -1;
        }
    if (!(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2])) return 0;
    /* An orthonormal frame oblique to every axis and to the planes at 45°
     * between them (the standard axes turned 0.7 rad about (2, 3, 5)): no
     * face of an ordinary model lies along one of its directions. */
    double frame[3][3] = {{0.789595641255, 0.559659724661, -0.251634091299},
                          {-0.485399362751, 0.820537458717, 0.301837269870},
                          {0.375401361149, -0.116186365095, 0.919551274597}};
    pass P[3];
    int rc = 0;
    double(*leaf)[2][3];
    int nleaf = leaf_boxes(s, root, &leaf); /* for seed_hints */
    if (nleaf < 0) rc = -1;
    for (int k = 0; k < 3; k++) {
        pass_init(&P[k], s, root, frame, k, lo, hi, tol);
        P[k].seeds = nleaf > 0 ? malloc((size_t)nleaf * sizeof(seed)) : NULL;
        if (nleaf > 0 && !P[k].seeds) rc = -1;
        for (int i = 0; P[k].seeds && i < nleaf; i++)
            project_box(&P[k], leaf[i][0], leaf[i][1], &P[k].seeds[P[k].nseeds++]);
        P[k].arena = iv_arena_new(0);
        if (!P[k].arena) rc = -1;
        if (P[k].arena && max_intervals > 0) iv_arena_set_list_limit(P[k].arena, max_intervals);
        P[k].budget = max_rays > 0 ? max_rays / 3 + 1 : -1;
        P[k].limits = limits;
    }
    free(leaf);
    for (int round = 0; rc == 0; round++) {
        run_passes(P);
        if (round == RECHECKS || P[0].rc || P[1].rc || P[2].rc || !passes_disagree(P, tol)) break;
        for (int k = 0; k < 3; k++)
            pass_again(&P[k]);
    }
    long long count = 0;
    int too_long = 0, over = 0, cancelled = 0;
    for (int k = 0; k < 3; k++) {
        if (P[k].rc != 0) rc = -1;
        if (P[k].arena && iv_arena_failure(P[k].arena) == IV_ARENA_LIST_TOO_LONG) too_long = 1;
        over |= P[k].over;
        cancelled |= P[k].cancelled;
        count += P[k].count;
    }
    for (int a = 0; a < 3 && rc == 0; a++)
        for (int e = 0; e < 2 && rc == 0; e++) {
            double x[3];
            memcpy(x, P[0].ext[e][a], sizeof x);
            for (int k = 1; k < 3; k++)
                if (e ? P[k].ext[e][a][a] > x[a] : P[k].ext[e][a][a] < x[a])
                    memcpy(x, P[k].ext[e][a], sizeof x);
            if (!isfinite(x[a])) continue; /* empty */
            rc = extreme(&P[0], a, e ? 1 : -1, x, &count);
            (e ? out->hi : out->lo)[a] = x[a];
        }
    out->crossings = count;
    if (rc == 0) {
        out->volume = P[0].outer.sum[0];
        for (int k = 0; k < 3; k++) {
            out->area += P[k].outer.sum[4];
            out->centroid[k] =
                out->volume > 0 ? P[0].c[k] + P[0].outer.sum[1 + k] / out->volume : 0;
        }
    } else if (too_long) {
        rc = RAYSCAD_ERROR_INTERVALS;
        snprintf(err, errlen, "a ray's interval list holds more than %d intervals",
                 max_intervals > 0 ? max_intervals : IV_LIST_LIMIT_DEFAULT);
    } else if (cancelled) {
        rc = RAYSCAD_CANCELLED;
        snprintf(err, errlen, "the exact measurement was stopped");
    } else if (over) {
        rc = RAYSCAD_ERROR_RAYS;
        snprintf(err, errlen, "the exact measurement needs more than %lld rays", max_rays);
    } else {
        snprintf(err, errlen, "out of memory");
    }
    for (int k = 0; k < 3; k++)
        pass_free(&P[k]);
    return rc;
}
