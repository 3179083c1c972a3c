/*
 * svg.c — import() of an SVG drawing as a 2D region leaf, as OpenSCAD
 * 2021.01's import_svg builds it: each shape's outlines (its open lines
 * stroked by the paths_stroke service) filled even-odd, the shapes
 * unioned (paths_clip), placed on the page by geom_svg_frame_of — dpi and
 * units to millimetres, y flipped, or centred on the bounding box.
 *
 * The file is read through the services.  What OpenSCAD reports as an
 * ERROR there (a missing file, XML that does not parse) is on its console
 * only, not in its echo output; here it is a note at the call, with the
 * parser's line and column in the SVG, and nothing is built, as there.
 * import()'s scale and origin do not apply to SVG in 2021.01.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../../geom/svg.h"
#include "builtins.h"

/* An SVG file is at most this long. */
#define MAX_SVG_BYTES ((size_t)1 << 28)

/* A growing set of paths. */
typedef struct pathset {
    scad_paths p;
    int cappts, cappaths, npts;
    int oom;
} pathset;

static int set_begin(pathset *s)
{
    if (s->p.npaths + 2 > s->cappaths) {
        int c = s->cappaths ? 2 * s->cappaths : 64;
        int *st = realloc(s->p.start, (size_t)c * sizeof *st);
        if (!st) return s->oom = -1;
        s->p.start = st;
        s->cappaths = c;
    }
    if (s->p.npaths == 0) s->p.start[0] = s->npts;
    s->p.npaths++;
    s->p.start[s->p.npaths] = s->npts;
    return 0;
}

static int set_point(pathset *s, double x, double y)
{
    if (s->npts + 1 > s->cappts) {
        int c = s->cappts ? 2 * s->cappts : 256;
        double(*q)[2] = realloc(s->p.pts, (size_t)c * sizeof *q);
        if (!q) return s->oom = -1;
        s->p.pts = q;
        s->cappts = c;
    }
    s->p.pts[s->npts][0] = x;
    s->p.pts[s->npts][1] = y;
    s->npts++;
    s->p.start[s->p.npaths] = s->npts;
    return 0;
}

/* Appends every path of q to s. */
static int set_append(pathset *s, const scad_paths *q)
{
    for (int i = 0; i < q->npaths; i++) {
        if (set_begin(s)) return -1;
        for (int k = q->start[i]; k < q->start[i + 1]; k++)
            if (set_point(s, q->pts[k][0], q->pts[k][1])) return -1;
    }
    return 0;
}

static void set_clear(pathset *s)
{
    s->p.npaths = 0;
    s->npts = 0;
}

/* Shape k's outlines in world user units into s (cleared first): its
 * closed paths as they are, its open ones stroked.  0; 1 when the stroke
 * failed (coordinates out of Clipper's range: why in err); -1 when out of
 * memory. */
static int shape_outlines(scad_eval *ev, const geom_svg *d, int k, pathset *s, char *err,
                          size_t errlen)
{
    const scad_services *sv = ev->services;
    const geom_svg_shape *sh = &d->shapes[k];
    set_clear(s);
    for (int i = sh->first; i < sh->first + sh->count; i++) {
        int a = d->start[i], n = d->start[i + 1] - a;
        if (!d->stroke[i]) {
            if (set_begin(s)) return -1;
            for (int j = 0; j < n; j++)
                if (set_point(s, d->pts[a + j][0], d->pts[a + j][1])) return -1;
            continue;
        }
        if (n == 0) continue;
        scad_paths r = {0};
        if (sv->paths_stroke(sv->ud, (const double(*)[2])d->pts + a, n, sh->stroke_width, sh->cap,
                             &r, err, errlen) != 0)
            return strstr(err, "out of memory") ? -1 : 1;
        int rc = set_append(s, &r);
        scad_paths_free(&r);
        if (rc) return -1;
    }
    const double *m = sh->world_from_local;
    for (int j = 0; j < s->npts; j++) {
        double x = s->p.pts[j][0], y = s->p.pts[j][1];
        s->p.pts[j][0] = m[0] * x + m[2] * y + m[4];
        s->p.pts[j][1] = m[1] * x + m[3] * y + m[5];
    }
    return 0;
}

/* The drawing's region: each shape filled even-odd, all unioned, placed on
 * the page.  0 and *out; 1 when Clipper refused it (coordinates out of its
 * range: why in err); -1 when out of memory. */
