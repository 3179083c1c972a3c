/*
 * overlay.c — what openscad's --view adds to an image, drawn over a
 * rendered one (render_overlays):
 *
 *   edges       crease and silhouette lines, in the colour openscad's preview
 *               gives polygon edges: halfway from the surface's colour to
 *               white.  OpenSCAD outlines every polygon of its tessellation;
 *               our surfaces are exact, so the lines are where the exact
 *               normal turns by more than EDGE_ANGLE between neighbouring
 *               pixels, where the depth jumps (one surface in front of
 *               another) and where the model meets the background.
 *   axes        the axes through the origin, dist long (the view distance):
 *               solid on the positive side, dashed (GL stipple 3, 0xAAAA) on
 *               the negative, one pixel wide, hidden behind the model; and
 *               the small axes in the lower left corner (red x, green y,
 *               blue z, letters X Y Z), over everything.
 *   scales      with axes: ticks every 10^floor(log10 dist)/10 along the axes
 *               and numbers at every tenth (every second when the view is
 *               less than 3 decades wide), in openscad's seven-segment
 *               strokes.
 *   crosshairs  the four diagonals of a cube dist/4 wide around the view
 *               centre.  openscad 2021.01 draws them in its window only, not
 *               in exported images; here they are drawn.
 *
 * The geometry follows OpenSCAD 2021.01's GLView (showAxes, showSmallaxes,
 * showScalemarkers, showCrosshairs, at one pixel per dpi unit).  Lines are
 * drawn by stepping one pixel along their longer screen axis, as GL's
 * rasteriser does for one-pixel lines, and depth-tested against the first
 * surface each pixel's centre ray meets (the model and its '#' parts, as
 * the section view leaves them).
 */
#include "overlay.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sampling.h"
#include "section.h"
#include "surface.h"
#include "tiles.h"

#define PI 3.14159265358979323846
#define EDGE_ANGLE_DEG 30.0
/* A depth step between neighbouring pixels counts as an occlusion edge
 * beyond this many pixel footprints off the nearer surface's plane. */
#define EDGE_DEPTH_STEPS 3.0

/* What the centre ray of a pixel meets first. */
typedef struct gpix {
    float depth; /* along the view direction; INFINITY: nothing */
    float n[3];  /* unit normal there */
    float c[3];  /* the surface's unshaded colour */
} gpix;

typedef struct overlay {
    render_frame f;
    gpix *g;
    int w, h;
    double near; /* lines are clipped to depth >= near */
    double aspect, s;
    double dist, centre[3];
} overlay;

static int gbuf_tile(const void *job, iv_arena *a, void *state, int x0, int y0, int x1, int y1)
{
    (void)state;
    const overlay *ov = job;
    const csg_scene *s = ov->f.scene;
    int nroots = csg_scene_root_count(s);
    if (nroots > RAYSCAD_ROOT_HIGHLIGHT + 1) nroots = RAYSCAD_ROOT_HIGHLIGHT + 1;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            gpix *p = &ov->g[(size_t)y * ov->w + x];
            p->depth = INFINITY;
            double o[3], d[3], tmin, tmax;
            render_raygen_ray(&ov->f.gen, x + 0.5, y + 0.5, o, d);
            ray_range(ov->f.cam, d, &tmin, &tmax);
            iv_bound best;
            int root = -1;
            for (int r = 0; r < nroots; r++) {
                if (csg_scene_root_node(s, r) < 0) continue;
                iv_bound b;
                int rc = render_trace_first(s, ov->f.opt->section, r, o, d, tmin, tmax, a, &b);
                iv_arena_reset(a);
                if (rc < 0) return -1;
                if (rc == 1 && (root < 0 || b.t < best.t)) {
                    best = b;
                    root = r;
                }
            }
            if (root < 0) continue;
            double n[3];
            float c[4];
            const csg_material *m;
            if (best.flip & RENDER_SECTION_FLIP)
                render_section_normal(ov->f.opt->section, n);
            else
                csg_scene_normal(s, &best, o, d, n);
            render_surface_color(s, ov->f.opt, root, &best, c, &m);
            p->depth = (float)(best.t * dot3(d, ov->f.cam->forward));
            for (int k = 0; k < 3; k++) {
                p->n[k] = (float)n[k];
                p->c[k] = c[k];
            }
        }
    return 0;
}

