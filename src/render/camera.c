/*
 * camera.c — OpenSCAD 2021.01's camera, rebuilt from its sources so that our
 * silhouettes land on the same pixels as its preview PNG.
 *
 * OpenSCAD keeps every camera as a "gimbal": object_trans, object_rot (GL
 * rotation angles) and viewer_distance (Camera.cc).  GLView::setupCamera
 * draws with
 *     view = lookAt(eye (0,-dist,0), centre 0, up +z)
 *            · Rx(rot.x) · Ry(rot.y) · Rz(rot.z) · T(object_trans)
 * and gluPerspective(22.5°, w/h, 0.1·dist, 100·dist), or for --projection=o
 * glOrtho(±h·w/h, ±h, -100·dist, 100·dist) with h = dist·tan(22.5°/2).
 * --camera=tx,ty,tz,rx,ry,rz,d goes through Camera::setVpt/setVpr:
 *     object_trans = -t,  rot = wrap(90-rx, -ry, -rz),
 * where wrap() is fmodf(360 + a, 360) — in float, which we repeat so that the
 * angles round as OpenSCAD's do.  --camera=eye,centre becomes a gimbal too
 * (Camera::setup): object_trans = -centre, dist = |centre-eye|, rot.y = 0,
 * rot.x = -atan2(dir.z, |dir.xy|), rot.z = 90 - atan2(dir.y, dir.x) (or 0 /
 * 180 when dir is vertical).  Camera::viewAll: with autocenter,
 * object_trans = -bbox.centre; then
 *     dist = (|bbox.centre + object_trans| + |bbox.diagonal|/2) / sin(fov/2).
 * The invariant here: forward, up, right are orthonormal and eye is where the
 * GL eye-space origin lies in world space.
 */
#include "render.h"
#include "../intervals/vec3.h"

#include <math.h>

#define FOVY_DEG 22.5      /* Camera::Camera(): fov(22.5) */
#define DEFAULT_DIST 140.0 /* Camera::resetView(): setVpd(140) */
#define PI 3.14159265358979323846

/* Camera.cc's wrap(): fmodf(360 + angle, 360), float on purpose. */
static double wrap(double angle)
{
    return (double)fmodf((float)(360.0 + angle), 360.0f);
}

/* rows = Rx(ax) · Ry(ay) · Rz(az), angles in degrees, as glRotated builds
 * them (right-handed, counter-clockwise looking down the axis). */
static void gl_rotation(double ax, double ay, double az, double m[3][3])
{
    double a = ax * PI / 180, b = ay * PI / 180, c = az * PI / 180;
    double rx[3][3] = {{1, 0, 0}, {0, cos(a), -sin(a)}, {0, sin(a), cos(a)}};
    double ry[3][3] = {{cos(b), 0, sin(b)}, {0, 1, 0}, {-sin(b), 0, cos(b)}};
    double rz[3][3] = {{cos(c), -sin(c), 0}, {sin(c), cos(c), 0}, {0, 0, 1}};
    double t[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            t[i][j] = 0;
            for (int k = 0; k < 3; k++)
                t[i][j] += rx[i][k] * ry[k][j];
        }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            m[i][j] = 0;
            for (int k = 0; k < 3; k++)
                m[i][j] += t[i][k] * rz[k][j];
        }
}

static int finite3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

