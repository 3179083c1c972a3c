/*
 * import.c — import() and surface(): geometry read from files, as
 * closed triangle meshes (iv_shape_mesh); a .dxf or .svg drawing is a 2D
 * region (geom/dxf.c and geom/svg.c read them, builtins/dxf.c and
 * builtins/svg.c build the leaf).
 *
 * Files are named relative to the folder of the .scad file that makes the
 * call, as OpenSCAD resolves them.  Reading goes through the injected
 * services (scad_services: read_mesh for mesh files — stl, off, obj,
 * ply, amf, 3mf — read_image for PNG heightmaps), so src/scad needs no
 * file-format library; the text .dat
 * heightmaps are parsed here.  A file that is missing or unreadable is a
 * warning worded as OpenSCAD words it, and builds nothing, as OpenSCAD does.
 * surface()'s polyhedron is geom_heightmap_mesh's.
 */
#include "builtins.h"
#include "../../geom/heightmap.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The extension of path, lower-cased, into ext (at most n bytes). */
static void extension(const char *path, char *ext, size_t n)
{
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    ext[0] = 0;
    if (!dot || (slash && dot < slash)) return;
    size_t i = 0;
    for (dot++; *dot && i + 1 < n; dot++)
        ext[i++] = (char)tolower((unsigned char)*dot);
    ext[i] = 0;
}

/* ---- import ------------------------------------------------------------------- */

enum {
    IM_FILE,
    IM_LAYER,
    IM_CONVEXITY,
    IM_ORIGIN,
    IM_SCALE,
    IM_WIDTH,
    IM_HEIGHT,
    IM_FILENAME,
    IM_LAYERNAME,
    IM_CENTER,
    IM_DPI
};

typedef struct import_args {
    scad_file_arg file;
    double scale;
    int convexity;
    scad_facet_params f;
    int center; /* SVG's center and dpi (72 by default), printed for .svg */
    double dpi;
} import_args;

static void import_read(scad_call *c, void *out)
{
    import_args *p = out;
    /* sic: 2021.01's import() names linear_extrude in its origin warning */
    scad_file_arg_read(c, IM_FILE, IM_LAYER, IM_ORIGIN, IM_FILENAME, IM_LAYERNAME, "linear_extrude",
                       &p->file);
    if (c->arg[IM_FILE].kind == SV_UNDEF && c->arg[IM_FILENAME].kind != SV_UNDEF)
        scad_deprecated_once(c->ev, "filename= is deprecated. Please use file=");
    if (c->arg[IM_LAYER].kind == SV_UNDEF && c->arg[IM_LAYERNAME].kind != SV_UNDEF)
        scad_deprecated_once(c->ev, "layername= is deprecated. Please use layer=");
    p->scale = 1;
    scad_arg_num(c->arg[IM_SCALE], &p->scale);
    if (p->scale <= 0) p->scale = 1;
    p->convexity = scad_arg_int(c->arg[IM_CONVEXITY], 1);
    if (p->convexity <= 0) p->convexity = 1;
    p->f = scad_facets_read(c);
    p->center = c->arg[IM_CENTER].kind == SV_BOOL && c->arg[IM_CENTER].u.b;
    p->dpi = 72;
    if (c->arg[IM_DPI].kind == SV_NUM) {
        if (c->arg[IM_DPI].u.num >= 0.001) {
            p->dpi = c->arg[IM_DPI].u.num;
        } else {
            /* sic: 2021.01's message, its arguments misplaced as it prints them */
            char shown[1024], line[2400];
            const char *f = scad_diag_file_name(c->ev->d, c->st->loc.file, shown, sizeof shown);
            snprintf(line, sizeof line,
                     "WARNING: Invalid dpi value giving, using default of undef dpi. Value must be "
                     "positive and >= 0.001, file %s, import() at line %s",
                     f, f);
            scad_diag_line(c->ev->d, RAYSCAD_MSG_WARNING, line);
        }
    }
}