static int drawing(scad_eval *ev, const geom_svg *d, double dpi, int center, scad_paths *out,
                   char *err, size_t errlen)
{
    const scad_services *sv = ev->services;
    memset(out, 0, sizeof *out);
    /* every shape's outlines, kept apart (start of shape k: first[k]) */
    pathset all = {0}, one = {0};
    int *first = malloc(((size_t)d->nshapes + 1) * sizeof *first);
    double bbox[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
    int rc = first ? 0 : -1;
    for (int k = 0; k < d->nshapes && rc == 0; k++) {
        first[k] = all.p.npaths;
        rc = shape_outlines(ev, d, k, &one, err, errlen);
        if (one.oom) rc = -1;
        if (rc == 0) {
            double sc[2];
            geom_svg_scale(d, d->shapes[k].page, dpi, sc);
            for (int j = 0; j < one.npts; j++) {
                double x = sc[0] * one.p.pts[j][0], y = sc[1] * one.p.pts[j][1];
                bbox[0] = fmin(bbox[0], x);
                bbox[1] = fmin(bbox[1], y);
                bbox[2] = fmax(bbox[2], x);
                bbox[3] = fmax(bbox[3], y);
            }
            rc = set_append(&all, &one.p);
        }
    }
    if (rc == 0) first[d->nshapes] = all.p.npaths;
    if (all.oom || one.oom) rc = -1;
    if (rc == 0) {
        geom_svg_frame f;
        geom_svg_frame_of(d, dpi, center, bbox, &f);
        for (int j = 0; j < all.npts; j++) {
            double x = all.p.pts[j][0], y = all.p.pts[j][1];
            all.p.pts[j][0] = f.s[0] * (-f.vb[0] + x) - f.c[0];
            all.p.pts[j][1] = f.s[1] * (-f.vb[1] - y) + f.c[1];
        }
    }
    /* each shape even-odd (ClipperUtils::sanitize), then the union */
    pathset filled = {0};
    scad_paths none = {0};
    for (int k = 0; k < d->nshapes && rc == 0; k++) {
        scad_paths shape = {all.p.pts, all.p.start + first[k], first[k + 1] - first[k]};
        if (shape.npaths == 0) continue;
        scad_paths r = {0};
        if (sv->paths_clip(sv->ud, CSG_OP_UNION, &shape, 1, &none, 0, &r, err, errlen) != 0) {
            rc = strstr(err, "out of memory") ? -1 : 1;
            break;
        }
        rc = set_append(&filled, &r);
        scad_paths_free(&r);
    }
    if (rc == 0 && filled.p.npaths > 0 &&
        sv->paths_clip(sv->ud, CSG_OP_UNION, &filled.p, 0, &none, 0, out, err, errlen) != 0)
        rc = strstr(err, "out of memory") ? -1 : 1;
    free(first);
    scad_paths_free(&all.p);
    scad_paths_free(&one.p);
    scad_paths_free(&filled.p);
    return rc;
}

scad_geom *scad_svg_import(scad_call *c, const char *path, double dpi, int center)
{
    scad_eval *ev = c->ev;
    const scad_stmt *st = c->st;
    const scad_services *sv = ev->services;
    if (!sv || !sv->paths_clip || !sv->paths_stroke) {
        scad_eval_error(ev, st->loc, "import() of SVG is not available here");
        return NULL;
    }
    char err[512];
    size_t len;
    char *text = path[0] && scad_file_stat(ev->d->opt, path, NULL)
                     ? scad_file_read(ev->d->opt, path, MAX_SVG_BYTES, &len, err, sizeof err)
                     : NULL;
    if (!text) {
        scad_diag_note(ev->d, st->loc, "import(): Can't open file '%s': nothing imported", path);
        return NULL;
    }
    geom_svg d;
    int rc = geom_svg_read(text, len, &d, err, sizeof err);
    free(text);
    scad_geom *g = NULL;
    if (rc == 1) {
        scad_diag_note(ev->d, st->loc, "import(): Error parsing file '%s': %s:%s: nothing imported",
                       path, path, err);
    } else if (rc != 0) {
        scad_eval_error(ev, st->loc, "out of memory");
    } else {
        if (d.npts >= GEOM_SVG_MAX_POINTS)
            scad_diag_note(ev->d, st->loc,
                           "import(): '%s' has more than %d points; the rest is left out", path,
                           GEOM_SVG_MAX_POINTS);
        scad_paths r;
        rc = drawing(ev, &d, dpi, center, &r, err, sizeof err);
        if (rc < 0)
            scad_eval_error(ev, st->loc, "out of memory");
        else if (rc > 0)
            scad_diag_note(ev->d, st->loc, "import(): '%s': %s: nothing imported", path, err);
        if (rc == 0 && r.npaths > 0) {
            g = scad_region_geom(ev, &r, c->state);
            scad_paths_free(&r);
        }
    }
    geom_svg_free(&d);
    return g;
}
