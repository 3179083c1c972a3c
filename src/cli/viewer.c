/*
 * viewer.c — see viewer.h.
 *
 * Three threads.  The event thread (main) owns the window: it turns the
 * mouse and keys into the view (openscad's --camera numbers: centre,
 * rotation, distance) and shows each picture the render thread hands it.
 * The render thread draws the newest view: while the view moves, at a
 * reduced resolution sized from the last frame's cost so that a frame takes
 * about FRAME_MS; once it rests, at full resolution, then again with 2×2
 * and 3×3 samples a pixel, and then it goes on adding passes that sample
 * elsewhere in each pixel (rayscad_render_options.pass; the light model's
 * and the path tracer's random numbers too) and shows their mean, until
 * that mean's standard error falls below half a step of 8-bit colour
 * (accumulate.h) or MAX_PASSES.  The path tracer skips the 2×2 and 3×3
 * pictures and draws every pass with one path a pixel.  A pass that a
 * newer view makes useless is cancelled (rayscad_render_options.cancelled).
 * The load thread evaluates the file and every time one of the files it
 * read changes (watch.h), evaluates it again and hands the new scene over;
 * a failed evaluation keeps the last good scene and puts its error in the
 * window's title with a red frame around the picture.
 */
#define _DEFAULT_SOURCE
#include "viewer.h"

#include <SDL.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "accumulate.h"
#include "progress.h"
#include "viewer_text.h"
#include "watch.h"

#define FRAME_MS 25.0         /* a moving frame's budget */
#define REST_MS 150           /* no input for this long: the view rests */
#define MAX_SAMPLES 3         /* the last fixed refinement: 3×3 samples a pixel */
#define CONVERGED (0.5 / 255) /* the mean's standard error where passes stop */
#define MAX_PASSES 64         /* of 3×3 samples; the path tracer's of 1 path: */
#define MAX_PATH_PASSES 1024
#define ZOOM_STEP 0.9 /* a wheel notch, as openscad's Camera::zoom */
#define DRAG_DEG 0.7  /* degrees a pixel of drag turns, as openscad */
#define PI 3.14159265358979323846

typedef struct view {
    double t[3], r[3], d; /* --camera=t,r,d */
    int ortho;
} view;

typedef struct viewer {
    const cli_options *o;
    cli_viewer_load load;
    void *load_ud;

    pthread_mutex_t mu;
    pthread_cond_t cv;
    atomic_uint gen; /* bumped by every change of what is to be drawn */
    int quit;
    /* what is to be drawn (under mu) */
    view v;
    int w, h;
    int flags;  /* RAYSCAD_VIEW_* */
    int scheme; /* rayscad_colors_name index */
    int shadows, xray;
    /* the section plane (rayscad_render_options.section) when on; its
     * direction: 0 the view's, 1..3 the x, y, z axis */
    int section_on, section_dir;
    double section[4];
    double moved_at; /* last input, seconds */
    rayscad_scene *scene, *pending;
    int have_model;
    char error[512];    /* the last load's error, "" when it loaded */
    int view_from_file; /* the first scene sets the view */
    int reload;         /* r pressed: evaluate again */
    int show_keys;      /* ? pressed: the keys drawn over the picture */
    viewer_text *text;  /* NULL: no font, no text in the window */
    /* the render thread's result (under mu) */
    float *img;
    size_t icap; /* floats img holds */
    int iw, ih, isamples, ipass;
    unsigned igen;
    double ims;
    int fresh;         /* a picture the event thread has not shown yet */
    Uint32 wake_event; /* SDL user event: a picture or a title to show */
    /* the render thread's own */
    /* of gen `level_gen`: 0 none, 1 reduced, 2 full, 3.. more samples or
     * the passes after them */
    int level;
    unsigned level_gen;
    int settled;         /* converged, at MAX_PASSES, or failed: nothing more to draw */
    cli_accum accum;     /* the passes' mean */
    double ms_per_pixel; /* of the last reduced frame */
} viewer;

