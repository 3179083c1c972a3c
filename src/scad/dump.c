/*
 * dump.c — the evaluated tree as OpenSCAD 2021.01's .csg text
 * (`openscad -o x.csg`): modules expanded into group(), transforms as
 * multmatrix, $fn/$fa/$fs resolved on the nodes that use them.
 *
 * Design: a dump is a second, separate run of the evaluator with
 * scad_eval.dump set (scad_dump_csg_file).  In that mode the evaluator makes
 * no geometry and does not call the geometry builtins at all; it builds
 * OpenSCAD's node tree out of scad_geom nodes that carry only a header text
 * (see eval.h), and the builtin modules are answered here, from their
 * arguments alone — so 2D shapes, extrusions, text or import dump exactly
 * even where rayscad cannot render them, and csg_node building is untouched.
 *
 * Each header is written the way OpenSCAD's Node::toString writes it: most
 * numbers through an ostream (printf "%g": "1e+06", "-0"), matrices and
 * point lists through OpenSCAD's value printer (scad_format_number), and
 * arguments resolved with OpenSCAD's defaults and its loose conversions
 * (a wrong type keeps the default).  Paths of imported files are printed
 * relative to the main file's folder, with the file's mtime as timestamp.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "eval.h"

scad_geom *scad_dump_node(scad_eval *ev, const char *text, scad_geom *list)
{
    scad_geom *g = scad_geom_op(ev, CSG_OP_UNION);
    if (!g) return NULL;
    size_t n = strlen(text);
    char *t = scad_arena_alloc(ev->arena, n + 1);
    if (!t) {
        scad_eval_error(ev, scad_eval_here(ev), "out of memory");
        return NULL;
    }
    memcpy(t, text, n + 1);
    g->text = t;
    scad_geom_add(ev, g, list);
    return g;
}

/* ---- printing -------------------------------------------------------------- */

/* Returns NULL, or the node being written when b ran out of memory. */
static const scad_geom *write_node(scad_buf *b, const scad_geom *g, int indent)
{
    for (int i = 0; i < indent; i++)
        scad_buf_put(b, "\t", 1);
    scad_buf_puts(b, g->text);
    if (g->n == 0) {
        scad_buf_puts(b, ";\n");
        return b->oom ? g : NULL;
    }
    scad_buf_puts(b, " {\n");
    if (b->oom) return g;
    for (int i = 0; i < g->n; i++) {
        const scad_geom *failed = write_node(b, g->kids[i], indent + 1);
        if (failed) return failed;
    }
    for (int i = 0; i < indent; i++)
        scad_buf_put(b, "\t", 1);
    scad_buf_puts(b, "}\n");
    return b->oom ? g : NULL;
}

const scad_geom *scad_dump_write(scad_buf *b, const scad_geom *list)
{
    const scad_geom *failed = NULL;
    if (list && list->text) {
        failed = write_node(b, list, 0);
    } else if (list) {
        for (int i = 0; i < list->n && !failed; i++)
            failed = write_node(b, list->kids[i], 0);
    }
    scad_buf_puts(b, "\n");
    return failed ? failed : b->oom ? list : NULL;
}

/* An ostream's default form of a double (6 significant digits). */
static void put_g(scad_buf *b, double x)
{
    scad_buf_printf(b, "%g", x);
}

static void put_bool(scad_buf *b, int x)
{
    scad_buf_puts(b, x ? "true" : "false");
}

/* A string as OpenSCAD's QuotedString / raw std::string insertion: quotes
 * around the bytes, nothing escaped. */
static void put_quoted(scad_buf *b, const char *s, size_t n)
{
    scad_buf_put(b, "\"", 1);
    scad_buf_put(b, s, n);
    scad_buf_put(b, "\"", 1);
}

/* ---- arguments ------------------------------------------------------------- */

static scad_value arg(const scad_argv *a, const char *name, int pos)
{
    return scad_argv_get(a, name, pos);
}

static int num(scad_value v, double *x)
{
    return scad_to_num(v, x);
}

