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

#include <stddef.h>

/* Draws tile `tile` of `job` with the worker's arena and its state (the
 * pool's state_size bytes, zeroed when the worker starts and kept across
 * its tiles).  Returns 0, or -1 when the arena failed. */
typedef int (*render_tile_fn)(const void *job, iv_arena *a, void *state, int tile);

typedef struct render_pool {
    int ntiles;
    int threads;       /* <= 0: one per online core */
    int max_intervals; /* each worker arena's list limit (<= 0: the default) */
    size_t state_size;
    render_tile_fn tile;
    const void *job;
    void (*progress)(void *ud, double fraction); /* may be NULL */
    void *ud;
} render_pool;

/* Draws every tile.  Returns 0, or why the first worker to fail stopped (an
 * iv_arena_failure_kind; IV_ARENA_OUT_OF_MEMORY also when a worker could not
 * get its arena or state).  Progress reaches 1.0 only on success. */
int render_pool_run(const render_pool *p);

#endif
