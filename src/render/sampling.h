/*
 * sampling.h — private to src/render: what the preview renderer (render.c)
 * and the path tracer (path_trace.c) both draw on: per-pixel random streams,
 * the concentric disc map, small vector helpers, the model's scale, the thin
 * lens and the camera's t range.  All static inline, so each file keeps its
 * own copy of the code it uses.
 */
#ifndef RAYSCAD_RENDER_SAMPLING_H
#define RAYSCAD_RENDER_SAMPLING_H

#include <math.h>
#include <stdint.h>

#include "../intervals/vec3.h"
#include "render.h"

/* ---- random numbers --------------------------------------------------------
 * splitmix64 over a counter: the stream of a pixel is fixed by (seed, x, y),
 * whatever thread draws it. */
typedef struct rng {
    uint64_t s;
} rng;

static inline uint64_t mix64(uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

/* The stream of pixel (x, y) under seed: xoring in its own constant
 * `stream` keeps one renderer's streams apart from the other's. */
static inline rng rng_for_pixel(unsigned seed, int x, int y, uint64_t stream)
{
    rng g = {mix64(((uint64_t)seed << 42) ^ ((uint64_t)(uint32_t)y << 21) ^ (uint32_t)x ^ stream)};
    return g;
}

/* The stream a renderer's constant `stream` becomes in progressive pass
 * `pass` (rayscad_render_options.pass): itself in pass 0, so that a
 * single picture is as it always was. */
static inline uint64_t rng_pass_stream(uint64_t stream, int pass)
{
    return pass ? stream ^ mix64(0x5851f42d4c957f2dULL * (uint64_t)pass) : stream;
}

/* Where pass `pass` samples each stratum, as a fraction of its width in
 * x and y: the centre in pass 0, then the R2 sequence (Roberts) from it,
 * which covers the square evenly for any number of passes. */
static inline void render_pass_offset(int pass, double *jx, double *jy)
{
    *jx = fmod(0.5 + pass * 0.75487766624669276, 1.0);
    *jy = fmod(0.5 + pass * 0.56984029099805327, 1.0);
}

/* Uniform in [0, 1): the top 53 bits. */
static inline double rng_next(rng *g)
{
    g->s += 0x9e3779b97f4a7c15ULL;
    return (double)(mix64(g->s) >> 11) * (1.0 / 9007199254740992.0);
}

/* Shirley–Chiu concentric map of the unit square onto the unit disc: keeps
 * strata compact, so stratified squares give stratified discs. */
static inline void square_to_disc(double u, double v, double *x, double *y)
{
    double a = 2 * u - 1, b = 2 * v - 1, r, phi;
    if (a == 0 && b == 0) {
        *x = *y = 0;
        return;
    }
    const double quarter = 0.78539816339744831; /* π/4 */
    if (fabs(a) > fabs(b)) {
        r = a;
        phi = quarter * (b / a);
    } else {
        r = b;
        phi = 2 * quarter - quarter * (a / b);
    }
    *x = r * cos(phi);
    *y = r * sin(phi);
}

/* ---- small vector helpers --------------------------------------------------- */

static inline void normalize3(double v[3])
{
    double l = sqrt(dot3(v, v));
    if (l > 0)
        for (int i = 0; i < 3; i++)
            v[i] /= l;
}

/* Two unit vectors orthogonal to unit w and to each other. */
static inline void basis_of(const double w[3], double u[3], double v[3])
{
    double a[3] = {0, 0, 0};
    a[fabs(w[0]) < 0.6 ? 0 : fabs(w[1]) < 0.6 ? 1 : 2] = 1;
    u[0] = a[1] * w[2] - a[2] * w[1];
    u[1] = a[2] * w[0] - a[0] * w[2];
    u[2] = a[0] * w[1] - a[1] * w[0];
    normalize3(u);
    v[0] = w[1] * u[2] - w[2] * u[1];
    v[1] = w[2] * u[0] - w[0] * u[2];
    v[2] = w[0] * u[1] - w[1] * u[0];
}

/* The point (dx, dy) of the unit disc on the disc of radius r about c
 * spanned by u and v. */
static inline void disc_point(const double c[3], double r, const double u[3], const double v[3],
                              double dx, double dy, double q[3])
{
    for (int i = 0; i < 3; i++)
        q[i] = c[i] + r * (dx * u[i] + dy * v[i]);
}

/* The unit direction dir from o to q; returns the distance, which is not
 * > 0 (and dir no direction) when q is o. */
static inline double toward(const double o[3], const double q[3], double dir[3])
{
    for (int i = 0; i < 3; i++)
        dir[i] = q[i] - o[i];
    double len = sqrt(dot3(dir, dir));
    if (len > 0)
        for (int i = 0; i < 3; i++)
            dir[i] /= len;
    return len;
}

/* ---- the model's scale, for offsets and the lens ---------------------------- */

/* The model's size — the diagonal of its bounds (infinite extents count as
 * 0), at least 1 and at least its centre's distance from the origin along
 * any axis — and its centre (the origin when it has no bounds): what
 * secondary rays' offsets (render_ray_offset), the lens's default focus and
 * the path tracer's light falloff scale with. */
static inline double model_scale(const csg_scene *s, double centre[3])
{
    double lo[3], hi[3], size = 1;
    for (int i = 0; i < 3; i++)
        centre[i] = 0;
    if (csg_scene_bounds(s, RAYSCAD_ROOT_MODEL, lo, hi) != 0) return size;
    double s2 = 0;
    for (int i = 0; i < 3; i++) {
        double e = isfinite(hi[i] - lo[i]) ? hi[i] - lo[i] : 0;
        s2 += e * e;
        centre[i] = isfinite(lo[i] + hi[i]) ? (lo[i] + hi[i]) / 2 : 0;
    }
    if (s2 > 0) size = sqrt(s2);
    for (int i = 0; i < 3; i++)
        size = fmax(size, fabs(centre[i]));
    return size;
}

/* The thin lens's focal distance along forward: the option's, else the
 * depth of the model's centre (at least 1e-6 of its size). */
static inline double lens_focus(const render_options *opt, const render_camera *c,
                                const double centre[3], double size)
{
    if (opt->focus > 0) return opt->focus;
    double v[3] = {centre[0] - c->eye[0], centre[1] - c->eye[1], centre[2] - c->eye[2]};
    return fmax(dot3(v, c->forward), 1e-6 * size);
}

/* A primary ray (o, d) from render_raygen_ray, moved onto a thin lens of
 * diameter `aperture` when it is open: every ray of a pixel meets the
 * others on the plane of focus, at depth `focus` along forward, and draws
 * its point on the lens from g. */
static inline void thin_lens(const render_camera *c, double aperture, double focus, rng *g,
                             double o[3], double d[3])
{
    if (!(aperture > 0)) return;
    double df = dot3(d, c->forward);
    if (!(df > 0)) return;
    double f[3], lx, ly;
    for (int i = 0; i < 3; i++)
        f[i] = o[i] + d[i] * (focus / df);
    square_to_disc(rng_next(g), rng_next(g), &lx, &ly);
    for (int i = 0; i < 3; i++) {
        o[i] += aperture / 2 * (lx * c->right[i] + ly * c->up[i]);
        d[i] = f[i] - o[i];
    }
    normalize3(d);
}

/* The parameter range [tmin, tmax] along o + t·d that the camera keeps: its
 * clip planes are depths along forward, and depth = t·(d·forward). */
static inline void ray_range(const render_camera *c, const double d[3], double *tmin, double *tmax)
{
    double df = d[0] * c->forward[0] + d[1] * c->forward[1] + d[2] * c->forward[2];
    if (c->clip_far > c->clip_near && df > 0) {
        *tmin = c->clip_near / df;
        *tmax = c->clip_far / df;
    } else {
        *tmin = c->ortho ? -INFINITY : 0;
        *tmax = INFINITY;
    }
}

#endif
