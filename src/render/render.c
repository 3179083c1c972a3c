/*
 * render.c — the image loop: 32×32 tiles drawn by the worker pool
 * (tiles.c), each worker with its own iv_arena that is reset after every
 * primary sample.
 *
 * Per ray (deferred shading): trace every root of the scene into interval
 * lists, merge their boundaries by depth (a three-way merge: each list is
 * already sorted), and walk them front to back.  Only then, for a boundary
 * that contributes colour, ask the scene for its normal and shade it;
 * compositing stops once the accumulated opacity is about 1, so an opaque
 * model costs one normal per ray however deep the list is.  Every boundary
 * counts, entering and exiting — OpenSCAD's preview draws back faces too,
 * which only transparency reveals.  Boundaries made by the camera's clip
 * planes are not surfaces and are skipped, as the GL near plane opens a
 * solid rather than capping it.  Since the order is the depth order of the
 * exact boundaries, permuting the objects of a file cannot change a pixel
 * (ties between roots go to the one OpenSCAD draws last).
 *
 * Most rays end at their first surface, opaque, so a ray first asks the
 * scene for that boundary alone (csg_trace_first, which skips what lies
 * behind it) and takes the full lists only when the first surface lets light
 * through; shadow rays likewise stop at an opaque occluder.  Both ways give
 * the same bytes.
 *
 * The opt-in light model (render_options below `ud`, $rs_ materials) adds,
 * in the same walk: shadow rays that multiply the transmittances of every
 * surface they cross (Beer–Lambert for absorbing spans); mirror rays and
 * refracted rays, recursively, to a depth limit; area lights sampled over
 * stratified discs; a thin lens; and jittered strata.  Random numbers come
 * from a counter hash of (seed, pixel, draw), so they too depend only on
 * the pixel.
 *
 * Invariant: a pixel's value depends only on its position and the inputs —
 * never on the tile order or the thread that drew it — so any thread count
 * gives the same bytes.
 */
#include "render.h"
#include "path_trace.h"
#include "sampling.h"
#include "section.h"
#include "shade.h"
#include "surface.h"
#include "tiles.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_ROOTS = 3, MAX_SAMPLES = 64, MAX_LIGHT_SAMPLES = 16 };

typedef struct job {
    render_frame f;
    int nroots;
    int live[MAX_ROOTS], nlive; /* the roots that are not empty, in order */
    /* the light model, resolved once */
    int lit;      /* shadow rays and the lights below */
    int keylight; /* lit by the preview's own pair, the key one shadowed */
    int jitter;   /* stratified samples jittered (stochastic features on) */
    render_light lights[RAYSCAD_MAX_LIGHTS];
    int nlights;
    int light_n;   /* shadow rays per light: light_n² */
    int max_depth; /* secondary rays */
    double eps;    /* offset of secondary ray origins (render_ray_offset) */
    double focus;  /* thin lens */
    int first_hit; /* csg_trace_first may stand in for the full lists */
    /* Primary samples outside cover (x0, x1, y0, y1) see the background
     * alone (render_raygen_cover); covered: no such rectangle is known. */
    double cover[4];
    int covered;
} job;

static void set_err(char *err, size_t errlen, const char *msg)
{
    if (err && errlen) snprintf(err, errlen, "%s", msg);
}

/* What a worker thread carries from ray to ray: its arena, the current
 * pixel's random stream, and whether the last primary (or shadow) ray's
 * first surface was one that csg_trace_first alone could not have handled.
 * Both paths give the same bytes (see trace_ray); the flags only guess which
 * is cheaper, so a transparent region is not traced twice per ray. */
typedef struct worker_ctx {
    iv_arena *a;
    rng g;
    int full_primary, full_shadow; /* 0 (as the pool starts it): try the first boundary */
} worker_ctx;

/* Where two boundaries share a depth, the one drawn later by OpenSCAD wins
 * the depth test (GL_LEQUAL for modifiers): highlight over background over
 * model.  Lower rank = nearer. */
