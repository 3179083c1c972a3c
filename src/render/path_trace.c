/*
 * path_trace.c — the path-traced quality mode: a unidirectional path tracer
 * with next-event estimation over the model root, in linear radiance.
 *
 * A path starts at the camera (thin lens as render.c's), finds its nearest
 * surface with csg_trace_first (the full interval list only where a ray
 * starts inside a solid or must cross a volume), and at each surface picks
 * one event by the material, stochastically so that the expectation is what
 * render.c composites: a colour of alpha a is a surface with probability a
 * and lets the ray through straight otherwise; $rs_reflect = r is a mirror
 * with probability r, Lambertian with its colour otherwise; a refracting
 * solid ($rs_ior, --refract) is a smooth dielectric (Fresnel by Schlick,
 * total internal reflection) where its alpha does not make it a surface;
 * an absorbing solid ($rs_absorb, --absorb) attenuates by Beer–Lambert over
 * the length a path runs inside it.  At each Lambertian vertex, every light
 * is sampled once (next-event estimation) and the path goes on along a
 * cosine-distributed direction; Russian roulette ends paths after three
 * bounces, --bounces limits them (default 8; 1 is direct light only).
 *
 * Light, in one unit: a light of intensity i gives a white Lambertian face
 * squarely toward it, at the centre of the model's bounds, the brightness i
 * — as the light model's direct term does — and falls off as 1/d²:
 *   - --light x,y,z,r,i: a point (r = 0) or a sphere of radius r sampled
 *     over the disc it shows, radiant intensity I = π·i·d_c², d_c its
 *     distance to the centre; it is not seen by camera or bounce rays;
 *   - a $rs_light = i solid emits radiance Le = i·(d_c/R)²·colour from its
 *     surface (R its enclosing radius, d_c at least R), which for a sphere
 *     is exactly the light above; it also reflects, Lambertian.  Spheres
 *     and boxes are sampled over their surface (uniform in object space,
 *     the pdf carried into world space through the transform's Jacobian);
 *     other emitting shapes are found by the bounce rays alone;
 *   - with neither, the preview's key light (from the viewer's upper left,
 *     at infinity) with irradiance π, so a white face toward it reads 1.
 * A path that leaves the scene sees the scheme's background colour when
 * only mirrors, glass and pass-throughs lie between it and the camera (the
 * backdrop), and a sky of 0.2 × that colour after a diffuse bounce — the
 * preview's ambient 0.2 as light from every direction.  Emission reached by
 * a bounce ray is counted only where next-event estimation cannot have
 * counted it (after the camera or a specular event, or for a shape that is
 * not sampled), so no light is counted twice; shadow rays treat refracting
 * solids as opaque and light through them arrives as caustics, whose
 * samples are capped at display white (CAUSTIC_MAX) — the one bias, and
 * one that scenes without mirrors or glass never meet.  Colours
 * are sRGB-encoded in materials and output: decoded to linear for albedo
 * and emission, and the mean radiance of a pixel clamped to [0, 1] and
 * encoded.
 *
 * Invariant: each pixel draws from its own random stream, seeded by
 * (seed, x, y), and tiles are handed out as in render.c, so the image is
 * the same bytes for any thread count.
 */
#include "path_trace.h"
#include "sampling.h"
#include "surface.h"
#include "tiles.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

enum { DEFAULT_DEPTH = 8, RR_AFTER = 3, MAX_PASS = 64 };

#define PI 3.14159265358979323846
/* The most radiance one sample of a caustic path may carry: display white.
 * A pixel of N samples is off by at most what its clipped samples lost. */
#define CAUSTIC_MAX 1.0
/* The sky after a diffuse bounce, as a fraction of the background colour:
 * the preview's ambient term. */
#define SKY 0.2

typedef enum pt_light_kind { PT_KEY, PT_POINT, PT_SPHERE, PT_BOX } pt_light_kind;

/* A light next-event estimation samples.  Emitters (PT_SPHERE, PT_BOX) are
 * primitives: sampled in object space, mapped by world_from_object. */