static void put(const overlay *ov, int x, int y, const float c[3])
{
    if (x < 0 || y < 0 || x >= ov->w || y >= ov->h) return;
    float *p = ov->f.rgba + 4 * ((size_t)y * ov->w + x);
    memcpy(p, c, 3 * sizeof *c);
    p[3] = 1;
}

/* ---- edges ---------------------------------------------------------------- */

/* Whether neighbouring pixels a and b (a hit) are on two sides of an edge,
 * and which of them draws it: 1 a, 2 b, 3 both (a crease). */
static int edge_between(const overlay *ov, const gpix *a, const gpix *b, double footprint)
{
    if (!isfinite(b->depth)) return 1;
    double cosang = a->n[0] * b->n[0] + a->n[1] * b->n[1] + a->n[2] * b->n[2];
    if (cosang < cos(EDGE_ANGLE_DEG * PI / 180)) return 3;
    /* b's point off a's tangent plane, measured along the view direction
     * (the planes agree within the angle above) */
    const double *fw = ov->f.cam->forward;
    double fa = fabs(a->n[0] * fw[0] + a->n[1] * fw[1] + a->n[2] * fw[2]);
    double step = fabs(b->depth - a->depth);
    double fp = footprint * (ov->f.cam->ortho ? 1 : fmin(a->depth, b->depth));
    if (step > EDGE_DEPTH_STEPS * fp / fmax(fa, 0.05)) return a->depth < b->depth ? 1 : 2;
    return 0;
}

static void draw_edges(const overlay *ov)
{
    /* the world size of a pixel at unit depth (perspective) or anywhere */
    double footprint = 2 * ov->s / ov->h;
    unsigned char *mark = calloc((size_t)ov->w * ov->h, 1);
    if (!mark) return; /* an overlay is not worth failing the image for */
    for (int y = 0; y < ov->h; y++)
        for (int x = 0; x < ov->w; x++) {
            const gpix *a = &ov->g[(size_t)y * ov->w + x];
            for (int k = 0; k < 2; k++) {
                int xb = x + (k == 0), yb = y + (k == 1);
                if (xb >= ov->w || yb >= ov->h) continue;
                const gpix *b = &ov->g[(size_t)yb * ov->w + xb];
                int e = 0;
                if (isfinite(a->depth))
                    e = edge_between(ov, a, b, footprint);
                else if (isfinite(b->depth))
                    e = edge_between(ov, b, a, footprint) ? 2 : 0;
                /* two pixels wide, as openscad's edges: both sides of a
                 * crease, the front pixel and the one behind it otherwise */
                if (e == 1 && x - (k == 0) >= 0 && y - (k == 1) >= 0) {
                    size_t q = (size_t)(y - (k == 1)) * ov->w + (x - (k == 0));
                    if (isfinite(ov->g[q].depth)) mark[q] = 1;
                }
                if (e == 2 && xb + (k == 0) < ov->w && yb + (k == 1) < ov->h) {
                    size_t q = (size_t)(yb + (k == 1)) * ov->w + (xb + (k == 0));
                    if (isfinite(ov->g[q].depth)) mark[q] = 1;
                }
                if (e & 1) mark[(size_t)y * ov->w + x] = 1;
                if (e & 2) mark[(size_t)yb * ov->w + xb] = 1;
            }
        }
    for (int y = 0; y < ov->h; y++)
        for (int x = 0; x < ov->w; x++) {
            if (!mark[(size_t)y * ov->w + x]) continue;
            const gpix *a = &ov->g[(size_t)y * ov->w + x];
            float c[3];
            for (int k = 0; k < 3; k++)
                c[k] = (a->c[k] + 1) / 2;
            put(ov, x, y, c);
        }
    free(mark);
}

/* ---- lines ---------------------------------------------------------------- */

typedef struct pen {
    float c[3];
    int stipple; /* GL's stipple 3, 0xAAAA: three pixels off, three on */
} pen;

/* Eye coordinates of world point p: x right, y up, z the depth. */
static void to_eye(const overlay *ov, const double p[3], double e[3])
{
    const render_camera *c = ov->f.cam;
    double r[3] = {p[0] - c->eye[0], p[1] - c->eye[1], p[2] - c->eye[2]};
    e[0] = dot3(r, c->right);
    e[1] = dot3(r, c->up);
    e[2] = dot3(r, c->forward);
}

/* Screen position (pixels from the top left) of an eye point. */
static void to_screen(const overlay *ov, const double e[3], double *sx, double *sy)
{
    double z = ov->f.cam->ortho ? 1 : e[2];
    *sx = (e[0] / (z * ov->s * ov->aspect) + 1) / 2 * ov->w;
    *sy = (1 - e[1] / (z * ov->s)) / 2 * ov->h;
}