static const int root_rank[MAX_ROOTS] = {2, 0, 1};

/* ---- shadows ------------------------------------------------------------------ */

/* Whether transmittance's product is 0 once the first boundary b of a shadow
 * ray's list is crossed: a surface (not a clip, not an emitter) whose own
 * factor is already below the RENDER_DARK cut-off (an absorbing volume's is
 * 1: its span needs the exit).  Alphas lie in [0, 1] (color() rejects
 * negative ones, render_surface_color caps at 1), so the later factors are
 * at most 1 and the product stays below the cut-off, which transmittance
 * returns as 0. */
static int stops_light(const job *J, const iv_bound *b)
{
    if (b->prim == IV_PRIM_NONE) return 0;
    float c[4];
    const csg_material *m;
    render_surface_color(J->f.scene, J->f.opt, RAYSCAD_ROOT_MODEL, b, c, &m);
    if (m->emit > 0) return 0;
    double sigma = render_surface_absorption(J->f.opt, m, c[3]);
    return render_surface_transmittance(c[3], sigma) < RENDER_DARK;
}

/* The fraction of light that passes along o + t·d, t in (0, tmax), through
 * the model: the product of (1 - alpha) of every surface crossed, and
 * exp(-σ·L) over absorbing spans.  Emitters cast no shadow.  Returns -1
 * when the arena is out of memory. */
static double transmittance(const job *J, worker_ctx *wk, const double o[3], const double d[3],
                            double tmax)
{
    if (J->first_hit && !wk->full_shadow) {
        iv_bound b;
        int rc = render_trace_first(J->f.scene, J->f.opt->section, RAYSCAD_ROOT_MODEL, o, d, 0,
                                    tmax, wk->a, &b);
        if (rc < 0) return -1;
        if (rc == 0) return 1; /* nothing in the way: the loop below leaves T = 1 */
        if (stops_light(J, &b)) return 0;
        wk->full_shadow = 1;
    }
    iv_list l;
    memset(&l, 0, sizeof l);
    if (render_trace(J->f.scene, J->f.opt->section, RAYSCAD_ROOT_MODEL, o, d, 0, tmax, wk->a, &l) !=
        0)
        return -1;
    if (J->first_hit) wk->full_shadow = !(l.n == 0 || stops_light(J, &l.v[0].enter));
    double T = 1;
    for (int i = 0; i < l.n && T > RENDER_DARK; i++) {
        const iv_span *sp = &l.v[i];
        for (int e = 0; e < 2; e++) {
            const iv_bound *b = e ? &sp->exit : &sp->enter;
            if (b->prim == IV_PRIM_NONE) continue;
            float c[4];
            const csg_material *m;
            render_surface_color(J->f.scene, J->f.opt, RAYSCAD_ROOT_MODEL, b, c, &m);
            if (m->emit > 0) continue;
            double sigma = render_surface_absorption(J->f.opt, m, c[3]);
            T *= render_surface_transmittance(c[3], sigma);
            /* an absorbing span counts once: from its entry, or from o when
             * it was entered before o (the clip) */
            if (sigma > 0 && (e == 0 || sp->enter.prim == IV_PRIM_NONE))
                T *= render_span_transmittance(sigma, sp->exit.t - sp->enter.t);
        }
    }
    return T < RENDER_DARK ? 0 : T;
}

/* The lighting factor at hit h (its normal nf turned toward the viewer)
 * under the opt-in model: ambient 0.2 plus, per light, intensity ×
 * cos θ × the mean transmittance of its shadow rays.  The preview's pair of
 * opposite directional lights when no light is given: the key light
 * (-1,-1,1)/√3 in the viewer's frame casts shadows, its opposite fill does
 * not, so an unshadowed point gets exactly the preview's factor.  Returns
 * -1 when out of memory. */