typedef struct pt_light {
    pt_light_kind kind;
    double pos[3];       /* PT_POINT: position; PT_KEY: unit direction to it */
    double radius;       /* PT_POINT: sphere radius sampled as a disc */
    double intensity;    /* PT_POINT: radiant intensity I */
    int32_t prim;        /* emitters */
    double lin[9];       /* emitters: linear part of world_from_object */
    double off[3];       /* its translation */
    double inv[9];       /* the inverse of lin (normals: inv^T n) */
    double det;          /* |det lin| */
    double r;            /* PT_SPHERE: object radius */
    double lo[3], hi[3]; /* PT_BOX: object box */
    double area;         /* object-space surface area */
} pt_light;

typedef struct pt_job {
    render_frame f;
    pt_light *lights;
    int nlights;
    double *le;    /* per primitive: emitted radiance per unit linear colour */
    char *sampled; /* per primitive: an emitter next-event estimation samples */
    double bg[3];  /* background, linear */
    int max_depth;
    double eps; /* offset of secondary ray origins (render_ray_offset) */
    double focus;
} pt_job;

/* ---- random numbers: splitmix64 over a counter, per pixel --------------- */

/* xored into the pixels' seeds ("PT"): keeps these streams apart from
 * render.c's */
#define PT_STREAM 0x5054000000000000ULL

typedef struct pt_worker {
    iv_arena *a;
    rng g;
} pt_worker;

static double srgb_to_linear(double c)
{
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

/* c encoded on the sRGB curve, clamped to [0, 1] unless `unclamped`
 * (rayscad_render_options.unclamped), which only lifts the upper bound. */
static double linear_to_srgb(double c, int unclamped)
{
    c = c < 0 ? 0 : c > 1 && !unclamped ? 1 : c;
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1 / 2.4) - 0.055;
}

/* ---- materials ------------------------------------------------------------- */

/* What a boundary of the model is made of, resolved for the path tracer. */
typedef struct pt_surface {
    const csg_material *m;
    double rgb[3]; /* linear albedo (and emission colour) */
    double alpha;
    double sigma; /* Beer–Lambert coefficient per unit length, or 0 */
    double ior;   /* > 1: a dielectric, else 0 */
} pt_surface;

/* Boundary b of the model root as render.c sees it (surface.h), with its
 * colour decoded to linear. */
static void surface_of(const pt_job *J, const iv_bound *b, pt_surface *s)
{
    float c[4];
    s->alpha = render_surface_color(J->f.scene, J->f.opt, RAYSCAD_ROOT_MODEL, b, c, &s->m);
    for (int i = 0; i < 3; i++)
        s->rgb[i] = srgb_to_linear(c[i]);
    s->sigma = render_surface_absorption(J->f.opt, s->m, s->alpha);
    s->ior = render_surface_ior(J->f.opt, s->m, s->alpha);
}

/* ---- tracing ------------------------------------------------------------------ */

/* The nearest surface of the model along o + t·d, t in [tmin, tmax], into
 * *hit.  Clip boundaries (a ray that starts inside a solid) and boundaries
 * at infinite t are not surfaces; then the full list is walked for the
 * first that is.  Returns 1, 0 for none, -1 out of memory. */
static int nearest(const pt_job *J, pt_worker *w, const double o[3], const double d[3], double tmin,
                   double tmax, iv_bound *hit)
{
    const double *cut = J->f.opt->section;
    int rc = render_trace_first(J->f.scene, cut, RAYSCAD_ROOT_MODEL, o, d, tmin, tmax, w->a, hit);
    if (rc <= 0) return rc;
    if (hit->prim != IV_PRIM_NONE && isfinite(hit->t)) return 1;
    iv_list l;
    memset(&l, 0, sizeof l);
    if (render_trace(J->f.scene, cut, RAYSCAD_ROOT_MODEL, o, d, tmin, tmax, w->a, &l) != 0)
        return -1;
    for (int i = 0; i < 2 * l.n; i++) {
        const iv_bound *b = (i & 1) ? &l.v[i / 2].exit : &l.v[i / 2].enter;
        if (b->prim != IV_PRIM_NONE && isfinite(b->t)) {
            *hit = *b;
            return 1;
        }
    }
    return 0;
}

/* Whether boundary b is the point a shadow ray toward an emitter sample
 * aims at: primitive `target`, at the sample's distance.  The sample lies
 * on the primitive's exact surface, so the traced t agrees to rounding;
 * 1e-6 relative plus a few offsets also keeps the near and far side of a
 * sphere apart except at grazing angles, where the geometry term is ~0. */
