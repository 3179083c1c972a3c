/*
 * section.c — see section.h.
 */
#include "section.h"

#include <math.h>

int render_section_on(const double plane[4])
{
    return plane[0] != 0 || plane[1] != 0 || plane[2] != 0;
}

void render_section_normal(const double plane[4], double n[3])
{
    double len = sqrt(plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2]);
    for (int k = 0; k < 3; k++)
        n[k] = plane[k] / len;
}

void render_section_clip(const double plane[4], const double o[3], const double d[3], iv_list *l)
{
    double no = plane[0] * o[0] + plane[1] * o[1] + plane[2] * o[2] - plane[3];
    double nd = plane[0] * d[0] + plane[1] * d[1] + plane[2] * d[2];
    double lo = -INFINITY, hi = INFINITY; /* the t the section keeps */
    if (nd > 0)
        hi = -no / nd;
    else if (nd < 0)
        lo = -no / nd;
    else if (no > 0)
        hi = -INFINITY; /* parallel, on the cut-away side: nothing */
    int k = 0;
    for (int i = 0; i < l->n; i++) {
        iv_span s = l->v[i];
        if (!(s.exit.t > lo) || !(s.enter.t < hi)) continue;
        if (s.enter.t < lo) {
            s.enter.t = lo;
            s.enter.flip |= RENDER_SECTION_FLIP;
            if (s.enter.prim == IV_PRIM_NONE) s.enter.prim = s.exit.prim;
        }
        if (s.exit.t > hi) {
            s.exit.t = hi;
            s.exit.flip |= RENDER_SECTION_FLIP;
            if (s.exit.prim == IV_PRIM_NONE) s.exit.prim = s.enter.prim;
        }
        l->v[k++] = s;
    }
    l->n = k;
}

int render_trace(const csg_scene *s, const double plane[4], int r, const double o[3],
                 const double d[3], double tmin, double tmax, iv_arena *a, iv_list *l)
{
    if (csg_trace(s, r, o, d, tmin, tmax, a, l) != 0) return -1;
    if (render_section_on(plane)) render_section_clip(plane, o, d, l);
    return 0;
}

int render_trace_first(const csg_scene *s, const double plane[4], int r, const double o[3],
                       const double d[3], double tmin, double tmax, iv_arena *a, iv_bound *b)
{
    if (!render_section_on(plane)) return csg_trace_first(s, r, o, d, tmin, tmax, a, b);
    iv_list l;
    if (render_trace(s, plane, r, o, d, tmin, tmax, a, &l) != 0) return -1;
    if (l.n == 0) return 0;
    *b = l.v[0].enter;
    return 1;
}