static void wake(viewer *V)
{
    SDL_Event e;
    memset(&e, 0, sizeof e);
    e.type = V->wake_event;
    SDL_PushEvent(&e);
}

static rayscad_view to_view(const view *v)
{
    rayscad_view rv;
    memset(&rv, 0, sizeof rv);
    rv.kind = RAYSCAD_CAMERA_GIMBAL;
    for (int k = 0; k < 3; k++) {
        rv.v[k] = v->t[k];
        rv.v[3 + k] = v->r[k];
    }
    rv.v[6] = v->d;
    rv.ortho = v->ortho;
    return rv;
}

/* The view a camera resolved by the library shows: its centre and
 * distance; the rotation is the caller's. */
static void from_camera(const rayscad_camera *c, view *v)
{
    v->d = c->clip_far / 100;
    for (int k = 0; k < 3; k++)
        v->t[k] = c->eye[k] + v->d * c->forward[k];
}

/* The view the command line asked for, framed on scene s. */
static void initial_view(viewer *V, const rayscad_scene *s, const rayscad_file_view *file)
{
    const cli_options *o = V->o;
    rayscad_view rv = o->view;
    if (rv.kind == RAYSCAD_CAMERA_DEFAULT && file) rv.file = *file;
    rayscad_camera cam;
    view v = {{0, 0, 0}, {55, 0, 25}, 140, o->view.ortho};
    if (rayscad_camera_frame(s, &rv, V->w, V->h, &cam, NULL, 0) == RAYSCAD_OK)
        from_camera(&cam, &v);
    if (rv.kind == RAYSCAD_CAMERA_GIMBAL) {
        for (int k = 0; k < 3; k++)
            v.r[k] = rv.v[3 + k];
    } else if (rv.kind == RAYSCAD_CAMERA_EYE) { /* as src/render/camera.c turns it */
        double dir[3] = {rv.v[3] - rv.v[0], rv.v[4] - rv.v[1], rv.v[5] - rv.v[2]};
        double rz = (dir[1] == 0 && dir[0] == 0) ? (dir[2] < 0 ? 0 : 180)
                                                 : -atan2(dir[1], dir[0]) * 180 / PI + 90;
        double rx = -atan2(dir[2], hypot(dir[0], dir[1])) * 180 / PI;
        v.r[0] = 90 - rx;
        v.r[1] = 0;
        v.r[2] = -rz;
    } else if (file && (file->set & 1)) {
        for (int k = 0; k < 3; k++)
            v.r[k] = file->vpr[k];
    }
    V->v = v;
}

/* ---- the render thread ----------------------------------------------------- */

typedef struct cancel_ctx {
    viewer *V;
    unsigned gen;
} cancel_ctx;

static int cancelled(void *ud)
{
    const cancel_ctx *c = ud;
    return atomic_load(&c->V->gen) != c->gen;
}