static int is_target(const pt_job *J, const iv_bound *b, int32_t target, double dist)
{
    return target >= 0 && b->prim == target && !(b->flip & RENDER_SECTION_FLIP) &&
           fabs(b->t - dist) <= 1e-6 * dist + 4 * J->eps;
}

/* The fraction of light that travels along o + t·d from t = dist back to
 * o: the product of (1 - alpha) over the surfaces crossed and Beer–Lambert
 * over absorbing spans; refracting solids and opaque surfaces stop it.
 * With target >= 0 the ray must end on that primitive's surface at t ≈ dist
 * (else 0), and nt gets the surface's normal there.  Returns -1 when out of
 * memory. */
static double shadow(const pt_job *J, pt_worker *w, const double o[3], const double d[3],
                     double dist, int32_t target, double nt[3])
{
    double tlim = target >= 0 ? dist * (1 + 2e-6) + 8 * J->eps : dist;
    iv_bound b;
    const double *cut = J->f.opt->section;
    int rc = render_trace_first(J->f.scene, cut, RAYSCAD_ROOT_MODEL, o, d, 0, tlim, w->a, &b);
    if (rc < 0) return -1;
    if (rc == 0) return target >= 0 ? 0 : 1;
    pt_surface s;
    if (b.prim != IV_PRIM_NONE) {
        if (is_target(J, &b, target, dist)) {
            csg_scene_normal(J->f.scene, &b, o, d, nt);
            return 1;
        }
        surface_of(J, &b, &s);
        if (s.ior > 1 || render_surface_opaque(J->f.opt, s.m, s.alpha)) return 0;
    }
    iv_list l;
    memset(&l, 0, sizeof l);
    if (render_trace(J->f.scene, cut, RAYSCAD_ROOT_MODEL, o, d, 0, tlim, w->a, &l) != 0) return -1;
    double T = 1;
    for (int i = 0; i < l.n && T > 0; i++) {
        const iv_span *sp = &l.v[i];
        /* a span's material: of its entry, or of its exit when clipped */
        const iv_bound *mb = sp->enter.prim != IV_PRIM_NONE ? &sp->enter : &sp->exit;
        if (mb->prim == IV_PRIM_NONE) continue;
        surface_of(J, mb, &s);
        if (s.sigma > 0 && s.ior <= 1) {
            double t0 = sp->enter.t > 0 ? sp->enter.t : 0,
                   t1 = sp->exit.t < tlim ? sp->exit.t : tlim;
            if (t1 > t0) T *= render_span_transmittance(s.sigma, t1 - t0);
        }
        for (int e = 0; e < 2; e++) {
            const iv_bound *bb = e ? &sp->exit : &sp->enter;
            if (bb->prim == IV_PRIM_NONE) continue;
            if (is_target(J, bb, target, dist)) {
                csg_scene_normal(J->f.scene, bb, o, d, nt);
                return T;
            }
            surface_of(J, bb, &s);
            if (s.ior > 1) return 0;
            T *= render_surface_transmittance(s.alpha, s.sigma);
        }
    }
    if (target >= 0) return 0;
    return T < RENDER_DARK ? 0 : T;
}

/* ---- lights -------------------------------------------------------------------- */

/* A point on emitter L, uniform over its object-space surface: world point
 * y, and the area pdf there in world space, 1 / (object area × Jacobian),
 * the Jacobian of an affine map on a surface element with object normal n
 * being |det| · |inv^T n|. */
static void sample_emitter(const pt_light *L, rng *g, double y[3], double *pdf)
{
    double p[3], n[3] = {0, 0, 0};
    double u = rng_next(g), v = rng_next(g);
    if (L->kind == PT_SPHERE) {
        double z = 1 - 2 * u, s = sqrt(fmax(0, 1 - z * z)), phi = 2 * PI * v;
        n[0] = s * cos(phi);
        n[1] = s * sin(phi);
        n[2] = z;
        for (int i = 0; i < 3; i++)
            p[i] = L->r * n[i];
    } else {
        double e[3], fa[3];
        for (int i = 0; i < 3; i++)
            e[i] = L->hi[i] - L->lo[i];
        fa[0] = e[1] * e[2];
        fa[1] = e[0] * e[2];
        fa[2] = e[0] * e[1];
        /* a face by its share of the area (each axis's pair: 2·fa), then a
         * point on it from the reused remainder of u */
        double x = u * (fa[0] + fa[1] + fa[2]);
        int ax = x < fa[0] ? 0 : x < fa[0] + fa[1] ? 1 : 2;
        x -= ax == 0 ? 0 : ax == 1 ? fa[0] : fa[0] + fa[1];
        double side = rng_next(g) < 0.5 ? 0 : 1;
        int a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
        p[ax] = side ? L->hi[ax] : L->lo[ax];
        p[a1] = L->lo[a1] + e[a1] * (fa[ax] > 0 ? x / fa[ax] : 0.5);
        p[a2] = L->lo[a2] + e[a2] * v;
        n[ax] = side ? 1 : -1;
    }
    double nw[3];
    for (int i = 0; i < 3; i++) {
        y[i] =
            L->off[i] + L->lin[3 * i] * p[0] + L->lin[3 * i + 1] * p[1] + L->lin[3 * i + 2] * p[2];
        nw[i] = L->inv[i] * n[0] + L->inv[3 + i] * n[1] + L->inv[6 + i] * n[2];
    }
    *pdf = 1 / (L->area * L->det * sqrt(dot3(nw, nw)));
}

