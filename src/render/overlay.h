/*
 * overlay.h — openscad's --view lines over a rendered image: edges, axes,
 * scale ticks, crosshairs (overlay.c).
 */
#ifndef RAYSCAD_RENDER_OVERLAY_H
#define RAYSCAD_RENDER_OVERLAY_H

#include <stddef.h>

#include "render.h"

/* Draw what opt->view asks for into rgba (the image render_image made
 * with the same scene, camera and options).  0, or -1 / RAYSCAD_ERROR_INTERVALS
 * with a message when the rays that find the visible surfaces fail. */
int render_overlays(const csg_scene *s, const render_camera *cam, const render_options *opt,
                    float *rgba, char *err, size_t errlen);

#endif
