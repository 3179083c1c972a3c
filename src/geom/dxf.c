/*
 * dxf.c — OpenSCAD 2021.01's DXF reader (DxfData), in C.
 *
 * A DXF file is a list of (group code, value) line pairs.  The reader
 * keeps OpenSCAD's single pass: the values of an entity accumulate in one
 * state (its layer, its x and y lists, radius, angles, the seven DIMENSION
 * points) and the entity is built when the next code 0 starts another, so
 * OpenSCAD's quirks carry over: a value that does not parse is skipped
 * with a warning; an entity short of points is skipped and the state is
 * *not* reset, so the next entity's values pile on it; ELLIPSE's ratio and
 * INSERT's scales share the slots of other codes.
 *
 * Segments are snapped to a 0.001 grid as they are added: a point takes an
 * existing grid cell among its 3 × 3 neighbours when there is one
 * (OpenSCAD's Grid2d, whose neighbour loop moves its own bounds — kept as
 * is).  Each cell lists the segments that end in it, in the order they were
 * added; the segments of BLOCKs are listed too, under the index the next
 * entity segment will get (as in OpenSCAD), which the joining sees.
 * Joining takes open paths first — from the first segment (by index) with
 * an end no other live segment shares — then closed paths, following at
 * each end the first live segment of the cell whose end is grid-equal.
 *
 * Bounds: at most GEOM_DXF_MAX_SEGMENTS segments (the rest is dropped with
 * a note), coordinates beyond ±1e12 or not finite drop their segment (the
 * grid index must fit 64 bits), angles that are not finite build nothing,
 * and the joining's cell visits are capped (WORK_MAX), so a hostile file
 * ends in bounded time and memory.  OpenSCAD's fixup_path_direction is
 * left out: the region is even-odd, and no caller reads the direction.
 */
#include "dxf.h"
#include "dxf_grid.h"
#include "../intervals/angles.h"
#include "fragments.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define COORD_MAX 1e12      /* |coordinate| / GRID must stay far inside int64 */
#define WORK_MAX 400000000L /* cell entries visited while joining */

/* ---- the reader's state -------------------------------------------------- */

typedef struct line {
    int p[2]; /* points */
    int disabled;
} line;

typedef struct counted {
    char *name;
    long n;
} counted;

typedef struct reader {
    const geom_dxf_params *prm;
    geom_dxf_message_fn msg;
    void *ud;
    const char *abs_path, *rel_path; /* as OpenSCAD names the file */
    geom_dxf *out;
    size_t cappts, capidx, cappaths, capdims;
    grid g;
    line *lines;
    size_t nlines, caplines;
    blocks blk;
    long segments, dropped;
    int capped;
    int in_entities, in_blocks;
    char *current_block; /* NULL: none */
    /* the entity being read */
    char *mode, *layer, *name, *iddata;
    int dimtype;
    double coords[7][2];
    dvec xv, yv;
    double radius, arc_start, arc_stop, ell_start, ell_stop;
    counted *unsupported;
    size_t nunsupported, capunsupported;
} reader;

enum { OK = 0, SHORT = 1, BAD_VALUE = 2, NOMEM = -1 };