/* Irradiance / π at hit h (its normal nf toward the side the light must be
 * on) from one sample of every light, per channel: a Lambertian surface of
 * linear albedo ρ there sends ρ × this.  Returns -1 when out of memory. */
static int direct(const pt_job *J, pt_worker *w, const render_hit *h, double E[3])
{
    const double *p = h->p, *nf = h->nf;
    double o[3]; /* every light sample leaves on the side nf faces */
    render_ray_spawn(h, nf, RENDER_SPAWN_SIDE, J->eps, o);
    for (int i = 0; i < 3; i++)
        E[i] = 0;
    for (int li = 0; li < J->nlights; li++) {
        const pt_light *L = &J->lights[li];
        double q[3], dir[3], pdf = 1, nt[3];
        if (L->kind == PT_KEY) {
            double cs = dot3(nf, L->pos);
            if (cs <= 0) continue;
            double T = shadow(J, w, o, L->pos, INFINITY, -1, nt);
            if (T < 0) return -1;
            for (int i = 0; i < 3; i++)
                E[i] += cs * T; /* irradiance π·cos θ, over π */
            continue;
        }
        if (L->kind == PT_POINT) {
            memcpy(q, L->pos, sizeof q);
            if (L->radius > 0) {
                double wv[3], u[3], v[3], dx, dy;
                for (int i = 0; i < 3; i++)
                    wv[i] = L->pos[i] - p[i];
                normalize3(wv);
                basis_of(wv, u, v);
                square_to_disc(rng_next(&w->g), rng_next(&w->g), &dx, &dy);
                disc_point(L->pos, L->radius, u, v, dx, dy, q);
            }
        } else {
            sample_emitter(L, &w->g, q, &pdf);
        }
        double dist = toward(o, q, dir);
        if (!(dist > 0)) continue;
        double cs = dot3(nf, dir);
        if (cs <= 0) continue;
        int32_t target = L->kind == PT_POINT ? -1 : L->prim;
        double T = shadow(J, w, o, dir, dist, target, nt);
        if (T < 0) return -1;
        if (T == 0) continue;
        if (L->kind == PT_POINT) {
            for (int i = 0; i < 3; i++)
                E[i] += L->intensity * cs / (dist * dist) * T / PI;
            continue;
        }
        /* the emitter's surface must face the point: the ray meets its front */
        double cy = -dot3(nt, dir);
        if (cy <= 0) continue;
        iv_bound b = {0, L->prim, 0, 0};
        pt_surface s;
        surface_of(J, &b, &s);
        double g = J->le[L->prim] * cs * cy / (dist * dist * pdf) * T / PI;
        for (int i = 0; i < 3; i++)
            E[i] += g * s.rgb[i];
    }
    return 0;
}

/* ---- paths ------------------------------------------------------------------------ */

/* A direction about unit n with density cos θ / π (Malley: a uniform disc
 * lifted onto the hemisphere). */
static void cosine_dir(rng *g, const double n[3], double out[3])
{
    double u[3], v[3], x, y;
    basis_of(n, u, v);
    square_to_disc(rng_next(g), rng_next(g), &x, &y);
    double z = sqrt(fmax(0, 1 - x * x - y * y));
    for (int i = 0; i < 3; i++)
        out[i] = x * u[i] + y * v[i] + z * n[i];
    normalize3(out);
}