static void *render_main(void *arg)
{
    viewer *V = arg;
    float *buf = NULL;
    size_t cap = 0;
    pthread_mutex_lock(&V->mu);
    while (!V->quit) {
        if (V->pending) { /* a new scene: the old one is no longer drawn */
            rayscad_scene_free(V->scene);
            V->scene = V->pending;
            V->pending = NULL;
        }
        unsigned gen = atomic_load(&V->gen);
        if (V->level_gen != gen) {
            V->level_gen = gen;
            V->level = 0;
            V->settled = 0;
        }
        int moving = cli_now_s() - V->moved_at < REST_MS / 1000.0;
        int next = moving ? 1 : V->level < 2 ? 2 : V->level + 1;
        int traced = V->o->optics.path_trace > 0;
        int fixed = traced ? 2 : MAX_SAMPLES + 1; /* the last level drawn once; then passes */
        if (!V->scene || (moving && V->level >= 1) || V->settled) {
            struct timespec ts;
            clock_gettime(CLOCK_REALTIME, &ts);
            ts.tv_nsec += 30 * 1000 * 1000;
            if (ts.tv_nsec >= 1000000000L) {
                ts.tv_sec++;
                ts.tv_nsec -= 1000000000L;
            }
            pthread_cond_timedwait(&V->cv, &V->mu, &ts);
            continue;
        }
        /* this pass: its size, samples and options */
        int w = V->w, h = V->h, samples = next == 1 ? 1 : next > fixed ? MAX_SAMPLES : next - 1;
        int pass = next > fixed ? next - fixed : 0;
        if (next == 1) {
            double f = 1;
            if (V->ms_per_pixel > 0) f = sqrt(w * (double)h * V->ms_per_pixel / FRAME_MS);
            f = f < 1 ? 1 : f > 16 ? 16 : ceil(f);
            w = (int)(w / f) > 0 ? (int)(w / f) : 1;
            h = (int)(h / f) > 0 ? (int)(h / f) : 1;
        }
        rayscad_render_options ro = V->o->optics;
        rayscad_colors_by_name(rayscad_colors_name(V->scheme), &ro.colors);
        ro.width = w;
        ro.height = h;
        ro.samples = samples;
        ro.pass = pass;
        if (traced) {
            ro.path_trace = 1;
            ro.unclamped = 1; /* the mean of passes is the light's */
        }
        ro.threads = V->o->threads;
        ro.max_intervals = V->o->max_intervals;
        ro.view = V->flags;
        if (V->section_on) memcpy(ro.section, V->section, sizeof ro.section);
        ro.shadows = V->shadows || ro.shadows;
        if (V->xray) ro.xray = 0.35;
        cancel_ctx cc = {V, gen};
        if (next > 1) { /* a refinement a newer view makes useless */
            ro.cancelled = cancelled;
            ro.cancel_ud = &cc;
        }
        rayscad_view rv = to_view(&V->v);
        rayscad_scene *scene = V->scene;
        pthread_mutex_unlock(&V->mu);

        size_t need = (size_t)w * h * 4;
        if (need > cap) {
            float *b = realloc(buf, need * sizeof *b);
            if (b) {
                buf = b;
                cap = need;
            }
        }
        rayscad_camera cam;
        double t0 = cli_now_s();
        int ok = need <= cap &&
                 rayscad_camera_frame(scene, &rv, w, h, &cam, NULL, 0) == RAYSCAD_OK &&
                 rayscad_render(scene, &cam, &ro, buf, NULL, 0) == RAYSCAD_OK;
        double ms = 1000 * (cli_now_s() - t0);
        /* the passes: their mean, from the last fixed level's picture on */
        double err = INFINITY;
        if (ok && next >= fixed) {
            if (next == fixed) ok = cli_accum_reset(&V->accum, (size_t)w * h, traced) == 0;
            if (ok) cli_accum_add(&V->accum, buf);
            if (ok && next > fixed) {
                cli_accum_mean(&V->accum, buf);
                err = cli_accum_error(&V->accum);
            }
        }

        pthread_mutex_lock(&V->mu);
        if (ok && next == 1) V->ms_per_pixel = ms / ((double)w * h);
        if (V->level_gen == gen) {
            V->level = next;
            V->settled = !ok || err < CONVERGED || pass >= (traced ? MAX_PATH_PASSES : MAX_PASSES);
            if (ok && pass > 0 && V->settled && V->o->stats)
                fprintf(stderr, "%s after %d passes: standard error %.2f/255\n",
                        err < CONVERGED ? "converged" : "stopped", pass, 255 * err);
        }
        if (!ok) continue;
        float *t = V->img; /* hand the picture over, take the old buffer */
        size_t tcap = V->icap;
        V->img = buf;
        V->icap = cap;
        buf = t;
        cap = tcap;
        V->iw = w;
        V->ih = h;
        V->isamples = traced ? 1 : samples;
        V->ipass = pass;
        V->igen = gen;
        V->ims = ms;
        V->fresh = 1;
        wake(V);
    }
    pthread_mutex_unlock(&V->mu);
    free(buf);
    cli_accum_free(&V->accum);
    return NULL;
}

/* ---- the load thread --------------------------------------------------------- */

