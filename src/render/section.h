/*
 * section.h — the section view: the model cut by a plane, exactly, on
 * every primary ray (rayscad_render_options.section).  The part on the
 * plane's positive side is taken away; where a ray meets the plane inside
 * the solid, the cut face is drawn in the colour of the surface the ray
 * entered that solid through (the cut object's), lit with the plane's
 * normal.
 */
#ifndef RAYSCAD_RENDER_SECTION_H
#define RAYSCAD_RENDER_SECTION_H

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
 * replaced. */
void render_section_clip(const double plane[4], const double o[3], const double d[3], iv_list *l);

/* The outward normal of a cut face (the plane's, unit). */
void render_section_normal(const double plane[4], double n[3]);

#endif
