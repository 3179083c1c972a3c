/*
 * shade.h — private to src/render: OpenSCAD's preview lighting.
 */
#ifndef RAYSCAD_RENDER_SHADE_H
#define RAYSCAD_RENDER_SHADE_H

#include "render.h"

/* The factor OpenSCAD's fixed-function lighting multiplies a colour by at a
 * surface with world-space unit normal n seen through camera c: 0.2 ambient
 * plus the two opposite eye-space lights, in [0.2, 0.2 + 1]. */
double render_shade_factor(const render_camera *c, const double n[3]);

/* rgb × factor, each channel clamped to [0, 1] as the framebuffer does. */
void render_shade_apply(const float rgb[3], double factor, float out[3]);

#endif