/* A $-variable: the call's own $-argument, else the dynamic scope. */
static double special(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                      const char *name)
{
    scad_value v = scad_argv_get(a, name, -1);
    if (!scad_argv_given(a, name, -1)) v = scad_env_lookup_cstr(ev, env, name, st->loc, 1, NULL);
    double x = 0;
    num(v, &x);
    return x;
}

/* ", $fn = …, $fa = …, $fs = …" ($fa and $fs clamped at 0.01 as OpenSCAD). */
static void put_fnas(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                     scad_buf *b, int leading_comma)
{
    double fn = special(ev, env, st, a, "$fn");
    double fa = special(ev, env, st, a, "$fa");
    double fs = special(ev, env, st, a, "$fs");
    if (fs < 0.01) fs = 0.01;
    if (fa < 0.01) fa = 0.01;
    scad_buf_puts(b, leading_comma ? ", $fn = " : "$fn = ");
    put_g(b, fn);
    scad_buf_puts(b, ", $fa = ");
    put_g(b, fa);
    scad_buf_puts(b, ", $fs = ");
    put_g(b, fs);
}

/* OpenSCAD's lookup_radius: a numeric diameter wins over the radius. */
static int radius(const scad_argv *a, const char *dname, const char *rname, int rpos, double *out)
{
    double x;
    if (num(arg(a, dname, -1), &x)) {
        *out = x / 2;
        return 1;
    }
    if (num(arg(a, rname, rpos), &x)) {
        *out = x;
        return 1;
    }
    return 0;
}

/* Elements of a numeric vector of exactly n entries into out; an element
 * that is not a number keeps its value (Value::getVec3's loose reading). */
static int vecn(scad_value v, int n, double *out)
{
    if (v.kind != SV_VEC || v.u.vec->n != n) return 0;
    for (int i = 0; i < n; i++)
        num(v.u.vec->v[i], &out[i]);
    return 1;
}

static int as_int(scad_value v, int dflt)
{
    double x;
    if (!num(v, &x) || !isfinite(x)) return dflt;
    if (x >= INT_MAX) return INT_MAX;
    if (x <= INT_MIN) return INT_MIN;
    return (int)x;
}

static int bool_arg(scad_value v, int dflt)
{
    return v.kind == SV_BOOL ? v.u.b : dflt;
}

/* ---- file names ------------------------------------------------------------ */

/* Lexically normalised absolute form of path (no symlinks resolved). */
static char *absolute(const char *path)
{
    char cwd[PATH_MAX];
    size_t n = strlen(path);
    char *joined;
    if (path[0] == '/') {
        joined = malloc(n + 1);
        if (!joined) return NULL;
        memcpy(joined, path, n + 1);
    } else {
        if (!getcwd(cwd, sizeof cwd)) return NULL;
        size_t c = strlen(cwd);
        joined = malloc(c + n + 2);
        if (!joined) return NULL;
        memcpy(joined, cwd, c);
        joined[c] = '/';
        memcpy(joined + c + 1, path, n + 1);
    }
    /* squeeze "//", "/./" and "/x/../" */
    char *out = malloc(strlen(joined) + 2);
    if (!out) {
        free(joined);
        return NULL;
    }
    size_t k = 0;
    const char *p = joined;
    while (*p) {
        while (*p == '/')
            p++;
        if (!*p) break;
        const char *e = strchr(p, '/');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == 1 && p[0] == '.') {
            /* nothing */
        } else if (len == 2 && p[0] == '.' && p[1] == '.') {
            while (k > 0 && out[k - 1] != '/')
                k--;
            if (k > 0) k--;
        } else {
            out[k++] = '/';
            memcpy(out + k, p, len);
            k += len;
        }
        p += len;
    }
    if (k == 0) out[k++] = '/';
    out[k] = 0;
    free(joined);
    return out;
}

/* The path of `name` (as written in the file `from`) relative to the main
 * file's folder, as OpenSCAD prints it; *mtime gets its modification time
 * (0 when it does not exist). */
