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