static void free_files(char **files, int n)
{
    for (int i = 0; i < n; i++)
        free(files[i]);
    free(files);
}

static void *load_main(void *arg)
{
    viewer *V = arg;
    cli_watch *watch = cli_watch_new();
    int again = 1;
    while (again) {
        pthread_mutex_lock(&V->mu);
        view v = V->v;
        int quit = V->quit;
        pthread_mutex_unlock(&V->mu);
        if (quit) break;
        rayscad_scene *scene = NULL;
        rayscad_file_view file;
        memset(&file, 0, sizeof file);
        char **files = NULL, err[512] = "";
        int nfiles = 0;
        double t0 = cli_now_s();
        rayscad_status st =
            V->load(V->load_ud, v.r, v.t, v.d, &scene, &file, &files, &nfiles, err, sizeof err);
        if (V->o->stats)
            fprintf(stderr, "loaded in %.1f ms%s\n", 1000 * (cli_now_s() - t0),
                    st == RAYSCAD_OK ? "" : " (failed)");
        if (watch) cli_watch_set(watch, (const char *const *)files, nfiles);
        free_files(files, nfiles);
        pthread_mutex_lock(&V->mu);
        if (st == RAYSCAD_OK) {
            if (V->view_from_file) {
                initial_view(V, scene, &file);
                V->view_from_file = 0;
            }
            rayscad_scene_free(V->pending);
            V->pending = scene;
            V->have_model = 1;
            V->error[0] = '\0';
        } else {
            snprintf(V->error, sizeof V->error, "%s", err[0] ? err : "the model did not load");
        }
        atomic_fetch_add(&V->gen, 1);
        pthread_cond_broadcast(&V->cv);
        pthread_mutex_unlock(&V->mu);
        wake(V); /* the title */
        /* wait for a change, or for the window to close */
        again = 0;
        while (!again) {
            pthread_mutex_lock(&V->mu);
            quit = V->quit;
            pthread_mutex_unlock(&V->mu);
            if (quit) break;
            again = watch ? cli_watch_wait(watch, 200, 50) : (SDL_Delay(200), 0);
            pthread_mutex_lock(&V->mu);
            again |= V->reload;
            V->reload = 0;
            pthread_mutex_unlock(&V->mu);
        }
    }
    cli_watch_free(watch);
    return NULL;
}

/* ---- the event thread ---------------------------------------------------------- */

static void set_title(SDL_Window *win, const viewer *V)
{
    const char *slash = strrchr(V->o->input, '/');
    char title[700];
    if (V->error[0])
        snprintf(title, sizeof title, "%s - rayscad - %s", slash ? slash + 1 : V->o->input,
                 V->error);
    else
        snprintf(title, sizeof title, "%s - rayscad", slash ? slash + 1 : V->o->input);
    SDL_SetWindowTitle(win, title);
}

static const char help[] =
    "rayscad viewer keys (as openscad's View menu):\n"
    "  left drag: rotate (shift: about the view axis)   right/middle drag: pan\n"
    "  wheel, shift+right drag, + and -: zoom\n"
    "  Ctrl+1 edges  Ctrl+2 axes  Ctrl+3 crosshairs  Ctrl+Shift+2 scales\n"
    "  Ctrl+4 top  Ctrl+5 bottom  Ctrl+6 left  Ctrl+7 right  Ctrl+8 front  Ctrl+9 back\n"
    "  Ctrl+0 diagonal  Ctrl+P centre  Ctrl+Shift+V view all  Ctrl+Shift+0 reset view\n"
    "  o orthogonal/perspective  k next colour scheme  h shadows  x x-ray\n"
    "  v section plane on/off (through the view centre)  a its direction: the\n"
    "    view's, x, y, z  [ and ] move it\n"
    "  s save a screenshot (NAME-N.png)  c print --camera=…  r reload  q, Esc quit\n";

/* Show the last picture scaled to the window, with a red frame when the
 * last load failed. */
