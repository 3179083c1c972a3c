/*
 * render.h — cameras that follow OpenSCAD's conventions, and the image
 * renderer: primary rays through a csg_scene, visibility first, shading once
 * at the visible boundaries, colour alpha composited front to back.
 */
#ifndef RAYSCAD_RENDER_H
#define RAYSCAD_RENDER_H

#include "../../include/rayscad.h"
#include "../csg/csg.h"

/* The camera, view, colour scheme, lights and options are the public
 * plain-data types of rayscad.h. */
typedef rayscad_camera render_camera;
typedef rayscad_view render_view;
typedef rayscad_colors render_colors;
typedef rayscad_light render_light;
typedef rayscad_render_options render_options;

/* Resolve a view for an image of width × height pixels and a model whose
 * bounds are lo/hi (used by viewall/autocenter; pass have_bounds = 0 for an
 * empty model).  Follows OpenSCAD 2021.01 exactly (22.5° vertical field of
 * view, its viewall distance and centring), so that the images line up
 * pixel for pixel.  Returns 0, or -1 for a degenerate view (eye == centre). */
int render_camera_resolve(const render_view *v, const double lo[3], const double hi[3],
                          int have_bounds, int width, int height, render_camera *out);

/* The world ray through image position (px, py) in pixels, (0,0) the
 * top-left corner of the top-left pixel: origin o and direction d (unit). */
void render_camera_ray(const render_camera *c, int width, int height, double px, double py,
                       double o[3], double d[3]);

/* The same rays precomputed for one image size, for the per-pixel loops:
 * o = org + px·odx + py·ody and d = d0 + px·ddx + py·ddy, normalised. */
typedef struct render_raygen {
    double org[3], odx[3], ody[3];
    double d0[3], ddx[3], ddy[3];
} render_raygen;

void render_raygen_init(render_raygen *g, const render_camera *c, int width, int height);
void render_raygen_ray(const render_raygen *g, double px, double py, double o[3], double d[3]);

/* The image rectangle rect = {x0, x1, y0, y1} (pixel coordinates, as
 * render_raygen_ray takes them) outside which every ray of g misses the box
 * [lo, hi]: the bounds of its corners' projections, widened by a pixel.
 * Returns 0, or -1 when there is no such rectangle to state (an infinite
 * box, or one reaching to or behind the eye). */
int render_raygen_cover(const render_raygen *g, const double lo[3], const double hi[3],
                        double rect[4]);

/* Fill *out with scheme `name` ("Cornfield", "Metallic", …, as OpenSCAD
 * names them).  Returns 0, or -1 for an unknown name. */
int render_colors_by_name(const char *name, render_colors *out);
/* Scheme i's name (OpenSCAD's order), NULL past the last. */
const char *render_colors_name(int i);

/* Scene roots by role (RAYSCAD_ROOT_MODEL …): root 0 is the model; root 1,
 * when present, the '#' highlight subtrees (drawn in colors.highlight over
 * the model); root 2, when present, the '%' background subtrees (drawn in
 * colors.background_modifier).  An empty root is simply absent from the
 * image. */

/* Render the roots of scene s, composited front to back, into
 * rgba: width*height*4 floats, row-major from the top row, sRGB-encoded,
 * alpha 1 where the background shows.  The result is identical for any
 * thread count (random numbers, when the light model draws any, come from
 * per-pixel streams).  The light model is on when opt asks for shadows,
 * lights or a lens, or when the scene has emitters ($rs_light); materials
 * with reflect, absorb or ior take effect in either look.  Returns 0, or
 * with a message in err: RAYSCAD_ERROR (out of memory, bad options) or
 * RAYSCAD_ERROR_INTERVALS (a ray's interval list passed
 * opt->max_intervals).  Nothing is promised about rgba after a failure. */
int render_image(const csg_scene *s, const render_camera *cam, const render_options *opt,
                 float *rgba, char *err, size_t errlen);

/* The roots of scene s as POV-Ray 3.7 SDL (src/render/pov_export.c): the
 * same solids as analytic POV primitives and CSG, colours as srgbt
 * pigments, camera cam as an image of opt->width × opt->height, the
 * preview's lights and opt->colors' background.  On success *text is a
 * malloc'd string of *len bytes (NUL-terminated), owned by the caller.
 * Returns 0, or -1 with a message in err (out of memory, CSG too deep). */
int render_pov_export(const csg_scene *s, const render_camera *cam, const render_options *opt,
                      char **text, size_t *len, char *err, size_t errlen);

#endif
