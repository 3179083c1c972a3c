/*
 * path_trace.h — private to src/render: the path-traced quality mode
 * (render_options.path_trace > 0), which render_image hands the whole image
 * to.
 */
#ifndef RAYSCAD_RENDER_PATH_TRACE_H
#define RAYSCAD_RENDER_PATH_TRACE_H

#include "render.h"

/* Render root RAYSCAD_ROOT_MODEL of scene s through camera cam with a
 * unidirectional path tracer, opt->path_trace samples per pixel, into rgba
 * (opt->width × opt->height × 4 floats, sRGB-encoded, alpha 1) — the same
 * layout as render_image.  The image is identical for any opt->threads.
 * Returns 0, or -1 with a message in err (out of memory, bad options). */
int render_path_trace(const csg_scene *s, const render_camera *cam, const render_options *opt,
                      float *rgba, char *err, size_t errlen);

#endif