/* A line from world a to b, one pixel wide, hidden where the model is in
 * front of it. */
static void line3(const overlay *ov, const double a[3], const double b[3], const pen *p)
{
    double ea[3], eb[3];
    to_eye(ov, a, ea);
    to_eye(ov, b, eb);
    if (!ov->f.cam->ortho) { /* clip to the near plane */
        if (ea[2] < ov->near && eb[2] < ov->near) return;
        for (int q = 0; q < 2; q++) {
            double *u = q ? eb : ea, *v = q ? ea : eb;
            if (u[2] >= ov->near) continue;
            double t = (ov->near - u[2]) / (v[2] - u[2]);
            for (int k = 0; k < 3; k++)
                u[k] += t * (v[k] - u[k]);
        }
    }
    double x0, y0, x1, y1;
    to_screen(ov, ea, &x0, &y0);
    to_screen(ov, eb, &x1, &y1);
    double dx = x1 - x0, dy = y1 - y0;
    int major_x = fabs(dx) >= fabs(dy);
    double from = major_x ? x0 : y0, to = major_x ? x1 : y1;
    if (from > to) { /* the stipple counts from a's end */
        double t = from;
        from = to;
        to = t;
    }
    double len = major_x ? dx : dy;
    if (len == 0) return;
    long first = lround(ceil(from - 0.5)), last = lround(ceil(to - 0.5)) - 1;
    long lim = 4L * (ov->w > ov->h ? ov->w : ov->h);
    if (first < -lim) first = -lim; /* off screen: no need to step there */
    if (last > lim) last = lim;
    for (long i = first; i <= last; i++) {
        double t = (i + 0.5 - (major_x ? x0 : y0)) / len; /* 0 at a, 1 at b */
        long count = lround(fabs(t * len) - 0.5);
        if (p->stipple && !((0xAAAA >> (count / 3 % 16)) & 1)) continue;
        double other = major_x ? y0 + t * dy : x0 + t * dx;
        int x = major_x ? (int)i : (int)floor(other), y = major_x ? (int)floor(other) : (int)i;
        if (x < 0 || y < 0 || x >= ov->w || y >= ov->h) continue;
        /* the depth at t: linear in eye space, so 1/z linear on screen */
        double z = ov->f.cam->ortho ? ea[2] + t * (eb[2] - ea[2])
                                    : 1 / (1 / ea[2] + t * (1 / eb[2] - 1 / ea[2]));
        if (ov->g && !(z < ov->g[(size_t)y * ov->w + x].depth)) continue;
        put(ov, x, y, p->c);
    }
}

static void line3v(const overlay *ov, double ax, double ay, double az, double bx, double by,
                   double bz, const pen *p)
{
    double a[3] = {ax, ay, az}, b[3] = {bx, by, bz};
    line3(ov, a, b, p);
}

/* A line between two screen points (pixels, y down), over everything. */
static void line2(const overlay *ov, double x0, double y0, double x1, double y1, const float c[3])
{
    double dx = x1 - x0, dy = y1 - y0;
    int major_x = fabs(dx) >= fabs(dy);
    double from = major_x ? x0 : y0, to = major_x ? x1 : y1, len = major_x ? dx : dy;
    if (len == 0) return;
    if (from > to) {
        double t = from;
        from = to;
        to = t;
    }
    for (long i = lround(ceil(from - 0.5)); i <= lround(ceil(to - 0.5)) - 1; i++) {
        double t = (i + 0.5 - (major_x ? x0 : y0)) / len;
        double other = major_x ? y0 + t * dy : x0 + t * dx;
        put(ov, major_x ? (int)i : (int)floor(other), major_x ? (int)floor(other) : (int)i, c);
    }
}

/* ---- axes, scales, crosshairs ------------------------------------------- */

static void draw_axes(const overlay *ov, const float col[3])
{
    double l = ov->dist;
    pen solid = {{col[0], col[1], col[2]}, 0}, dashed = {{col[0], col[1], col[2]}, 1};
    for (int a = 0; a < 3; a++) {
        double o[3] = {0, 0, 0}, e[3] = {0, 0, 0};
        e[a] = l;
        line3(ov, o, e, &solid);
        e[a] = -l;
        line3(ov, o, e, &dashed);
    }
}