static void present(SDL_Renderer *ren, SDL_Texture **tex, int *tw, int *th, viewer *V)
{
    if (V->img && (V->iw != *tw || V->ih != *th || !*tex)) {
        if (*tex) SDL_DestroyTexture(*tex);
        *tex = SDL_CreateTexture(ren, SDL_PIXELFORMAT_ABGR8888, SDL_TEXTUREACCESS_STREAMING, V->iw,
                                 V->ih);
        *tw = V->iw;
        *th = V->ih;
    }
    if (V->img && *tex && V->fresh) {
        void *pixels;
        int pitch;
        if (SDL_LockTexture(*tex, NULL, &pixels, &pitch) == 0) {
            for (int y = 0; y < V->ih; y++) {
                unsigned char *row = (unsigned char *)pixels + (size_t)y * pitch;
                const float *src = V->img + (size_t)y * V->iw * 4;
                for (int x = 0; x < V->iw * 4; x++) {
                    float c = src[x] < 0 ? 0 : src[x] > 1 ? 1 : src[x];
                    row[x] = (unsigned char)(c * 255 + 0.5f);
                }
            }
            SDL_UnlockTexture(*tex);
        }
    }
    V->fresh = 0;
    rayscad_colors cs;
    rayscad_colors_by_name(rayscad_colors_name(V->scheme), &cs);
    SDL_SetRenderDrawColor(ren, (Uint8)(cs.background[0] * 255), (Uint8)(cs.background[1] * 255),
                           (Uint8)(cs.background[2] * 255), 255);
    SDL_RenderClear(ren);
    if (*tex) SDL_RenderCopy(ren, *tex, NULL, NULL);
    if (V->error[0]) {
        SDL_SetRenderDrawColor(ren, 220, 30, 30, 255);
        for (int k = 0; k < 4; k++) {
            SDL_Rect r = {k, k, V->w - 2 * k, V->h - 2 * k};
            SDL_RenderDrawRect(ren, &r);
        }
        SDL_Color fg = {255, 255, 255, 255}, bg = {180, 20, 20, 220};
        viewer_text_draw(V->text, ren, V->error, 4, V->h - 4, 1, V->w - 8, fg, bg);
    }
    if (V->show_keys) {
        SDL_Color fg = {255, 255, 255, 255}, bg = {30, 30, 30, 210};
        viewer_text_draw(V->text, ren, help, 10, 10, 0, V->w - 20, fg, bg);
    }
    SDL_RenderPresent(ren);
}

static void changed(viewer *V)
{
    V->moved_at = cli_now_s();
    atomic_fetch_add(&V->gen, 1);
    pthread_cond_broadcast(&V->cv);
}

static void set_rotation(viewer *V, double rx, double ry, double rz)
{
    V->v.r[0] = rx;
    V->v.r[1] = ry;
    V->v.r[2] = rz;
}

/* View all: the scene framed as openscad frames it, the rotation kept. */
static void view_all(viewer *V)
{
    if (!V->scene && !V->pending) return;
    rayscad_view rv = to_view(&V->v);
    rv.viewall = rv.autocenter = 1;
    rayscad_camera cam;
    if (rayscad_camera_frame(V->pending ? V->pending : V->scene, &rv, V->w, V->h, &cam, NULL, 0) ==
        RAYSCAD_OK)
        from_camera(&cam, &V->v);
}

/* The world's right and up directions on screen now, and the size of a
 * pixel at the view centre; also the view direction. */
static int screen_axes(viewer *V, double right[3], double up[3], double *per_px, double forward[3])
{
    rayscad_view rv = to_view(&V->v);
    rayscad_camera cam;
    const rayscad_scene *s = V->scene ? V->scene : V->pending;
    if (!s || rayscad_camera_frame(s, &rv, V->w, V->h, &cam, NULL, 0) != RAYSCAD_OK) return -1;
    memcpy(right, cam.right, sizeof cam.right);
    memcpy(up, cam.up, sizeof cam.up);
    memcpy(forward, cam.forward, sizeof cam.forward);
    double half = cam.ortho ? cam.ortho_half_height : V->v.d * tan(cam.fovy_deg / 2 * PI / 180);
    *per_px = 2 * half / V->h;
    return 0;
}