static int import_print(scad_call *c, const void *args, scad_buf *b)
{
    const import_args *p = args;
    long long mtime = 0;
    scad_buf_puts(b, "import(");
    if (p->file.name)
        scad_file_arg_print(c, &p->file, b, &mtime);
    else
        scad_buf_puts(b, "file = \"\", layer = \"\", origin = [0, 0]");
    char ext[8];
    extension(p->file.name ? p->file.name : "", ext, sizeof ext);
    if (!strcmp(ext, "svg")) {
        scad_buf_printf(b, ", center = %s, dpi = ", p->center ? "true" : "false");
        scad_print_g(b, p->dpi);
    }
    scad_buf_puts(b, ", scale = ");
    scad_print_g(b, p->scale);
    scad_buf_printf(b, ", convexity = %d", p->convexity);
    scad_print_facets(b, p->f, ", ", ", timestamp = ");
    scad_buf_printf(b, "%lld)", mtime);
    return 0;
}

/* The reader's messages in err: '\n'-separated lines, each a warning
 * (prefix before it) or, starting "note: ", a note. */
static void show_messages(scad_call *c, const char *err, const char *prefix)
{
    const char *line = err;
    while (*line) {
        const char *nl = strchr(line, '\n');
        int n = nl ? (int)(nl - line) : (int)strlen(line);
        if (n >= 6 && !strncmp(line, "note: ", 6))
            scad_diag_note(c->ev->d, c->st->loc, "%.*s", n - 6, line + 6);
        else if (n > 0)
            scad_diag_warning(c->ev->d, c->st->loc, "%s%.*s", prefix, n, line);
        line += n + (nl != NULL);
    }
}