static double light_factor(const job *J, worker_ctx *wk, const render_hit *h)
{
    const render_camera *c = J->f.cam;
    const double *p = h->p, *nf = h->nf;
    double o[3]; /* every shadow ray leaves on the side nf faces */
    render_ray_spawn(h, nf, RENDER_SPAWN_SIDE, J->eps, o);
    double f = 0.2;
    if (J->keylight) {
        const double k = 0.57735026918962576;
        double L[3];
        for (int i = 0; i < 3; i++)
            L[i] = k * (-c->right[i] - c->forward[i] + c->up[i]);
        double cs = dot3(nf, L);
        if (cs > 0) {
            double T = transmittance(J, wk, o, L, INFINITY);
            if (T < 0) return -1;
            f += cs * T;
        } else {
            f -= cs;
        }
        return f;
    }
    int n = J->light_n;
    for (int li = 0; li < J->nlights; li++) {
        const render_light *L = &J->lights[li];
        double w[3], u[3], v[3];
        for (int i = 0; i < 3; i++)
            w[i] = L->pos[i] - p[i];
        double dist = sqrt(dot3(w, w));
        if (!(dist > 0)) continue;
        normalize3(w);
        int ns = L->radius > 0 ? n : 1;
        basis_of(w, u, v); /* used only when ns > 1 */
        double sum = 0;
        for (int sj = 0; sj < ns; sj++)
            for (int si = 0; si < ns; si++) {
                double q[3];
                memcpy(q, L->pos, sizeof q);
                if (ns > 1) {
                    double dx, dy;
                    square_to_disc((si + rng_next(&wk->g)) / ns, (sj + rng_next(&wk->g)) / ns, &dx,
                                   &dy);
                    disc_point(L->pos, L->radius, u, v, dx, dy, q);
                }
                double dir[3], len = toward(o, q, dir);
                if (!(len > 0)) continue;
                double cs = dot3(nf, dir);
                if (cs <= 0) continue;
                double T = transmittance(J, wk, o, dir, len);
                if (T < 0) return -1;
                sum += cs * T;
            }
        f += L->intensity * sum / (ns * ns);
    }
    return f;
}

/* ---- the walk ------------------------------------------------------------------ */

/* Whether trace_ray's walk ends at boundary b of root r when b comes first:
 * an opaque surface (render_surface_opaque; not a clip, not at an infinite
 * t, which the walk skips), so the accumulated opacity passes RENDER_OPAQUE
 * at once — and then neither later surfaces nor refraction are looked at.
 * Mirror rays and shadow rays are traced from b alone, so they do not care.
 * Fills c with b's colour and *m with its material (render_surface_color)
 * when it does. */
static int ends_walk(const job *J, int r, const iv_bound *b, float c[4], const csg_material **m)
{
    if (b->prim == IV_PRIM_NONE || !isfinite(b->t)) return 0;
    render_surface_color(J->f.scene, J->f.opt, r, b, c, m);
    return render_surface_opaque(J->f.opt, *m, c[3]);
}

static int trace_ray(const job *J, worker_ctx *wk, const double o[3], const double d[3],
                     double tmin, double tmax, int depth, double out[3]);

/* A secondary ray (mirror, refracted) leaving hit h along dir, on the side
 * of the surface dir points to. */
static int trace_from(const job *J, worker_ctx *wk, const render_hit *h, const double dir[3],
                      int depth, double out[3])
{
    double o[3];
    render_ray_spawn(h, dir, RENDER_SPAWN_SIDE, J->eps, o);
    return trace_ray(J, wk, o, dir, 0, INFINITY, depth, out);
}

/* The light a surface sends back along the ray at boundary bb, whose
 * material (sb's: bb itself, or the exit of the span a clip opened) has
 * colour c and material m: its shading, mixed with a mirror ray when it
 * reflects, in local; the hit (its point and the normal facing the ray) in
 * h, for a refracted ray.  Returns 0, or -1 when the arena is out of
 * memory. */
