/*
 * render.c — the image loop: 32×32 tiles handed out by a shared atomic
 * counter to `threads` pthreads, each with its own iv_arena that is reset
 * after every ray.
 *
 * Per ray (deferred shading): trace every root of the scene into interval
 * lists, merge their boundaries by depth (a three-way merge: each list is
 * already sorted), and walk them front to back.  Only then, for a boundary
 * that contributes colour, ask the scene for its normal and shade it;
 * compositing stops once the accumulated opacity is about 1, so an opaque
 * model costs one normal per ray however deep the list is.  Every boundary
 * counts, entering and exiting — OpenSCAD's preview draws back faces too,
 * which only transparency reveals.  Boundaries made by the camera's clip
 * planes are not surfaces and are skipped, as the GL near plane opens a
 * solid rather than capping it.
 *
 * Invariant: a pixel's value depends only on its position and the inputs —
 * never on the tile order or the thread that drew it — so any thread count
 * gives the same bytes.
 */
#include "render.h"
#include "shade.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

enum { TILE = 32, MAX_ROOTS = 3, MAX_SAMPLES = 64, MAX_THREADS = 256 };

/* Opacity past which the surfaces behind cannot change a byte. */
#define OPAQUE (1.0 - 1.0 / 4096)

typedef struct job {
    const csg_scene *scene;
    const render_camera *cam;
    const render_options *opt;
    float *rgba;
    int nroots;
    int tiles_x, ntiles;
    double tmin_scale, tmax_scale; /* see ray_range */
    atomic_int next;               /* next tile to hand out */
    atomic_int done;               /* tiles finished */
    atomic_int failed;             /* a worker ran out of memory */
    pthread_mutex_t mu;
    pthread_cond_t cv;
    int exited; /* workers that returned; guarded by mu */
} job;

static void set_err(char *err, size_t errlen, const char *msg)
{
    if (err && errlen) snprintf(err, errlen, "%s", msg);
}

/* The parameter range [tmin, tmax] along o + t·d that the camera keeps: its
 * clip planes are depths along forward, and depth = t·(d·forward). */
static void ray_range(const render_camera *c, const double d[3], double *tmin, double *tmax)
{
    double df = d[0] * c->forward[0] + d[1] * c->forward[1] + d[2] * c->forward[2];
    if (c->clip_far > c->clip_near && df > 0) {
        *tmin = c->clip_near / df;
        *tmax = c->clip_far / df;
    } else {
        *tmin = c->ortho ? -INFINITY : 0;
        *tmax = INFINITY;
    }
}

/* Where two boundaries share a depth, the one drawn later by OpenSCAD wins
 * the depth test (GL_LEQUAL for modifiers): highlight over background over
 * model.  Lower rank = nearer. */
static const int root_rank[MAX_ROOTS] = {2, 0, 1};

/* The sRGB colour and alpha of boundary b of root r, before lighting. */
static void surface_color(const job *J, int r, const iv_bound *b, float c[4])
{
    const render_colors *cs = &J->opt->colors;
    const csg_material *m = csg_scene_material(J->scene, b->prim);
    if (r == RENDER_ROOT_HIGHLIGHT) {
        /* Renderer::setColor: HIGHLIGHT ignores the object's own colour. */
        memcpy(c, cs->highlight, sizeof cs->highlight);
    } else if (m && m->has_color) {
        memcpy(c, m->rgba, sizeof m->rgba);
    } else if (r == RENDER_ROOT_BACKGROUND) {
        memcpy(c, cs->background_modifier, sizeof cs->background_modifier);
    } else {
        memcpy(c, b->flip ? cs->back : cs->face, 3 * sizeof(float));
        c[3] = 1;
    }
}

/* One ray: composite every surface of every root front to back over the
 * scheme's background.  Returns 0, or -1 when the arena is out of memory. */