static void draw_crosshairs(const overlay *ov, const float col[3])
{
    pen p = {{col[0], col[1], col[2]}, 0};
    double vd = ov->dist / 8;
    const double *c = ov->centre;
    for (int xf = -1; xf <= 1; xf += 2)
        for (int yf = -1; yf <= 1; yf += 2)
            line3v(ov, c[0] - xf * vd, c[1] - yf * vd, c[2] - vd, c[0] + xf * vd, c[1] + yf * vd,
                   c[2] + vd, &p);
}

/* The seven-segment corners of a character: A B (top), C D (middle), E F
 * (bottom), left then right as it reads.  Each glyph is a strip through
 * them ("0" a loop back to its start). */
static const struct glyph {
    char ch;
    const char *strip;
    int loop;
} glyphs[] = {
    {'1', "AE", 0},      {'2', "ABDCEF", 0}, {'3', "ABDCDFE", 0}, {'4', "ACDBF", 0},
    {'5', "BACDFE", 0},  {'6', "BAEFDC", 0}, {'7', "ABE", 0},     {'8', "CDBAEFD", 0},
    {'9', "FBACD", 0},   {'0', "ABFE", 1},   {'-', "CD", 0},      {'.', "EF", 0},
    {'e', "BACDCEF", 0},
};

/* Character k of a label at position `at` along axis di (0..5: x, y, z,
 * then the negative ones), its cell w wide and h high, kern apart, lying
 * in the xy plane (the z axis's in the xz plane) on the side away from
 * the ticks.  Labels along x read toward +x; along y and z they read
 * toward -y and -z, the characters mirrored, as openscad draws them (its
 * '1', drawn by fixed corners, stands on the side of the cell nearer the
 * origin on the negative axes and farther on the positive ones). */
static void draw_char(const overlay *ov, char ch, int di, double at, int k, double w, double h,
                      double buf, double kern, const pen *p)
{
    const struct glyph *g = NULL;
    for (size_t i = 0; i < sizeof glyphs / sizeof *glyphs; i++)
        if (glyphs[i].ch == ch) g = &glyphs[i];
    if (!g) return;
    int axis = di % 3;
    double pol = di > 2 ? -1 : 1, mid = pol * (at + k * (w + kern));
    /* which way along the axis the character's left side lies */
    double left = ch == '1' ? -pol : axis == 0 ? -1 : 1;
    double pts[8][3];
    size_t n = strlen(g->strip);
    for (size_t i = 0; i < n; i++) {
        int c = g->strip[i] - 'A', row = c / 2;
        double u = mid + ((c & 1) ? -left : left) * w / 2;
        double v = row == 0 ? h : row == 1 ? h / 2 + buf : buf;
        pts[i][0] = axis == 0 ? u : v;
        pts[i][1] = axis == 0 ? v : axis == 1 ? u : 0;
        pts[i][2] = axis == 2 ? u : 0;
    }
    for (size_t i = 0; i + 1 < n; i++)
        line3(ov, pts[i], pts[i + 1], p);
    if (g->loop) line3(ov, pts[n - 1], pts[0], p);
}

static void draw_label(const overlay *ov, double at, double l, const pen *p)
{
    char num[32];
    snprintf(num, sizeof num, "%g", at); /* as C++'s stream prints a double */
    double size = l / 60, buf = size / 4, w = size / 2, h = size + buf, kern = buf;
    for (int di = 0; di < 6; di++) {
        char s[40];
        snprintf(s, sizeof s, "%s%s", di > 2 ? "-" : "", num);
        size_t n = strlen(s);
        if (di > 0 && di < 4) /* these run against the reading direction */
            for (size_t i = 0; i < n / 2; i++) {
                char t = s[i];
                s[i] = s[n - 1 - i];
                s[n - 1 - i] = t;
            }
        for (size_t k = 0; k < n; k++)
            draw_char(ov, s[k], di, at, (int)k, w, h, buf, kern, p);
    }
}