static void resolve_file(scad_eval *ev, const char *from, const char *name, scad_buf *out,
                         long long *mtime)
{
    scad_buf full = {0};
    if (name[0] != '/') {
        const char *slash = strrchr(from, '/');
        if (slash) scad_buf_put(&full, from, (size_t)(slash - from + 1));
    }
    scad_buf_puts(&full, name);
    struct stat sb;
    *mtime = stat(scad_buf_str(&full), &sb) == 0 ? (long long)sb.st_mtime : 0;
    scad_buf base = {0};
    scad_buf_puts(&base, ev->d->base_dir && ev->d->base_dir[0] ? ev->d->base_dir : ".");
    char *t = absolute(scad_buf_str(&full));
    char *d = absolute(scad_buf_str(&base));
    if (!t || !d) {
        scad_buf_puts(out, name);
    } else {
        /* common prefix by whole components */
        size_t i = 0, last = 0;
        size_t dl = strlen(d);
        if (dl == 1) dl = 0; /* the root folder */
        while (i < dl && t[i] == d[i]) {
            i++;
            if (d[i] == '/' || i == dl) last = i;
        }
        if (i == dl && (t[i] == '/' || t[i] == 0)) last = dl;
        for (size_t k = last; k < dl; k++)
            if (d[k] == '/') scad_buf_puts(out, "../");
        const char *rest = t + last;
        if (*rest == '/') rest++;
        scad_buf_puts(out, rest);
    }
    free(t);
    free(d);
    scad_buf_free(&full);
    scad_buf_free(&base);
}

/* ---- text() ------------------------------------------------------------------ */

/* The ISO 15924 script of a code point, as HarfBuzz guesses a segment's
 * script: NULL for the common and inherited ones (digits, punctuation). */
static const char *script_of(unsigned long c)
{
    static const struct {
        unsigned long lo, hi;
        const char *tag;
    } ranges[] = {
        {'A', 'Z', "Latn"},        {'a', 'z', "Latn"},        {0xAA, 0xAA, "Latn"},
        {0xBA, 0xBA, "Latn"},      {0xC0, 0xD6, "Latn"},      {0xD8, 0xF6, "Latn"},
        {0xF8, 0x24F, "Latn"},     {0x250, 0x2AF, "Latn"},    {0x370, 0x3FF, "Grek"},
        {0x400, 0x52F, "Cyrl"},    {0x530, 0x58F, "Armn"},    {0x591, 0x5FF, "Hebr"},
        {0x600, 0x6FF, "Arab"},    {0x700, 0x74F, "Syrc"},    {0x750, 0x77F, "Arab"},
        {0x780, 0x7BF, "Thaa"},    {0x900, 0x97F, "Deva"},    {0x980, 0x9FF, "Beng"},
        {0xA00, 0xA7F, "Guru"},    {0xA80, 0xAFF, "Gujr"},    {0xB80, 0xBFF, "Taml"},
        {0xE00, 0xE7F, "Thai"},    {0x10A0, 0x10FF, "Geor"},  {0x1100, 0x11FF, "Hang"},
        {0x1E00, 0x1EFF, "Latn"},  {0x1F00, 0x1FFF, "Grek"},  {0x3040, 0x309F, "Hira"},
        {0x30A0, 0x30FF, "Kana"},  {0x3400, 0x4DBF, "Hani"},  {0x4E00, 0x9FFF, "Hani"},
        {0xAC00, 0xD7AF, "Hang"},  {0xFB1D, 0xFB4F, "Hebr"},  {0xFB50, 0xFDFF, "Arab"},
        {0xFE70, 0xFEFF, "Arab"},  {0xFF21, 0xFF3A, "Latn"},  {0xFF41, 0xFF5A, "Latn"},
    };
    for (size_t i = 0; i < sizeof ranges / sizeof ranges[0]; i++)
        if (c >= ranges[i].lo && c <= ranges[i].hi) return ranges[i].tag;
    return NULL;
}

static int script_rtl(const char *tag)
{
    static const char *const rtl[] = {"Arab", "Hebr", "Syrc", "Thaa", "Nkoo", "Samr", "Mand",
                                      "Cprt", "Khar", "Phnx", "Lydi", "Avst", "Armi", "Phli",
                                      "Prti", "Sarb", "Orkh", "Mend", "Nbat", "Palm", "Hatr",
                                      "Hung", "Mani", "Phlp", "Adlm", "Rohg", "Sogo", "Sogd"};
    for (size_t i = 0; i < sizeof rtl / sizeof rtl[0]; i++)
        if (strcmp(rtl[i], tag) == 0) return 1;
    return 0;
}

