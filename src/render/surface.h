/*
 * surface.h — private to src/render: what both renderers (render.c's
 * preview and light model, path_trace.c's path tracer) ask of a boundary a
 * ray has met — its colour and material, the optics that go with them, the
 * light it lets through, the point and normal of the hit — and where a
 * secondary ray leaving it starts (render_ray_spawn: one function for every
 * such ray of either renderer).
 */
#ifndef RAYSCAD_RENDER_SURFACE_H
#define RAYSCAD_RENDER_SURFACE_H

#include "../intervals/vec3.h"
#include "render.h"
#include "section.h"

#include <math.h>
#include <string.h>

/* Opacity past which what lies behind a surface cannot change a byte of the
 * image, and the transmittance below which light can no longer change one:
 * 1/4096, a sixteenth of an 8-bit step. */
#define RENDER_OPAQUE (1.0 - 1.0 / 4096)
#define RENDER_DARK (1.0 / 4096)

/* ---- the material at a hit ------------------------------------------------ */

/* The sRGB colour of boundary b of root `root` (RAYSCAD_ROOT_*) into c and
 * its material (csg_scene_material, borrowed from s) into *m: the highlight
 * colour for the '#' root and for every leaf under a '#' (OpenSCAD's
 * Renderer::setColor ignores the object's own there), else the material's colour, else the '%'
 * root's background modifier colour, else the scheme's face colour, or its back colour for a
 * subtracted surface (b->flip), opaque.  Alpha is capped at 1 and at opt->xray when that is > 0.
 * Returns the alpha; c[3] holds it rounded to float, as the preview composites with its float
 * colours (the two differ only where the x-ray cap is not a float).  Inline, as is
 * render_ray_spawn: as calls across files the two cost the path tracer's
 * loop 0.6 % more instructions (callgrind, few.scad). */
static inline double render_surface_color(const csg_scene *s, const render_options *opt, int root,
                                          const iv_bound *b, float c[4], const csg_material **m)
{
    const render_colors *cs = &opt->colors;
    *m = csg_scene_material(s, b->prim);
    if (root == RAYSCAD_ROOT_HIGHLIGHT || (*m)->highlight) {
        memcpy(c, cs->highlight, sizeof cs->highlight);
    } else if ((*m)->has_color) {
        memcpy(c, (*m)->rgba, sizeof(*m)->rgba);
    } else if (root == RAYSCAD_ROOT_BACKGROUND) {
        memcpy(c, cs->background_modifier, sizeof cs->background_modifier);
    } else {
        memcpy(c, (b->flip & 1) ? cs->back : cs->face, 3 * sizeof(float));
        c[3] = 1;
    }
    /* The caps in double: c[3] rounds the x-ray opacity to float, as the
     * preview's colours always have; the path tracer keeps it exact. */
    double alpha = c[3] > 1 ? 1 : c[3];
    if (opt->xray > 0 && alpha > opt->xray) alpha = opt->xray;
    c[3] = (float)alpha;
    return alpha;
}

/* The Beer–Lambert coefficient (per unit length) of a solid with material m
 * and alpha `alpha`, or 0 when its surfaces composite one by one: the
 * material's own ($rs_absorb) wins; otherwise, in absorption mode
 * (opt->absorb > 0), a transparent colour's alpha is the opacity of
 * opt->absorb units of it, so σ = -ln(1 - alpha) / opt->absorb.  Opaque
 * and clear solids stay surfaces.  Inline, as render_surface_hit is. */
static inline double render_surface_absorption(const render_options *opt, const csg_material *m,
                                               double alpha)
{
    if (m->absorb > 0) return m->absorb;
    if (opt->absorb > 0 && alpha > 0 && alpha < 1) return -log1p(-alpha) / opt->absorb;
    return 0;
}

/* Whether a surface of material m and alpha `alpha` hides what lies behind
 * it: alpha of at least RENDER_OPAQUE, composited as a surface (an
 * absorbing solid's opacity is its span's, known only at its exit).  The
 * preview's walk ends there, and the path tracer's shadow rays stop. */
static inline int render_surface_opaque(const render_options *opt, const csg_material *m,
                                        double alpha)
{
    return alpha >= RENDER_OPAQUE && render_surface_absorption(opt, m, alpha) == 0;
}

/* The index of refraction of a solid with material m seen with opacity
 * alpha, or 0 when it does not refract: the material's own ($rs_ior > 1),
 * else --refract's (opt->ior > 1) for a solid that is not opaque. */
double render_surface_ior(const render_options *opt, const csg_material *m, double alpha);

/* ---- the light it lets through ---------------------------------------------- */

/* The fraction of light that crosses a boundary of alpha `alpha` and
 * absorption sigma (render_surface_absorption): 1 - alpha, or 1 for an
 * absorbing solid, whose surfaces are clear and whose inside attenuates
 * instead (render_span_transmittance). */
double render_surface_transmittance(double alpha, double sigma);