int render_camera_resolve(const render_view *v, const double lo[3], const double hi[3],
                          int have_bounds, int width, int height, render_camera *out)
{
    double trans[3] = {0, 0, 0}, rot[3], dist, fovy = FOVY_DEG;
    int viewall = v->viewall, autocenter = v->autocenter;

    switch (v->kind) {
    case RAYSCAD_CAMERA_GIMBAL:
        for (int i = 0; i < 3; i++)
            trans[i] = -v->v[i];
        rot[0] = wrap(90 - v->v[3]);
        rot[1] = wrap(-v->v[4]);
        rot[2] = wrap(-v->v[5]);
        dist = v->v[6];
        break;
    case RAYSCAD_CAMERA_EYE: {
        double dir[3];
        for (int i = 0; i < 3; i++) {
            trans[i] = -v->v[3 + i];
            dir[i] = v->v[3 + i] - v->v[i];
        }
        dist = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        if (!(dist > 0)) return -1;
        rot[2] = (dir[1] == 0 && dir[0] == 0) ? (dir[2] < 0 ? 0 : 180)
                                              : -atan2(dir[1], dir[0]) * 180 / PI + 90;
        rot[1] = 0;
        rot[0] = -atan2(dir[2], hypot(dir[0], dir[1])) * 180 / PI;
        break;
    }
    case RAYSCAD_CAMERA_DEFAULT:
    default:
        /* No --camera: resetView() (vpr 55,0,25, vpd 140) and openscad.cc
         * turns on both viewall and autocenter. */
        rot[0] = wrap(90 - 55.0);
        rot[1] = wrap(-0.0);
        rot[2] = wrap(-25.0);
        dist = DEFAULT_DIST;
        viewall = autocenter = 1;
        if (v->file.set & 1) { /* Camera::setVpr */
            rot[0] = wrap(90 - v->file.vpr[0]);
            rot[1] = wrap(-v->file.vpr[1]);
            rot[2] = wrap(-v->file.vpr[2]);
        }
        if (v->file.set & 2)
            for (int i = 0; i < 3; i++)
                trans[i] = -v->file.vpt[i];
        if (v->file.set & 4) dist = v->file.vpd;
        if ((v->file.set & 8) && v->file.vpf > 0 && v->file.vpf < 180) fovy = v->file.vpf;
        if (v->file.auto_off) viewall = autocenter = 0;
        break;
    }

    /* Camera::viewAll.  OpenSCAD 2021.01 has no empty-box case: an empty
     * Eigen box has centre 0 and an infinite diagonal, so it would centre on
     * the origin and put the eye at infinity — an empty picture either way.
     * We centre on the origin and keep a finite distance. */
    int bounded = have_bounds && finite3(lo) && finite3(hi);
    if (viewall) {
        double c[3] = {0, 0, 0}, diag2 = 0;
        if (bounded)
            for (int i = 0; i < 3; i++) {
                c[i] = (lo[i] + hi[i]) / 2;
                diag2 += (hi[i] - lo[i]) * (hi[i] - lo[i]);
            }
        if (autocenter)
            for (int i = 0; i < 3; i++)
                trans[i] = -c[i];
        if (bounded) {
            double off[3] = {c[0] + trans[0], c[1] + trans[1], c[2] + trans[2]};
            double radius =
                sqrt(off[0] * off[0] + off[1] * off[1] + off[2] * off[2]) + sqrt(diag2) / 2;
            dist = radius / sin(fovy / 2 * PI / 180);
        }
    }
    if (!(dist > 0) || !isfinite(dist)) {
        if (!viewall) return -1;
        dist = DEFAULT_DIST; /* a model that is a single point */
    }

    /* Eye space (x right, y up, -z forward) = L · R · (p + trans) with
     * L = lookAt((0,-dist,0), 0, +z): x_e = w.x, y_e = w.z, z_e = -(w.y + dist).
     * So in world space right = R^T e_x, up = R^T e_z, forward = R^T e_y:
     * the rows 0, 2, 1 of R; and the eye is R^T (0,-dist,0) - trans. */
    double r[3][3];
    gl_rotation(rot[0], rot[1], rot[2], r);
    for (int i = 0; i < 3; i++) {
        out->right[i] = r[0][i];
        out->forward[i] = r[1][i];
        out->up[i] = r[2][i];
        out->eye[i] = -dist * r[1][i] - trans[i];
    }
    out->fovy_deg = fovy;
    out->ortho_half_height = dist * tan(fovy / 2 * PI / 180);
    out->ortho = v->ortho;
    if (v->ortho) {
        out->clip_near = -100 * dist;
        out->clip_far = 100 * dist;
    } else {
        out->clip_near = 0.1 * dist;
        out->clip_far = 100 * dist;
    }
    (void)width;
    (void)height;
    return 0;
}

/* Pixel (px, py) maps to GL's normalised device coordinates as the
 * rasteriser samples it: x_ndc = 2·px/W - 1, y_ndc = 1 - 2·py/H (the PNG's
 * top row is GL's last).  gluPerspective puts the image plane at unit depth
 * with half-height s = tan(fovy/2) and half-width aspect times that;
 * glOrtho's half-height s is ortho_half_height.  Both are linear in px and
 * py, so one image's rays are a base plus per-pixel steps. */
