/*
 * dxf.c — what the language does with DXF drawings (read by
 * dxf.c): import() of a .dxf as a 2D region leaf, and the functions
 * dxf_dim() and dxf_cross() of OpenSCAD 2021.01, with its arguments,
 * defaults and warnings.
 *
 * Files are named relative to the folder of the calling file.  The reader's
 * own warnings carry no location, as OpenSCAD's DxfData gives none; those of
 * the calls read "… in file x.scad, line N".  dxf_dim and dxf_cross read the
 * file with $fn = 36, as OpenSCAD does (it only changes arcs, which neither
 * measures).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../geom/dxf.h"
#include "builtins.h"

typedef struct sink {
    scad_eval *ev;
    scad_loc loc;
} sink;

static void on_message(void *ud, int kind, const char *text)
{
    sink *s = ud;
    if (kind == GEOM_DXF_NOTE) {
        scad_diag_note(s->ev->d, s->loc, "%s", text);
    } else {
        scad_buf b = {0};
        scad_buf_printf(&b, "WARNING: %s", text);
        scad_diag_line(s->ev->d, RAYSCAD_MSG_WARNING, scad_buf_str(&b));
        scad_buf_free(&b);
    }
}

/* Value::toString: a string as is, anything else as str() prints it. */
static void to_string(scad_value v, scad_buf *out)
{
    if (v.kind == SV_STR)
        scad_buf_puts(out, v.u.str->s);
    else
        scad_value_format(out, v, 0);
}

/* Value::getVec2: a list of two numbers, or nothing assigned. */
static int vec2(scad_value v, double o[2])
{
    if (v.kind != SV_VEC || v.u.vec->n != 2 || v.u.vec->v[0].kind != SV_NUM ||
        v.u.vec->v[1].kind != SV_NUM)
        return 0;
    o[0] = v.u.vec->v[0].u.num;
    o[1] = v.u.vec->v[1].u.num;
    return 1;
}

/* ---- dxf_dim and dxf_cross ----------------------------------------------------- */

typedef struct dxf_args {
    scad_buf raw, file, layer, name;
    double origin[2], scale;
} dxf_args;

/* The arguments as OpenSCAD's loop over them reads them (later ones win);
 * unknown and positional ones warn.  with_name: dxf_dim's "name". */
static void read_args(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *fn,
                      int with_name, dxf_args *d)
{
    memset(d, 0, sizeof *d);
    d->scale = 1;
    for (int i = 0; i < a->n; i++) {
        const char *n = a->names[i] ? a->names[i] : "";
        scad_value v = scad_arg_at(a, i);
        scad_buf *into = NULL;
        if (!strcmp(n, "file")) {
            into = &d->raw;
        } else if (!strcmp(n, "layer")) {
            into = &d->layer;
        } else if (with_name && !strcmp(n, "name")) {
            into = &d->name;
        } else if (!strcmp(n, "origin")) {
            int ok = vec2(v, d->origin) && isfinite(d->origin[0]) && isfinite(d->origin[1]);
            if (!ok) {
                scad_buf b = {0};
                scad_value_format(&b, v, 1);
                scad_diag_warning(ev->d, loc, "%s(..., origin=%s) could not be converted", fn,
                                  scad_buf_str(&b));
                scad_buf_free(&b);
            }
        } else if (!strcmp(n, "scale")) {
            if (v.kind == SV_NUM) d->scale = v.u.num;
        } else {
            scad_diag_warning(ev->d, loc, "%s(..., %s=...) is not supported", fn, n);
        }
        if (into) {
            into->n = 0;
            to_string(v, into);
        }
    }
    scad_lookup_file(ev, loc.file ? loc.file : "", scad_buf_str(&d->raw), &d->file);
}

static void free_args(dxf_args *d)
{
    scad_buf_free(&d->raw);
    scad_buf_free(&d->file);
    scad_buf_free(&d->layer);
    scad_buf_free(&d->name);
}

/* The file's name as OpenSCAD shows it in the reader's messages: absolute
 * (lookup_file's), and relative to the working folder
 * (boostfs_uncomplete's). */