static int shade_ray(const job *J, iv_arena *a, double px, double py, float out[3])
{
    const render_camera *cam = J->cam;
    double o[3], d[3], tmin, tmax;
    render_camera_ray(cam, J->opt->width, J->opt->height, px, py, o, d);
    ray_range(cam, d, &tmin, &tmax);

    iv_list lists[MAX_ROOTS];
    int pos[MAX_ROOTS]; /* next boundary of each list: span pos/2, exit if odd */
    for (int r = 0; r < J->nroots; r++) {
        memset(&lists[r], 0, sizeof lists[r]);
        pos[r] = 0;
        if (csg_trace(J->scene, r, o, d, tmin, tmax, a, &lists[r]) != 0) return -1;
    }

    double acc[3] = {0, 0, 0}, acc_a = 0; /* premultiplied */
    while (acc_a < OPAQUE) {
        int best = -1;
        const iv_bound *bb = NULL;
        for (int r = 0; r < J->nroots; r++) {
            if (pos[r] >= 2 * lists[r].n) continue;
            const iv_span *sp = &lists[r].v[pos[r] / 2];
            const iv_bound *b = (pos[r] & 1) ? &sp->exit : &sp->enter;
            if (!bb || b->t < bb->t || (b->t == bb->t && root_rank[r] < root_rank[best])) {
                best = r;
                bb = b;
            }
        }
        if (best < 0) break;
        pos[best]++;
        if (bb->prim == IV_PRIM_NONE || !isfinite(bb->t)) continue;

        float c[4];
        surface_color(J, best, bb, c);
        if (!(c[3] > 0)) continue;
        double n[3];
        csg_scene_normal(J->scene, bb, o, d, n);
        float lit[3];
        render_shade_apply(c, render_shade_factor(cam, n), lit);
        double w = (1 - acc_a) * (c[3] > 1 ? 1 : c[3]);
        for (int i = 0; i < 3; i++)
            acc[i] += w * lit[i];
        acc_a += w;
    }
    const float *bg = J->opt->colors.background;
    for (int i = 0; i < 3; i++)
        out[i] = (float)(acc[i] + (1 - acc_a) * bg[i]);
    return 0;
}

static int render_tile(const job *J, iv_arena *a, int tile)
{
    const render_options *opt = J->opt;
    int x0 = (tile % J->tiles_x) * TILE, y0 = (tile / J->tiles_x) * TILE;
    int x1 = x0 + TILE < opt->width ? x0 + TILE : opt->width;
    int y1 = y0 + TILE < opt->height ? y0 + TILE : opt->height;
    int s = opt->samples;
    double inv = 1.0 / ((double)s * s);
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            double sum[3] = {0, 0, 0};
            /* s×s strata, each sampled at its centre: deterministic, and
             * s = 1 is the pixel centre where GL samples coverage. */
            for (int j = 0; j < s; j++)
                for (int i = 0; i < s; i++) {
                    float c[3];
                    int rc = shade_ray(J, a, x + (i + 0.5) / s, y + (j + 0.5) / s, c);
                    iv_arena_reset(a);
                    if (rc != 0) return -1;
                    for (int k = 0; k < 3; k++)
                        sum[k] += c[k];
                }
            float *p = J->rgba + ((size_t)y * (size_t)opt->width + (size_t)x) * 4;
            for (int k = 0; k < 3; k++)
                p[k] = (float)(sum[k] * inv);
            p[3] = 1;
        }
    return 0;
}

static void *worker(void *arg)
{
    job *J = arg;
    iv_arena *a = iv_arena_new(0);
    if (!a) atomic_store(&J->failed, 1);
    while (a && !atomic_load(&J->failed)) {
        int t = atomic_fetch_add(&J->next, 1);
        if (t >= J->ntiles) break;
        if (render_tile(J, a, t) != 0) {
            atomic_store(&J->failed, 1);
            break;
        }
        atomic_fetch_add(&J->done, 1);
        pthread_mutex_lock(&J->mu);
        pthread_cond_signal(&J->cv);
        pthread_mutex_unlock(&J->mu);
    }
    iv_arena_free(a);
    pthread_mutex_lock(&J->mu);
    J->exited++;
    pthread_cond_signal(&J->cv);
    pthread_mutex_unlock(&J->mu);
    return NULL;
}

