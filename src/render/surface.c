/*
 * surface.c — what a surface is to both renderers (surface.h): a boundary's
 * colour and material from the scheme and the $rs_ optics, the light it
 * lets through (1 - alpha at a surface, Beer–Lambert inside an absorbing
 * solid), the mirror and refracted directions, and where every secondary
 * ray starts.  The two asked on every primary ray of the preview,
 * render_surface_absorption and render_surface_hit, are inline in
 * surface.h.
 *
 * Invariant: render.c and path_trace.c look at a surface only through these,
 * so the preview and the path tracer agree on what it is made of and on how
 * light passes it, and each secondary ray of either starts where
 * render_ray_spawn puts it.  Where the two have always differed — the facing
 * of an exact graze, a path stepping along the ray through a surface it
 * passes — the caller names its rule (render_graze, render_spawn) instead of
 * keeping code of its own.
 */
#include "surface.h"

#include "sampling.h"

#include <math.h>
#include <string.h>

double render_surface_color(const csg_scene *s, const render_options *opt, int root,
                            const iv_bound *b, float c[4], const csg_material **m)
{
    const render_colors *cs = &opt->colors;
    *m = csg_scene_material(s, b->prim);
    if (root == RAYSCAD_ROOT_HIGHLIGHT) {
        memcpy(c, cs->highlight, sizeof cs->highlight);
    } else if ((*m)->has_color) {
        memcpy(c, (*m)->rgba, sizeof(*m)->rgba);
    } else if (root == RAYSCAD_ROOT_BACKGROUND) {
        memcpy(c, cs->background_modifier, sizeof cs->background_modifier);
    } else {
        memcpy(c, b->flip ? cs->back : cs->face, 3 * sizeof(float));
        c[3] = 1;
    }
    /* The caps in double: c[3] rounds the x-ray opacity to float, as the
     * preview's colours always have; the path tracer keeps it exact. */
    double alpha = c[3] > 1 ? 1 : c[3];
    if (opt->xray > 0 && alpha > opt->xray) alpha = opt->xray;
    c[3] = (float)alpha;
    return alpha;
}

double render_surface_ior(const render_options *opt, const csg_material *m, double alpha)
{
    return m->ior > 1 ? m->ior : opt->ior > 1 && alpha < 1 ? opt->ior : 0;
}

double render_surface_transmittance(double alpha, double sigma)
{
    return sigma > 0 ? 1 : 1 - alpha;
}

double render_span_transmittance(double sigma, double len)
{
    return exp(-sigma * len);
}

double render_span_opacity(double sigma, double len)
{
    return isfinite(len) ? -expm1(-sigma * len) : 1;
}

void render_reflect_dir(const double d[3], const double nf[3], double out[3])
{
    double dn = dot3(d, nf);
    for (int i = 0; i < 3; i++)
        out[i] = d[i] - 2 * dn * nf[i];
}

double render_refract_dir(const double d[3], const double nf[3], double eta, double out[3])
{
    double ci = -dot3(nf, d);
    double k = 1 - eta * eta * (1 - ci * ci); /* the refracted cosine, squared */
    if (k < 0) return -1;
    double ct = sqrt(k);
    for (int i = 0; i < 3; i++)
        out[i] = eta * d[i] + (eta * ci - ct) * nf[i];
    normalize3(out);
    return ct;
}

double render_ray_offset(double size)
{
    return 1e-7 * size;
}

void render_ray_spawn(const render_hit *h, const double dir[3], render_spawn rule, double eps,
                      double o[3])
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