static int surface_light(const job *J, worker_ctx *wk, const iv_bound *bb, const iv_bound *sb,
                         const float c[4], const csg_material *m, const double o[3],
                         const double d[3], int depth, double local[3], render_hit *h)
{
    render_surface_hit(J->f.scene, J->f.opt->section, sb, bb->t, o, d, RENDER_GRAZE_ENTERS, h);

    float lit[3];
    if (m->emit > 0) {
        for (int i = 0; i < 3; i++)
            lit[i] = c[i];
    } else if (J->lit) {
        double f = light_factor(J, wk, h);
        if (f < 0) return -1;
        render_shade_apply(c, f, lit);
    } else {
        render_shade_apply(c, render_shade_factor(J->f.cam, h->n), lit);
    }
    for (int i = 0; i < 3; i++)
        local[i] = lit[i];

    if (m->reflect > 0 && depth < J->max_depth && bb->prim != IV_PRIM_NONE) {
        double rd[3], rc[3];
        render_reflect_dir(d, h->nf, rd);
        if (trace_from(J, wk, h, rd, depth + 1, rc) != 0) return -1;
        for (int i = 0; i < 3; i++)
            local[i] = (1 - m->reflect) * local[i] + m->reflect * rc[i];
    }
    return 0;
}

/* The root whose first boundary fb[r] (NULL: none) comes first, ties to the
 * one OpenSCAD draws last (root_rank); -1 when no live root has one. */
static int nearest_root(const job *J, const iv_bound *const fb[MAX_ROOTS])
{
    int best = -1;
    for (int q = 0; q < J->nlive; q++) {
        int r = J->live[q];
        if (fb[r] && (best < 0 || fb[r]->t < fb[best]->t ||
                      (fb[r]->t == fb[best]->t && root_rank[r] < root_rank[best])))
            best = r;
    }
    return best;
}

/* Composite a surface of opacity alpha sending light `local` under what
 * the ray has gathered so far (acc, *acc_a: premultiplied). */
static void composite(double acc[3], double *acc_a, double alpha, const double local[3])
{
    double w = (1 - *acc_a) * alpha;
    for (int i = 0; i < 3; i++)
        acc[i] += w * local[i];
    *acc_a += w;
}

/* What the ray shows once compositing stops: acc over the background. */
static void over_background(const job *J, const double acc[3], double acc_a, double out[3])
{
    const float *bg = J->f.opt->colors.background;
    for (int i = 0; i < 3; i++)
        out[i] = acc[i] + (1 - acc_a) * bg[i];
}

/* One ray: composite every surface of every root front to back over the
 * scheme's background.  Returns 0, or -1 when the arena is out of memory. */