void render_raygen_init(render_raygen *g, const render_camera *c, int width, int height)
{
    double aspect = (double)width / (double)height;
    double s = c->ortho ? c->ortho_half_height : tan(c->fovy_deg / 2 * PI / 180);
    double ax = 2 * aspect * s / width, ay = -2 * s / height; /* per pixel */
    for (int i = 0; i < 3; i++) {
        double base = -aspect * s * c->right[i] + s * c->up[i];
        double dx = ax * c->right[i], dy = ay * c->up[i];
        g->org[i] = c->eye[i] + (c->ortho ? base : 0);
        g->odx[i] = c->ortho ? dx : 0;
        g->ody[i] = c->ortho ? dy : 0;
        g->d0[i] = c->forward[i] + (c->ortho ? 0 : base);
        g->ddx[i] = c->ortho ? 0 : dx;
        g->ddy[i] = c->ortho ? 0 : dy;
    }
}

void render_raygen_ray(const render_raygen *g, double px, double py, double o[3], double d[3])
{
    double len2 = 0;
    for (int i = 0; i < 3; i++) {
        o[i] = g->org[i] + px * g->odx[i] + py * g->ody[i];
        d[i] = g->d0[i] + px * g->ddx[i] + py * g->ddy[i];
        len2 += d[i] * d[i];
    }
    double inv = 1 / sqrt(len2);
    for (int i = 0; i < 3; i++)
        d[i] *= inv;
}

/* det[a b c] = a · (b × c). */
static double det3(const double a[3], const double b[3], const double c[3])
{
    double bc[3];
    cross3(b, c, bc);
    return dot3(a, bc);
}

/* A point c lies on the ray of pixel (px, py) when c - org = px·odx + py·ody
 * + t·d with t > 0 and d = d0 + px·ddx + py·ddy.  Perspective (odx = ody =
 * 0): c - org = s·d0 + s·px·ddx + s·py·ddy, solved for (s, s·px, s·py) by
 * Cramer's rule, s > 0.  Orthographic (ddx = ddy = 0): c - org = px·odx +
 * py·ody + t·d0, solved for (px, py, t).  Either map sends the box, convex
 * and in front of the eye, onto the convex hull of its corners' images, so
 * a pixel outside their bounds sees none of it; the pixel of margin covers
 * rounding, in these solves and in the rays themselves, many times over. */
int render_raygen_cover(const render_raygen *g, const double lo[3], const double hi[3],
                        double rect[4])
{
    int ortho = dot3(g->ddx, g->ddx) == 0 && dot3(g->ddy, g->ddy) == 0;
    const double *a = ortho ? g->odx : g->d0, *b = ortho ? g->ody : g->ddx,
                 *c = ortho ? g->d0 : g->ddy;
    double det = det3(a, b, c);
    if (!(fabs(det) > 0) || !isfinite(det)) return -1;
    rect[0] = rect[2] = INFINITY;
    rect[1] = rect[3] = -INFINITY;
    for (int k = 0; k < 8; k++) {
        double p[3] = {k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]}, v[3];
        sub3(p, g->org, v);
        double u0 = det3(v, b, c) / det, u1 = det3(a, v, c) / det, u2 = det3(a, b, v) / det;
        double px = ortho ? u0 : u1 / u0, py = ortho ? u1 : u2 / u0;
        if (!ortho && !(u0 > 0)) return -1; /* at or behind the eye */
        if (!isfinite(px) || !isfinite(py)) return -1;
        rect[0] = fmin(rect[0], px);
        rect[1] = fmax(rect[1], px);
        rect[2] = fmin(rect[2], py);
        rect[3] = fmax(rect[3], py);
    }
    rect[0] -= 1;
    rect[1] += 1;
    rect[2] -= 1;
    rect[3] += 1;
    return 0;
}

void render_camera_ray(const render_camera *c, int width, int height, double px, double py,
                       double o[3], double d[3])
{
    render_raygen g;
    render_raygen_init(&g, c, width, height);
    render_raygen_ray(&g, px, py, o, d);
}