/* The fraction of light that crosses len units inside a solid of absorption
 * sigma > 0: exp(-σ·len), 0 for an infinite len. */
double render_span_transmittance(double sigma, double len);

/* The opacity of the same span, 1 - exp(-σ·len), by expm1 so that a thin
 * span keeps its digits; 1 for an infinite (or NaN) len. */
double render_span_opacity(double sigma, double len);

/* ---- the optics of a smooth surface ---------------------------------------- */

/* The mirror image of d about unit normal nf into out (which may be d):
 * d - 2(d·nf)·nf, as long as d. */
void render_reflect_dir(const double d[3], const double nf[3], double out[3]);

/* The direction of unit d refracted through a surface whose unit normal nf
 * faces d's origin (nf·d <= 0), eta = n_from / n_to, into out (unit).
 * Returns the cosine of the refracted ray's angle to -nf, or -1 with out
 * untouched at total internal reflection. */
double render_refract_dir(const double d[3], const double nf[3], double eta, double out[3]);

/* ---- the hit ---------------------------------------------------------------- */

/* Which way render_surface_hit faces a ray that grazes the surface (n·d is
 * 0, or NaN), which neither enters nor leaves it.  The two renderers have
 * always decided this differently, and nf steers the secondary rays and the
 * light there, so one rule could move the pixels where a ray grazes
 * exactly. */
typedef enum render_graze {
    RENDER_GRAZE_ENTERS, /* as a ray that enters: nf = n (the preview) */
    RENDER_GRAZE_LEAVES  /* as a ray that leaves: nf = -n (the path tracer) */
} render_graze;

typedef struct render_hit {
    double p[3];  /* the point, o + t·d */
    double n[3];  /* the surface's unit normal there (csg_scene_normal; a cut face's
                     is the section plane's) */
    double nf[3]; /* n turned toward the side the ray arrives from */
    int entering; /* the ray passes into the solid: n·d < 0 (grazes: see render_graze) */
} render_hit;

/* The hit of the ray o + t·d (d unit) at parameter t on the surface of
 * boundary b of a list traced along it, cut by plane section (b->t is t, or for a clip the
 * surface is the exit of the span the clip opened).  Inline: the preview
 * asks this and render_surface_absorption on every primary ray, and as
 * calls the two cost its render loop 1 % more instructions (callgrind,
 * bench/scenes/few.scad). */
static inline void render_surface_hit(const csg_scene *s, const double section[4],
                                      const iv_bound *b, double t, const double o[3],
                                      const double d[3], render_graze graze, render_hit *h)
{
    if (b->flip & RENDER_SECTION_FLIP)
        render_section_normal(section, h->n);
    else
        csg_scene_normal(s, b, o, d, h->n);
    for (int i = 0; i < 3; i++)
        h->p[i] = o[i] + t * d[i];
    double nd = dot3(h->n, d);
    h->entering = graze == RENDER_GRAZE_ENTERS ? !(nd > 0) : nd < 0;
    for (int i = 0; i < 3; i++)
        h->nf[i] = h->entering ? h->n[i] : -h->n[i];
}

/* ---- secondary rays --------------------------------------------------------- */

/* How far, in a model of size `size` (model_scale), a secondary ray starts
 * off the surface it leaves: 1e-7 of it, far above the rounding of t (a few
 * ulps of the distances involved) and far below any feature. */
double render_ray_offset(double size);

/* Which way render_ray_spawn steps off the surface. */
typedef enum render_spawn {
    /* eps along the normal, to the side of the surface dir points to.  A ray
     * bound for the front — a shadow ray, a light sample, the path tracer's
     * mirror and diffuse bounces — passes nf itself as dir, so rounding in
     * its direction cannot send it to the back. */
    RENDER_SPAWN_SIDE,
    /* eps along dir: the path tracer going straight on through a surface
     * it lets pass, or on from the exit of an absorbing span, whose normal
     * it has not looked up.  It has always stepped so; a step along the
     * normal would move its pixels. */
    RENDER_SPAWN_AHEAD
} render_spawn;

/* The origin o of every secondary ray (shadow, mirror, refracted,
 * transmitted, bounce, light sample) that leaves hit h along dir: h->p
 * moved eps (render_ray_offset) by rule `rule`, so that the ray does not
 * meet h's own surface again at t ≈ 0.  The ray is then traced from t = 0. */
static inline void render_ray_spawn(const render_hit *h, const double dir[3], render_spawn rule,
                                    double eps, double o[3])
{
    if (rule == RENDER_SPAWN_AHEAD) {
        for (int i = 0; i < 3; i++)
            o[i] = h->p[i] + eps * dir[i];
        return;
    }
    /* Negating eps is exact: leaving on nf's side is p + eps·nf bit for bit,
     * on the other p - eps·nf. */
    double step = dot3(dir, h->nf) >= 0 ? eps : -eps;
    for (int i = 0; i < 3; i++)
        o[i] = h->p[i] + step * h->nf[i];
}

#endif