static int trace_ray(const job *J, worker_ctx *wk, const double o[3], const double d[3],
                     double tmin, double tmax, int depth, double out[3])
{
    double acc[3] = {0, 0, 0}, acc_a = 0; /* premultiplied */
    const double *cut = J->f.opt->section;
    if (J->first_hit && !wk->full_primary) {
        /* The walk below composites the nearest boundary of all roots
         * first; when that one is opaque it ends there, and the ray needs
         * that boundary alone. */
        iv_bound fb[MAX_ROOTS];
        const iv_bound *have[MAX_ROOTS] = {NULL};
        for (int q = 0; q < J->nlive; q++) {
            int r = J->live[q];
            int rc = render_trace_first(J->f.scene, cut, r, o, d, tmin, tmax, wk->a, &fb[r]);
            if (rc < 0) return -1;
            if (rc) have[r] = &fb[r];
        }
        int best = nearest_root(J, have);
        float c[4];
        const csg_material *m;
        if (best < 0) {
            over_background(J, acc, acc_a, out);
            return 0;
        }
        if (ends_walk(J, best, &fb[best], c, &m)) {
            /* The walk's one step, as it takes it for this boundary. */
            double local[3];
            render_hit h;
            if (surface_light(J, wk, &fb[best], &fb[best], c, m, o, d, depth, local, &h) != 0)
                return -1;
            composite(acc, &acc_a, c[3], local);
            over_background(J, acc, acc_a, out);
            return 0;
        }
        wk->full_primary = 1;
    }

    iv_list lists[MAX_ROOTS];
    int pos[MAX_ROOTS];    /* next boundary of each list: span pos/2, exit if odd */
    int volume[MAX_ROOTS]; /* the current span was composited as a volume */
    const iv_bound *first[MAX_ROOTS] = {NULL};
    for (int q = 0; q < J->nlive; q++) {
        int r = J->live[q];
        pos[r] = 0;
        volume[r] = 0;
        if (render_trace(J->f.scene, cut, r, o, d, tmin, tmax, wk->a, &lists[r]) != 0) return -1;
        if (lists[r].n > 0) first[r] = &lists[r].v[0].enter;
    }
    if (J->first_hit) {
        int best = nearest_root(J, first);
        float c[4];
        const csg_material *m;
        wk->full_primary = !(best < 0 || ends_walk(J, best, first[best], c, &m));
    }

    while (acc_a < RENDER_OPAQUE) {
        int best = -1;
        const iv_bound *bb = NULL;
        for (int q = 0; q < J->nlive; q++) {
            int r = J->live[q];
            if (pos[r] >= 2 * lists[r].n) continue;
            const iv_span *sp = &lists[r].v[pos[r] / 2];
            const iv_bound *b = (pos[r] & 1) ? &sp->exit : &sp->enter;
            if (!bb || b->t < bb->t || (b->t == bb->t && root_rank[r] < root_rank[best])) {
                best = r;
                bb = b;
            }
        }
        if (best < 0) break;
        const iv_span *span = &lists[best].v[pos[best] / 2];
        int is_exit = pos[best] & 1;
        pos[best]++;
        if (!isfinite(bb->t)) continue;
        const iv_bound *sb = bb; /* the surface whose material fills the span */
        if (bb->prim == IV_PRIM_NONE) {
            /* A clip: the ray starts inside a solid (a secondary ray) or
             * the camera's near plane opened one.  Only an absorbing solid
             * shows, as a volume from here to its exit. */
            if (is_exit || span->exit.prim == IV_PRIM_NONE) continue;
            sb = &span->exit;
        }

        float c[4];
        const csg_material *m;
        render_surface_color(J->f.scene, J->f.opt, best, sb, c, &m);
        double alpha = c[3];
        double sigma = render_surface_absorption(J->f.opt, m, alpha);
        if (sigma > 0) {
            if (is_exit) {
                int was = volume[best];
                volume[best] = 0;
                if (was) continue;
            } else {
                alpha = render_span_opacity(sigma, span->exit.t - span->enter.t);
                volume[best] = 1;
            }
        } else if (bb->prim == IV_PRIM_NONE) {
            continue;
        }
        if (!(alpha > 0)) continue;

        double local[3];
        render_hit h;
        if (surface_light(J, wk, bb, sb, c, m, o, d, depth, local, &h) != 0) return -1;

        composite(acc, &acc_a, alpha, local);

        double ior = acc_a < RENDER_OPAQUE && depth < J->max_depth && bb->prim != IV_PRIM_NONE
                         ? render_surface_ior(J->f.opt, m, alpha)
                         : 0;
        if (ior > 1) {
            /* What lies behind is seen along the refracted ray, not the
             * straight one: entering a solid bends by 1/ior, leaving it by
             * ior; total internal reflection mirrors instead. */
            double td[3], tc[3];
            if (render_refract_dir(d, h.nf, is_exit ? ior : 1 / ior, td) < 0)
                render_reflect_dir(d, h.nf, td);
            if (trace_from(J, wk, &h, td, depth + 1, tc) != 0) return -1;
            for (int i = 0; i < 3; i++)
                out[i] = acc[i] + (1 - acc_a) * tc[i];
            return 0;
        }
    }
    over_background(J, acc, acc_a, out);
    return 0;
}