static unsigned long utf8_next(const unsigned char **p)
{
    const unsigned char *s = *p;
    unsigned long c = *s++;
    int more = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
    if (more) c &= 0x3F >> more;
    while (more-- && (*s & 0xC0) == 0x80)
        c = (c << 6) | (*s++ & 0x3F);
    *p = s;
    return c;
}

static void put_text(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                     scad_buf *b)
{
    scad_value t = arg(a, "text", 0);
    const char *text = t.kind == SV_STR ? t.u.str->s : "";
    size_t tlen = t.kind == SV_STR ? t.u.str->len : 0;
    double size = 10, spacing = 1;
    num(arg(a, "size", 1), &size);
    num(arg(a, "spacing", -1), &spacing);
    scad_value font = arg(a, "font", 2), dir = arg(a, "direction", -1);
    scad_value lang = arg(a, "language", -1), scr = arg(a, "script", -1);
    scad_value ha = arg(a, "halign", -1), va = arg(a, "valign", -1);
    char script[8] = "";
    if (scr.kind == SV_STR && scr.u.str->len > 0) {
        /* hb_script_from_string: four letters, the first upper case */
        size_t n = scr.u.str->len < 4 ? scr.u.str->len : 4;
        for (size_t i = 0; i < 4; i++) {
            char c = i < n ? scr.u.str->s[i] : ' ';
            if (c >= 'A' && c <= 'Z' && i > 0) c = (char)(c + 32);
            if (c >= 'a' && c <= 'z' && i == 0) c = (char)(c - 32);
            script[i] = c;
        }
        script[4] = 0;
    } else {
        const unsigned char *p = (const unsigned char *)text, *end = p + tlen;
        while (p < end) {
            const char *tag = script_of(utf8_next(&p));
            if (tag) {
                memcpy(script, tag, 5);
                break;
            }
        }
    }
    scad_buf_puts(b, "text(text = ");
    put_quoted(b, text, tlen);
    scad_buf_puts(b, ", size = ");
    put_g(b, size);
    scad_buf_puts(b, ", spacing = ");
    put_g(b, spacing);
    scad_buf_puts(b, ", font = ");
    if (font.kind == SV_STR)
        put_quoted(b, font.u.str->s, font.u.str->len);
    else
        put_quoted(b, "", 0);
    scad_buf_puts(b, ", direction = ");
    if (dir.kind == SV_STR && dir.u.str->len)
        put_quoted(b, dir.u.str->s, dir.u.str->len);
    else
        put_quoted(b, script[0] && script_rtl(script) ? "rtl" : "ltr", 3);
    scad_buf_puts(b, ", language = ");
    if (lang.kind == SV_STR && lang.u.str->len)
        put_quoted(b, lang.u.str->s, lang.u.str->len);
    else
        put_quoted(b, "en", 2);
    if (script[0]) {
        scad_buf_puts(b, ", script = ");
        put_quoted(b, script, strlen(script));
    }
    scad_buf_puts(b, ", halign = ");
    if (ha.kind == SV_STR)
        put_quoted(b, ha.u.str->s, ha.u.str->len);
    else
        put_quoted(b, "left", 4);
    scad_buf_puts(b, ", valign = ");
    if (va.kind == SV_STR)
        put_quoted(b, va.u.str->s, va.u.str->len);
    else
        put_quoted(b, "baseline", 8);
    put_fnas(ev, env, st, a, b, 1);
    scad_buf_puts(b, ")");
}

/* ---- colour ------------------------------------------------------------------ */