/* The radiance arriving at the camera along o + t·d, t in [tmin, tmax],
 * from one random path, linear, into out.  Returns -1 when out of memory. */
static int path(const pt_job *J, pt_worker *w, double o[3], double d[3], double tmin, double tmax,
                double out[3])
{
    double beta[3] = {1, 1, 1};
    int bounces = 0, specular = 1, passes = 0, caustic = 0;
    for (int i = 0; i < 3; i++)
        out[i] = 0;
    for (;;) {
        iv_bound b;
        int rc = nearest(J, w, o, d, tmin, tmax, &b);
        if (rc < 0) return -1;
        if (rc == 0) {
            for (int i = 0; i < 3; i++)
                out[i] += beta[i] * J->bg[i] * (specular ? 1 : SKY);
            return 0;
        }
        render_hit h;
        render_surface_hit(J->f.scene, J->f.opt->section, &b, b.t, o, d, RENDER_GRAZE_LEAVES, &h);
        int entering = h.entering;
        pt_surface s;
        surface_of(J, &b, &s);

        /* A ray that leaves an absorbing solid ran inside it from its origin. */
        if (!entering && s.sigma > 0) {
            double tr = render_span_transmittance(s.sigma, b.t - tmin);
            for (int i = 0; i < 3; i++)
                beta[i] *= tr;
        }
        if (s.m->emit > 0 && entering && (specular || !J->sampled[b.prim])) {
            double c[3], m = 0;
            for (int i = 0; i < 3; i++) {
                c[i] = beta[i] * J->le[b.prim] * s.rgb[i];
                m = fmax(m, c[i]);
            }
            /* A caustic (a light seen by a diffuse vertex through mirrors or
             * glass) is found by bounce rays alone, rarely and brightly; its
             * samples are capped at CAUSTIC_MAX, biased but without the
             * fireflies. */
            double k = caustic && m > CAUSTIC_MAX ? CAUSTIC_MAX / m : 1;
            for (int i = 0; i < 3; i++)
                out[i] += k * c[i];
        }

        double u = rng_next(&w->g), surface = s.alpha;
        int pass = 0;
        if (s.ior <= 1 && s.sigma > 0) {
            /* A volume seen from outside shows with the opacity of the span
             * it spans, as render.c composites it; otherwise the ray goes on
             * from the span's exit. */
            surface = 0;
            if (entering) {
                iv_list l;
                memset(&l, 0, sizeof l);
                if (render_trace(J->f.scene, J->f.opt->section, RAYSCAD_ROOT_MODEL, o, d, tmin,
                                 tmax, w->a, &l) != 0)
                    return -1;
                double len = INFINITY;
                for (int i = 0; i < l.n; i++)
                    if (l.v[i].enter.t == b.t) len = l.v[i].exit.t - b.t;
                surface = render_span_opacity(s.sigma, len);
                if (u >= surface && isfinite(len)) {
                    for (int i = 0; i < 3; i++)
                        h.p[i] += len * d[i];
                    entering = 0; /* leave from the exit, beyond it */
                }
            }
        }
        if (u >= surface) pass = 1;

        if (pass && s.ior > 1) {
            /* a smooth dielectric: reflect with Schlick's Fresnel, refract
             * otherwise; total internal reflection always reflects */
            if (++bounces >= J->max_depth) return 0;
            double eta = entering ? 1 / s.ior : s.ior, ci = -dot3(h.nf, d);
            double r0 = (1 - s.ior) / (1 + s.ior), nd[3];
            r0 *= r0;
            double ct = render_refract_dir(d, h.nf, eta, nd);
            double cosv = entering ? ci : ct; /* the cosine in the thinner medium */
            double F = ct < 0 ? 1 : r0 + (1 - r0) * pow(1 - cosv, 5);
            if (rng_next(&w->g) < F) {
                render_reflect_dir(d, h.nf, nd);
                normalize3(nd);
            }
            render_ray_spawn(&h, nd, RENDER_SPAWN_SIDE, J->eps, o);
            memcpy(d, nd, sizeof nd);
            caustic |= !specular;
            specular = 1;
            tmin = 0;
            tmax = INFINITY;
            continue;
        }
        if (pass) {
            /* straight through, not a bounce */
            if (++passes > MAX_PASS) return 0;
            render_ray_spawn(&h, d, RENDER_SPAWN_AHEAD, J->eps, o);
            tmin = 0;
            tmax = INFINITY;
            continue;
        }

        if (rng_next(&w->g) < s.m->reflect) {
            if (++bounces >= J->max_depth) return 0;
            render_reflect_dir(d, h.nf, d);
            normalize3(d);
            render_ray_spawn(&h, h.nf, RENDER_SPAWN_SIDE, J->eps, o); /* on the front */
            caustic |= !specular;
            specular = 1;
        } else {
            double E[3];
            if (direct(J, w, &h, E) != 0) return -1;
            for (int i = 0; i < 3; i++)
                out[i] += beta[i] * s.rgb[i] * E[i];
            if (++bounces >= J->max_depth) return 0;
            cosine_dir(&w->g, h.nf, d);
            render_ray_spawn(&h, h.nf, RENDER_SPAWN_SIDE, J->eps, o); /* on the front */
            for (int i = 0; i < 3; i++)
                beta[i] *= s.rgb[i]; /* f·cos θ / pdf = (ρ/π)·cos θ / (cos θ/π) */
            specular = 0;
        }
        tmin = 0;
        tmax = INFINITY;
        if (bounces >= RR_AFTER) {
            /* Russian roulette: go on with the probability of the largest
             * throughput (at most 0.95, so no path lives forever), and
             * divide by it, which keeps the estimate unbiased. */
            double q = fmax(beta[0], fmax(beta[1], beta[2]));
            q = q > 0.95 ? 0.95 : q;
            if (!(rng_next(&w->g) < q)) return 0;
            for (int i = 0; i < 3; i++)
                beta[i] /= q;
        }
    }
}