static scad_geom *import_build(scad_call *c, const void *args)
{
    const import_args *p = args;
    scad_eval *ev = c->ev;
    const scad_stmt *st = c->st;
    const scad_state *state = c->state;
    const char *name = p->file.name ? p->file.name : "";
    char ext[16];
    extension(name, ext, sizeof ext);
    int amf_3mf = !strcmp(ext, "amf") || !strcmp(ext, "3mf");
    int mesh = amf_3mf || !strcmp(ext, "stl") || !strcmp(ext, "off") || !strcmp(ext, "obj") ||
               !strcmp(ext, "ply");
    if (!strcmp(ext, "dxf")) {
        scad_buf path = {0}, layer = {0};
        scad_file_path(c, name, &path);
        if (p->file.layer.kind == SV_STR)
            scad_buf_puts(&layer, p->file.layer.u.str->s);
        else if (p->file.layer.kind != SV_UNDEF)
            scad_value_format(&layer, p->file.layer, 0);
        scad_geom *g = NULL;
        if (path.oom || layer.oom)
            scad_eval_error(ev, st->loc, "out of memory");
        else
            g = scad_dxf_import(c, scad_buf_str(&path), scad_buf_str(&layer), p->file.origin,
                                p->scale, p->f);
        scad_buf_free(&path);
        scad_buf_free(&layer);
        return g;
    }
    if (!strcmp(ext, "svg")) {
        scad_buf path = {0};
        scad_file_path(c, name, &path);
        scad_geom *g = NULL;
        if (path.oom)
            scad_eval_error(ev, st->loc, "out of memory");
        else
            g = scad_svg_import(c, scad_buf_str(&path), p->dpi, p->center);
        scad_buf_free(&path);
        return g;
    }
    if (!mesh) {
        scad_diag_warning(ev->d, st->loc,
                          "Unsupported file format while trying to import file '\"%s\"'", name);
        return NULL;
    }
    if (!ev->services->read_mesh) {
        scad_eval_error(ev, st->loc, "import() is not available here");
        return NULL;
    }
    scad_buf path = {0};
    scad_file_path(c, name, &path);
    float *v = NULL;
    int32_t *t = NULL;
    int nv = 0, nt = 0;
    char err[2048];
    err[0] = 0;
    scad_geom *g = NULL;
    int read = -1;
    if (!path.oom) scad_file_want(ev->d->opt, scad_buf_str(&path));
    if (path.oom) {
        scad_eval_error(ev, st->loc, "out of memory");
    } else if (!scad_file_stat(ev->d->opt, scad_buf_str(&path), NULL)) {
        /* 2021.01's 3MF reader words it its own way */
        scad_diag_warning(ev->d, st->loc,
                          strcmp(ext, "3mf") ? "Can't open import file '%s'"
                                             : "Could not read file '%s'",
                          scad_buf_str(&path));
    } else {
        read = ev->services->read_mesh(ev->services->ud, scad_buf_str(&path), &v, &nv, &t, &nt, err,
                                       sizeof err);
        /* the AMF and 3MF readers word their warnings as OpenSCAD does */
        show_messages(c, err, read != 0 && !amf_3mf ? "import(): " : "");
    }
    if (read == 0 && nt > 0) {
        /* the service's triangles turn counter-clockwise seen from
         * outside; iv_shape_mesh takes OpenSCAD's clockwise faces */
        double(*V)[3] = malloc((size_t)nv * sizeof *V);
        int *idx = malloc((size_t)nt * 3 * sizeof *idx);
        int *start = malloc((size_t)(nt + 1) * sizeof *start);
        if (V && idx && start) {
            for (int i = 0; i < nv; i++)
                for (int k = 0; k < 3; k++)
                    V[i][k] = v[3 * i + k];
            for (int i = 0; i < nt; i++) {
                idx[3 * i] = t[3 * i];
                idx[3 * i + 1] = t[3 * i + 2];
                idx[3 * i + 2] = t[3 * i + 1];
                start[i] = 3 * i;
            }
            start[nt] = 3 * nt;
            iv_shape s;
            int rc = (ev->for_mesh ? iv_shape_polyhedron_solid : iv_shape_polyhedron)(
                &s, (const double(*)[3])V, nv, idx, start, nt);
            if (rc < 0) {
                scad_diag_note(ev->d, st->loc, "import(): '%s' is not a valid mesh",
                               scad_buf_str(&path));
            } else {
                if (rc == 3 && !ev->for_mesh)
                    scad_diag_note(ev->d, st->loc,
                                   "import(): '%s' is not closed (it has holes); it is drawn "
                                   "as a surface without inside",
                                   scad_buf_str(&path));
                g = scad_geometry_leaf(ev, &s, state);
            }
        } else {
            scad_eval_error(ev, st->loc, "out of memory");
        }
        free(V);
        free(idx);
        free(start);
    }
    free(v);
    free(t);
    scad_buf_free(&path);
    return g;
}

/* ---- surface ------------------------------------------------------------------- */

/* A heightmap file is at most this long. */
#define MAX_HEIGHTMAP_BYTES ((size_t)1 << 28)

typedef geom_heightmap heightmap;

/* OpenSCAD's read_dat: lines of numbers separated by spaces or tabs; blank
 * lines and lines starting with '#' skipped; a ragged row is padded with 0.  A
 * token that is not a number ends the file with a warning, keeping what was
 * read before it, as there.  Returns 0, 1 with a warning sent, or -1 (out
 * of memory). */