static void say(reader *r, int kind, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static void say(reader *r, int kind, const char *fmt, ...)
{
    if (!r->msg) return;
    char text[4096];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    r->msg(r->ud, kind, text);
}

static int set_str(char **dst, const char *s)
{
    char *c = strdup(s);
    if (!c) return -1;
    free(*dst);
    *dst = c;
    return 0;
}

static int layer_ok(const reader *r)
{
    const char *want = r->prm->layer;
    return !want || !*want || (r->layer && !strcmp(r->layer, want));
}

static int add_point(reader *r, double x, double y)
{
    geom_dxf *d = r->out;
    if (geom_dxf_grow((void **)&d->pts, &r->cappts, (size_t)d->npts + 1, sizeof *d->pts)) return -1;
    d->pts[d->npts][0] = x;
    d->pts[d->npts][1] = y;
    return d->npts++;
}

static int usable(double v)
{
    return isfinite(v) && fabs(v) <= COORD_MAX;
}

/* OpenSCAD's ADD_LINE: outside ENTITIES and BLOCKS nothing; in ENTITIES
 * only on the wanted layer; both ends aligned and listed in their cells;
 * kept as an entity segment or in the current block. */
static int add_line(reader *r, double x1, double y1, double x2, double y2)
{
    if (!r->in_entities && !r->in_blocks) return OK;
    if (r->in_entities && !layer_ok(r)) return OK;
    if (!usable(x1) || !usable(y1) || !usable(x2) || !usable(y2)) {
        r->dropped++;
        return OK;
    }
    if (r->segments >= GEOM_DXF_MAX_SEGMENTS) {
        r->capped = 1;
        return OK;
    }
    r->segments++;
    long c1 = geom_dxf_grid_align(&r->g, &x1, &y1);
    if (c1 < 0) return NOMEM;
    long c2 = geom_dxf_grid_align(&r->g, &x2, &y2);
    if (c2 < 0) return NOMEM;
    if (geom_dxf_grid_add(&r->g, c1, (int)r->nlines) ||
        geom_dxf_grid_add(&r->g, c2, (int)r->nlines))
        return NOMEM;
    if (r->in_entities) {
        if (geom_dxf_grow((void **)&r->lines, &r->caplines, r->nlines + 1, sizeof *r->lines))
            return NOMEM;
        int a = add_point(r, x1, y1), b = add_point(r, x2, y2);
        if (a < 0 || b < 0) return NOMEM;
        r->lines[r->nlines++] = (line){{a, b}, 0};
    }
    if (r->in_blocks && r->current_block) {
        int oom = 0;
        block *b = geom_dxf_block_get(&r->blk, r->current_block, 1, &oom);
        if (!b) return NOMEM;
        if (geom_dxf_grow((void **)&b->seg, &b->cap, b->n + 1, sizeof *b->seg)) return NOMEM;
        b->seg[b->n][0] = x1;
        b->seg[b->n][1] = y1;
        b->seg[b->n][2] = x2;
        b->seg[b->n][3] = y2;
        b->n++;
    }
    return OK;
}

static int fragments(double r, const geom_dxf_params *p)
{
    return geom_fragments(r, p->fn, p->fa, p->fs);
}

/* The segment count of an arc of n fragments per turn over sweep / turn,
 * OpenSCAD's ceil(n * sweep / turn), bounded by the segments left. */
static long arc_count(reader *r, int n, double sweep, double turn)
{
    double c = ceil(n * sweep / turn);
    if (!(c > 0)) return 0;
    double left = (double)(GEOM_DXF_MAX_SEGMENTS - r->segments) + 1;
    if (c > left) {
        r->capped = 1;
        c = left;
    }
    return (long)c;
}

/* while (start > stop) stop += turn, without looping for ever. */
static double unwind(double start, double stop, double turn)
{
    if (start - stop > 1000 * turn) stop += floor((start - stop) / turn - 1) * turn;
    for (int i = 0; start > stop && i < 2000; i++)
        stop += turn;
    return stop;
}

#define X(i) r->xv.v[i]
#define Y(i) r->yv.v[i]
#define HAVE(i) ((size_t)(i) < r->xv.n && (size_t)(i) < r->yv.n)
#define TRY(e)                                                                                     \
    do {                                                                                           \
        int rc_ = (e);                                                                             \
        if (rc_) return rc_;                                                                       \
    } while (0)

/* The entity in r->mode, finished by a code 0.  SHORT: it lacks a point
 * (OpenSCAD's out_of_range; segments added before stay). */
static int finish_entity(reader *r)
{
    const char *m = r->mode ? r->mode : "";
    if (!strcmp(m, "SECTION")) {
        const char *s = r->iddata ? r->iddata : "";
        r->in_entities = !strcmp(s, "ENTITIES");
        r->in_blocks = !strcmp(s, "BLOCKS");
    } else if (!strcmp(m, "LINE")) {
        if (!HAVE(1)) return SHORT;
        TRY(add_line(r, X(0), Y(0), X(1), Y(1)));
    } else if (!strcmp(m, "LWPOLYLINE")) {
        size_t n = r->xv.n > r->yv.n ? r->xv.n : r->yv.n;
        for (size_t i = 1; i < n; i++) {
            if (!HAVE(i)) return SHORT;
            TRY(add_line(r, X(i - 1), Y(i - 1), X(i % n), Y(i % n)));
        }
        if (r->dimtype & 1) {
            if (n == 0 || !HAVE(n - 1)) return SHORT;
            TRY(add_line(r, X(n - 1), Y(n - 1), X(0), Y(0)));
        }
    } else if (!strcmp(m, "CIRCLE")) {
        int n = fragments(r->radius, r->prm);
        if (!HAVE(0)) return SHORT;
        double cx = X(0), cy = Y(0), rad = r->radius;
        for (int i = 0; i < n; i++) {
            double a1 = (360.0 * i) / n, a2 = (360.0 * (i + 1)) / n;
            TRY(add_line(r, iv_cos_degrees(a1) * rad + cx, iv_sin_degrees(a1) * rad + cy,
                         iv_cos_degrees(a2) * rad + cx, iv_sin_degrees(a2) * rad + cy));
        }
    } else if (!strcmp(m, "ARC")) {
        if (!HAVE(0)) return SHORT;
        double cx = X(0), cy = Y(0), rad = r->radius;
        int n0 = fragments(rad, r->prm);
        if (!isfinite(r->arc_start) || !isfinite(r->arc_stop)) return OK;
        double stop = unwind(r->arc_start, r->arc_stop, 360.0);
        double angle = stop - r->arc_start;
        long n = arc_count(r, n0, angle, 360);
        for (long i = 0; i < n; i++) {
            double a1 = r->arc_start + angle * (double)i / (double)n;
            double a2 = r->arc_start + angle * (double)(i + 1) / (double)n;
            TRY(add_line(r, iv_cos_degrees(a1) * rad + cx, iv_sin_degrees(a1) * rad + cy,
                         iv_cos_degrees(a2) * rad + cx, iv_sin_degrees(a2) * rad + cy));
        }
    } else if (!strcmp(m, "ELLIPSE")) {
        if (!isfinite(r->ell_start) || !isfinite(r->ell_stop)) return HAVE(1) ? OK : SHORT;
        double stop = unwind(r->ell_start, r->ell_stop, 2 * IV_PI);
        if (!HAVE(1)) return SHORT;
        double cx = X(0), cy = Y(0), ex = X(1), ey = Y(1);
        double r_major = sqrt(ex * ex + ey * ey);
        double cosval = ex / r_major;
        if (cosval > 1.0) cosval = 1.0;
        if (cosval < -1.0) cosval = -1.0;
        double rot = acos(cosval);
        if (ey < 0.0) rot = 2 * IV_PI - rot;
        /* the ratio was read into radius, and scaled with it (as there) */
        double r_minor = r_major * r->radius;
        double sweep = stop - r->ell_start;
        long n = arc_count(r, fragments(r_major, r->prm), sweep, 2 * IV_PI);
        double px = 0, py = 0;
        for (long i = 0; i <= n; i++) {
            double a = r->ell_start + sweep * (double)i / (double)n;
            double qx = cos(a) * r_major, qy = sin(a) * r_minor;
            double rx = cos(rot) * qx - sin(rot) * qy + cx;
            double ry = sin(rot) * qx + cos(rot) * qy + cy;
            if (i > 0) TRY(add_line(r, px, py, rx, ry));
            px = rx;
            py = ry;
        }
    } else if (!strcmp(m, "INSERT")) {
        /* the scales were read into the ellipse slots, the rotation into
         * the arc's start angle */
        int oom = 0;
        block *b = geom_dxf_block_get(&r->blk, r->iddata ? r->iddata : "", 0, &oom);
        size_t n = b ? b->n : 0;
        size_t bi = b ? (size_t)(b - r->blk.b) : 0;
        for (size_t i = 0; i < n; i++) {
            if (!HAVE(0)) return SHORT;
            const double *s = r->blk.b[bi].seg[i]; /* re-read: add_line may grow it */
            double a = r->arc_start;
            double lx1 = s[0] * r->ell_start, ly1 = s[1] * r->ell_stop;
            double lx2 = s[2] * r->ell_start, ly2 = s[3] * r->ell_stop;
            double sc = r->prm->scale;
            double px1 = (iv_cos_degrees(a) * lx1 - iv_sin_degrees(a) * ly1) * sc + X(0);
            double py1 = (iv_sin_degrees(a) * lx1 + iv_cos_degrees(a) * ly1) * sc + Y(0);
            double px2 = (iv_cos_degrees(a) * lx2 - iv_sin_degrees(a) * ly2) * sc + X(0);
            double py2 = (iv_sin_degrees(a) * lx2 + iv_cos_degrees(a) * ly2) * sc + Y(0);
            TRY(add_line(r, px1, py1, px2, py2));
        }
    } else if (!strcmp(m, "DIMENSION") && layer_ok(r)) {
        geom_dxf *d = r->out;
        if (geom_dxf_grow((void **)&d->dims, &r->capdims, (size_t)d->ndims + 1, sizeof *d->dims))
            return NOMEM;
        geom_dxf_dim *dm = &d->dims[d->ndims];
        memset(dm, 0, sizeof *dm);
        dm->type = r->dimtype;
        memcpy(dm->coords, r->coords, sizeof dm->coords);
        dm->angle = r->arc_start;
        dm->length = r->radius;
        dm->name = strdup(r->name ? r->name : "");
        if (!dm->name) return NOMEM;
        d->ndims++;
    } else if (!strcmp(m, "BLOCK")) {
        if (set_str(&r->current_block, r->iddata ? r->iddata : "")) return NOMEM;
    } else if (!strcmp(m, "ENDBLK")) {
        free(r->current_block);
        r->current_block = NULL;
    } else if (!strcmp(m, "ENDSEC")) {
    } else if (r->in_blocks || (r->in_entities && layer_ok(r))) {
        size_t i = 0;
        while (i < r->nunsupported && strcmp(r->unsupported[i].name, m))
            i++;
        if (i == r->nunsupported) {
            if (geom_dxf_grow((void **)&r->unsupported, &r->capunsupported, i + 1,
                              sizeof *r->unsupported))
                return NOMEM;
            r->unsupported[i].name = strdup(m);
            if (!r->unsupported[i].name) return NOMEM;
            r->unsupported[i].n = 0;
            r->nunsupported++;
        }
        r->unsupported[i].n++;
    }
    return OK;
}

static void reset_entity(reader *r)
{
    free(r->layer);
    free(r->name);
    free(r->iddata);
    r->layer = r->name = r->iddata = NULL;
    r->dimtype = 0;
    memset(r->coords, 0, sizeof r->coords);
    r->xv.n = r->yv.n = 0;
    r->radius = r->arc_start = r->arc_stop = 0;
    r->ell_start = r->ell_stop = 0;
    if (r->mode && !strcmp(r->mode, "INSERT")) r->ell_start = r->ell_stop = 1.0;
}

/* boost::lexical_cast<int>: an optional sign and digits, in range. */
static int parse_int(const char *s, int *out)
{
    const char *p = s;
    if (*p == '+' || *p == '-') p++;
    if (!*p) return 0;
    for (const char *q = p; *q; q++)
        if (*q < '0' || *q > '9') return 0;
    errno = 0;
    long v = strtol(s, NULL, 10);
    if (errno || v < INT_MIN || v > INT_MAX) return 0;
    *out = (int)v;
    return 1;
}

/* boost::lexical_cast<double>: the whole text a decimal number (inf and
 * nan included, hexadecimal not). */
static int parse_double(const char *s, double *out)
{
    if (!*s || strpbrk(s, "xX")) return 0;
    char *end;
    *out = strtod(s, &end);
    return *end == 0;
}

/* One (code, value) pair. */
static int group(reader *r, int id, const char *data)
{
    const geom_dxf_params *p = r->prm;
    double v;
    if (id >= 10 && id <= 16) {
        if (!parse_double(data, &v)) return BAD_VALUE;
        r->coords[id - 10][0] = r->in_blocks                         ? v
                                : (id == 11 || id == 12 || id == 16) ? v * p->scale
                                                                     : (v - p->xorigin) * p->scale;
    }
    if (id >= 20 && id <= 26) {
        if (!parse_double(data, &v)) return BAD_VALUE;
        r->coords[id - 20][1] = r->in_blocks                         ? v
                                : (id == 21 || id == 22 || id == 26) ? v * p->scale
                                                                     : (v - p->yorigin) * p->scale;
    }
    switch (id) {
    case 0: {
        int rc = finish_entity(r);
        if (rc) return rc; /* OpenSCAD's exception skips the reset too */
        if (set_str(&r->mode, data)) return NOMEM;
        reset_entity(r);
        return OK;
    }
    case 1:
        return set_str(&r->name, data) ? NOMEM : OK;
    case 2:
        return set_str(&r->iddata, data) ? NOMEM : OK;
    case 8:
        return set_str(&r->layer, data) ? NOMEM : OK;
    case 10:
    case 11:
    case 20:
    case 21:
        if (!parse_double(data, &v)) return BAD_VALUE;
        if (!r->in_blocks) v = (v - (id < 20 ? p->xorigin : p->yorigin)) * p->scale;
        return geom_dxf_dvec_push(id < 20 ? &r->xv : &r->yv, v) ? NOMEM : OK;
    case 40:
        if (!parse_double(data, &v)) return BAD_VALUE;
        r->radius = r->in_blocks ? v : v * p->scale;
        return OK;
    case 41:
        return parse_double(data, &r->ell_start) ? OK : BAD_VALUE;
    case 42:
        return parse_double(data, &r->ell_stop) ? OK : BAD_VALUE;
    case 50:
        return parse_double(data, &r->arc_start) ? OK : BAD_VALUE;
    case 51:
        return parse_double(data, &r->arc_stop) ? OK : BAD_VALUE;
    case 70:
        return parse_int(data, &r->dimtype) ? OK : BAD_VALUE;
    }
    return OK;
}

/* boost::trim: leading and trailing white space off, in place. */
static char *trim(char *s)
{
    while (*s == ' ' || *s == '\t' || *s == '\n' || *s == '\r' || *s == '\v' || *s == '\f')
        s++;
    size_t n = strlen(s);
    while (n && strchr(" \t\n\r\v\f", s[n - 1]))
        n--;
    s[n] = 0;
    return s;
}

/* ---- joining ------------------------------------------------------------- */

static int path_begin(reader *r, int closed)
{
    geom_dxf *d = r->out;
    if (geom_dxf_grow((void **)&d->path_start, &r->cappaths, (size_t)d->npaths + 2,
                      sizeof *d->path_start))
        return -1;
    unsigned char *c = realloc(d->closed, (size_t)d->npaths + 1);
    if (!c) return -1;
    d->closed = c;
    d->closed[d->npaths] = (unsigned char)closed;
    d->path_start[d->npaths + 1] = d->path_start[d->npaths];
    d->npaths++;
    return 0;
}

static int path_add(reader *r, int point)
{
    geom_dxf *d = r->out;
    size_t n = (size_t)d->path_start[d->npaths];
    if (n >= INT_MAX - 1 || geom_dxf_grow((void **)&d->idx, &r->capidx, n + 1, sizeof *d->idx))
        return -1;
    d->idx[n] = point;
    d->path_start[d->npaths]++;
    return 0;
}

static int dead(const reader *r, int k)
{
    return k < 0 || (size_t)k >= r->nlines || r->lines[k].disabled;
}

/* The cell of point pt (grid.data), its leading dead entries dropped:
 * they are skipped by every walk, and a segment never comes back. */
static long cell_of(reader *r, int pt)
{
    double x = r->out->pts[pt][0], y = r->out->pts[pt][1];
    long c = geom_dxf_grid_align(&r->g, &x, &y);
    if (c < 0) return -1;
    cell *p = &r->g.cells[c];
    while (p->head >= 0 && dead(r, r->g.ents[p->head].line))
        p->head = r->g.ents[p->head].next;
    return c;
}

/* Grid2d::eq of two stored points.  They are grid points already, and
 * aligning a grid point again gives itself back (round(ix * 0.001 / 0.001)
 * is ix for |ix| <= 1e15), so the comparison is OpenSCAD's without the
 * second alignment. */
static int grid_eq(const reader *r, int a, int b)
{
    const double *p = r->out->pts[a], *q = r->out->pts[b];
    return fabs(p[0] - q[0]) < GRID && fabs(p[1] - q[1]) < GRID;
}

/* Follow segments from segment cur's end !cp on, disabling each: one path. */
static int walk(reader *r, int cur, int cp, size_t *enabled, long *work)
{
    if (path_add(r, r->lines[cur].p[cp])) return -1;
    for (;;) {
        int end = r->lines[cur].p[!cp];
        if (path_add(r, end)) return -1;
        r->lines[cur].disabled = 1;
        (*enabled)--;
        long c = cell_of(r, end);
        if (c < 0) return -1;
        int next = -1, np = 0;
        for (int e = r->g.cells[c].head; e >= 0 && next < 0; e = r->g.ents[e].next) {
            ++*work;
            int k = r->g.ents[e].line;
            if (dead(r, k)) continue;
            if (grid_eq(r, end, r->lines[k].p[0]))
                next = k, np = 0;
            else if (grid_eq(r, end, r->lines[k].p[1]))
                next = k, np = 1;
        }
        if (next < 0) return 0;
        cur = next;
        cp = np;
    }
}

static int join(reader *r)
{
    size_t enabled = r->nlines;
    long work = 0;
    /* open paths: from the first live segment with an end no other live
     * segment shares */
    while (enabled > 0 && work <= WORK_MAX) {
        int cur = -1, cp = 0;
        for (size_t i = 0; i < r->nlines && cur < 0; i++) {
            if (r->lines[i].disabled) continue;
            for (int j = 0; j < 2 && cur < 0; j++) {
                long c = cell_of(r, r->lines[i].p[j]);
                if (c < 0) return -1;
                int shared = 0;
                for (int e = r->g.cells[c].head; e >= 0 && !shared; e = r->g.ents[e].next) {
                    work++;
                    int k = r->g.ents[e].line;
                    shared = !dead(r, k) && (size_t)k != i;
                }
                if (!shared) cur = (int)i, cp = j;
            }
        }
        if (cur < 0) break;
        if (path_begin(r, 0) || walk(r, cur, cp, &enabled, &work)) return -1;
    }
    /* closed paths: from the first live segment */
    size_t lo = 0;
    while (enabled > 0 && work <= WORK_MAX) {
        while (r->lines[lo].disabled)
            lo++;
        if (path_begin(r, 1) || walk(r, (int)lo, 0, &enabled, &work)) return -1;
    }
    if (work > WORK_MAX)
        say(r, GEOM_DXF_NOTE,
            "DXF file '%s': joining its segments took more than %ld steps; %zu segments are "
            "left out",
            r->abs_path, WORK_MAX, enabled);
    return 0;
}

/* ---- the whole file ------------------------------------------------------ */

void geom_dxf_free(geom_dxf *d)
{
    free(d->pts);
    free(d->idx);
    free(d->path_start);
    free(d->closed);
    for (int i = 0; i < d->ndims; i++)
        free(d->dims[i].name);
    free(d->dims);
    memset(d, 0, sizeof *d);
}

/* The lines of the file's text, as getline reads a stream: a line ends
 * after its '\n' or at the end, and eof is set by the read that reaches
 * the end without one (as feof after getline). */
typedef struct lines {
    const char *p, *end;
    int eof;
    char *buf;
    size_t cap;
} lines;

static char *next_line(lines *L)
{
    size_t n = 0;
    if (L->p >= L->end) {
        L->eof = 1;
    } else {
        const char *nl = memchr(L->p, '\n', (size_t)(L->end - L->p));
        n = nl ? (size_t)(nl - L->p) + 1 : (size_t)(L->end - L->p);
        if (!nl) L->eof = 1;
    }
    if (geom_dxf_grow((void **)&L->buf, &L->cap, n + 1, 1) != 0) return NULL;
    memcpy(L->buf, L->p, n);
    L->buf[n] = 0;
    L->p += n;
    return L->buf;
}

int geom_dxf_read(const char *text, size_t len, const char *abs, const char *rel,
                  const geom_dxf_params *p, geom_dxf_message_fn msg, void *ud, geom_dxf *out)
{
    memset(out, 0, sizeof *out);
    reader r = {.prm = p, .msg = msg, .ud = ud, .abs_path = abs, .rel_path = rel, .out = out};
    out->path_start = malloc(sizeof *out->path_start);
    int rc = out->path_start ? 0 : -1;
    if (out->path_start) {
        out->path_start[0] = 0;
        r.cappaths = 1;
    }
    lines L1 = {text, text + len, 0, NULL, 0};
    lines L2 = {NULL, NULL, 0, NULL, 0};
    while (rc == 0 && !L1.eof) {
        char *l1 = next_line(&L1);
        L2.p = L1.p;
        L2.end = L1.end;
        char *l2 = next_line(&L2);
        L1.p = L2.p;
        L1.eof |= L2.eof;
        if (!l1 || !l2) {
            rc = -1;
            break;
        }
        char *id_str = trim(l1), *data = trim(l2);
        int id;
        if (!parse_int(id_str, &id)) {
            if (!L1.eof) say(&r, GEOM_DXF_WARNING, "Illegal ID '%s' in `%s'", id_str, abs);
            break;
        }
        int g = group(&r, id, data);
        if (g == NOMEM)
            rc = -1;
        else if (g == BAD_VALUE)
            say(&r, GEOM_DXF_WARNING, "Illegal value '%s'in `%s'", data, abs);
        else if (g == SHORT)
            say(&r, GEOM_DXF_WARNING, "Not enough input values for %s. in '%s'", data, abs);
    }
    free(L1.buf);
    free(L2.buf);
    /* libstdc++'s unordered_map lists a few keys newest first */
    for (size_t i = r.nunsupported; rc == 0 && i-- > 0;) {
        if (!p->layer || !*p->layer)
            say(&r, GEOM_DXF_WARNING, "Unsupported DXF Entity '%s' (%lx) in \"%s\".",
                r.unsupported[i].name, (unsigned long)r.unsupported[i].n, r.rel_path);
        else
            say(&r, GEOM_DXF_WARNING, "Unsupported DXF Entity '%s' (%lx) in layer '%s' of %s",
                r.unsupported[i].name, (unsigned long)r.unsupported[i].n, p->layer, r.rel_path);
    }
    if (rc == 0 && r.dropped)
        say(&r, GEOM_DXF_NOTE,
            "DXF file '%s': %ld segments with coordinates not finite or beyond 1e12 are left out",
            abs, r.dropped);
    if (rc == 0 && r.capped)
        say(&r, GEOM_DXF_NOTE, "DXF file '%s' has more than %d segments; the rest is left out", abs,
            GEOM_DXF_MAX_SEGMENTS);
    if (rc == 0) rc = join(&r);
    geom_dxf_grid_free(&r.g);
    free(r.lines);
    geom_dxf_blocks_free(&r.blk);
    free(r.current_block);
    free(r.mode);
    free(r.layer);
    free(r.name);
    free(r.iddata);
    free(r.xv.v);
    free(r.yv.v);
    for (size_t i = 0; i < r.nunsupported; i++)
        free(r.unsupported[i].name);
    free(r.unsupported);
    if (rc) geom_dxf_free(out);
    return rc;
}

int geom_dxf_outlines(const geom_dxf *d, double (**pts)[2], int **start, int *npaths)
{
    *pts = NULL;
    *npaths = 0;
    *start = malloc(((size_t)d->npaths + 1) * sizeof **start);
    size_t total = d->npaths ? (size_t)d->path_start[d->npaths] : 0;
    *pts = malloc((total ? total : 1) * sizeof **pts);
    if (!*start || !*pts) {
        free(*start);
        free(*pts);
        *start = NULL;
        *pts = NULL;
        return -1;
    }
    int k = 0, np = 0;
    (*start)[0] = 0;
    for (int i = 0; i < d->npaths; i++) {
        int a = d->path_start[i], b = d->path_start[i + 1];
        /* toPolygon2d: the points backwards, a closed path's first
         * (repeated at its end) dropped */
        int lo = d->closed[i] ? a + 1 : a;
        if (b - lo < 3) continue;
        for (int j = b - 1; j >= lo; j--) {
            (*pts)[k][0] = d->pts[d->idx[j]][0];
            (*pts)[k][1] = d->pts[d->idx[j]][1];
            k++;
        }
        (*start)[++np] = k;
    }
    *npaths = np;
    return 0;
}