int render_image(const csg_scene *s, const render_camera *cam, const render_options *opt,
                 float *rgba, char *err, size_t errlen)
{
    if (!s || !cam || !opt || !rgba || opt->width < 1 || opt->height < 1 || opt->samples < 1 ||
        opt->samples > MAX_SAMPLES) {
        set_err(err, errlen,
                "render: bad options (need a scene, a camera, an image of at "
                "least 1x1 pixels and 1 to 64 samples)");
        return -1;
    }
    job J;
    memset(&J, 0, sizeof J);
    J.scene = s;
    J.cam = cam;
    J.opt = opt;
    J.rgba = rgba;
    J.nroots = csg_scene_root_count(s);
    if (J.nroots > MAX_ROOTS) J.nroots = MAX_ROOTS;
    if (J.nroots < 0) J.nroots = 0;
    J.tiles_x = (opt->width + TILE - 1) / TILE;
    int tiles_y = (opt->height + TILE - 1) / TILE;
    J.ntiles = J.tiles_x * tiles_y;
    atomic_init(&J.next, 0);
    atomic_init(&J.done, 0);
    atomic_init(&J.failed, 0);
    if (pthread_mutex_init(&J.mu, NULL) != 0) {
        set_err(err, errlen, "render: cannot create a mutex");
        return -1;
    }
    if (pthread_cond_init(&J.cv, NULL) != 0) {
        pthread_mutex_destroy(&J.mu);
        set_err(err, errlen, "render: cannot create a condition variable");
        return -1;
    }

    int nthreads = opt->threads;
    if (nthreads <= 0) {
        long n = sysconf(_SC_NPROCESSORS_ONLN);
        nthreads = n > 0 ? (int)n : 1;
    }
    if (nthreads > MAX_THREADS) nthreads = MAX_THREADS;
    if (nthreads > J.ntiles) nthreads = J.ntiles;
    pthread_t tids[MAX_THREADS];
    int started = 0;
    for (int i = 0; i < nthreads; i++) {
        if (pthread_create(&tids[started], NULL, worker, &J) != 0) break;
        started++;
    }

    if (started == 0) {
        /* No thread to be had: draw on the calling thread. */
        worker(&J);
        if (opt->progress && !atomic_load(&J.failed)) opt->progress(opt->ud, 1.0);
    } else {
        /* The calling thread reports progress while the workers draw. */
        int reported = -1;
        pthread_mutex_lock(&J.mu);
        while (J.exited < started) {
            int d = atomic_load(&J.done);
            if (d != reported && opt->progress) {
                reported = d;
                pthread_mutex_unlock(&J.mu);
                opt->progress(opt->ud, (double)d / J.ntiles);
                pthread_mutex_lock(&J.mu);
                continue;
            }
            struct timespec ts;
            clock_gettime(CLOCK_REALTIME, &ts);
            ts.tv_nsec += 100 * 1000 * 1000;
            if (ts.tv_nsec >= 1000000000L) {
                ts.tv_sec++;
                ts.tv_nsec -= 1000000000L;
            }
            pthread_cond_timedwait(&J.cv, &J.mu, &ts);
        }
        pthread_mutex_unlock(&J.mu);
        for (int i = 0; i < started; i++)
            pthread_join(tids[i], NULL);
        if (opt->progress && !atomic_load(&J.failed) && reported != J.ntiles)
            opt->progress(opt->ud, 1.0);
    }
    pthread_cond_destroy(&J.cv);
    pthread_mutex_destroy(&J.mu);
    if (atomic_load(&J.failed)) {
        set_err(err, errlen, "render: out of memory while tracing rays");
        return -1;
    }
    return 0;
}