static int read_dat(scad_eval *ev, const scad_stmt *st, const char *path, const char *text,
                    size_t textlen, heightmap *m)
{
    double *val = NULL; /* row-major as read, rows of `cap_w` */
    int *len = NULL, rows = 0, caprows = 0, cols = 0, rc = 0, bad = 0;
    double lowest = INFINITY;
    size_t capval = 0, nval = 0;
    const char *at = text, *stop = text + textlen;
    char *line = NULL;
    size_t linecap = 0;
    while (at < stop) {
        const char *nl = memchr(at, '\n', (size_t)(stop - at));
        size_t n_line = nl ? (size_t)(nl - at) + 1 : (size_t)(stop - at);
        if (n_line + 1 > linecap) {
            char *nb = realloc(line, n_line + 1);
            if (!nb) {
                rc = -1;
                break;
            }
            line = nb;
            linecap = n_line + 1;
        }
        memcpy(line, at, n_line);
        line[n_line] = 0;
        at += n_line;
        char *p = line;
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')
            p++;
        if (*p == 0 || *p == '#') continue;
        if (rows == caprows) {
            caprows = caprows ? 2 * caprows : 64;
            int *l = realloc(len, (size_t)caprows * sizeof *l);
            if (!l) {
                rc = -1;
                break;
            }
            len = l;
        }
        int n = 0;
        for (;;) {
            while (*p == ' ' || *p == '\t')
                p++;
            if (*p == 0 || *p == '\r' || *p == '\n') break;
            char *end;
            errno = 0;
            double x = strtod(p, &end);
            if (end == p || (*end && !strchr(" \t\r\n", *end))) {
                scad_diag_warning(ev->d, st->loc,
                                  "Illegal value in '%s': bad lexical cast: source type value "
                                  "could not be interpreted as target",
                                  path);
                bad = 1;
                break;
            }
            if (nval == capval) {
                capval = capval ? 2 * capval : 1024;
                double *v = realloc(val, capval * sizeof *v);
                if (!v) {
                    rc = -1;
                    break;
                }
                val = v;
            }
            val[nval++] = x;
            lowest = fmin(lowest, x);
            n++;
            p = end;
        }
        if (rc) break;
        if (n > 0 || !bad) len[rows++] = n;
        if (n > cols) cols = n;
        if (bad) break;
    }
    free(line);
    if (rc == 0 && rows > 0 && cols > 0) {
        m->z = calloc((size_t)rows * (size_t)cols, sizeof *m->z);
        if (!m->z) {
            rc = -1;
        } else {
            size_t k = 0;
            for (int i = 0; i < rows; i++)
                for (int j = 0; j < len[i]; j++)
                    m->z[(size_t)i * (size_t)cols + (size_t)j] = val[k++];
            m->w = cols;
            m->h = rows;
            m->base = fmin(lowest - 1, 0);
        }
    }
    free(val);
    free(len);
    return rc;
}

/* OpenSCAD's PNG heightmap: the pixel as lodepng's 8-bit RGB (a 16-bit
 * channel keeps its high byte), its luminance 0.2126 R + 0.7152 G + 0.0722 B
 * (0..255) scaled by 100/255; invert takes 1 - luminance (not 255 -: that
 * is OpenSCAD 2021.01's formula, heights go negative).  The image's top row
 * is at the largest y. */
static int read_png(scad_eval *ev, const scad_stmt *st, const char *path, int invert, heightmap *m)
{
    int w, h, ch;
    float *px = NULL;
    char err[512];
    if (!ev->services->read_image) {
        scad_eval_error(ev, st->loc, "surface() of an image is not available here");
        return 1;
    }
    err[0] = 0;
    if (ev->services->read_image(ev->services->ud, path, &w, &h, &ch, &px, err, sizeof err) != 0) {
        /* an image that is there but does not fit is an error, not OpenSCAD's
         * warning for a file it cannot read (the model would lose a part) */
        if (strstr(err, "out of memory")) {
            scad_eval_error(ev, st->loc, "surface(): %s", err);
            return 1;
        }
        scad_diag_warning(ev->d, st->loc, "Can't read PNG image '%s'", path);
        if (err[0]) scad_diag_note(ev->d, st->loc, "surface(): %s", err); /* why, in our words */
        return 1;
    }
    m->z = malloc((size_t)w * (size_t)h * sizeof *m->z);
    if (!m->z) {
        free(px);
        return -1;
    }
    double lowest = INFINITY;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const float *q = px + ((size_t)y * (size_t)w + (size_t)x) * (size_t)ch;
            double c[3];
            for (int k = 0; k < 3; k++) {
                float f = q[ch >= 3 ? k : 0];
                long v16 = lround(fmin(fmax(f, 0), 1) * 65535.0);
                c[k] = (double)(v16 >> 8);
            }
            double lum = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
            double z = 100.0 / 255 * (invert ? 1 - lum : lum);
            m->z[(size_t)(h - 1 - y) * (size_t)w + (size_t)x] = z;
            lowest = fmin(lowest, z);
        }
    free(px);
    m->w = w;
    m->h = h;
    m->base = fmin(lowest - 1, 0);
    return 0;
}

