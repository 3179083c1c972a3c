/*
 * tiles.c — the renderers' worker pool (see tiles.h).
 *
 * Workers do not wake the calling thread per tile: a render of a few
 * hundred small tiles would switch contexts that often on cores the
 * workers need.  The caller polls the finished-tile count ten times a
 * second instead and is woken only when a worker exits.
 */
#include "tiles.h"

#include <pthread.h>
#include <stdio.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

enum { MAX_THREADS = 256, POLL_NS = 100 * 1000 * 1000, TILE = 32 };
/* run()'s result when the cancel hook stopped it (no arena failure kind). */
enum { RENDER_CANCELLED = -100 };

typedef struct render_pool {
    const render_options *opt;
    int tiles_x, ntiles;
    size_t state_size;
    render_tile_fn tile;
    const void *job;
} render_pool;

typedef struct pool_run {
    const render_pool *p;
    atomic_int next;      /* next tile to hand out */
    atomic_int done;      /* tiles finished */
    atomic_int failed;    /* the first failing worker's iv_arena_failure_kind */
    atomic_int cancelled; /* the options' cancel hook said stop */
    pthread_mutex_t mu;
    pthread_cond_t cv;
    int exited; /* workers that returned; guarded by mu */
} pool_run;

/* Keep the first reason a worker stops (a worker without an arena ran out
 * of memory). */
static void fail(pool_run *R, const iv_arena *a)
{
    int none = 0;
    int why = a ? (int)iv_arena_failure(a) : IV_ARENA_OUT_OF_MEMORY;
    atomic_compare_exchange_strong(&R->failed, &none, why ? why : IV_ARENA_OUT_OF_MEMORY);
}

static void draw(pool_run *R)
{
    const render_pool *p = R->p;
    iv_arena *a = iv_arena_new(0);
    void *state = calloc(1, p->state_size ? p->state_size : 1);
    if (!a || !state) {
        fail(R, NULL);
    } else {
        iv_arena_set_list_limit(a, p->opt->max_intervals);
        while (!atomic_load(&R->failed) && !atomic_load(&R->cancelled)) {
            if (p->opt->cancelled && p->opt->cancelled(p->opt->cancel_ud)) {
                atomic_store(&R->cancelled, 1);
                break;
            }
            int t = atomic_fetch_add(&R->next, 1);
            if (t >= p->ntiles) break;
            int x0 = (t % p->tiles_x) * TILE, y0 = (t / p->tiles_x) * TILE;
            int x1 = x0 + TILE < p->opt->width ? x0 + TILE : p->opt->width;
            int y1 = y0 + TILE < p->opt->height ? y0 + TILE : p->opt->height;
            if (p->tile(p->job, a, state, x0, y0, x1, y1) != 0) {
                fail(R, a);
                break;
            }
            atomic_fetch_add(&R->done, 1);
        }
    }
    free(state);
    iv_arena_free(a);
}

static void *worker(void *arg)
{
    pool_run *R = arg;
    draw(R);
    pthread_mutex_lock(&R->mu);
    R->exited++;
    pthread_cond_signal(&R->cv);
    pthread_mutex_unlock(&R->mu);
    return NULL;
}

/* The calling thread reports progress until `started` workers exited;
 * returns the last count of finished tiles it reported (-1: none). */
static int watch(pool_run *R, int started)
{
    const render_pool *p = R->p;
    int reported = -1;
    pthread_mutex_lock(&R->mu);
    while (R->exited < started) {
        int d = atomic_load(&R->done);
        if (d != reported && p->opt->progress) {
            reported = d;
            pthread_mutex_unlock(&R->mu);
            p->opt->progress(p->opt->ud, (double)d / p->ntiles);
            pthread_mutex_lock(&R->mu);
            continue;
        }
        struct timespec ts;
        clock_gettime(CLOCK_REALTIME, &ts);
        ts.tv_nsec += POLL_NS;
        if (ts.tv_nsec >= 1000000000L) {
            ts.tv_sec++;
            ts.tv_nsec -= 1000000000L;
        }
        pthread_cond_timedwait(&R->cv, &R->mu, &ts);
    }
    pthread_mutex_unlock(&R->mu);
    return reported;
}

/* Draws every tile.  Returns 0, or why the first worker to fail stopped (an
 * iv_arena_failure_kind; IV_ARENA_OUT_OF_MEMORY also when a worker could not
 * get its arena or state). */
static int run(const render_pool *p)
{
    pool_run R = {.p = p};
    atomic_init(&R.next, 0);
    atomic_init(&R.done, 0);
    atomic_init(&R.failed, 0);
    atomic_init(&R.cancelled, 0);
    if (p->ntiles <= 0) return 0;
    int nthreads = p->opt->threads;
    if (nthreads <= 0) {
        long n = sysconf(_SC_NPROCESSORS_ONLN);
        nthreads = n > 0 ? (int)n : 1;
    }
    if (nthreads > MAX_THREADS) nthreads = MAX_THREADS;
    if (nthreads > p->ntiles) nthreads = p->ntiles;
    pthread_t tids[MAX_THREADS];
    int started = 0, reported = -1;
    if (pthread_mutex_init(&R.mu, NULL) == 0) {
        if (pthread_cond_init(&R.cv, NULL) == 0) {
            for (int i = 0; i < nthreads; i++) {
                if (pthread_create(&tids[started], NULL, worker, &R) != 0) break;
                started++;
            }
            if (started > 0) reported = watch(&R, started);
            for (int i = 0; i < started; i++)
                pthread_join(tids[i], NULL);
            pthread_cond_destroy(&R.cv);
        }
        pthread_mutex_destroy(&R.mu);
    }
    if (started == 0) draw(&R); /* no thread to be had: draw on this one */
    int failed = atomic_load(&R.failed);
    if (!failed && atomic_load(&R.cancelled)) return RENDER_CANCELLED;
    if (!failed && p->opt->progress && reported != p->ntiles) p->opt->progress(p->opt->ud, 1.0);
    return failed;
}

int render_tiles_draw(const render_options *opt, size_t state_size, render_tile_fn tile,
                      const void *job, const char *doing, char *err, size_t errlen)
{
    render_pool p = {.opt = opt, .state_size = state_size, .tile = tile, .job = job};
    p.tiles_x = (opt->width + TILE - 1) / TILE;
    p.ntiles = p.tiles_x * ((opt->height + TILE - 1) / TILE);
    int failed = run(&p);
    if (!failed) return 0;
    if (failed == RENDER_CANCELLED) {
        if (err && errlen) snprintf(err, errlen, "render: cancelled");
        return RAYSCAD_CANCELLED;
    }
    if (failed == IV_ARENA_LIST_TOO_LONG) {
        if (err && errlen)
            snprintf(err, errlen, "render: a ray's interval list holds more than %d intervals",
                     opt->max_intervals > 0 ? opt->max_intervals : IV_LIST_LIMIT_DEFAULT);
        return RAYSCAD_ERROR_INTERVALS;
    }
    if (err && errlen) snprintf(err, errlen, "render: out of memory while %s", doing);
    return -1;
}