/* ---- the image --------------------------------------------------------------------- */

static int render_tile(const void *job, iv_arena *a, void *state, int x0, int y0, int x1, int y1)
{
    const pt_job *J = job;
    pt_worker *w = state;
    w->a = a;
    const render_options *opt = J->f.opt;
    const render_camera *c = J->f.cam;
    int ns = opt->path_trace;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            w->g = rng_for_pixel(opt->seed, x, y, rng_pass_stream(PT_STREAM, opt->pass));
            double sum[3] = {0, 0, 0}, ox = rng_next(&w->g), oy = rng_next(&w->g);
            for (int k = 0; k < ns; k++) {
                /* pixel positions from the R2 sequence (Roberts), shifted per
                 * pixel: well spread for any sample count */
                double jx = fmod(ox + k * 0.75487766624669276, 1.0);
                double jy = fmod(oy + k * 0.56984029099805327, 1.0);
                double o[3], d[3], tmin, tmax, L[3];
                render_raygen_ray(&J->f.gen, x + jx, y + jy, o, d);
                thin_lens(c, opt->aperture, J->focus, &w->g, o, d);
                ray_range(c, d, &tmin, &tmax);
                int rc = path(J, w, o, d, tmin, tmax, L);
                iv_arena_reset(w->a);
                if (rc != 0) return -1;
                if (isfinite(L[0]) && isfinite(L[1]) && isfinite(L[2]))
                    for (int i = 0; i < 3; i++)
                        sum[i] += L[i];
            }
            float *px = J->f.rgba + ((size_t)y * (size_t)opt->width + (size_t)x) * 4;
            for (int i = 0; i < 3; i++)
                px[i] = (float)linear_to_srgb(sum[i] / ns, opt->unclamped);
            px[3] = 1;
        }
    return 0;
}