enum { SF_FILE, SF_CENTER, SF_CONVEXITY, SF_INVERT };

typedef struct surface_args {
    const char *file; /* borrowed; "" when none */
    int center, invert;
} surface_args;

static void surface_read(scad_call *c, void *out)
{
    surface_args *p = out;
    scad_value f = c->arg[SF_FILE];
    p->file = f.kind == SV_STR ? f.u.str->s : "";
    p->center = scad_arg_bool(c->arg[SF_CENTER], 0);
    p->invert = scad_arg_bool(c->arg[SF_INVERT], 0);
}

static int surface_print(scad_call *c, const void *args, scad_buf *b)
{
    const surface_args *p = args;
    long long mtime = 0;
    scad_buf path = {0};
    if (c->arg[SF_FILE].kind == SV_STR)
        scad_print_path(c->ev, c->st->loc.file ? c->st->loc.file : "", p->file, &path, &mtime);
    scad_buf_puts(b, "surface(file = ");
    scad_quote_escaped(b, scad_buf_str(&path), strlen(scad_buf_str(&path)));
    scad_buf_free(&path);
    scad_buf_puts(b, ", center = ");
    scad_print_bool(b, p->center);
    scad_buf_puts(b, ", invert = ");
    scad_print_bool(b, p->invert);
    scad_buf_printf(b, ", timestamp = %lld)", mtime);
    return 0;
}

static scad_geom *surface_build(scad_call *c, const void *args)
{
    const surface_args *sa = args;
    scad_eval *ev = c->ev;
    const scad_stmt *st = c->st;
    const scad_state *state = c->state;
    int center = sa->center, invert = sa->invert;
    scad_buf path = {0};
    scad_file_path(c, sa->file, &path);
    if (path.oom) {
        scad_eval_error(ev, st->loc, "out of memory");
        return NULL;
    }
    const char *p = scad_buf_str(&path);
    /* PNG by its signature, as OpenSCAD tells them apart; else text */
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    char err[256];
    size_t len = 0;
    char *text = scad_file_stat(ev->d->opt, p, NULL)
                     ? scad_file_read(ev->d->opt, p, MAX_HEIGHTMAP_BYTES, &len, err, sizeof err)
                     : NULL;
    if (!text) {
        scad_diag_warning(ev->d, st->loc, "The file '%s' couldn't be opened.", p);
        scad_buf_free(&path);
        return NULL;
    }
    heightmap m = {NULL, 0, 0, 0};
    int rc = len >= sizeof sig && !memcmp(text, sig, sizeof sig)
                 ? read_png(ev, st, p, invert, &m)
                 : read_dat(ev, st, p, text, len, &m);
    free(text);
    scad_buf_free(&path);
    scad_geom *g = NULL;
    if (rc < 0) {
        scad_eval_error(ev, st->loc, "out of memory");
    } else if (rc == 0 && m.w > 1 && m.h > 1) {
        iv_shape s;
        if (geom_heightmap_mesh(&m, center, &s) == 0)
            g = scad_geometry_leaf(ev, &s, state);
        else
            scad_eval_error(ev, st->loc, "surface(): out of memory");
    }
    free(m.z);
    return g;
}

static const char *const import_params[] = {"file",      "layer",  "convexity", "origin",
                                            "scale",     "width",  "height",    "filename",
                                            "layername", "center", "dpi",       NULL};
static const scad_module_def import = {"import",    import_params, 5,           sizeof(import_args),
                                       import_read, import_print,  import_build};

static const char *const surface_params[] = {"file", "center", "convexity", "invert", NULL};
static const scad_module_def surface = {
    "surface", surface_params, 3, sizeof(surface_args), surface_read, surface_print, surface_build};

const scad_module_def *const scad_import_modules[] = {&import, &surface, NULL};