static void put_color(scad_eval *ev, const scad_stmt *st, const scad_argv *a, scad_buf *b)
{
    float rgba[4] = {-1, -1, -1, 1};
    scad_value c = arg(a, "c", 0);
    if (c.kind == SV_VEC) {
        for (int i = 0; i < 4; i++) {
            double x = 1;
            if (i < c.u.vec->n) {
                x = 0;
                num(c.u.vec->v[i], &x);
            }
            rgba[i] = (float)x;
        }
    } else if (c.kind == SV_STR) {
        char name[64];
        size_t n = c.u.str->len < sizeof name - 1 ? c.u.str->len : sizeof name - 1;
        for (size_t i = 0; i < n; i++) {
            char ch = c.u.str->s[i];
            name[i] = (ch >= 'A' && ch <= 'Z') ? (char)(ch + 32) : ch;
        }
        name[n] = 0;
        float named[4];
        if (c.u.str->len < sizeof name && scad_color_by_name(name, named))
            memcpy(rgba, named, sizeof rgba);
        else if (name[0] == '#' && scad_color_by_hex(name, named))
            memcpy(rgba, named, sizeof rgba);
    }
    double alpha;
    if (num(arg(a, "alpha", 1), &alpha)) rgba[3] = (float)alpha;
    (void)ev, (void)st;
    scad_buf_puts(b, "color([");
    for (int i = 0; i < 4; i++) {
        if (i) scad_buf_puts(b, ", ");
        put_g(b, rgba[i]);
    }
    scad_buf_puts(b, "])");
}

/* ---- the modules ------------------------------------------------------------- */

static const char *const builtins[] = {
    "circle",         "color",      "cube",        "cylinder",  "difference", "group",
    "hull",           "import",     "intersection", "linear_extrude", "minkowski", "mirror",
    "multmatrix",     "offset",     "polygon",     "polyhedron", "projection", "render",
    "resize",         "rotate",     "rotate_extrude", "scale",   "sphere",     "square",
    "surface",        "text",       "translate",   "union",
};

int scad_dump_is_builtin(const char *name)
{
    for (size_t i = 0; i < sizeof builtins / sizeof builtins[0]; i++)
        if (strcmp(builtins[i], name) == 0) return 1;
    return 0;
}

static int is(const scad_stmt *st, const char *name)
{
    return strcmp(st->name, name) == 0;
}

/* file = "…", layer = "…", origin = [x, y] of import and the extrusions. */
static int file_part(scad_eval *ev, const scad_stmt *st, const scad_argv *a, scad_buf *b,
                     int filepos, int layerpos, int originpos, long long *mtime)
{
    scad_value f = arg(a, "file", filepos);
    if (f.kind != SV_STR && is(st, "import")) f = arg(a, "filename", -1);
    if (f.kind != SV_STR) return 0;
    scad_buf path = {0};
    resolve_file(ev, st->loc.file ? st->loc.file : "", f.u.str->s, &path, mtime);
    scad_buf_puts(b, "file = ");
    put_quoted(b, scad_buf_str(&path), strlen(scad_buf_str(&path)));
    scad_buf_free(&path);
    scad_value layer = arg(a, "layer", layerpos);
    if (layer.kind == SV_UNDEF && is(st, "import")) layer = arg(a, "layername", -1);
    scad_buf_puts(b, ", layer = ");
    if (layer.kind == SV_STR)
        put_quoted(b, layer.u.str->s, layer.u.str->len);
    else if (layer.kind == SV_UNDEF)
        put_quoted(b, "", 0);
    else {
        scad_buf s = {0};
        scad_value_format(&s, layer, 0);
        put_quoted(b, scad_buf_str(&s), strlen(scad_buf_str(&s)));
        scad_buf_free(&s);
    }
    double o[2] = {0, 0}, v[2] = {0, 0};
    scad_value ov = arg(a, "origin", originpos);
    /* Value::getVec2: two numbers, or neither is taken */
    if (vecn(ov, 2, v) && ov.u.vec->v[0].kind == SV_NUM && ov.u.vec->v[1].kind == SV_NUM)
        o[0] = v[0], o[1] = v[1];
    scad_buf_puts(b, ", origin = [");
    put_g(b, o[0]);
    scad_buf_puts(b, ", ");
    put_g(b, o[1]);
    scad_buf_puts(b, "]");
    return 1;
}