static void names(const char *path, char *abs, size_t n, const char **rel)
{
    char cwd[4096];
    if (path[0] == '/' || !getcwd(cwd, sizeof cwd))
        snprintf(abs, n, "%s", path);
    else
        snprintf(abs, n, "%s/%s", cwd, path);
    *rel = path;
    if (path[0] == '/' && getcwd(cwd, sizeof cwd)) {
        size_t k = strlen(cwd);
        if (!strncmp(path, cwd, k) && path[k] == '/') *rel = path + k + 1;
    } else if (!strncmp(path, "./", 2)) {
        *rel = path + 2;
    }
}

/* A DXF file is at most this long (a drawing, not a model). */
#define MAX_DXF_BYTES ((size_t)1 << 28)

/* Read and parse the drawing at path (through the file services) into
 * *dxf.  0; 1 when the file cannot be read (*dxf empty; the caller warns,
 * as OpenSCAD words it for the call); -1 after an out-of-memory error. */
static int read_dxf(scad_eval *ev, scad_loc loc, const char *path, const geom_dxf_params *p,
                    geom_dxf *dxf)
{
    memset(dxf, 0, sizeof *dxf);
    char err[256];
    size_t len;
    char *text =
        path[0] ? scad_file_read(ev->d->opt, path, MAX_DXF_BYTES, &len, err, sizeof err) : NULL;
    if (!text) return 1;
    char abs[4200];
    const char *rel;
    names(path, abs, sizeof abs, &rel);
    sink s = {ev, loc};
    int rc = geom_dxf_read(text, len, abs, rel, p, on_message, &s, dxf);
    free(text);
    if (rc != 0) {
        scad_eval_error(ev, loc, "out of memory");
        return -1;
    }
    return 0;
}

/* Reads the drawing for a function call; 0, or 1 after a warning (no such
 * file) or an error (out of memory). */
static int read_for(scad_eval *ev, scad_loc loc, dxf_args *d, geom_dxf *dxf)
{
    geom_dxf_params p = {scad_buf_str(&d->layer), d->origin[0], d->origin[1], d->scale, 36, 0, 0};
    int rc = read_dxf(ev, loc, scad_buf_str(&d->file), &p, dxf);
    if (rc == 1) scad_diag_warning(ev->d, loc, "Can't open DXF file '%s'!", scad_buf_str(&d->raw));
    return rc != 0;
}

/* The arguments of fname (has_name: it takes a name) and the drawing they
 * name; nonzero when that could not be read (the arguments are freed). */
static int open_dxf(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *fname,
                    int has_name, dxf_args *d, geom_dxf *dxf)
{
    read_args(ev, a, loc, fname, has_name, d);
    if (!read_for(ev, loc, d, dxf)) return 0;
    free_args(d);
    return 1;
}

static double atan2_degrees(double y, double x)
{
    return atan2(y, x) * 180.0 / IV_PI;
}

/* dxf_dim: the measure of the dimension d names in dxf, or undef. */
static scad_value dimension(scad_eval *ev, scad_loc loc, dxf_args *d, const geom_dxf *dxf)
{
    scad_value r = scad_undef();
    const char *want = scad_buf_str(&d->name);
    int found = 0;
    for (int i = 0; i < dxf->ndims && !found; i++) {
        const geom_dxf_dim *m = &dxf->dims[i];
        if (want[0] && strcmp(m->name, want)) continue;
        found = 1;
        const double(*c)[2] = m->coords;
        double x = c[4][0] - c[3][0], y = c[4][1] - c[3][1];
        switch (m->type & 7) {
        case 0: /* rotated, horizontal or vertical */
            r = scad_num(fabs(x * iv_cos_degrees(m->angle) + y * iv_sin_degrees(m->angle)));
            break;
        case 1: /* aligned */
            r = scad_num(sqrt(x * x + y * y));
            break;
        case 2: { /* angular; OpenSCAD's arguments (dx, dy) kept */
            double a1 = atan2_degrees(c[0][0] - c[5][0], c[0][1] - c[5][1]);
            double a2 = atan2_degrees(x, y);
            r = scad_num(fabs(a1 - a2));
            break;
        }
        case 3: /* diameter */
        case 4: /* radius */
            x = c[5][0] - c[0][0];
            y = c[5][1] - c[0][1];
            r = scad_num(sqrt(x * x + y * y));
            break;
        case 6: /* ordinate */
            r = scad_num(m->type & 64 ? c[3][0] : c[3][1]);
            break;
        default: /* 5: angular 3 point, 7 */
            scad_diag_warning(ev->d, loc,
                              "Dimension '%s' in '%s', layer '%s' has unsupported type!", want,
                              scad_buf_str(&d->raw), scad_buf_str(&d->layer));
        }
    }
    if (!found)
        scad_diag_warning(ev->d, loc, "Can't find dimension '%s' in '%s', layer '%s'!", want,
                          scad_buf_str(&d->raw), scad_buf_str(&d->layer));
    return r;
}