/* A section plane through the view centre: facing the viewer (the near
 * half taken away) or across an axis (the positive side taken away). */
static void section_here(viewer *V)
{
    double n[3] = {0, 0, 0}, right[3], up[3], fw[3], per_px;
    if (V->section_dir > 0) {
        n[V->section_dir - 1] = 1;
    } else {
        if (screen_axes(V, right, up, &per_px, fw) != 0) return;
        for (int k = 0; k < 3; k++)
            n[k] = -fw[k];
    }
    for (int k = 0; k < 3; k++)
        V->section[k] = n[k];
    V->section[3] = n[0] * V->v.t[0] + n[1] * V->v.t[1] + n[2] * V->v.t[2];
    V->section_on = 1;
}

static void screenshot(viewer *V)
{
    static int n;
    char path[512];
    const char *slash = strrchr(V->o->input, '/'), *base = slash ? slash + 1 : V->o->input;
    const char *dot = strrchr(base, '.');
    snprintf(path, sizeof path, "%.*s-%d.png", dot ? (int)(dot - base) : (int)strlen(base), base,
             ++n);
    char err[512];
    if (V->img && rayscad_image_write(path, V->iw, V->ih, 4, V->img, err, sizeof err) == RAYSCAD_OK)
        fprintf(stderr, "rayscad: saved %s (%dx%d)\n", path, V->iw, V->ih);
    else
        fprintf(stderr, "rayscad: error: %s\n", V->img ? err : "nothing drawn yet");
}

static void key(viewer *V, const SDL_KeyboardEvent *k, int *quit)
{
    int ctrl = (k->keysym.mod & KMOD_CTRL) != 0, shift = (k->keysym.mod & KMOD_SHIFT) != 0;
    SDL_Keycode c = k->keysym.sym;
    if (ctrl) {
        switch (c) {
        case SDLK_1:
            V->flags ^= RAYSCAD_VIEW_EDGES;
            break;
        case SDLK_2:
            V->flags ^= shift ? RAYSCAD_VIEW_SCALES : RAYSCAD_VIEW_AXES;
            break;
        case SDLK_3:
            V->flags ^= RAYSCAD_VIEW_CROSSHAIRS;
            break;
        case SDLK_4:
            set_rotation(V, 0, 0, 0);
            break;
        case SDLK_5:
            set_rotation(V, 180, 0, 0);
            break;
        case SDLK_6:
            set_rotation(V, 90, 0, 270);
            break;
        case SDLK_7:
            set_rotation(V, 90, 0, 90);
            break;
        case SDLK_8:
            set_rotation(V, 90, 0, 0);
            break;
        case SDLK_9:
            set_rotation(V, 90, 0, 180);
            break;
        case SDLK_0:
            if (shift) { /* reset view, as openscad's resetView */
                set_rotation(V, 55, 0, 25);
                memset(V->v.t, 0, sizeof V->v.t);
                V->v.d = 140;
            } else {
                set_rotation(V, 55, 0, 25);
            }
            break;
        case SDLK_p:
            memset(V->v.t, 0, sizeof V->v.t);
            break;
        case SDLK_v:
            if (shift) view_all(V);
            break;
        case SDLK_q:
            *quit = 1;
            return;
        default:
            return;
        }
        changed(V);
        return;
    }
    switch (c) {
    case SDLK_q:
    case SDLK_ESCAPE:
        *quit = 1;
        return;
    case SDLK_PLUS:
    case SDLK_EQUALS:
    case SDLK_KP_PLUS:
        V->v.d *= ZOOM_STEP;
        break;
    case SDLK_MINUS:
    case SDLK_KP_MINUS:
        V->v.d /= ZOOM_STEP;
        break;
    case SDLK_o:
        V->v.ortho = !V->v.ortho;
        break;
    case SDLK_k:
        V->scheme = rayscad_colors_name(V->scheme + 1) ? V->scheme + 1 : 0;
        break;
    case SDLK_h:
        V->shadows = !V->shadows;
        break;
    case SDLK_x:
        V->xray = !V->xray;
        break;
    case SDLK_v:
        if (V->section_on)
            V->section_on = 0;
        else
            section_here(V);
        break;
    case SDLK_a:
        V->section_dir = (V->section_dir + 1) % 4;
        section_here(V);
        break;
    case SDLK_LEFTBRACKET:
    case SDLK_RIGHTBRACKET: {
        if (!V->section_on) return;
        double len = sqrt(V->section[0] * V->section[0] + V->section[1] * V->section[1] +
                          V->section[2] * V->section[2]);
        V->section[3] += (c == SDLK_RIGHTBRACKET ? 1 : -1) * len * V->v.d / 40;
        break;
    }
    case SDLK_s:
        screenshot(V);
        return;
    case SDLK_r:
        V->reload = 1;
        return;
    case SDLK_c:
        printf("--camera=%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g%s", V->v.t[0], V->v.t[1], V->v.t[2],
               V->v.r[0], V->v.r[1], V->v.r[2], V->v.d, V->v.ortho ? " --projection=o" : "");
        if (V->section_on)
            printf(" --section=%.9g,%.9g,%.9g,%.9g", V->section[0], V->section[1], V->section[2],
                   V->section[3]);
        printf("\n");
        fflush(stdout);
        return;
    case SDLK_SLASH:
    case SDLK_QUESTION:
        if (c == SDLK_SLASH && !shift) return;
        V->show_keys = !V->show_keys;
        V->fresh = 1; /* redraw */
        return;
    default:
        return;
    }
    changed(V);
}