static void header(scad_eval *ev, scad_env *env, const scad_stmt *st, const scad_argv *a,
                   scad_buf *b, int *children)
{
    double x;
    *children = 1;
    if (is(st, "cube")) {
        double s[3] = {1, 1, 1};
        scad_value size = arg(a, "size", 0);
        if (num(size, &x)) s[0] = s[1] = s[2] = x;
        vecn(size, 3, s);
        scad_buf_puts(b, "cube(size = [");
        put_g(b, s[0]);
        scad_buf_puts(b, ", ");
        put_g(b, s[1]);
        scad_buf_puts(b, ", ");
        put_g(b, s[2]);
        scad_buf_puts(b, "], center = ");
        put_bool(b, bool_arg(arg(a, "center", 1), 0));
        scad_buf_puts(b, ")");
        *children = 0;
    } else if (is(st, "square")) {
        double s[2] = {1, 1};
        scad_value size = arg(a, "size", 0);
        if (num(size, &x)) s[0] = s[1] = x;
        vecn(size, 2, s);
        scad_buf_puts(b, "square(size = [");
        put_g(b, s[0]);
        scad_buf_puts(b, ", ");
        put_g(b, s[1]);
        scad_buf_puts(b, "], center = ");
        put_bool(b, bool_arg(arg(a, "center", 1), 0));
        scad_buf_puts(b, ")");
        *children = 0;
    } else if (is(st, "sphere") || is(st, "circle")) {
        double r = 1;
        radius(a, "d", "r", 0, &r);
        scad_buf_puts(b, st->name);
        scad_buf_puts(b, "(");
        put_fnas(ev, env, st, a, b, 0);
        scad_buf_puts(b, ", r = ");
        put_g(b, r);
        scad_buf_puts(b, ")");
        *children = 0;
    } else if (is(st, "cylinder")) {
        double h = 1, r1 = 1, r2 = 1, r;
        num(arg(a, "h", 0), &h);
        if (radius(a, "d", "r", -1, &r)) r1 = r2 = r;
        radius(a, "d1", "r1", 1, &r1);
        radius(a, "d2", "r2", 2, &r2);
        scad_buf_puts(b, "cylinder(");
        put_fnas(ev, env, st, a, b, 0);
        scad_buf_puts(b, ", h = ");
        put_g(b, h);
        scad_buf_puts(b, ", r1 = ");
        put_g(b, r1);
        scad_buf_puts(b, ", r2 = ");
        put_g(b, r2);
        scad_buf_puts(b, ", center = ");
        put_bool(b, bool_arg(arg(a, "center", 3), 0));
        scad_buf_puts(b, ")");
        *children = 0;
    } else if (is(st, "polygon") || is(st, "polyhedron")) {
        int poly = is(st, "polyhedron");
        scad_value pts = arg(a, "points", 0);
        scad_value second = arg(a, poly ? "faces" : "paths", 1);
        if (poly && second.kind == SV_UNDEF) {
            second = arg(a, "triangles", -1);
            if (second.kind != SV_UNDEF)
                scad_diag_line(ev->d, SCAD_MSG_WARNING,
                               "DEPRECATED: polyhedron(triangles=[]) will be removed in future "
                               "releases. Use polyhedron(faces=[]) instead.");
        }
        int convexity = as_int(arg(a, "convexity", 2), 1);
        if (convexity < 1) convexity = 1;
        scad_buf_puts(b, poly ? "polyhedron(points = " : "polygon(points = ");
        scad_value_format(b, pts, 1);
        scad_buf_puts(b, poly ? ", faces = " : ", paths = ");
        scad_value_format(b, second, 1);
        scad_buf_printf(b, ", convexity = %d)", convexity);
        *children = 0;
    } else if (is(st, "text")) {
        put_text(ev, env, st, a, b);
        *children = 0;
    } else if (is(st, "import")) {
        long long mtime = 0;
        scad_buf_puts(b, "import(");
        if (!file_part(ev, st, a, b, 0, 1, 3, &mtime)) {
            scad_buf_puts(b, "file = \"\", layer = \"\", origin = [0, 0]");
        }
        double scale = 1;
        num(arg(a, "scale", 4), &scale);
        if (scale <= 0) scale = 1; /* as ImportNode */
        int convexity = as_int(arg(a, "convexity", 2), 1);
        if (convexity <= 0) convexity = 1;
        scad_buf_puts(b, ", scale = ");
        put_g(b, scale);
        scad_buf_printf(b, ", convexity = %d", convexity);
        put_fnas(ev, env, st, a, b, 1);
        scad_buf_printf(b, ", timestamp = %lld)", mtime);
        *children = 0;
    } else if (is(st, "surface")) {
        long long mtime = 0;
        scad_value f = arg(a, "file", 0);
        scad_buf path = {0};
        if (f.kind == SV_STR)
            resolve_file(ev, st->loc.file ? st->loc.file : "", f.u.str->s, &path, &mtime);
        scad_buf_puts(b, "surface(file = ");
        put_quoted(b, scad_buf_str(&path), strlen(scad_buf_str(&path)));
        scad_buf_free(&path);
        scad_buf_puts(b, ", center = ");
        put_bool(b, bool_arg(arg(a, "center", 1), 0));
        scad_buf_puts(b, ", invert = ");
        put_bool(b, bool_arg(arg(a, "invert", -1), 0));
        scad_buf_printf(b, ", timestamp = %lld)", mtime);
        *children = 0;
    } else if (is(st, "linear_extrude")) {
        long long mtime = 0;
        scad_buf_puts(b, "linear_extrude(");
        if (file_part(ev, st, a, b, 0, 1, 3, &mtime)) {
            scad_buf_printf(b, ", timestamp = %lld, ", mtime);
            *children = 0;
        }
        double height = 100;
        scad_value hv = arg(a, "height", -1);
        if (hv.kind != SV_UNDEF) {
            num(hv, &height);
        } else if (a->n > 0 && !a->names[0]) {
            num(a->v[0], &height);
        }
        if (!isfinite(height)) height = 100;
        if (height <= 0) height = 0;
        int convexity = as_int(arg(a, "convexity", -1), 0);
        if (convexity <= 0) convexity = 1;
        double sx = 1, sy = 1;
        scad_value sv = arg(a, "scale", 4);
        if (num(sv, &x)) sx = sy = x;
        double s2[2] = {1, 1};
        if (vecn(sv, 2, s2)) sx = s2[0], sy = s2[1];
        if (sx < 0) sx = 0;
        if (sy < 0) sy = 0;
        double twist = 0, slices = 0;
        num(arg(a, "twist", 6), &twist);
        if (!isfinite(twist)) twist = 0;
        num(arg(a, "slices", 7), &slices);
        int nslices = isfinite(slices) ? (int)slices : 0;
        scad_buf_puts(b, "height = ");
        put_g(b, height);
        scad_buf_puts(b, ", center = ");
        put_bool(b, bool_arg(arg(a, "center", 5), 0));
        scad_buf_printf(b, ", convexity = %d", convexity);
        if (twist != 0) {
            scad_buf_puts(b, ", twist = ");
            put_g(b, twist);
        }
        if (nslices > 0) scad_buf_printf(b, ", slices = %d", nslices);
        scad_buf_puts(b, ", scale = [");
        put_g(b, sx);
        scad_buf_puts(b, ", ");
        put_g(b, sy);
        scad_buf_puts(b, "]");
        if (nslices <= 0) put_fnas(ev, env, st, a, b, 1);
        scad_buf_puts(b, ")");
    } else if (is(st, "rotate_extrude")) {
        long long mtime = 0;
        scad_buf_puts(b, "rotate_extrude(");
        if (file_part(ev, st, a, b, 0, 1, 2, &mtime)) {
            double scale = 1;
            num(arg(a, "scale", 3), &scale);
            scad_buf_puts(b, ", scale = ");
            put_g(b, scale);
            scad_buf_printf(b, ", timestamp = %lld, ", mtime);
            *children = 0;
        }
        double angle = 360;
        num(arg(a, "angle", -1), &angle);
        if (!isfinite(angle) || angle <= -360 || angle > 360) angle = 360;
        int convexity = as_int(arg(a, "convexity", -1), 0);
        if (convexity <= 0) convexity = 2;
        scad_buf_puts(b, "angle = ");
        put_g(b, angle);
        scad_buf_printf(b, ", convexity = %d", convexity);
        put_fnas(ev, env, st, a, b, 1);
        scad_buf_puts(b, ")");
    } else if (is(st, "projection")) {
        scad_buf_puts(b, "projection(cut = ");
        put_bool(b, bool_arg(arg(a, "cut", 0), 0));
        scad_buf_printf(b, ", convexity = %d)", as_int(arg(a, "convexity", -1), 0));
    } else if (is(st, "offset")) {
        double delta = 1;
        int round = 1, chamfer = 0;
        scad_value r = arg(a, "r", 0), d = arg(a, "delta", 1);
        if (num(r, &x)) {
            if (isfinite(x)) delta = x;
        } else if (num(d, &x)) {
            if (isfinite(x)) delta = x;
            round = 0;
            chamfer = scad_value_truthy(arg(a, "chamfer", 2));
        }
        scad_buf_puts(b, round ? "offset(r = " : "offset(delta = ");
        put_g(b, delta);
        if (!round) {
            scad_buf_puts(b, ", chamfer = ");
            put_bool(b, chamfer);
        }
        put_fnas(ev, env, st, a, b, 1);
        scad_buf_puts(b, ")");
    } else if (is(st, "minkowski")) {
        scad_buf_printf(b, "minkowski(convexity = %d)", as_int(arg(a, "convexity", -1), 0));
    } else if (is(st, "render")) {
        scad_buf_printf(b, "render(convexity = %d)", as_int(arg(a, "convexity", 0), 1));
    } else if (is(st, "resize")) {
        double ns[3] = {0, 0, 0};
        int aut[3] = {0, 0, 0};
        scad_value nv = arg(a, "newsize", 0), av = arg(a, "auto", 1);
        if (nv.kind == SV_VEC)
            for (int i = 0; i < 3 && i < nv.u.vec->n; i++)
                num(nv.u.vec->v[i], &ns[i]);
        if (av.kind == SV_BOOL) {
            aut[0] = aut[1] = aut[2] = av.u.b;
        } else if (av.kind == SV_VEC) {
            for (int i = 0; i < 3 && i < av.u.vec->n; i++)
                aut[i] = scad_value_truthy(av.u.vec->v[i]);
        }
        scad_buf_puts(b, "resize(newsize = [");
        for (int i = 0; i < 3; i++) {
            if (i) scad_buf_puts(b, ",");
            put_g(b, ns[i]);
        }
        scad_buf_printf(b, "], auto = [%d,%d,%d], convexity = %d)", aut[0], aut[1], aut[2],
                        as_int(arg(a, "convexity", 2), 0));
    } else if (is(st, "color")) {
        put_color(ev, st, a, b);
    } else {
        csg_affine m;
        if (scad_transform_matrix(ev, st, a, m)) {
            scad_buf_puts(b, "multmatrix([");
            for (int i = 0; i < 4; i++) {
                scad_buf_puts(b, i ? ", [" : "[");
                for (int j = 0; j < 4; j++) {
                    char t[32];
                    scad_format_number(i < 3 ? m[i * 4 + j] : (j == 3 ? 1 : 0), t);
                    if (j) scad_buf_puts(b, ", ");
                    scad_buf_puts(b, t);
                }
                scad_buf_puts(b, "]");
            }
            scad_buf_puts(b, "])");
        } else {
            scad_buf_printf(b, "%s()", st->name); /* group, union, difference, … hull */
        }
    }
}

scad_geom *scad_dump_builtin(scad_eval *ev, scad_env *env, const scad_stmt *st,
                             const scad_argv *a)
{
    if (!scad_dump_is_builtin(st->name)) return NULL;
    scad_buf b = {0};
    int children;
    header(ev, env, st, a, &b, &children);
    scad_geom *kids = NULL;
    if (children) {
        scad_state state;
        memcpy(state.xf, csg_affine_identity, sizeof state.xf);
        memset(&state.mat, 0, sizeof state.mat);
        kids = scad_eval_children(ev, env, st, &state, CSG_OP_UNION);
    }
    scad_geom *g = b.oom ? NULL : scad_dump_node(ev, scad_buf_str(&b), kids);
    if (b.oom) scad_eval_error(ev, st->loc, "out of memory");
    scad_buf_free(&b);
    return g;
}
