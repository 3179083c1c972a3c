/*
 * section.h — the section view: the model cut by a plane, exactly, on
 * every ray the renderers trace (rayscad_render_options.section): primary,
 * shadow, mirror, refracted and the path tracer's.  The part on the
 * plane's positive side is taken away; where a ray meets the plane inside
 * the solid, the cut face is drawn in the colour of the solid it cuts,
 * lit with the plane's normal.  The renderers trace through
 * render_trace/render_trace_first, which apply the cut when there is one.
 */
#ifndef RAYSCAD_RENDER_SECTION_H
#define RAYSCAD_RENDER_SECTION_H

#include "../csg/csg.h"
#include "../intervals/intervals.h"

/* A cut face's boundary: its flip has this bit besides the entered
 * surface's own flip (bit 0). */
enum { RENDER_SECTION_FLIP = 2 };

/* 1 when plane (a, b, c, d: the plane ax + by + cz = d, (a, b, c) not 0)
 * asks for a section. */
int render_section_on(const double plane[4]);

/* Clip list l of ray o + t·d to the part the section keeps (n·p <= d):
 * spans beyond it dropped, a span the plane cuts ended (or begun) at the
 * plane by a boundary marked RENDER_SECTION_FLIP that keeps the prim it
 * replaced — or, where that was a clip (the ray began inside the solid),
 * the prim of the span's other end, so the cut face has a material. */
void render_section_clip(const double plane[4], const double o[3], const double d[3], iv_list *l);

/* The outward normal of a cut face (the plane's, unit). */
void render_section_normal(const double plane[4], double n[3]);

/* csg_trace of root r of scene s, cut by plane when render_section_on. */
int render_trace(const csg_scene *s, const double plane[4], int r, const double o[3],
                 const double d[3], double tmin, double tmax, iv_arena *a, iv_list *l);

/* csg_trace_first likewise: 1 with the first boundary in *b, 0 for none,
 * -1 out of memory.  With a cut, the whole list is traced and clipped. */
int render_trace_first(const csg_scene *s, const double plane[4], int r, const double o[3],
                       const double d[3], double tmin, double tmax, iv_arena *a, iv_bound *b);

#endif