/* dxf_cross: where the first two single-segment paths of dxf cross, or
 * undef. */
static scad_value cross(scad_eval *ev, scad_loc loc, dxf_args *d, const geom_dxf *dxf)
{
    scad_value r = scad_undef();
    /* the first two single-segment paths, crossed as infinite lines */
    double c[4][2];
    int j = 0, found = 0;
    for (int i = 0; i < dxf->npaths && !found; i++) {
        int a0 = dxf->path_start[i];
        if (dxf->path_start[i + 1] - a0 != 2) continue;
        for (int k = 0; k < 2; k++, j++) {
            c[j][0] = dxf->pts[dxf->idx[a0 + k]][0];
            c[j][1] = dxf->pts[dxf->idx[a0 + k]][1];
        }
        if (j < 4) continue;
        double dem =
            (c[3][1] - c[2][1]) * (c[1][0] - c[0][0]) - (c[3][0] - c[2][0]) * (c[1][1] - c[0][1]);
        if (dem == 0) break;
        double ua = ((c[3][0] - c[2][0]) * (c[0][1] - c[2][1]) -
                     (c[3][1] - c[2][1]) * (c[0][0] - c[2][0])) /
                    dem;
        r = scad_vec_new(2);
        if (r.kind == SV_VEC) {
            r.u.vec->v[0] = scad_num(c[0][0] + ua * (c[1][0] - c[0][0]));
            r.u.vec->v[1] = scad_num(c[0][1] + ua * (c[1][1] - c[0][1]));
        }
        found = 1;
    }
    if (!found)
        scad_diag_warning(ev->d, loc, "Can't find cross in '%s', layer '%s'!",
                          scad_buf_str(&d->raw), scad_buf_str(&d->layer));
    return r;
}

/* ---- import() ------------------------------------------------------------------ */

scad_geom *scad_dxf_import(scad_call *c, const char *path, const char *layer,
                           const double origin[2], double scale, scad_facet_params f)
{
    scad_eval *ev = c->ev;
    const scad_stmt *st = c->st;
    geom_dxf_params p = {layer, origin[0], origin[1], scale, f.fn, f.fa, f.fs};
    geom_dxf dxf;
    int rc = read_dxf(ev, st->loc, path, &p, &dxf);
    if (rc == 1) {
        char abs[4200];
        const char *rel;
        names(path, abs, sizeof abs, &rel);
        scad_buf b = {0};
        scad_buf_printf(&b, "WARNING: Can't open DXF file '%s'.", abs);
        scad_diag_line(ev->d, RAYSCAD_MSG_WARNING, scad_buf_str(&b));
        scad_buf_free(&b);
        return NULL;
    }
    if (rc != 0) return NULL;
    double(*pts)[2];
    int *start, n;
    scad_geom *g = NULL;
    if (geom_dxf_outlines(&dxf, &pts, &start, &n) != 0) {
        scad_eval_error(ev, st->loc, "out of memory");
    } else if (n > 0) {
        scad_paths outlines = {pts, start, n};
        g = scad_region_geom(ev, &outlines, c->state);
    }
    free(pts);
    free(start);
    geom_dxf_free(&dxf);
    return g;
}

/* dxf_dim and dxf_cross: the drawing their arguments name, measured. */
static scad_value f_dxf(scad_eval *ev, const scad_argv *a, scad_loc loc, const char *fname)
{
    int dim = strcmp(fname, "dxf_dim") == 0;
    dxf_args d;
    geom_dxf dxf;
    if (open_dxf(ev, a, loc, fname, dim, &d, &dxf)) return scad_undef();
    scad_value r = dim ? dimension(ev, loc, &d, &dxf) : cross(ev, loc, &d, &dxf);
    geom_dxf_free(&dxf);
    free_args(&d);
    return r;
}

const scad_function_def scad_dxf_functions[] = {
    {"dxf_cross", "file, layer, origin, scale", f_dxf},
    {"dxf_dim", "file, name, layer, origin, scale", f_dxf},
    {NULL, NULL, NULL},
};