static void drag(viewer *V, int buttons, int shift, int dx, int dy)
{
    if (buttons & SDL_BUTTON_LMASK) {
        double a = dx * DRAG_DEG, b = dy * DRAG_DEG;
        V->v.r[0] -= b; /* openscad's object_rot.x += dy is vpr.x -= dy */
        if (shift)
            V->v.r[1] -= a;
        else
            V->v.r[2] -= a;
        for (int k = 0; k < 3; k++)
            V->v.r[k] = fmod(fmod(V->v.r[k], 360) + 360, 360);
    } else if (shift) {
        V->v.d *= pow(ZOOM_STEP, -12.0 * dy / 120);
    } else {
        double right[3], up[3], per_px, fw[3];
        if (screen_axes(V, right, up, &per_px, fw) != 0) return;
        for (int k = 0; k < 3; k++) /* the model follows the pointer */
            V->v.t[k] -= per_px * (dx * right[k] - dy * up[k]);
    }
    changed(V);
}

int cli_viewer_run(const cli_options *o, cli_viewer_load load, void *ud)
{
    const char *x = getenv("DISPLAY"), *wl = getenv("WAYLAND_DISPLAY");
    if (!(x && *x) && !(wl && *wl)) { /* SDL would fall back to a console driver */
        fprintf(stderr, "rayscad: error: cannot open a window: no display (DISPLAY is not "
                        "set); give -o to write a file instead\n");
        return 2;
    }
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        fprintf(stderr,
                "rayscad: error: cannot open a window: %s (is there a display? give -o "
                "to write a file instead)\n",
                SDL_GetError());
        return 2;
    }
    static viewer V;
    memset(&V, 0, sizeof V);
    V.o = o;
    V.load = load;
    V.load_ud = ud;
    V.w = o->width;
    V.h = o->height;
    V.flags = o->view_flags & (RAYSCAD_VIEW_AXES | RAYSCAD_VIEW_SCALES | RAYSCAD_VIEW_EDGES |
                               RAYSCAD_VIEW_CROSSHAIRS);
    for (int k = 0; rayscad_colors_name(k); k++)
        if (!strcmp(rayscad_colors_name(k), o->colorscheme)) V.scheme = k;
    V.view_from_file = 1;
    V.v = (view){{0, 0, 0}, {55, 0, 25}, 140, o->view.ortho};
    V.wake_event = SDL_RegisterEvents(1);
    atomic_init(&V.gen, 1);
    pthread_mutex_init(&V.mu, NULL);
    pthread_cond_init(&V.cv, NULL);

    SDL_Window *win = SDL_CreateWindow("rayscad", SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                                       V.w, V.h, SDL_WINDOW_RESIZABLE);
    SDL_Renderer *ren = win ? SDL_CreateRenderer(win, -1, 0) : NULL;
    if (!win || !ren) {
        fprintf(stderr, "rayscad: error: cannot open a window: %s\n", SDL_GetError());
        if (win) SDL_DestroyWindow(win);
        SDL_Quit();
        return 2;
    }
    set_title(win, &V);
    V.text = viewer_text_new(14);
    pthread_t rt, lt;
    int have_rt = pthread_create(&rt, NULL, render_main, &V) == 0;
    int have_lt = pthread_create(&lt, NULL, load_main, &V) == 0;
    SDL_Texture *tex = NULL;
    int tw = 0, th = 0, quit = !have_rt || !have_lt, last_x = 0, last_y = 0;
    while (!quit) {
        SDL_Event e;
        if (!SDL_WaitEventTimeout(&e, 100)) continue;
        pthread_mutex_lock(&V.mu);
        do {
            if (e.type == SDL_QUIT) {
                quit = 1;
            } else if (e.type == SDL_WINDOWEVENT &&
                       e.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) {
                V.w = e.window.data1 > 0 ? e.window.data1 : 1;
                V.h = e.window.data2 > 0 ? e.window.data2 : 1;
                changed(&V);
            } else if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_EXPOSED) {
                V.fresh = 1;
            } else if (e.type == SDL_MOUSEBUTTONDOWN) {
                last_x = e.button.x;
                last_y = e.button.y;
            } else if (e.type == SDL_MOUSEMOTION && e.motion.state) {
                drag(&V, (int)e.motion.state, (SDL_GetModState() & KMOD_SHIFT) != 0,
                     e.motion.x - last_x, e.motion.y - last_y);
                last_x = e.motion.x;
                last_y = e.motion.y;
            } else if (e.type == SDL_MOUSEWHEEL) {
                V.v.d *= pow(ZOOM_STEP, e.wheel.y);
                changed(&V);
            } else if (e.type == SDL_KEYDOWN) {
                key(&V, &e.key, &quit);
            } else if (e.type == V.wake_event) {
                set_title(win, &V);
                if (V.fresh && o->stats && V.img) {
                    struct timespec t;
                    clock_gettime(CLOCK_REALTIME, &t);
                    fprintf(stderr,
                            "frame %dx%d samples %d pass %d: %.1f ms, %.0f ms after the last "
                            "input, at %.3f\n",
                            V.iw, V.ih, V.isamples * V.isamples, V.ipass, V.ims,
                            1000 * (cli_now_s() - V.moved_at),
                            (double)t.tv_sec + 1e-9 * (double)t.tv_nsec);
                }
            }
        } while (!quit && SDL_PollEvent(&e));
        present(ren, &tex, &tw, &th, &V);
        pthread_mutex_unlock(&V.mu);
    }
    pthread_mutex_lock(&V.mu);
    V.quit = 1;
    atomic_fetch_add(&V.gen, 1);
    pthread_cond_broadcast(&V.cv);
    pthread_mutex_unlock(&V.mu);
    if (have_rt) pthread_join(rt, NULL);
    if (have_lt) pthread_join(lt, NULL);
    rayscad_scene_free(V.scene);
    rayscad_scene_free(V.pending);
    free(V.img);
    if (tex) SDL_DestroyTexture(tex);
    viewer_text_free(V.text);
    SDL_DestroyRenderer(ren);
    SDL_DestroyWindow(win);
    SDL_Quit();
    pthread_cond_destroy(&V.cv);
    pthread_mutex_destroy(&V.mu);
    return 0;
}