/* The lights, per-primitive emission and the scale of the scene, once. */
static int setup(pt_job *J)
{
    const csg_scene *S = J->f.scene;
    const render_options *opt = J->f.opt;
    int np = csg_scene_prim_count(S);
    J->le = calloc((size_t)np + 1, sizeof *J->le);
    J->sampled = calloc((size_t)np + 1, 1);
    J->lights = calloc((size_t)np + RAYSCAD_MAX_LIGHTS + 1, sizeof *J->lights);
    if (!J->le || !J->sampled || !J->lights) return -1;

    double centre[3], size = model_scale(S, centre); /* as render.c's */
    J->eps = render_ray_offset(size);
    J->focus = lens_focus(opt, J->f.cam, centre, size);

    for (int li = 0; li < opt->nlights && li < RAYSCAD_MAX_LIGHTS; li++) {
        const render_light *R = &opt->lights[li];
        pt_light *L = &J->lights[J->nlights++];
        L->kind = PT_POINT;
        memcpy(L->pos, R->pos, sizeof L->pos);
        L->radius = R->radius > 0 ? R->radius : 0;
        double v[3] = {R->pos[0] - centre[0], R->pos[1] - centre[1], R->pos[2] - centre[2]};
        /* a light at the centre itself is taken at 1e-3 of the model's size */
        double dc = fmax(sqrt(dot3(v, v)), 1e-3 * size);
        L->intensity = PI * (R->intensity > 0 ? R->intensity : 1) * dc * dc;
    }
    int emitters = 0;
    for (int p = 0; p < np; p++) {
        const csg_material *m = csg_scene_material(S, p);
        if (!(m->emit > 0)) continue;
        emitters++;
        double v[3] = {m->light[0] - centre[0], m->light[1] - centre[1], m->light[2] - centre[2]};
        double R = m->light[3], dc = sqrt(dot3(v, v));
        J->le[p] = R > 0 ? m->emit * fmax(dc, R) * fmax(dc, R) / (R * R) : m->emit;
        const iv_shape *sh = csg_scene_prim_shape(S, p);
        if (sh->kind != IV_SHAPE_SPHERE && sh->kind != IV_SHAPE_BOX) continue;
        csg_affine xf, inv;
        csg_scene_prim_transform(S, p, xf);
        if (csg_affine_invert(xf, inv) != 0) continue;
        pt_light *L = &J->lights[J->nlights];
        L->kind = sh->kind == IV_SHAPE_SPHERE ? PT_SPHERE : PT_BOX;
        L->prim = p;
        for (int i = 0; i < 3; i++) {
            L->off[i] = xf[4 * i + 3];
            for (int j = 0; j < 3; j++) {
                L->lin[3 * i + j] = xf[4 * i + j];
                L->inv[3 * i + j] = inv[4 * i + j];
            }
        }
        L->det = fabs(csg_affine_det(xf));
        if (L->kind == PT_SPHERE) {
            L->r = sh->u.sphere.r;
            L->area = 4 * PI * L->r * L->r;
        } else {
            double e[3];
            for (int i = 0; i < 3; i++) {
                L->lo[i] = sh->u.box.lo[i];
                L->hi[i] = sh->u.box.hi[i];
                e[i] = L->hi[i] - L->lo[i];
            }
            L->area = 2 * (e[0] * e[1] + e[1] * e[2] + e[0] * e[2]);
        }
        if (!(L->area > 0) || !(L->det > 0) || !isfinite(L->area * L->det)) continue;
        J->sampled[p] = 1;
        J->nlights++;
    }
    if (opt->nlights == 0 && emitters == 0) {
        /* the preview's key light, (-1,-1,1)/√3 in (right, forward, up) */
        const render_camera *c = J->f.cam;
        pt_light *L = &J->lights[J->nlights++];
        L->kind = PT_KEY;
        for (int i = 0; i < 3; i++)
            L->pos[i] = (-c->right[i] - c->forward[i] + c->up[i]) / sqrt(3.0);
    }
    for (int i = 0; i < 3; i++)
        J->bg[i] = srgb_to_linear(opt->colors.background[i]);
    J->max_depth = opt->bounces > 0 ? opt->bounces : DEFAULT_DEPTH;
    return 0;
}

int render_path_trace(const csg_scene *s, const render_camera *cam, const render_options *opt,
                      float *rgba, char *err, size_t errlen)
{
    if (opt->path_trace < 1 || opt->nlights < 0 || opt->nlights > RAYSCAD_MAX_LIGHTS ||
        opt->bounces < 0 || !(opt->aperture >= 0) || !(opt->focus >= 0) || !(opt->absorb >= 0) ||
        !(opt->xray >= 0) || opt->xray > 1) {
        if (err && errlen)
            snprintf(err, errlen,
                     "render: bad path-tracing options (samples >= 1, at most 16 "
                     "lights, no negative bounces, aperture, focus or absorption)");
        return -1;
    }
    pt_job J = {0};
    render_frame_init(&J.f, s, cam, opt, rgba);
    int rc = -1;
    if (setup(&J) != 0) {
        if (err && errlen) snprintf(err, errlen, "render: out of memory while path tracing");
    } else {
        rc =
            render_tiles_draw(opt, sizeof(pt_worker), render_tile, &J, "path tracing", err, errlen);
    }
    free(J.le);
    free(J.sampled);
    free(J.lights);
    return rc;
}
