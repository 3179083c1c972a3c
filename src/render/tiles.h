/*
 * tiles.h — the pool of worker threads both renderers draw with: tiles are
 * handed out from one shared counter (a worker that finishes early takes
 * the next one, so the load balances itself), each worker owns an arena
 * reset by the tile function after every ray, and the calling thread
 * reports progress while the workers draw.
 */
#ifndef RAYSCAD_RENDER_TILES_H
#define RAYSCAD_RENDER_TILES_H

#include "../intervals/intervals.h"
#include "render.h"

#include <stddef.h>

/* What both renderers draw from: the scene, the camera and its primary
 * rays at the image size, the options and the image (rgba). */
typedef struct render_frame {
    const csg_scene *scene;
    const render_camera *cam;
    render_raygen gen;
    const render_options *opt;
    float *rgba;
} render_frame;

static inline void render_frame_init(render_frame *f, const csg_scene *s, const render_camera *cam,
                                     const render_options *opt, float *rgba)
{
    f->scene = s;
    f->cam = cam;
    render_raygen_init(&f->gen, cam, opt->width, opt->height);
    f->opt = opt;
    f->rgba = rgba;
}

/* Draws the pixels [x0, x1) × [y0, y1) of `job` with the worker's arena and
 * its state (state_size bytes, zeroed when the worker starts and kept across
 * its tiles).  Returns 0, or -1 when the arena failed. */
typedef int (*render_tile_fn)(const void *job, iv_arena *a, void *state, int x0, int y0, int x1,
                              int y1);

/* Draws opt's width × height image in RENDER_TILE-pixel squares with opt's
 * threads (<= 0: one per online core), interval limit and progress
 * callback; progress reaches 1.0 only on success.  Returns 0;
 * RAYSCAD_CANCELLED when opt's cancel hook said stop;
 * RAYSCAD_ERROR_INTERVALS when a ray's list outgrew the limit, or -1 when
 * memory ran out ("render: out of memory while <doing>"), each with its
 * message in err. */
int render_tiles_draw(const render_options *opt, size_t state_size, render_tile_fn tile,
                      const void *job, const char *doing, char *err, size_t errlen);

#endif