/* Pixel (x, y): the mean of its s² samples, whose sum is sum (inv = 1/s²). */
static void put_pixel(const job *J, int x, int y, const double sum[3], double inv)
{
    float *p = J->f.rgba + ((size_t)y * (size_t)J->f.opt->width + (size_t)x) * 4;
    for (int k = 0; k < 3; k++)
        p[k] = (float)(sum[k] * inv);
    p[3] = 1;
}

static int render_tile(const void *job_, iv_arena *a, void *state, int x0, int y0, int x1, int y1)
{
    const job *J = job_;
    worker_ctx *wk = state;
    wk->a = a;
    const render_options *opt = J->f.opt;
    int s = opt->samples;
    double inv = 1.0 / ((double)s * s);
    if (!J->covered &&
        !(x1 >= J->cover[0] && x0 <= J->cover[1] && y1 >= J->cover[2] && y0 <= J->cover[3])) {
        /* Every sample lies in [x0, x1] × [y0, y1], so none is covered:
         * the loop below would give each pixel this background sum. */
        double sum[3] = {0, 0, 0};
        for (int k = 0; k < s * s; k++)
            for (int i = 0; i < 3; i++)
                sum[i] += (float)(double)opt->colors.background[i];
        for (int y = y0; y < y1; y++)
            for (int x = x0; x < x1; x++)
                put_pixel(J, x, y, sum, inv);
        return 0;
    }
    double fx, fy; /* where the preview look samples its strata */
    render_pass_offset(opt->pass, &fx, &fy);
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            double sum[3] = {0, 0, 0};
            if (J->jitter) /* only the light model draws random numbers */
                wk->g = rng_for_pixel(opt->seed, x, y, rng_pass_stream(0, opt->pass));
            /* s×s strata.  The preview look samples each at one point,
             * the centre in pass 0 (deterministic, and s = 1 is the pixel
             * centre where GL samples coverage); the light model jitters
             * within them. */
            for (int j = 0; j < s; j++)
                for (int i = 0; i < s; i++) {
                    double jx = J->jitter ? rng_next(&wk->g) : fx;
                    double jy = J->jitter ? rng_next(&wk->g) : fy;
                    double o[3], d[3], tmin, tmax, c[3], px = x + (i + jx) / s,
                                                         py = y + (j + jy) / s;
                    if (!J->covered && !(px >= J->cover[0] && px <= J->cover[1] &&
                                         py >= J->cover[2] && py <= J->cover[3])) {
                        /* what trace_ray gives a ray that meets nothing */
                        for (int k = 0; k < 3; k++)
                            sum[k] += (float)(double)J->f.opt->colors.background[k];
                        continue;
                    }
                    render_raygen_ray(&J->f.gen, px, py, o, d);
                    thin_lens(J->f.cam, opt->aperture, J->focus, &wk->g, o, d);
                    ray_range(J->f.cam, d, &tmin, &tmax);
                    int rc = trace_ray(J, wk, o, d, tmin, tmax, 0, c);
                    iv_arena_reset(wk->a);
                    if (rc != 0) return -1;
                    for (int k = 0; k < 3; k++)
                        sum[k] += (float)c[k];
                }
            put_pixel(J, x, y, sum, inv);
        }
    return 0;
}

/* Resolve the opt-in light model once, before any ray: the lights (the
 * options' and the scene's emitters), whether shadow rays are cast, the
 * secondary-ray offset and the focal distance. */