static void draw_scales(const overlay *ov, const float col[3])
{
    double l = ov->dist;
    double decade = pow(10, floor(log10(l))), tick = decade / 10;
    pen solid = {{col[0], col[1], col[2]}, 0}, dashed = {{col[0], col[1], col[2]}, 1};
    int count = 0;
    for (double i = 0; i < l && count < 200; i += tick, count++) {
        double size_div = 60;
        if (count > 0 && count % 10 == 0) {
            size_div = 30;
            draw_label(ov, i, l, &solid);
        } else if (count > 0 && count % 2 == 0 && l / decade < 3) {
            draw_label(ov, i, l, &solid);
        }
        double t = l / size_div;
        line3v(ov, i, 0, 0, i, -t, 0, &solid);
        line3v(ov, 0, i, 0, -t, i, 0, &solid);
        line3v(ov, 0, 0, i, -t, 0, i, &solid);
        line3v(ov, -i, 0, 0, -i, -t, 0, &dashed);
        line3v(ov, 0, -i, 0, -t, -i, 0, &dashed);
        line3v(ov, 0, 0, -i, -t, 0, -i, &dashed);
    }
}

/* The small axes in the lower left corner: an orthographic view of the
 * camera's rotation, H/180 pixels a unit, centred 10 % in from the left and
 * bottom edges. */
static void draw_small_axes(const overlay *ov, const float col[3])
{
    const render_camera *c = ov->f.cam;
    double unit = ov->h / 180.0, ox = 0.1 * ov->w, oy = 0.9 * ov->h;
    static const float rgb[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double lab[3][2];
    for (int a = 0; a < 3; a++) {
        /* axis a seen through the rotation: right and up are R's rows */
        double sx = c->right[a] * unit, sy = c->up[a] * unit;
        line2(ov, ox, oy, ox + 10 * sx, oy - 10 * sy, rgb[a]);
        /* gluProject's window position, rounded, turned top-down */
        double wx = round(ox + 12 * sx), wy = round((ov->h - oy) + 12 * sy);
        lab[a][0] = wx;
        lab[a][1] = ov->h - wy;
    }
    double d = 3;
    double x = lab[0][0], y = lab[0][1];
    line2(ov, x - d, y + d, x + d, y - d, col); /* X */
    line2(ov, x - d, y - d, x + d, y + d, col);
    x = lab[1][0], y = lab[1][1];
    line2(ov, x - d, y + d, x + d, y - d, col); /* Y */
    line2(ov, x - d, y - d, x, y, col);
    x = lab[2][0], y = lab[2][1];
    line2(ov, x - d, y + d, x + d, y + d, col); /* Z */
    line2(ov, x - d, y - d, x + d, y - d, col);
    line2(ov, x - d, y + d, x + d, y - d, col);
}

int render_overlays(const csg_scene *s, const render_camera *cam, const render_options *opt,
                    float *rgba, char *err, size_t errlen)
{
    int v = opt->view;
    if (!(v & (RAYSCAD_VIEW_AXES | RAYSCAD_VIEW_CROSSHAIRS | RAYSCAD_VIEW_EDGES))) return 0;
    overlay ov;
    memset(&ov, 0, sizeof ov);
    render_frame_init(&ov.f, s, cam, opt, rgba);
    ov.w = opt->width;
    ov.h = opt->height;
    ov.aspect = (double)ov.w / ov.h;
    ov.s = cam->ortho ? cam->ortho_half_height : tan(cam->fovy_deg / 2 * PI / 180);
    /* the view distance: clip_far is 100 of it for both projections */
    ov.dist = cam->clip_far > 0 ? cam->clip_far / 100 : 140;
    ov.near = cam->ortho ? -INFINITY : fmax(cam->clip_near, 1e-9 * ov.dist);
    for (int k = 0; k < 3; k++)
        ov.centre[k] = cam->eye[k] + ov.dist * cam->forward[k];
    ov.g = malloc((size_t)ov.w * ov.h * sizeof *ov.g);
    if (!ov.g) {
        snprintf(err, errlen, "render: out of memory while drawing the view's lines");
        return -1;
    }
    render_options quiet = *opt;
    quiet.progress = NULL;
    int rc = render_tiles_draw(&quiet, 0, gbuf_tile, &ov, "drawing the view's lines", err, errlen);
    if (rc == 0) {
        if (v & RAYSCAD_VIEW_EDGES) draw_edges(&ov);
        if (v & RAYSCAD_VIEW_CROSSHAIRS) draw_crosshairs(&ov, opt->colors.crosshair);
        if (v & RAYSCAD_VIEW_AXES) draw_axes(&ov, opt->colors.axes);
        if ((v & RAYSCAD_VIEW_AXES) && (v & RAYSCAD_VIEW_SCALES))
            draw_scales(&ov, opt->colors.axes);
        if (v & RAYSCAD_VIEW_AXES) draw_small_axes(&ov, opt->colors.axes);
    }
    free(ov.g);
    return rc;
}