static int resolve_light_model(job *J, char *err, size_t errlen)
{
    const render_options *opt = J->f.opt;
    if (opt->nlights < 0 || opt->nlights > RAYSCAD_MAX_LIGHTS || opt->light_samples < 0 ||
        opt->light_samples > MAX_LIGHT_SAMPLES || opt->bounces < 0 || opt->aperture < 0 ||
        opt->focus < 0 || opt->xray < 0 || opt->xray > 1 || opt->absorb < 0 ||
        !isfinite(opt->aperture) || !isfinite(opt->focus) || !isfinite(opt->absorb)) {
        set_err(err, errlen,
                "render: bad light options (at most 16 lights, 0 to 16 light samples, "
                "x-ray opacity in 0..1, no negative aperture, focus, bounces or absorption)");
        return -1;
    }
    for (int i = 0; i < opt->nlights; i++)
        J->lights[J->nlights++] = opt->lights[i];
    for (int i = 0; i < J->nlights; i++)
        if (!(J->lights[i].intensity > 0)) J->lights[i].intensity = 1;
    for (int p = 0; p < csg_scene_prim_count(J->f.scene); p++) {
        const csg_material *m = csg_scene_material(J->f.scene, p);
        if (!(m->emit > 0)) continue;
        if (J->nlights == RAYSCAD_MAX_LIGHTS) continue;
        render_light *L = &J->lights[J->nlights++];
        for (int i = 0; i < 3; i++)
            L->pos[i] = m->light[i];
        L->radius = m->light[3];
        L->intensity = m->emit;
    }
    J->lit = opt->shadows || J->nlights > 0;
    J->keylight = J->lit && J->nlights == 0;
    J->light_n = opt->light_samples > 0 ? opt->light_samples : 4;
    J->max_depth = opt->bounces > 0 ? opt->bounces : 4;
    J->jitter = J->lit || opt->aperture > 0;
    /* An x-ray opacity below RENDER_OPAQUE makes every surface transparent, so the
     * first boundary never settles a ray. */
    J->first_hit = !(opt->xray > 0 && opt->xray < RENDER_OPAQUE);

    double centre[3], size = model_scale(J->f.scene, centre);
    J->eps = render_ray_offset(size);
    J->focus = lens_focus(opt, J->f.cam, centre, size);
    return 0;
}

/* The image rectangle the scene's bounds project to (job.cover).  A lens
 * moves the rays' origins off the pinhole, so it has none. */
static void find_cover(job *J)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    int any = 0;
    J->covered = 1;
    if (J->f.opt->aperture > 0) return;
    for (int r = 0; r < J->nroots; r++) {
        double l[3], h[3];
        if (csg_scene_bounds(J->f.scene, r, l, h) != 0) continue;
        any = 1;
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], l[k]);
            hi[k] = fmax(hi[k], h[k]);
        }
    }
    if (!any) { /* nothing to see: every sample is background */
        J->cover[0] = J->cover[2] = 1;
        J->cover[1] = J->cover[3] = -1;
        J->covered = 0;
        return;
    }
    J->covered = render_raygen_cover(&J->f.gen, lo, hi, J->cover) != 0;
}

int render_image(const csg_scene *s, const render_camera *cam, const render_options *opt,
                 float *rgba, char *err, size_t errlen)
{
    if (!s || !cam || !opt || !rgba || opt->width < 1 || opt->height < 1 || opt->samples < 1 ||
        opt->samples > MAX_SAMPLES || opt->pass < 0) {
        set_err(err, errlen,
                "render: bad options (need a scene, a camera, an image of at "
                "least 1x1 pixels, 1 to 64 samples and a pass >= 0)");
        return -1;
    }
    /* ---- the path-traced quality mode: a separate integrator -------------- */
    if (opt->path_trace > 0) return render_path_trace(s, cam, opt, rgba, err, errlen);
    job J = {0};
    render_frame_init(&J.f, s, cam, opt, rgba);
    J.nroots = csg_scene_root_count(s);
    if (J.nroots > MAX_ROOTS) J.nroots = MAX_ROOTS;
    if (J.nroots < 0) J.nroots = 0;
    for (int r = 0; r < J.nroots; r++)
        if (csg_scene_root_node(s, r) >= 0) J.live[J.nlive++] = r;
    if (resolve_light_model(&J, err, errlen) != 0) return -1;
    find_cover(&J);
    return render_tiles_draw(opt, sizeof(worker_ctx), render_tile, &J, "tracing rays", err, errlen);
}
